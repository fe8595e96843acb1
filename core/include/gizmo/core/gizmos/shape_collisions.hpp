#pragma once
// Ball against a fixed shape (segments and circles): the first contact over all features, and
// the normal at a contact. Polygonal bumpers, absorbers, the walls, circle bumpers and a
// flipper at rest all use these.
#include <optional>

#include "gizmo/core/geometry/time_of_impact.hpp"
#include "gizmo/core/gizmos/ball.hpp"

namespace gizmo {

template <class Real>
struct FeatureHit {
  Real tau;
  std::int32_t feature;  // segments first, then circles
};

// Whether circle c caps an end of segment s (a polygon's vertex, a capsule's end): the end
// lies on the circle's rim.
template <class Real>
bool capsEndOf(const CircleFeature<Real>& c, const SegmentFeature<Real>& s) {
  const Real tolerance = Real(64) * epsilonOf<Real>() * (Real(1) + c.radius);
  return absOf(Real(length(s.a - c.centre) - c.radius)) <= tolerance ||
         absOf(Real(length(s.b - c.centre) - c.radius)) <= tolerance;
}

// slidingOn: the segment a ball slides on. It is no obstacle to that ball, and neither are the
// round features that cap its ends: the ball can only graze them tangentially while it slides
// (rounding would turn the graze into a hit that the contact then cancels, for ever), and it
// meets them as soon as the contact ends at either end.
template <class Real>
std::optional<FeatureHit<Real>> shapeTimeOfImpact(const Shape<Real>& shape, const Trajectory<Real>& t, const Real& r,
                                                  const Real& limit, std::int32_t slidingOn) {
  std::optional<FeatureHit<Real>> best;
  auto consider = [&](const std::optional<Real>& tau, std::int32_t feature) {
    if (tau && (!best || *tau < best->tau)) best = FeatureHit<Real>{*tau, feature};
  };
  const SegmentFeature<Real>* contact = slidingOn >= 0 && std::size_t(slidingOn) < shape.segments.size()
                                            ? &shape.segments[std::size_t(slidingOn)]
                                            : nullptr;
  std::int32_t f = 0;
  for (const SegmentFeature<Real>& s : shape.segments) {
    if (f != slidingOn) consider(segmentTimeOfImpact(t, r, s, best ? best->tau : limit), f);
    ++f;
  }
  for (const CircleFeature<Real>& c : shape.circles) {
    if (!contact || !capsEndOf(c, *contact)) consider(circleTimeOfImpact(t, r, c, best ? best->tau : limit), f);
    ++f;
  }
  return best;
}

// The unit normal from the feature towards the ball at ball centre p; nullopt when p sits on a
// circle's centre (no direction to push along).
template <class Real>
std::optional<Vec2<Real>> shapeNormal(const Shape<Real>& shape, std::int32_t feature, const Vec2<Real>& p) {
  const std::size_t f = static_cast<std::size_t>(feature);
  if (f < shape.segments.size()) return shape.segments[f].normal;
  const CircleFeature<Real>& c = shape.circles.at(f - shape.segments.size());
  const Vec2<Real> d = p - c.centre;
  const Real dist = length(d);
  if (dist == Real(0)) return std::nullopt;
  return Vec2<Real>(d.x / dist, d.y / dist);
}

// The fixed-shape response: reflect with coefficient c; a slow ball pressed onto a segment
// starts sliding on it.
template <class Real>
void bounceOffShape(const Shape<Real>& shape, GizmoId owner, const Real& coefficient, Ball<Real>& ball,
                    std::int32_t feature, BoardAccess<Real>& board) {
  const std::optional<Vec2<Real>> n = shapeNormal(shape, feature, ball.positionAt(board.now()));
  if (!n) return;
  const std::size_t f = static_cast<std::size_t>(feature);
  if (f < shape.segments.size()) {
    const SurfaceContact<Real> surface{owner, feature, shape.segments[f], coefficient};
    ball.reflect(*n, coefficient, Vec2<Real>(), SurfaceType::StaticSegment, owner, &surface, board);
  } else {
    ball.reflect(*n, coefficient, Vec2<Real>(), SurfaceType::Round, owner, nullptr, board);
  }
}

template <class Real>
Box<Real> shapeBounds(const Shape<Real>& shape) {
  Box<Real> b{Vec2<Real>(Real(1e30), Real(1e30)), Vec2<Real>(Real(-1e30), Real(-1e30))};
  auto add = [&](const Vec2<Real>& p, const Real& r) {
    b.lo.x = minOf(b.lo.x, Real(p.x - r));
    b.lo.y = minOf(b.lo.y, Real(p.y - r));
    b.hi.x = maxOf(b.hi.x, Real(p.x + r));
    b.hi.y = maxOf(b.hi.y, Real(p.y + r));
  };
  for (const auto& s : shape.segments) {
    add(s.a, Real(0));
    add(s.b, Real(0));
  }
  for (const auto& c : shape.circles) add(c.centre, c.radius);
  return b;
}

}  // namespace gizmo
