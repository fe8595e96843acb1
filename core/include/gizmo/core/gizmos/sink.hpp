#pragma once
// The sink (docs/physics.md, "Gizmos other programs added"), lheckemann/gizmoball's addition: a
// square that takes every ball that hits it out of play. lheckemann's Sink deletes the ball
// (Sink.java:23-33); here the ball stays on the board's list, captured at the sink's centre for
// good, so that a ball's id names the same ball from the first decision of a log to the last. A
// captured ball meets nothing, feels no force and counts for no energy, as in an absorber; no
// trigger ever fires it again. The hit fires the sink's own triggers, as any gizmo's does:
// lheckemann's logic-gate boards connect sinks to spawners.
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"

namespace gizmo {

template <class Real>
class Sink final : public GridBumper<Real> {
 public:
  explicit Sink(const GizmoSpec& spec) : GridBumper<Real>(spec) {}

  GizmoKind kind() const override { return GizmoKind::Sink; }

 protected:
  void respond(Ball<Real>& ball, const Contact<Real>&, BoardAccess<Real>& board) override {
    ball.leaveContact(board);
    ball.capture(board.now(), this->centre());
    board.reportRule(ModelRule::Sunk, this->id(), ball.id());
  }
};

}  // namespace gizmo
