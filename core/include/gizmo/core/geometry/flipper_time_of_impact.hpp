#pragma once
// Time of impact of a ball against a swinging flipper: a capsule whose axis turns about a fixed
// pivot at constant angular velocity. The gaps are smooth but not polynomial (they hold sin and
// cos of the angle), so they go to the certified subdivision search, which needs bounds on the
// gap's first and second derivatives over any interval; those are derived below.
#include <optional>

#include "gizmo/core/geometry/time_of_impact.hpp"
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
  Real length{0};  // pivot centre to tip centre
  Real radius{0};  // capsule radius

  Vec2<Real> direction(const Real& tau) const {
    Real s, c;
    math::sinCos(Real(phi0 + omega * tau), s, c);
    Vec2<Real> u(c, s);
    for (int i = 0; i < ((baseQuarter % 4) + 4) % 4; ++i) u = Vec2<Real>(-u.y, u.x);
    return u;
  }
};

// The axis as it stands τ from now (direction(0) of the result is direction(τ) of this one).
template <class Real>
SwingingAxis<Real> axisAfter(SwingingAxis<Real> axis, const Real& tau) {
  axis.phi0 = Real(axis.phi0 + axis.omega * tau);
  return axis;
}

// The axis a quarter turn on: the normal of its side 0 is this axis's direction.
template <class Real>
SwingingAxis<Real> quarterTurned(SwingingAxis<Real> axis) {
  ++axis.baseQuarter;
  return axis;
}

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

// The swinging capsule's surface where a ball (path anchored at the present, radius r) meets
// feature 0 or 1 (a long side) or 3 (the tip), at the present:
// - normal: from the surface toward the ball's centre;
// - surfaceVelocity: the velocity of the surface point under the ball (ω × its offset);
// - gap: the distance between the two surfaces (negative: overlapping);
// - bend: what the capsule's own motion adds to the gap's second derivative, besides the
//   ball's acceleration along the normal. A ball touching a capsule that turns into it with no
//   closing speed (at the pivot the surface does not move) is pressed by this alone.
// A side's gap is h = σ q·n − reach with n = (u.y, −u.x) turning at ω, so
// h'' = σ(q''·n + 2ω q'·u − ω² q·n) = q''·n_σ + σ 2ω q'·u − ω² q·n_σ for the side's normal n_σ = σ n.
// The tip's is d = |e| − reach with e = q − L u, so d'' = e''·ê + (|e'|² − (e'·ê)²)/|e|,
// where e' = q' − Lω u⊥ and e'' = q'' + Lω² u.
template <class Real>
struct SwingTouch {
  Vec2<Real> normal, surfaceVelocity;
  Real gap{0}, bend{0};
  bool alongAxis = true;  // a side's contact point lies on the side, the centre on its side
};

// The velocity of the capsule's surface point under a ball centred at p (radius r, normal n
// from the surface to the centre): ω × its offset from the pivot.
template <class Real>
Vec2<Real> swingSurfaceVelocity(const SwingingAxis<Real>& axis, const Vec2<Real>& p, const Real& r,
                                const Vec2<Real>& n) {
  const Vec2<Real> offset = p - r * n - axis.pivot;
  return axis.omega * Vec2<Real>(-offset.y, offset.x);
}

