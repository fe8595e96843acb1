#pragma once
// Times of impact of a ball against each kind of feature, as times τ from the present in
// [0, limit]. Every function reports the first *entry* only: the gap between ball and feature
// going from positive to zero while closing (docs/physics.md §5: a ball that touches or
// overlaps a feature while receding gets no collision). Roots come from the certified
// first-root searches of math/roots.hpp, which never step over a root.
#include <array>
#include <optional>

#include "gizmo/core/geometry/features.hpp"
#include "gizmo/core/geometry/trajectory.hpp"
#include "gizmo/core/math/roots.hpp"

namespace gizmo {

// The gap polynomial g(τ) = c0 + c1 τ + c2 τ² + … is already touching at τ = 0 and about to
// close: the first non-zero derivative at 0 is negative. firstEntry handles g'(0) < 0; this
// also catches a ball at rest on a surface that gravity presses into it (g'(0) = 0, g'' < 0).
// And a touching ball that opens at a rounding-level speed but is pressed back before the gap
// ever becomes positive (c2 < 0 and c0 + c1²/(4|c2|) <= 0): no entry from a positive gap would
// ever be found for it, and it would sink through the surface (a ball sliding off a flipper's
// side onto the round end, found by the no-tunnelling property).
template <class Real>
bool closingFromContact(const std::array<Real, 5>& c) {
  if (Real(0) < c[0]) return false;
  if (Real(0) < c[1] && c[2] < Real(0) && Real(Real(4) * -c[2] * c[0] + c[1] * c[1]) <= Real(0)) return true;
  for (int i = 1; i < 5; ++i) {
    if (c[i] < Real(0)) return true;
    if (Real(0) < c[i]) return false;
  }
  return false;
}

template <class Real, class Accept>
std::optional<Real> firstPolynomialEntry(const std::array<Real, 5>& c, const Real& limit, Accept&& accept) {
  if (closingFromContact(c) && accept(Real(0))) return Real(0);
  return math::firstEntry(c, Real(0), limit, accept);
}

// How far apart representable positions near p are, give or take a few roundings: a ball's
// centre cannot move by less. Zero for an exact scalar.
template <class Real>
Real positionResolution(const Vec2<Real>& p) {
  return Real(4) * epsilonOf<Real>() * Real(absOf(p.x) + absOf(p.y));
}

// A graze (docs/physics.md, "Grazes"): a path that touches a round feature with a closing
// speed of at most κ times its speed, while curving away from it (|v|² + d·a > 0: the gap's
// second derivative is positive), passes it. The dip of the gap below zero is then at most
// (r + R) κ² / 2, and at an exact tangency whether it dips at all is decided by rounding:
// without the rule two runs that differ by an ulp (the two motion models) would part there.
// κ² = min(2^20 ε, 2^-20): a thousand times above the rounding of a near-double root
// (√ε relative), and 0 for an exact scalar, where only a true tangency is a graze.
template <class Real>
Real grazeFractionSquared() {
  const Real scale = Real(1048576);
  return minOf(Real(scale * epsilonOf<Real>()), Real(Real(1) / scale));
}

// Whether a ball at u along segment s (du, ddu: its speed and acceleration along it) is leaving
// it over an end now: at the end, or closer to it than the position resolution, and moving out.
// Closer than the resolution counts as there because the ball can never get there by moving:
// every step towards the end rounds back to where it was, and a sliding contact would end and
// begin again at the same place for ever (found by the fuzzer on a ball sliding off a flipper).
template <class Real>
bool leavingOverEnd(const SegmentFeature<Real>& s, const Real& u, const Real& du, const Real& ddu,
                    const Real& resolution) {
  auto movingOut = [](const Real& rate, const Real& accel) {
    return rate < Real(0) || (rate == Real(0) && accel < Real(0));
  };
  return (u <= resolution && movingOut(du, ddu)) || (Real(s.length - u) <= resolution && movingOut(-du, -ddu));
}

// A ball whose centre comes over an end of segment s (its distance behind the end's line falling
// to zero) while it touches the segment's line and moves into it: the instant it does, if within
// `limit`. The gap's own entry is no help there: it happened beyond the end, where the end's
// vertex passed the ball as a graze (which lets a path dip up to r κ²/2 into it), so on the
// segment the gap is already zero or a hair below and only falls. Without this a ball knocked
// along a square's top at 5000 L/s, 10⁻¹³ L beyond its end when it came down to the top's line,
// grazed the corner and sank into the square (campaign seed 667430151, case 701).
// "Touching": within the larger of its position resolution and the graze's dip. "Moving into
// it": faster than a few roundings of its speed, so that a ball sliding on a collinear
// neighbour (whose normal speed is such a rounding) meets this edge when its contact ends there,
// as it always has, and is not struck while it still slides. Or "pressed into it": a normal
// speed at that rounding's level, either way, and an acceleration into the line beyond a few
// roundings of its own size. A sliding ball's acceleration is gravity less the part its surface
// takes, so along a collinear neighbour it has no more than rounding across the line; a free
// ball's is all of gravity, and gravity dips it below the line at once. Without that a ball sent
// back along a flipper's side by the wall at the side's pivot end, over the end by 10⁻¹⁶ L with a
// normal speed of 3·10⁻¹⁵ L/s, sank into the side under gravity 1000 (campaign seed 27182818,
// case 174). An exact scalar has neither rounding nor grazes: the vertex stops such a ball, and
// this search is not made.
template <class Real>
std::optional<Real> comingOverAnEnd(const Trajectory<Real>& t, const Real& r, const SegmentFeature<Real>& s,
                                    const Real& limit) {
  if constexpr (kExactScalar<Real>) {
    return std::nullopt;
  } else {
    const Real half = Real(1) / Real(2);
    const Real u0 = dot(Vec2<Real>(t.p - s.a), s.direction), du = dot(t.v, s.direction);
    const Real ddu = half * dot(t.a, s.direction);
    const Real dip = half * r * grazeFractionSquared<Real>();
    const Real eps = epsilonOf<Real>();
    // At the end (the search also offers an instant at which the centre is over the segment
    // already and moving on), touching the line, and moving into it.
    auto overEndTouchingAndClosing = [&](const Real& end) {
      return [&, end](const Real& tau) {
        const Vec2<Real> p = t.positionAt(tau), v = t.velocityAt(tau);
        const Real resolution = positionResolution(p);
        if (resolution < absOf(Real(dot(Vec2<Real>(p - s.a), s.direction) - end))) return false;
        const Real gap = Real(dot(Vec2<Real>(p - s.a), s.normal) - r);
        if (maxOf(resolution, dip) < absOf(gap)) return false;
        const Real closing = dot(v, s.normal), pressing = dot(t.a, s.normal);
        const bool closingBeyondRounding = Real(Real(4096) * eps * eps * lengthSquared(v)) < Real(closing * closing);
        if (closingBeyondRounding) return closing < Real(0);
        return pressing < Real(0) && Real(Real(4096) * eps * eps * lengthSquared(t.a)) < Real(pressing * pressing);
      };
    };
    // Cheap rejection, as for the gap: an end farther than the most the motion along the segment
    // covers in the time is not reached.
    const Real travel = absOf(du) * limit + absOf(ddu) * limit * limit;
    auto outOfReach = [&](const Real& end) { return travel < absOf(Real(u0 - end)); };
    if (outOfReach(Real(0)) && outOfReach(s.length)) return std::nullopt;
    const std::optional<Real> overA = math::firstEntry(std::array<Real, 5>{-u0, -du, -ddu, Real(0), Real(0)}, Real(0),
                                                       limit, overEndTouchingAndClosing(Real(0)));
    const std::optional<Real> overB =
        math::firstEntry(std::array<Real, 5>{Real(u0 - s.length), du, ddu, Real(0), Real(0)}, Real(0),
                         overA ? *overA : limit, overEndTouchingAndClosing(s.length));
    return overB ? overB : overA;
  }
}

// Ball (centre path t, radius r) against a segment, from its free side only; the contact point
// must lie on the segment (beyond its ends the vertex circles take over).
template <class Real>
std::optional<Real> segmentTimeOfImpact(const Trajectory<Real>& t, const Real& r, const SegmentFeature<Real>& s,
                                        const Real& limit) {
  const Vec2<Real> d = t.p - s.a;
  const Real height = dot(d, s.normal);
  const Real half = Real(1) / Real(2);
  const std::array<Real, 5> c{height - r, dot(t.v, s.normal), half * dot(t.a, s.normal), Real(0), Real(0)};
  // A centre behind the line is on the gizmo's side of this edge. A path can still come to the
  // edge from its free side if gravity bends it back over the line beyond an end of the edge (a
  // ball thrown up beside a bumper lands on its top): the gap, concave, first rises above zero
  // and then falls to it. Only such an entry counts, never a contact at the present: the ball is
  // not touching this edge, whatever the sign of the gap says.
  const bool behind = height < Real(0);
  if (behind && !(Real(0) < c[1] && c[2] < Real(0) && Real(0) < Real(Real(4) * -c[2] * c[0] + c[1] * c[1])))
    return std::nullopt;
  // Cheap rejection: the gap cannot close within the limit (it only grows, or it is wider than
  // the most the motion can close: |c1| limit + |c2| limit²). Both tests are evaluated and
  // joined without branches: most segments of a shape are rejected, so the one branch left is
  // predictable, where one per comparison was not. (As ints: clang warns of a bitwise & between
  // bools whose operands call functions, here std::array's operator[].)
  const bool opening = (int(Real(0) < c[0]) & int(Real(0) <= c[1]) & int(Real(0) <= c[2])) != 0;
  const bool outOfReach = absOf(c[1]) * limit + absOf(c[2]) * limit * limit < c[0];
  if ((int(opening) | int(outOfReach)) != 0) return std::nullopt;
  // The contact point must lie on the segment; at either end it must also be moving onto it
  // (a ball leaving over an end meets that end's vertex instead, not the edge again).
  auto onSegment = [&](const Real& tau) {
    const Vec2<Real> p = t.positionAt(tau);
    const Real u = dot(p - s.a, s.direction);
    if (u < Real(0) || s.length < u) return false;
    return !leavingOverEnd(s, u, dot(t.velocityAt(tau), s.direction), dot(t.a, s.direction), positionResolution(p));
  };
  const std::optional<Real> entry =
      behind ? math::firstEntry(c, Real(0), limit, onSegment) : firstPolynomialEntry(c, limit, onSegment);
  if (behind) return entry;
  const std::optional<Real> overEnd = comingOverAnEnd(t, r, s, entry ? *entry : limit);
  return overEnd ? overEnd : entry;
}

// The rule on a path e relative to the feature's centre, with its rate de and acceleration dde.
template <class Real>
bool grazing(const Vec2<Real>& e, const Vec2<Real>& de, const Vec2<Real>& dde) {
  const Real speed2 = lengthSquared(de);
  if (!(Real(0) < Real(speed2 + dot(e, dde)))) return false;  // curving into it: a contact
  const Real closing = dot(e, de);
  return closing * closing <= grazeFractionSquared<Real>() * lengthSquared(e) * speed2;
}

template <class Real>
bool grazesAt(const Trajectory<Real>& t, const Vec2<Real>& centre, const Real& tau) {
  return grazing(Vec2<Real>(t.positionAt(tau) - centre), t.velocityAt(tau), t.a);
}

// Ball against a circle of radius R around centre (R = 0: a polygon's vertex), or two balls
// with the relative path: the gap is |d(τ)|² − (r + R)², a quartic when a ≠ 0. Grazes pass.
// afterNow: a contact at τ = 0 does not count (a graze already let through at this instant).
template <class Real>
std::optional<Real> circleTimeOfImpact(const Trajectory<Real>& t, const Real& r, const CircleFeature<Real>& circle,
                                       const Real& limit, bool afterNow = false) {
  const Vec2<Real> d = t.p - circle.centre;
  const Real reach = r + circle.radius;
  const Real dist2 = lengthSquared(d);
  // Cheap rejection: the straight part of the path, d + v τ for τ in [0, limit], passes no
  // closer than `closest` to the centre, and gravity bends it by at most ½|a| limit².
  {
    const Real half = Real(1) / Real(2);
    const Real speed2 = lengthSquared(t.v);
    Real along = speed2 == Real(0) ? Real(0) : Real(-dot(d, t.v) / speed2);
    along = minOf(maxOf(along, Real(0)), limit);
    const Real closest2 = lengthSquared(Vec2<Real>(d + along * t.v));
    const Real bend = half * length(t.a) * limit * limit;
    // A little headroom for the rounding of the lines above keeps the test a bound. Squared,
    // so that an exact run takes no square root here.
    const Real slack = Real(1) + Real(16) * epsilonOf<Real>();
    const Real farthest = reach * slack + bend;
    if (farthest * farthest < closest2) return std::nullopt;
  }
  const Real quarter = Real(1) / Real(4);
  const std::array<Real, 5> c{dist2 - reach * reach, Real(2) * dot(d, t.v), lengthSquared(t.v) + dot(d, t.a),
                              dot(t.v, t.a), quarter * lengthSquared(t.a)};
  // A path that starts deeper in than a graze can leave it, (r + R) κ²/2 (c0 = −(r + R)² κ² in
  // the squared gap), is not let through again: grazes one after another, each from a path that
  // another event (a bounce on the floor) started again at the tangency, would add their dips.
  // A ball bouncing on a square beside a flipper's pivot, drifting into the pivot at 3e-7 L/s
  // against its 0.02 L/s, sank 1e-9 L into it (campaign seed 662607015, case 1906).
  // Closing beyond rounding only (|d·v| above 64 ε |d||v|): the response computes the closing
  // again with its own roundings, and a pair it finds not closing would be predicted to hit at
  // this instant for ever (a stall of two balls in a pile, seed 137035999, case 2822).
  const Real eps = epsilonOf<Real>();
  const bool deeperThanAGraze = c[0] < Real(-(reach * reach) * grazeFractionSquared<Real>()) && c[1] < Real(0) &&
                                Real(Real(16384) * eps * eps * dist2 * lengthSquared(t.v)) < Real(c[1] * c[1]);
  return firstPolynomialEntry(c, limit, [&](const Real& tau) {
    if (afterNow && !(Real(0) < tau)) return false;
    return (tau == Real(0) && deeperThanAGraze) || !grazesAt(t, circle.centre, tau);
  });
}

template <class Real>
std::optional<Real> ballTimeOfImpact(const Trajectory<Real>& x, const Trajectory<Real>& y, const Real& r,
                                     const Real& limit, bool afterNow = false) {
  const Trajectory<Real> relative{x.p - y.p, x.v - y.v, x.a - y.a};
  return circleTimeOfImpact(relative, r, CircleFeature<Real>{Vec2<Real>(), r}, limit, afterNow);
}

}  // namespace gizmo
