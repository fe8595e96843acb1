#pragma once
// A board that answers only what a gizmo's own methods ask of it (BoardAccess), over balls the
// test owns: for tests that call one gizmo's timeUntilCollision or collide by hand, without a
// GameBoard's queue in between.
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "gizmo/core/gizmos/ball.hpp"

namespace gizmo::test {

struct StubBall {
  std::string name;
  Vec2<double> position, velocity;
};

class StubBoard final : public BoardAccess<double> {
 public:
  // The balls take the ids 0, 1, ... in order.
  StubBoard(const std::vector<StubBall>& placed, double gravity, bool jammed = false) : jammed_(jammed) {
    params_.gravity = gravity;
    for (const StubBall& b : placed) {
      balls.emplace_back(b.name, b.position, b.velocity);
      balls.back().setId(GizmoId(balls.size() - 1));
    }
  }
  const double& now() const override { return now_; }
  const PhysicsParams<double>& params() const override { return params_; }
  Ball<double>& ballById(GizmoId id) override { return balls[std::size_t(id)]; }
  void markForRecompute(GizmoId) override {}
  void schedule(EventKind, const double&, GizmoId, GizmoId, std::int32_t) override {}
  void reportRule(ModelRule rule, GizmoId, GizmoId) override { rules.push_back(rule); }
  bool jammed() const override { return jammed_; }
  void releaseContactsOn(GizmoId) override {}
  bool roomForBall(const Vec2<double>&, GizmoId, GizmoId) const override { return true; }
  bool cradled(GizmoId, const Vec2<double>&, const Vec2<double>&, GizmoId) const override { return false; }
  bool boxedAlong(GizmoId, const Vec2<double>&, const Vec2<double>&, GizmoId) const override { return false; }
  void performAction(GizmoId) override {}
  GizmoId spawnBall(const Vec2<double>&) override { return kNoGizmo; }

  void setNow(double t) { now_ = t; }

  std::deque<Ball<double>> balls;  // a deque: a ball can be neither copied nor moved
  std::vector<ModelRule> rules;

 private:
  double now_ = 0;
  bool jammed_;
  PhysicsParams<double> params_;
};

}  // namespace gizmo::test
