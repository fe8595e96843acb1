#pragma once
// Geometry the fuzz checks compute for themselves, from the gizmos' vertices and centres
// (shapes.hpp: the contract) rather than from the simulator's features, so that a check does not
// share the code it checks.
#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo::verify::fuzz {

template <class Real>
Vec2<Real> nearestPointOnSegment(const Vec2<Real>& p, const Vec2<Real>& a, const Vec2<Real>& b) {
  const Vec2<Real> ab = b - a, ap = p - a;
  const Real len2 = lengthSquared(ab);
  Real s = len2 == Real(0) ? Real(0) : Real(dot(ap, ab) / len2);
  s = std::clamp(s, Real(0), Real(1));
  return a + s * ab;
}

template <class Real>
Real distanceToSegment(const Vec2<Real>& p, const Vec2<Real>& a, const Vec2<Real>& b) {
  return length(Vec2<Real>(p - nearestPointOnSegment(p, a, b)));
}

// Signed distance from p to a convex polygon whose vertices run clockwise on screen (y down):
// negative inside.
template <class Real>
Real signedDistanceToPolygon(const Vec2<Real>& p, const std::vector<Vec2<Real>>& v) {
  const std::size_t n = v.size();
  Real deepest = -std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2<Real> d = v[(i + 1) % n] - v[i];
    const Real len = length(d);
    const Vec2<Real> outward(d.y / len, -d.x / len);
    deepest = std::max(deepest, Real(dot(p - v[i], outward)));
  }
  if (deepest <= Real(0)) return deepest;
  Real nearest = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < n; ++i) nearest = std::min(nearest, distanceToSegment(p, v[i], v[(i + 1) % n]));
  return nearest;
}

// Where a ball touches a still grid gizmo (not a flipper): the unit normal from the gizmo to the
// ball's centre p, and whether the touch is on something round (a polygon's vertex, radius 0, or
// a disc, radius 0.5) rather than along an edge. None for p at the nearest point or the centre.
struct GizmoTouch {
  Vec2<double> normal;
  bool round = false;
  double radius = 0;
};

// The touch with its unit normal from the nearest point `from` to the ball's centre p; none for
// p on that point.
inline std::optional<GizmoTouch> touchFrom(const Vec2<double>& from, const Vec2<double>& p, GizmoTouch touch) {
  const Vec2<double> d = p - from;
  const double len = length(d);
  if (!(len > 0)) return std::nullopt;
  touch.normal = Vec2<double>(d.x / len, d.y / len);
  return touch;
}

inline std::optional<GizmoTouch> touchOnGizmo(const GizmoSpec& spec, const Vec2<double>& p) {
  const Shape<double> shape = restShape<double>(spec);
  GizmoTouch touch;
  Vec2<double> from;
  if (isDiscGizmo(spec.type)) {
    from = shape.circles.front().centre;
    touch.round = true;
    touch.radius = 0.5;
  } else {
    double best = std::numeric_limits<double>::infinity();
    const std::size_t n = shape.circles.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2<double>& a = shape.circles[i].centre;
      const Vec2<double>& b = shape.circles[(i + 1) % n].centre;
      const Vec2<double> q = nearestPointOnSegment(p, a, b);
      const double d = lengthSquared(Vec2<double>(p - q));
      if (d < best) {
        best = d;
        from = q;
        touch.round = q == a || q == b;
      }
    }
  }
  return touchFrom(from, p, touch);
}

// Where a ball touches a flipper standing still with its axis from pivot to tip (the capsule of
// that radius around it): round at either end's cap, an edge along its sides.
inline std::optional<GizmoTouch> touchOnCapsule(const Vec2<double>& pivot, const Vec2<double>& tip, double radius,
                                                const Vec2<double>& p) {
  const Vec2<double> q = nearestPointOnSegment(p, pivot, tip);
  return touchFrom(q, p, GizmoTouch{Vec2<double>(), q == pivot || q == tip, radius});
}

}  // namespace gizmo::verify::fuzz
