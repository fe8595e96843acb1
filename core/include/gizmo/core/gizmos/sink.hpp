#pragma once
// The sink (docs/physics.md, "Gizmos other programs added"), lheckemann/gizmoball's addition: a
// square that takes every ball that hits it out of play. lheckemann's Sink deletes the ball
// (Sink.java:23-33); here the ball stays on the board's list, captured at the sink's centre for
// good, so that a ball's id names one ball from one decision to the next. A captured ball meets
// nothing, feels no force and counts for no energy, as in an absorber. The hit fires the sink's
// own triggers, as any gizmo's does: lheckemann's logic-gate boards connect sinks to spawners,
// and a spawner takes the balls the sinks hold before it adds one to the board (the ball a sink
// took first, from the sink of lowest id), so that such a loop does not grow the board for ever.
#include <deque>

#include "gizmo/core/gizmos/polygonal_gizmo.hpp"

namespace gizmo {

// The sink's rule (model_rule.hpp): its code is in logs.
struct SinkRule {
  static constexpr ModelRule Sunk{11};  // it took a ball out of play
};

template <class Real>
class Sink final : public GridBumper<Real> {
 public:
  explicit Sink(const GizmoSpec& spec) : GridBumper<Real>(spec) {}

  GizmoKind kind() const override { return GizmoKind::Sink; }
  // It does more than reflect (it sinks): no ball rests against it.
  const Shape<Real>* restingShape() const override { return nullptr; }

  std::optional<Vec2<Real>> heldBallPosition() const override { return this->centre(); }

  GizmoId handBackRetiredBall() override {
    if (held_.empty()) return kNoGizmo;
    const GizmoId ball = held_.front();
    held_.pop_front();
    return ball;
  }

  // The balls it holds, in the order it took them (none: the state of a sink before spawners).
  void saveState(GizmoState<Real>& out) const override { out.ints.assign(held_.begin(), held_.end()); }
  void restoreState(GizmoStateReader<Real>& in, const GizmoIdCheck& ids) override {
    held_.clear();
    while (std::optional<std::int64_t> id = in.optionalInteger()) {
      if (!ids.isBall(*id)) throw StateError("sink state: " + std::to_string(*id) + " is not a ball");
      held_.push_back(static_cast<GizmoId>(*id));
    }
  }

 protected:
  void respond(Ball<Real>& ball, const Contact<Real>&, BoardAccess<Real>& board) override {
    ball.leaveContact(board);
    ball.capture(board.now(), this->centre());
    held_.push_back(ball.id());
    board.reportRule(SinkRule::Sunk, this->id(), ball.id());
  }

 private:
  std::deque<GizmoId> held_;
};

}  // namespace gizmo
