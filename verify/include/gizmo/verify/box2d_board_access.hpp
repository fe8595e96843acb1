#pragma once
// The core's gizmos ask a BoardAccess for the time, the constants and the balls when they act.
// The Box2D bridge drives the core's own flippers, spinners and absorbers (their swing and turn
// schedules, their capture queue) outside any event queue: this access gives them a clock that
// the bridge sets and balls that mirror Box2D's bodies, and ignores what only the event queue
// needs (recomputation, scheduling, sliding contacts).
#include <functional>
#include <utility>

#include "gizmo/core/gizmos/ball.hpp"

namespace gizmo::verify {

class DrivenBoardAccess final : public BoardAccess<double> {
 public:
  using BallLookup = std::function<Ball<double>&(GizmoId)>;
  DrivenBoardAccess(const PhysicsParams<double>& params, BallLookup balls)
      : params_(params), balls_(std::move(balls)) {}

  void setNow(double t) { now_ = t; }
  const double& now() const override { return now_; }
  const PhysicsParams<double>& params() const override { return params_; }
  Ball<double>& ballById(GizmoId id) override { return balls_(id); }
  void markForRecompute(GizmoId) override {}
  void schedule(EventKind, const double&, GizmoId, GizmoId, std::int32_t) override {}
  void reportRule(ModelRule, GizmoId, GizmoId) override {}
  bool jammed() const override { return false; }
  void releaseContactsOn(GizmoId) override {}
  // Box2D moves the bodies: a teleporter is a circle bumper here, and says where the runs part.
  bool roomForBall(const Vec2<double>&, GizmoId, GizmoId) const override { return false; }
  bool cradled(GizmoId, const Vec2<double>&, const Vec2<double>&, GizmoId) const override { return false; }
  bool boxedAlong(GizmoId, const Vec2<double>&, const Vec2<double>&, GizmoId) const override { return false; }
  // The driver calls a gizmo's action itself (a spinner's on its own hits, box2d_driver.cpp);
  // a board with a spawner, whose action adds balls, is refused before it gets here.
  void performAction(GizmoId) override {}
  GizmoId spawnBall(const Vec2<double>&) override { return kNoGizmo; }

 private:
  PhysicsParams<double> params_;
  BallLookup balls_;
  double now_ = 0;
};

}  // namespace gizmo::verify
