#pragma once
// A ball cradled in a V of two still surfaces (docs/physics.md, "A ball in a V of two surfaces"):
// touching one, within a minimum bounce's rise of the other, with gravity held between the two
// normals, so that every small displacement that keeps both gaps open raises the ball. Only
// products and comparisons: no square root and no library call, so that every scalar, the exact
// ones included, decides it the same way.
#include "gizmo/core/geometry/features.hpp"

namespace gizmo {

// Whether gravity is held between normals a and b (of any length): −g = λa·a + λb·b with both λ
// positive. Parallel normals hold nothing.
template <class Real>
bool gravityHeldBetween(const Vec2<Real>& a, const Vec2<Real>& b, const Vec2<Real>& gravity) {
  const Real ab = cross(a, b);
  if (ab == Real(0)) return false;
  const Vec2<Real> up(-gravity.x, -gravity.y);
  const Real la = cross(up, b), lb = cross(a, up);  // λa·ab and λb·ab
  return Real(0) < ab ? (Real(0) < la && Real(0) < lb) : (la < Real(0) && lb < Real(0));
}

// Whether some feature of `shape` lies within `reach` of the surface of a ball of radius r
// centred at p, on the feature's free side, and `accept` takes the direction from the feature
// to p (an edge's normal, or the offset from a circle's centre: not of unit length). An edge
// counts only where the ball's centre is over it; beyond its ends its vertices take over.
template <class Real, class Accept>
bool anyFeatureWithin(const Shape<Real>& shape, const Vec2<Real>& p, const Real& r, const Real& reach,
                      Accept&& accept) {
  for (const SegmentFeature<Real>& s : shape.segments) {
    const Vec2<Real> d = p - s.a;
    const Real along = dot(d, s.direction), height = dot(d, s.normal);
    if (along < Real(0) || s.length < along || !(Real(0) < height) || r + reach < height) continue;
    if (accept(s.normal)) return true;
  }
  for (const CircleFeature<Real>& c : shape.circles) {
    const Vec2<Real> d = p - c.centre;
    const Real most = r + c.radius + reach, dist2 = lengthSquared(d);
    if (!(Real(0) < dist2) || most * most < dist2) continue;
    if (accept(d)) return true;
  }
  return false;
}

}  // namespace gizmo
