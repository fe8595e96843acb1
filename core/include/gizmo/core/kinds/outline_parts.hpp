#pragma once
// The pieces the kinds' files build their outlines at rest from (their addRestShape), beside the
// polygons, capsules and crosses of geometry/shapes.hpp.
#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/shapes.hpp"

namespace gizmo {

// A point of a gizmo's box, given relative to its upper-left corner, in board coordinates.
template <class Real>
struct AtCell {
  const GizmoSpec& g;
  Vec2<Real> operator()(double dx, double dy) const {
    return Vec2<Real>(Real(g.x), Real(g.y)) + Vec2<Real>(fromDouble<Real>(dx), fromDouble<Real>(dy));
  }
};

// The triangle bumper's outline (the right angle at the upper left), turned by the gizmo's
// orientation and `extraQuarters` more quarter turns clockwise.
template <class Real>
void addTurnedTriangle(Shape<Real>& s, const GizmoSpec& g, int extraQuarters) {
  const AtCell<Real> at{g};
  const Vec2<Real> c = at(0.5, 0.5);
  const int k = g.orientation / 90 + extraQuarters;
  addPolygon(
      s, {rotateQuarterTurns(at(0, 0), c, k), rotateQuarterTurns(at(1, 0), c, k), rotateQuarterTurns(at(0, 1), c, k)});
}

// A flipper at its rest angle: the capsule from its pivot (flipperLayout).
template <class Real>
void addFlipperAtRest(Shape<Real>& s, const GizmoSpec& g) {
  const AtCell<Real> at{g};
  const FlipperLayout f = flipperLayout(g.type, g.orientation);
  const Vec2<Real> pivot = at(f.pivot.x, f.pivot.y);
  const Vec2<Real> tip = pivot + fromDouble<Real>(kFlipperLength) * quarterDirection<Real>(f.restQuarter);
  addCapsule(s, pivot, tip, fromDouble<Real>(kFlipperRadius));
}

}  // namespace gizmo
