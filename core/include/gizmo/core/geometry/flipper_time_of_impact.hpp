#pragma once
// Time of impact of a ball against a swinging flipper: a capsule whose axis turns about a fixed
// pivot at constant angular velocity. The gaps are smooth but not polynomial (they hold sin and
// cos of the angle), so they go to the certified subdivision search, which needs bounds on the
// gap's first and second derivatives over any interval; those are derived below.
#include <optional>

#include "gizmo/core/geometry/trajectory.hpp"
#include "gizmo/core/math/roots.hpp"
#include "gizmo/core/math/trig.hpp"

namespace gizmo {

// The capsule's axis direction at time τ: the quarter-turn base rotated by φ0 + ω τ.
template <class Real>
struct SwingingAxis {
  Vec2<Real> pivot;
  int baseQuarter = 0;
  Real phi0{0}, omega{0};
  Real length{0};   // pivot centre to tip centre
  Real radius{0};   // capsule radius

  Vec2<Real> direction(const Real& tau) const {
    Real s, c;
    math::sinCos(Real(phi0 + omega * tau), s, c);
    Vec2<Real> u(c, s);
    for (int i = 0; i < ((baseQuarter % 4) + 4) % 4; ++i) u = Vec2<Real>(-u.y, u.x);
    return u;
  }
};

// Bounds over τ ∈ [a, b] of the ball's offset from the pivot q(τ) and its derivatives.
template <class Real>
struct OffsetBounds {
  Real q, dq, ddq;
};

template <class Real>
OffsetBounds<Real> offsetBounds(const Trajectory<Real>& t, const Vec2<Real>& pivot, const Real& a, const Real& b) {
  const Real half = Real(1) / Real(2);
  const Real m = half * (a + b), w = half * (b - a);
  const Real accel = length(t.a);
  const Real speed = length(t.velocityAt(m)) + accel * w;
  const Real reach = length(t.positionAt(m) - pivot) + speed * w;
  // A little headroom for the rounding in the lengths above keeps the bounds bounds.
  const Real grow = Real(1) + Real(64) * epsilonOf<Real>();
  return OffsetBounds<Real>{reach * grow, speed * grow, accel * grow};
}

// Gap from one long side of the capsule: h = σ (q·n) − (r + radius), n = (u.y, −u.x).
// h' = σ (q'·n + ω q·u); h'' = σ (q''·n + 2ω q'·u − ω² q·n).
template <class Real>
struct SideGap {
  const Trajectory<Real>& ball;
  const SwingingAxis<Real>& axis;
  Real reach;  // ball radius + capsule radius
  Real sigma;  // +1 or −1: which side

  Real value(const Real& tau) const {
    const Vec2<Real> u = axis.direction(tau);
    const Vec2<Real> q = ball.positionAt(tau) - axis.pivot;
    return sigma * dot(q, Vec2<Real>(u.y, -u.x)) - reach;
  }
  Real slope(const Real& tau) const {
    const Vec2<Real> u = axis.direction(tau);
    const Vec2<Real> q = ball.positionAt(tau) - axis.pivot;
    return sigma * (dot(ball.velocityAt(tau), Vec2<Real>(u.y, -u.x)) + axis.omega * dot(q, u));
  }
  Real slopeBound(const Real& a, const Real& b) const {
    const OffsetBounds<Real> o = offsetBounds(ball, axis.pivot, a, b);
    return o.dq + absOf(axis.omega) * o.q;
  }
  Real curvatureBound(const Real& a, const Real& b) const {
    const OffsetBounds<Real> o = offsetBounds(ball, axis.pivot, a, b);
    const Real w = absOf(axis.omega);
    return o.ddq + Real(2) * w * o.dq + w * w * o.q;
  }
};

// Gap from the moving tip circle: g = |e|² − reach², e = q − L u.
// e' = q' − L ω u⊥, e'' = q'' + L ω² u; g' = 2 e·e', g'' = 2|e'|² + 2 e·e''.
template <class Real>
struct TipGap {
  const Trajectory<Real>& ball;
  const SwingingAxis<Real>& axis;
  Real reach;

  Vec2<Real> offset(const Real& tau, Vec2<Real>& u) const {
    u = axis.direction(tau);
    return ball.positionAt(tau) - axis.pivot - axis.length * u;
  }
  Real value(const Real& tau) const {
    Vec2<Real> u;
    const Vec2<Real> e = offset(tau, u);
    return lengthSquared(e) - reach * reach;
  }
  Real slope(const Real& tau) const {
    Vec2<Real> u;
    const Vec2<Real> e = offset(tau, u);
    const Vec2<Real> de = ball.velocityAt(tau) - (axis.length * axis.omega) * Vec2<Real>(-u.y, u.x);
    return Real(2) * dot(e, de);
  }
  Real slopeBound(const Real& a, const Real& b) const {
    const OffsetBounds<Real> o = offsetBounds(ball, axis.pivot, a, b);
    const Real w = absOf(axis.omega);
    return Real(2) * (o.q + axis.length) * (o.dq + axis.length * w);
  }
  Real curvatureBound(const Real& a, const Real& b) const {
    const OffsetBounds<Real> o = offsetBounds(ball, axis.pivot, a, b);
    const Real w = absOf(axis.omega);
    const Real e1 = o.dq + axis.length * w;
    return Real(2) * e1 * e1 + Real(2) * (o.q + axis.length) * (o.ddq + axis.length * w * w);
  }
};

// First contact of a ball (radius r) with a swinging capsule over τ ∈ [0, limit], and which
// feature: 0 and 1 the long sides, 3 the tip (the pivot circle, 2, does not move: the caller
// treats it as a static circle).
template <class Real>
struct SwingContact {
  Real tau;
  int feature;
};

template <class Real>
std::optional<SwingContact<Real>> swingingCapsuleTimeOfImpact(const Trajectory<Real>& ball, const Real& r,
                                                              const SwingingAxis<Real>& axis, const Real& limit) {
  std::optional<SwingContact<Real>> best;
  auto consider = [&](const std::optional<Real>& tau, int feature) {
    if (tau && (!best || *tau < best->tau)) best = SwingContact<Real>{*tau, feature};
  };
  const Real reach = r + axis.radius;
  // Cheap rejection: the ball cannot come within reach of the swept disc around the pivot.
  {
    const Real half = Real(1) / Real(2);
    const Real travel = length(ball.v) * limit + half * length(ball.a) * limit * limit;
    const Real far = axis.length + reach + travel;
    if (far * far < lengthSquared(ball.p - axis.pivot)) return best;
  }
  for (int side = 0; side < 2; ++side) {
    const SideGap<Real> gap{ball, axis, reach, side == 0 ? Real(1) : Real(-1)};
    // The contact point must lie along the axis, with the centre on this side of it (a ball
    // overlapping from the other side is that side's business).
    auto alongAxis = [&](const Real& tau) {
      const Vec2<Real> u = axis.direction(tau);
      const Vec2<Real> q = ball.positionAt(tau) - axis.pivot;
      const Real along = dot(q, u);
      return Real(0) <= along && along <= axis.length && Real(0) <= gap.sigma * dot(q, Vec2<Real>(u.y, -u.x));
    };
    const Real searchEnd = best ? best->tau : limit;
    consider(math::firstEntrySmooth(gap, Real(0), searchEnd, alongAxis), side);
  }
  {
    const TipGap<Real> gap{ball, axis, reach};
    const Real searchEnd = best ? best->tau : limit;
    consider(math::firstEntrySmooth(gap, Real(0), searchEnd, [](const Real&) { return true; }), 3);
  }
  return best;
}

}  // namespace gizmo
