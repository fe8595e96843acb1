#pragma once
// The seed's triggers: when a gizmo's trigger fires (a ball hit it), each gizmo connected to it
// performs its action; a key going down or up does the same for the gizmos connected to that key
// and direction. Connections are kept in the order they were made, which is the order the
// actions run in.
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/board_spec.hpp"

namespace gizmo {

class Triggers {
 public:
  // One more gizmo, connected to nothing yet; and the last one gone (a spawned ball unmade).
  void addSource() { bySource_.emplace_back(); }
  void removeLastSource() { bySource_.pop_back(); }

  void connect(GizmoId source, GizmoId target) { bySource_.at(static_cast<std::size_t>(source)).push_back(target); }
  void keyConnect(int key, KeyDirection direction, GizmoId target) {
    byKey_[{key, static_cast<int>(direction)}].push_back(target);
  }

  const std::vector<GizmoId>& targetsOf(GizmoId source) const { return bySource_[static_cast<std::size_t>(source)]; }
  const std::vector<GizmoId>& keyTargets(int key, KeyDirection direction) const {
    const auto it = byKey_.find({key, static_cast<int>(direction)});
    return it == byKey_.end() ? kNone : it->second;
  }

  // Every connection, by source in id order; every key connection, by key and direction.
  template <class Visit>
  void forEachConnection(Visit visit) const {
    for (std::size_t s = 0; s < bySource_.size(); ++s)
      for (GizmoId t : bySource_[s]) visit(GizmoId(s), t);
  }
  template <class Visit>
  void forEachKeyConnection(Visit visit) const {
    for (const auto& [key, targets] : byKey_)
      for (GizmoId t : targets) visit(key.first, static_cast<KeyDirection>(key.second), t);
  }

 private:
  inline static const std::vector<GizmoId> kNone{};
  std::vector<std::vector<GizmoId>> bySource_;
  std::map<std::pair<int, int>, std::vector<GizmoId>> byKey_;  // (key, direction) → targets
};

}  // namespace gizmo