template <class Real>
std::optional<SwingTouch<Real>> swingTouchNow(const Trajectory<Real>& ball, const Real& r,
                                              const SwingingAxis<Real>& axis, int feature) {
  const Vec2<Real> u = axis.direction(Real(0));
  const Vec2<Real> q = ball.p - axis.pivot;
  const Real reach = r + axis.radius;
  SwingTouch<Real> touch;
  if (feature == 0 || feature == 1) {
    touch.normal = feature == 0 ? Vec2<Real>(u.y, -u.x) : Vec2<Real>(-u.y, u.x);
    const Real across = dot(q, touch.normal);
    const Real along = dot(q, u);
    touch.gap = across - reach;
    // σ = +1 for side 0, −1 for side 1: it turns the Coriolis term with the side (across
    // already has it, through the side's normal). Without it a ball running along side 1 as
    // that side turned into it counted as opening and was not hit: it passed into the flipper
    // (a generated board of the fuzzer's first draw, classic, gravity 1000: docs/fuzzing.md).
    const Real sigma = feature == 0 ? Real(1) : Real(-1);
    touch.bend = sigma * Real(2) * axis.omega * dot(ball.v, u) - axis.omega * axis.omega * across;
    // At the pivot end, closer than the ball's position resolution counts as along the side: a
    // ball on the pivot's circle is met by the side where its end comes under the ball
    // (sideEndComesUnder below), and there `along` is zero only to within rounding. The tip end
    // needs no such rule: the tip's circle moves with the side, and its own gap closes.
    // But a side whose end is leaving the ball (along falling: (q·u)' = q'·u + ω q·u⊥ < 0) is not
    // under it: the ball stays on the pivot's circle, which turns in place, and the side's bend
    // (its line turning into the ball) never reaches it. Counted, it struck a still ball off the
    // pivot at the minimum bounce as the flipper swung away (campaign seed 173205080, case 272).
    // Nor is a side whose end leaves a ball sitting on it so near that end that the ball is off it,
    // at the rate the end leaves, before the side presses into it by its position resolution:
    // ½ p (along / rate)² ≤ resolution for the press p of the ball's acceleration and the side's
    // bend. Counted, a ball 4.5e-14 L from the pivot end (50 ulps of rounding) was struck at the
    // minimum bounce as the flipper swung away in the ballistic run, and not in the classic one,
    // whose ball lay a hair nearer the end (seed 223606798, case 2158): the press would be 2e-27 L.
    const Real behindPivot = positionResolution(ball.p);
    const Real alongRate = dot(ball.v, u) + axis.omega * dot(q, Vec2<Real>(-u.y, u.x));
    const Real press = -(dot(ball.a, touch.normal) + touch.bend);
    const bool offBeforePressed =
        Real(0) < press && Real(press * along * along) <= Real(Real(2) * behindPivot * alongRate * alongRate);
    const bool endLeaving = alongRate < Real(0) && (along < behindPivot || offBeforePressed);
    touch.alongAxis = -behindPivot <= along && along <= axis.length && Real(0) <= across && !endLeaving;
  } else if (feature == 3) {
    const Vec2<Real> e = ball.p - (axis.pivot + axis.length * u);
    const Real distance = length(e);
    if (distance == Real(0)) return std::nullopt;
    touch.normal = Vec2<Real>(e.x / distance, e.y / distance);
    touch.gap = distance - reach;
    const Vec2<Real> de = ball.v - (axis.length * axis.omega) * Vec2<Real>(-u.y, u.x);
    const Real radial = dot(de, touch.normal);
    touch.bend =
        axis.length * axis.omega * axis.omega * dot(u, touch.normal) + (lengthSquared(de) - radial * radial) / distance;
  } else {
    return std::nullopt;
  }
  touch.surfaceVelocity = swingSurfaceVelocity(axis, ball.p, r, touch.normal);
  return touch;
}

// Whether a ball on path `at` touching a swinging capsule (gap at most `slack`) is pressed into
// it, by its own acceleration or by the capsule turning into it, and not opening faster than
// restSpeed / 2. Such a ball is hit at once: the gap searches only find gaps that go from positive
// to zero, and this one starts at zero. (Half of restSpeed: the minimum bounce sends a ball off at
// restSpeed, which must not count again.)
// The callers asking about the present pass the ball's position resolution as the slack. The
// searches compute the gap otherwise (the tip's as |e|² − reach², its offset summed in another
// order), and a search that starts at a gap it rounds to zero or below finds no entry; with no
// slack, a ball an ulp or two off and pressed in was neither hit now nor found entering. Released
// at rest 2.2·10⁻¹⁶ L off a spinner's tip as the spinner started, a ball fell into the arm unmet
// (campaign seed 1796527371, case 704: 8.5·10⁻⁹ L inside, then a stall).
template <class Real>
bool pressedIntoSwing(const Trajectory<Real>& at, const SwingTouch<Real>& touch, const Real& slack,
                      const Real& restSpeed) {
  return !(slack < touch.gap) && dot(Vec2<Real>(at.v - touch.surfaceVelocity), touch.normal) < restSpeed / Real(2) &&
         Real(dot(at.a, touch.normal) + touch.bend) < Real(0);
}

