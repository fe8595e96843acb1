#pragma once
// The pinch rule's count (docs/physics.md, the pinch rule), shared by the gizmos that turn: how
// often each ball was struck in one swing of a flipper or one turning of a spinner. A ball struck
// more than the board's pinchLimit times in one swing is pinched against something, and the
// gizmo stops where it stands instead of pushing through it.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "gizmo/core/board/board_state.hpp"
#include "gizmo/core/board/event.hpp"

namespace gizmo {

class PinchCount {
 public:
  // Counts a hit on `ball`; true when it is more than `limit` in this swing.
  bool hit(GizmoId ball, int limit) {
    auto it = std::find_if(hits_.begin(), hits_.end(), [&](const auto& h) { return h.first == ball; });
    if (it == hits_.end()) it = hits_.insert(hits_.end(), {ball, 0});
    return ++it->second > limit;
  }
  void clear() { hits_.clear(); }

  // As part of the gizmo's saved state: the number of balls, then each ball and its count.
  template <class Real>
  void save(GizmoState<Real>& out) const {
    out.ints.push_back(std::int64_t(hits_.size()));
    for (const auto& [ball, count] : hits_) out.ints.insert(out.ints.end(), {ball, count});
  }
  template <class Real>
  void restore(GizmoStateReader<Real>& in, const GizmoIdCheck& ids, const char* owner) {
    const std::int64_t n = in.integer(0, 1 << 20);
    hits_.clear();
    for (std::int64_t k = 0; k < n; ++k) {
      const std::int64_t ball = in.integer();
      if (!ids.isBall(ball)) throw StateError(std::string(owner) + " hits: not a ball");
      hits_.emplace_back(static_cast<GizmoId>(ball), static_cast<int>(in.integer(0, std::numeric_limits<int>::max())));
    }
  }

 private:
  std::vector<std::pair<GizmoId, int>> hits_;
};

}  // namespace gizmo
