#pragma once
// GameBoard: what the gizmos ask of the board as they decide (room for a ball, whether a ball is
// cradled or boxed in a row: docs/physics.md, "Piles"), and what its callers look up.
// Included only by the explicit instantiations (core/src/instantiate.hpp).
#include <limits>
#include <optional>
#include <string_view>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/geometry/cradle.hpp"

namespace gizmo {

// Whether a still gizmo other than `except` (the walls, listed in no cell, or one listed in the
// cells around p) has a feature within `reach` of a ball centred at p that `accept` takes, given
// the direction from the feature towards the ball (geometry/cradle.hpp's anyFeatureWithin).
template <class Real>
template <class Accept>
bool GameBoard<Real>::stillFeatureNear(const Vec2<Real>& p, const Real& reach, GizmoId except, Accept accept) const {
  const Real r = Ball<Real>::radius();
  auto near = [&](GizmoId g) {
    if (g == except) return false;
    const Shape<Real>* shape = gizmos_[std::size_t(g)]->restingShape();
    return shape && anyFeatureWithin(*shape, p, r, reach, accept);
  };
  if (near(outerWallsId())) return true;
  bool found = false;
  broadPhase_.forEachFixedNear(Box<Real>::around(p, r + reach), [&](GizmoId g) { found = found || near(g); });
  return found;
}

template <class Real>
Real GameBoard<Real>::infinity() const {
  return Real(std::numeric_limits<double>::max());
}

template <class Real>
std::optional<GizmoId> GameBoard<Real>::find(std::string_view name) const {
  for (const auto& g : gizmos_)
    if (g->name() == name) return g->id();
  return std::nullopt;
}

template <class Real>
Ball<Real>& GameBoard<Real>::ballById(GizmoId id) {
  Ball<Real>* b = gizmo(id).asBall();
  if (!b) throw std::logic_error("gizmo " + std::to_string(id) + " is not a ball");
  return *b;
}

template <class Real>
Real GameBoard<Real>::energy() const {
  Real e(0);
  const Real half = Real(1) / Real(2);
  for (GizmoId id : balls_) {
    const Ball<Real>& b = *gizmos_[static_cast<std::size_t>(id)]->asBall();
    if (b.captured()) continue;
    const Vec2<Real> v = b.velocityAt(now_), p = b.positionAt(now_);
    e += half * lengthSquared(v) + params_.gravity * (Real(kBoardSize) - p.y);
  }
  return e;
}

template <class Real>
bool GameBoard<Real>::roomForBall(const Vec2<Real>& p, GizmoId ball, GizmoId ignore) const {
  const Real r = Ball<Real>::radius(), size(kBoardSize);
  if (p.x - r < Real(0) || size < p.x + r || p.y - r < Real(0) || size < p.y + r) return false;
  const Box<Real> box = Box<Real>::around(p, r);
  for (std::size_t g = 1; g < gizmos_.size(); ++g) {  // the walls (id 0) are checked above
    if (GizmoId(g) == ball || GizmoId(g) == ignore) continue;
    if (const Ball<Real>* other = gizmos_[g]->asBall()) {
      if (!other->captured() && lengthSquared(Vec2<Real>(other->positionAt(now_) - p)) < Real(4) * r * r) return false;
      continue;
    }
    const Box<Real> o = gizmos_[g]->bounds();
    if (box.lo.x < o.hi.x && o.lo.x < box.hi.x && box.lo.y < o.hi.y && o.lo.y < box.hi.y) return false;
  }
  return true;
}

// The other surface is looked for among the gizmos listed in the cells around the ball, and the
// walls (listed in none). Within a minimum bounce's rise, restSpeed²/(2|g|): the farthest the
// bounce that the rule replaces would lift the ball off the surface it struck. (A reach of
// settleRise rested more piles, and made a ball cradled against a flipper that its own hit
// triggered rest and wake every 0.4 ns: campaign seed 3162277660, case 99.) A ball at rest
// (docs/physics.md, "Piles") is a still surface too: a circle of the ball's radius (every ball is
// a candidate; a board holds few enough that the grid is not worth it here).
template <class Real>
bool GameBoard<Real>::cradled(GizmoId ball, const Vec2<Real>& p, const Vec2<Real>& normal, GizmoId by) const {
  if (params_.gravity == Real(0) || !isGizmoId(by)) return false;
  if (!gizmos_[std::size_t(by)]->restingShape() && !ballAtRest(by)) return false;
  const Vec2<Real> gravity(Real(0), params_.gravity);
  const Real r = Ball<Real>::radius();
  const Real rise = params_.restSpeed * params_.restSpeed / (Real(2) * absOf(params_.gravity));
  if (stillFeatureNear(p, rise, by,
                       [&](const Vec2<Real>& towardsBall) { return gravityHeldBetween(towardsBall, normal, gravity); }))
    return true;
  // Between two balls at rest the reach is settleRise: no gizmo's action is in the V, and the
  // V of two balls of a floor row is so flat that a ball falling into it strikes one side, then
  // the other, long before either is within a minimum bounce's rise of it while it touches the
  // first (many-balls: such a ball struck its two sides about 150 times per 1/60 s before it rested).
  const Real ballRise = ballAtRest(by) ? params_.settleRise : rise;
  for (GizmoId other : balls_) {
    if (other == by || other == ball || !ballAtRest(other)) continue;
    const Vec2<Real> d = p - gizmos_[std::size_t(other)]->asBall()->positionAt(now_);
    const Real most = Real(2) * r + ballRise, dist2 = lengthSquared(d);
    if (Real(0) < dist2 && !(most * most < dist2) && gravityHeldBetween(d, normal, gravity)) return true;
  }
  return false;
}

// The line is followed from ball to ball (the nearest slow one ahead, within 30° of m; ties to
// the lower id) and ends when a still gizmo or the walls lie ahead within settleRise. Slow: a
// speed that would rise less than settleRise against gravity. Products and comparisons only.
template <class Real>
bool GameBoard<Real>::boxedAlong(GizmoId ball, const Vec2<Real>& start, const Vec2<Real>& m, GizmoId behind) const {
  if (params_.gravity == Real(0)) return false;
  const Real r = Ball<Real>::radius();
  const Real reach = params_.settleRise;
  const Real slow2 = Real(2) * params_.settleRise * absOf(params_.gravity);
  // `towards` points from an obstacle to the ball: the obstacle lies ahead, within 30° of m.
  auto ahead = [&](const Vec2<Real>& towards) {
    const Real along = -dot(towards, m);
    return Real(0) < along && !(Real(4) * along * along < Real(3) * lengthSquared(towards));
  };
  const Real most = Real(2) * r + reach;
  GizmoId current = ball;
  Vec2<Real> p = start;
  // Each link advances along m by at least √3·r, so a line is shorter than the board is wide;
  // the count of balls bounds it whatever the geometry.
  for (std::size_t links = 0; links <= balls_.size(); ++links) {
    if (stillFeatureNear(p, reach, kNoGizmo, ahead)) return true;
    GizmoId next = kNoGizmo;
    Vec2<Real> nextAt;
    Real nearest2(0);
    broadPhase_.forEachBallNear(Box<Real>::around(p, most + r), [&](GizmoId other) {
      if (other == current || other == behind || other == ball) return;
      const Ball<Real>& o = *gizmos_[std::size_t(other)]->asBall();
      if (o.captured() || !(lengthSquared(o.velocityAt(now_)) < slow2)) return;
      const Vec2<Real> q = o.positionAt(now_);
      const Real dist2 = lengthSquared(Vec2<Real>(q - p));
      if (most * most < dist2 || !ahead(Vec2<Real>(p - q))) return;
      if (next == kNoGizmo || dist2 < nearest2 || (dist2 == nearest2 && other < next)) {
        next = other;
        nextAt = q;
        nearest2 = dist2;
      }
    });
    if (next == kNoGizmo) return false;
    current = next;
    p = nextAt;
  }
  return false;
}

template <class Real>
bool GameBoard<Real>::ballAtRest(GizmoId id) const {
  const Ball<Real>* b = gizmos_[std::size_t(id)]->asBall();
  return b && !b->captured() && b->resting();
}

}  // namespace gizmo
