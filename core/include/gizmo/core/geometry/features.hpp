#pragma once
// The features a ball can touch: segments (edges) and circles (round bumpers, flipper ends, and
// polygon vertices as circles of radius 0). A gizmo's shape is a list of each.
#include <vector>

#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo {

// A segment from a to b whose normal points to the side a ball may come from (for a polygon,
// outwards; for the outer walls, into the board).
template <class Real>
struct SegmentFeature {
  Vec2<Real> a, b;
  Vec2<Real> normal;     // unit, towards the free side
  Vec2<Real> direction;  // unit, from a to b
  Real length{0};
};

template <class Real>
struct CircleFeature {
  Vec2<Real> centre;
  Real radius{0};
};

template <class Real>
struct Shape {
  std::vector<SegmentFeature<Real>> segments;
  std::vector<CircleFeature<Real>> circles;
};

// The segment a→b with its free side on the left of the direction of travel as seen on
// screen (y down): normal = (d.y, −d.x). Walking a polygon clockwise on screen puts every
// normal outwards.
template <class Real>
SegmentFeature<Real> makeSegment(const Vec2<Real>& a, const Vec2<Real>& b) {
  SegmentFeature<Real> s;
  s.a = a;
  s.b = b;
  s.length = length(b - a);
  // Axis-aligned and 45° edges are all the board has; dividing by the rounded length keeps the
  // axis-aligned ones exact in every scalar.
  s.direction = Vec2<Real>((b.x - a.x) / s.length, (b.y - a.y) / s.length);
  s.normal = Vec2<Real>(s.direction.y, -s.direction.x);
  return s;
}

}  // namespace gizmo
