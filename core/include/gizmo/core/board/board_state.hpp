#pragma once
// Everything a board remembers between events, as plain data: enough to stop a run, store it,
// and carry on later with every decision as it would have been (the replay log's keyframes).
// The layout of the board itself (gizmos, connections, inputs) is not part of it: a state is
// restored onto a board built from the same spec.
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/geometry/trajectory.hpp"

namespace gizmo {

// A gizmo's own state: scalars and integers in the order the gizmo writes them.
template <class Real>
struct GizmoState {
  std::vector<Real> reals;
  std::vector<std::int64_t> ints;

  bool operator==(const GizmoState&) const = default;
};

template <class Real>
struct BoardState {
  Real now{0};
  std::uint64_t executedTotal = 0;
  std::array<std::uint64_t, kEventKindCount> executed{};
  std::uint64_t eventsInBurst = 0;
  Real jamWindowStart{0};
  std::uint64_t collisionsInWindow = 0;
  std::uint64_t nextInput = 0;
  // The queue: live events in scheduling order, and the next sequence number to hand out.
  std::vector<Event<Real>> events;
  std::uint64_t nextSequence = 0;
  // The broad phase, per gizmo: where it can be until its predictions run out. Kept because the
  // candidates it selects decide which predictions are made, and so the sequence numbers.
  std::vector<Box<Real>> boxes;
  std::vector<Real> validUntil;
  std::vector<GizmoState<Real>> gizmos;
};

// A restored state that cannot belong to the board it is restored onto.
class StateError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Reads a GizmoState back in the order it was written, refusing to read past its end.
template <class Real>
class GizmoStateReader {
 public:
  explicit GizmoStateReader(const GizmoState<Real>& s) : s_(s) {}
  const Real& real() {
    if (r_ >= s_.reals.size()) throw StateError("gizmo state: too few numbers");
    return s_.reals[r_++];
  }
  std::int64_t integer() {
    if (i_ >= s_.ints.size()) throw StateError("gizmo state: too few integers");
    return s_.ints[i_++];
  }
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    const std::int64_t v = integer();
    if (v < lo || v > hi)
      throw StateError("gizmo state: " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "]");
    return v;
  }
  bool flag() { return integer(0, 1) != 0; }
  // The next integer, or nothing at the end of them (a list that runs to the end of the state).
  std::optional<std::int64_t> optionalInteger() {
    if (i_ >= s_.ints.size()) return std::nullopt;
    return s_.ints[i_++];
  }
  void expectEnd() const {
    if (r_ != s_.reals.size() || i_ != s_.ints.size()) throw StateError("gizmo state: unexpected extra values");
  }

 private:
  const GizmoState<Real>& s_;
  std::size_t r_ = 0, i_ = 0;
};

// What a gizmo may check while restoring: whether an id names a ball.
class GizmoIdCheck {
 public:
  virtual ~GizmoIdCheck() = default;
  virtual bool isBall(std::int64_t id) const = 0;
  virtual bool isGizmo(std::int64_t id) const = 0;
};

}  // namespace gizmo
