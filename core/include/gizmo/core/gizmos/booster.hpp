#pragma once
// The booster (docs/physics.md, "Gizmos other programs added"), d-g-n/CS308-GizmoBall's
// addition: a triangular bumper that reflects the ball like any bumper and then doubles its
// speed, unless the doubled speed would pass kMaxBoostedSpeed. Doubling is exact in every
// scalar, and the cap is a comparison of squares: no square root, no library call.
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"

namespace gizmo {

// The fastest speed a booster produces, in L/s. Without a cap a ball that bounces between
// boosters doubles its speed on every round trip (d-g-n's multiballabsorber.txt reaches 1e13 L/s
// in the classic model, where each step then crosses the board many times over). 5000 L/s is
// the fastest speed the rest of the project is built and checked for: the fuzz generators'
// fastest ball, the speed at which the models-agree property's time tolerance is sized, and
// beyond the friction law's 4000 L/s limit at the default constants, so a booster never takes
// a ball where the checks do not reach.
inline constexpr double kMaxBoostedSpeed = 5000;

// The booster's rule (model_rule.hpp): its code is in logs.
struct BoosterRule {
  static constexpr ModelRule Boosted{9};  // it doubled a ball's speed
};

template <class Real>
class Booster final : public GridBumper<Real> {
 public:
  explicit Booster(const GizmoSpec& spec) : GridBumper<Real>(spec) {}

  GizmoKind kind() const override { return GizmoKind::Booster; }
  // It does more than reflect (it boosts): no ball rests against it.
  const Shape<Real>* restingShape() const override { return nullptr; }

  // The boost applied to a velocity: doubled when the doubled speed is at most the cap,
  // otherwise unchanged (nullopt).
  static std::optional<Vec2<Real>> boosted(const Vec2<Real>& v) {
    if (v == Vec2<Real>()) return std::nullopt;
    const Real cap = fromDouble<Real>(kMaxBoostedSpeed);
    if (cap * cap < Real(4) * lengthSquared(v)) return std::nullopt;
    return Vec2<Real>(Real(2) * v.x, Real(2) * v.y);
  }

 protected:
  void respond(Ball<Real>& ball, const Contact<Real>& contact, BoardAccess<Real>& board) override {
    const Real& now = board.now();
    const Vec2<Real> before = ball.velocityAt(now);
    GridBumper<Real>::respond(ball, contact, board);
    // A hit that changed nothing (the ball was not approaching after all) boosts nothing.
    const Vec2<Real> after = ball.velocityAt(now);
    if (after == before) return;
    const std::optional<Vec2<Real>> v = boosted(after);
    if (!v) return;
    board.reportRule(BoosterRule::Boosted, this->id(), ball.id());
    ball.setVelocity(now, ball.positionAt(now), *v, board);
  }
};

}  // namespace gizmo
