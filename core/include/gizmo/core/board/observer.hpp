#pragma once
// The one seam through which the board reports every event-queue decision
// (docs/architecture.md, seam 2). The replay recorder and the invariant checkers are observers;
// a board without one skips building the reports altogether.
#include <array>
#include <span>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/board/model_rule.hpp"
#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo {

// What an executed event did to the balls it touched.
template <class Real>
struct BallChange {
  GizmoId ball = kNoGizmo;
  Vec2<Real> position;
  Vec2<Real> velocityBefore;
  Vec2<Real> velocityAfter;
};

// An event touches at most two balls (a ball-ball collision), so the outcome lives inline: the
// board reports every executed event without allocating.
template <class Real>
struct EventOutcome {
  std::array<BallChange<Real>, 2> changes;
  std::size_t count = 0;

  void add(const BallChange<Real>& c) { changes[count++] = c; }
  std::span<BallChange<Real>> balls() { return {changes.data(), count}; }
  std::span<const BallChange<Real>> balls() const { return {changes.data(), count}; }
};

template <class Real>
class BoardObserver {
 public:
  virtual ~BoardObserver() = default;
  virtual void eventScheduled(const Event<Real>&) {}
  virtual void eventRemoved(const Event<Real>&) {}
  virtual void eventExecuted(const Event<Real>&, const EventOutcome<Real>&) {}
  virtual void triggerFired(const Real& /*time*/, GizmoId /*source*/, GizmoId /*target*/) {}
  virtual void actionPerformed(const Real& /*time*/, GizmoId /*target*/) {}
  virtual void inputApplied(const Real& /*time*/, int /*key*/, KeyDirection) {}
  virtual void modelRuleApplied(const Real& /*time*/, ModelRule, GizmoId /*gizmo*/, GizmoId /*other*/) {}
  virtual void tickBoundary(const Real& /*time*/) {}
};

}  // namespace gizmo
