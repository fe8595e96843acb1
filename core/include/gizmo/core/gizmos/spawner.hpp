#pragma once
// The spawner (docs/physics.md, "Gizmos other programs added"), lheckemann/gizmoball's addition:
// a cell that nothing meets (Spawner.java has no segments and no circles: balls pass through
// it), whose action puts a ball at its centre (Spawner.java, trigger()). lheckemann's ball starts
// with a random speed of about 1e-10 L/s; here it starts at rest, as no random source enters the
// core. The ball is one a sink took, if any sink holds one, or else a new ball of the board
// (BoardAccess::spawnBall). Where the centre has no room (a ball still there, as when a key
// fires it twice before gravity has taken the first away) the action puts nothing, and the log
// says so: lheckemann's would stack the two balls into each other.
#include "gizmo/core/gizmos/abstract_gizmo.hpp"
#include "gizmo/core/gizmos/ball.hpp"
#include "gizmo/core/gizmos/grid_properties.hpp"

namespace gizmo {

// The spawner's rules (model_rule.hpp): their codes are in logs.
struct SpawnerRule {
  static constexpr ModelRule Spawned{13};  // it put a ball at its centre (the other gizmo: that ball)
  static constexpr ModelRule Blocked{14};  // it acted with no room at its centre, or no ball to be had
};

template <class Real>
class Spawner final : public GridPlaced<AbstractGizmo<Real>> {
 public:
  explicit Spawner(const GizmoSpec& spec) : GridPlaced<AbstractGizmo<Real>>(spec, spec.name) { placed(); }

  GizmoKind kind() const override { return GizmoKind::Spawner; }
  CollisionAnswer canCollideWith(const AbstractGizmo<Real>&) const override { return CollisionAnswer::NeverCollides; }
  // Never hit, so it fires no trigger of its own.
  bool hasTrigger() const override { return false; }
  Box<Real> bounds() const override { return cell_; }

  Vec2<Real> centre() const {
    const Real half = Real(1) / Real(2);
    return Vec2<Real>(cell_.lo.x + half, cell_.lo.y + half);
  }

  std::optional<Vec2<Real>> spawnPosition() const override { return centre(); }

  void fireTrigger(BoardAccess<Real>& board) override {
    const Vec2<Real> p = centre();
    const GizmoId ball = board.roomForBall(p, kNoGizmo, this->id()) ? board.spawnBall(p) : kNoGizmo;
    board.reportRule(ball == kNoGizmo ? SpawnerRule::Blocked : SpawnerRule::Spawned, this->id(), ball);
  }

 protected:
  void placed() override {
    const GizmoSpec& s = this->placement();
    cell_ = Box<Real>{Vec2<Real>(Real(s.x), Real(s.y)), Vec2<Real>(Real(s.x + 1), Real(s.y + 1))};
  }

 private:
  Box<Real> cell_;
};

}  // namespace gizmo