// The first of a swinging capsule's features (the sides, then the tip) that the ball touches
// along the axis and that `accept` takes.
template <class Real, class Accept>
std::optional<int> touchedSwingFeature(const Trajectory<Real>& t, const Real& r, const SwingingAxis<Real>& axis,
                                       Accept&& accept) {
  for (const int feature : {0, 1, 3}) {
    const std::optional<SwingTouch<Real>> touch = swingTouchNow(t, r, axis, feature);
    if (touch && touch->alongAxis && accept(*touch)) return feature;
  }
  return std::nullopt;
}

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
    if (!pathMayComeWithin(ball, limit, axis.pivot, Real(axis.length + reach))) return best;
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
    // The tip is round: a graze passes it (time_of_impact.hpp, grazesAt), judged on the path
    // relative to the tip's centre, e(τ), which curves away when |e'|² + e·e'' > 0.
    auto notAGraze = [&](const Real& tau) {
      Vec2<Real> u;
      const Vec2<Real> e = gap.offset(tau, u);
      const Vec2<Real> de = ball.velocityAt(tau) - (axis.length * axis.omega) * Vec2<Real>(-u.y, u.x);
      const Vec2<Real> dde = ball.a + (axis.length * axis.omega * axis.omega) * u;
      return !grazing(e, de, dde);
    };
    consider(math::firstEntrySmooth(gap, Real(0), searchEnd, notAGraze), 3);
  }
  return best;
}

// A ball on the pivot's circle behind a side's end (−q·u > 0), as the flipper turns that side
// towards it. The side's gap is never positive there: its line passes within reach of the ball
// until the end comes under it, when the gap touches zero from below and then closes. No entry
// from a positive gap exists to be found, and the ball would pass into the flipper (a ball at
// rest on the pivot's circle 1.9·10⁻¹³ L behind the end, put there by a Newton's cradle of balls:
// the fuzzer, seed 299792458 case 11204, docs/fuzzing.md). So the instant the end comes under
// the ball is searched for instead: its distance behind the end's line, −q·u, is the side gap
// of the quarter-turned axis with σ = −1 and no reach, and falls to zero there. `touching`
// (trajectory and axis at that instant) names the side it then touches and is pressed by.
template <class Real, class Touching>
std::optional<SwingContact<Real>> sideEndComesUnder(const Trajectory<Real>& ball, const Real& r,
                                                    const SwingingAxis<Real>& axis, const Real& limit,
                                                    Touching&& touching) {
  // Only a ball that can be on the pivot's circle in the time: its distance from the pivot
  // within its travel (and a rounding) of the reach, or less. (A ball a few roundings inside the
  // circle is on it too: a still ball that a hit left 2.7e-14 L inside, twice its position
  // resolution, was passed by the side in the classic model; campaign seed 662607015, case 1669.)
  const Real half = Real(1) / Real(2);
  const Real travel = length(ball.v) * limit + half * length(ball.a) * limit * limit + positionResolution(ball.p);
  if (travel < Real(length(Vec2<Real>(ball.p - axis.pivot)) - (r + axis.radius))) return std::nullopt;
  const SideGap<Real> behindEnd{ball, quarterTurned(axis), Real(0), Real(-1)};
  std::optional<int> feature;
  const std::optional<Real> tau = math::firstEntrySmooth(behindEnd, Real(0), limit, [&](const Real& at) {
    feature = touching(Trajectory<Real>{ball.positionAt(at), ball.velocityAt(at), ball.a}, axisAfter(axis, at));
    return feature.has_value();
  });
  if (!tau || !feature) return std::nullopt;
  return SwingContact<Real>{*tau, *feature};
}

}  // namespace gizmo
