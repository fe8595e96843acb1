#pragma once
// A ball's path from the present: p(τ) = p + v τ + ½ a τ². The classic model predicts with
// a = 0 (straight lines), the ballistic model with the effective gravity.
#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo {

template <class Real>
struct Trajectory {
  Vec2<Real> p, v, a;

  Vec2<Real> positionAt(const Real& tau) const {
    const Real half = Real(1) / Real(2);
    return p + tau * v + (half * tau * tau) * a;
  }
  Vec2<Real> velocityAt(const Real& tau) const { return v + tau * a; }
};

// Axis-aligned box, for the broad phase.
template <class Real>
struct Box {
  Vec2<Real> lo, hi;
  // Without short-circuits: in the broad phase the outcome is a coin toss, and four comparisons
  // cost less than a mispredicted branch. (As ints: clang warns of a bitwise | between bools.)
  bool overlaps(const Box& o) const {
    return (int(hi.x < o.lo.x) | int(o.hi.x < lo.x) | int(hi.y < o.lo.y) | int(o.hi.y < lo.y)) == 0;
  }
  // The square of half-side r around c (a ball's box, or the reach around a ball's centre).
  static Box around(const Vec2<Real>& c, const Real& r) { return Box{c - Vec2<Real>(r, r), c + Vec2<Real>(r, r)}; }
};

// The box that holds every point within `radius` of the path over [0, T], grown by `margin`.
template <class Real>
Box<Real> sweptBox(const Trajectory<Real>& t, const Real& T, const Real& radius, const Real& margin) {
  auto axis = [&](const Real& p, const Real& v, const Real& a, Real& lo, Real& hi) {
    const Real half = Real(1) / Real(2);
    const Real end = p + v * T + half * a * T * T;
    lo = minOf(p, end);
    hi = maxOf(p, end);
    if (a != Real(0)) {
      const Real tStar = -v / a;  // the turning point of this coordinate
      if (Real(0) < tStar && tStar < T) {
        const Real ext = p + v * tStar + half * a * tStar * tStar;
        lo = minOf(lo, ext);
        hi = maxOf(hi, ext);
      }
    }
    lo = lo - radius - margin;
    hi = hi + radius + margin;
  };
  Box<Real> b;
  axis(t.p.x, t.v.x, t.a.x, b.lo.x, b.hi.x);
  axis(t.p.y, t.v.y, t.a.y, b.lo.y, b.hi.y);
  return b;
}

// Whether the path over [0, T] may come within `radius` of c; false only where it cannot. The
// path stays within |a| T²/8 of its chord from p(0) to p(T) (p(τ) − chord(τ) = −½ a τ (T − τ)),
// so a chord farther than radius + |a| T²/8 from c keeps the whole path away. Unlike the disc of
// the ball's travel around p(0), this holds a fast ball that passes by at a distance away: one
// at 5000 L/s travels 250 L in a tick, and its disc covers the board. A margin of 1/1024 on the
// distance covers the rounding of these products. No square root (|a| is bounded by |a.x| + |a.y|),
// so an exact run takes none here that it did not take before.
template <class Real>
bool pathMayComeWithin(const Trajectory<Real>& t, const Real& T, const Vec2<Real>& c, const Real& radius) {
  const Real bulge = (absOf(t.a.x) + absOf(t.a.y)) * T * T / Real(8);
  const Real near = (radius + bulge) * (Real(1) + Real(1) / Real(1024));
  const Real near2 = near * near;
  const Vec2<Real> end = t.positionAt(T);
  const Vec2<Real> d = end - t.p, w = c - t.p;
  const Real along = dot(w, d), chord2 = lengthSquared(d);
  if (!(Real(0) < along)) return !(near2 < lengthSquared(w));                   // nearest: p(0)
  if (!(along < chord2)) return !(near2 < lengthSquared(Vec2<Real>(c - end)));  // nearest: p(T)
  const Real across = cross(w, d);
  return !(near2 * chord2 < across * across);  // distance² = across² / chord²
}

}  // namespace gizmo
