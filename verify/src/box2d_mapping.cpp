#include "gizmo/verify/box2d_mapping.hpp"

#include <stdexcept>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/grid_properties.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "kinds/verify_registry.hpp"

namespace gizmo::verify {
namespace {

// The polygon of segments (clockwise on screen, normals outwards) moved inwards by `skin`: each
// vertex goes to where the two offset edge lines that meet there cross.
std::vector<Vec2<double>> insetPolygon(const std::vector<SegmentFeature<double>>& edges, double skin) {
  std::vector<Vec2<double>> out;
  const std::size_t n = edges.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2<double>& before = edges[(i + n - 1) % n].normal;
    const Vec2<double>& after = edges[i].normal;
    // w = v − s (n₁ + n₂) / (1 + n₁·n₂) lies at distance s inside both edge lines.
    out.push_back(edges[i].a - (skin / (1 + dot(before, after))) * (before + after));
  }
  return out;
}

Box2dPart polygonPart(std::vector<Vec2<double>> core) {
  Box2dPart p;
  p.kind = Box2dPart::Kind::Polygon;
  p.points = std::move(core);
  p.radius = kBox2dPolygonSkin;
  return p;
}

Box2dPart circlePart(const Vec2<double>& centre, double radius) {
  Box2dPart p;
  p.kind = Box2dPart::Kind::Circle;
  p.centre = centre;
  p.radius = radius;
  return p;
}

// Flipper parts in the body's frame: the pivot at the origin, the axis along +x. A rectangle
// whose long sides, with the skin, lie at the capsule's radius, and the two end circles. The
// union of the three is our capsule apart from the rectangle's skin-rounded corners, which lie
// inside the end circles.
std::vector<Box2dPart> flipperParts() {
  const double half = kFlipperRadius - kBox2dPolygonSkin, l = kFlipperLength;
  // Clockwise on screen (y down): along the top side, then back along the bottom.
  return {polygonPart({Vec2<double>(0, -half), Vec2<double>(l, -half), Vec2<double>(l, half), Vec2<double>(0, half)}),
          circlePart(Vec2<double>(0, 0), kFlipperRadius), circlePart(Vec2<double>(l, 0), kFlipperRadius)};
}

// Spinner parts in the body's frame: the centre at the origin, the still cross's arms along the
// axes. Each of its two capsules is a rectangle whose long sides, with the skin, lie at the arm's
// radius, and its two end circles; where the rectangles cross, they overlap.
std::vector<Box2dPart> spinnerParts() {
  const double half = kSpinnerArmRadius - kBox2dPolygonSkin, l = kSpinnerArmLength;
  std::vector<Box2dPart> parts = {
      polygonPart({Vec2<double>(-l, -half), Vec2<double>(l, -half), Vec2<double>(l, half), Vec2<double>(-l, half)}),
      polygonPart({Vec2<double>(-half, -l), Vec2<double>(half, -l), Vec2<double>(half, l), Vec2<double>(-half, l)})};
  for (const Vec2<double> tip : {Vec2<double>(l, 0), Vec2<double>(0, l), Vec2<double>(-l, 0), Vec2<double>(0, -l)})
    parts.push_back(circlePart(tip, kSpinnerArmRadius));
  return parts;
}

// A sensor's contacts go to the Absorber's capture and shot (box2d_driver.cpp): a kind the bridge
// makes a sensor must be one whose gizmo is an Absorber, which its core entry holdsPlacedBalls says
// (tests/unit/kinds_registry_test.cpp checks that entry against the gizmo each kind builds).
constexpr bool sensorsAreAbsorbers() {
  bool all = true;
  forEachKind([&]<GizmoType T>(KindTag<T>) {
    if (KindVerify<T>::box2dSensor && !KindCore<T>::holdsPlacedBalls) all = false;
  });
  return all;
}
static_assert(sensorsAreAbsorbers(),
              "a kind whose verify file sets box2dSensor must be one whose gizmo is an Absorber");

// A kind the bridge does not model says so, and why, in its own file (verify/src/kinds/STEM.hpp):
// refused by name rather than compared as something else.
std::optional<std::string> cannotModel(const GizmoSpec& gizmo) {
  if (verifyFact(gizmo.type, [](auto k) { return k.box2dModels; })) return std::nullopt;
  return std::string("the Box2D cross-check does not model the ") + gizmoTypeWord(gizmo.type) + " '" + gizmo.name +
         "' yet";
}

}  // namespace

std::optional<std::string> box2dCannotModel(const BoardSpec& board) {
  for (const GizmoSpec& g : board.gizmos)
    if (std::optional<std::string> why = cannotModel(g)) return why;
  return std::nullopt;
}

Box2dBody box2dBodyOf(const GizmoSpec& gizmo) {
  Box2dBody body;
  body.name = gizmo.name;
  body.type = gizmo.type;
  if (swings(gizmo.type)) {
    const FlipperLayout f = flipperLayout(gizmo.type, gizmo.orientation);
    body.kinematic = true;
    body.restitution = 0.95;  // Flipper<Real>::coefficient()
    body.origin = Vec2<double>(gizmo.x + f.pivot.x, gizmo.y + f.pivot.y);
    body.angle = f.restQuarter * (piOf<double>() / 2);
    body.parts = flipperParts();
    return body;
  }
  if (turns(gizmo.type)) {
    // Still at load, its arms along the axes; the bridge turns it on the core's schedule.
    body.kinematic = true;
    body.restitution = Spinner<double>::coefficient();
    body.origin = Vec2<double>(gizmo.x + 1, gizmo.y + 1);
    body.parts = spinnerParts();
    return body;
  }
  if (const std::optional<std::string> why = cannotModel(gizmo)) throw std::invalid_argument(*why);
  const Shape<double> shape = restShape<double>(gizmo);
  body.sensor = verifyFact(gizmo.type, [](auto k) { return k.box2dSensor; });
  if (shape.segments.empty()) body.parts.push_back(circlePart(shape.circles.at(0).centre, shape.circles.at(0).radius));
  else body.parts.push_back(polygonPart(insetPolygon(shape.segments, kBox2dPolygonSkin)));
  return body;
}

Box2dBody box2dOuterWalls() {
  Box2dBody body;
  body.name = kOuterWallsName;
  body.walls = true;
  for (const SegmentFeature<double>& s : outerWallsShape<double>().segments) {
    Box2dPart p;
    p.kind = Box2dPart::Kind::Edge;
    p.radius = kBox2dPolygonSkin;
    // Moved out of the board by the skin, so that the skin's inner face is the wall.
    const Vec2<double> out = -kBox2dPolygonSkin * s.normal;
    p.points = {s.a + out, s.b + out};
    body.parts.push_back(p);
  }
  return body;
}

Box2dPart placePart(const Box2dPart& part, const Vec2<double>& origin, int quarterTurns) {
  Box2dPart placed = part;
  const Vec2<double> zero;
  for (Vec2<double>& p : placed.points) p = origin + rotateQuarterTurns(p, zero, quarterTurns);
  placed.centre = origin + rotateQuarterTurns(part.centre, zero, quarterTurns);
  return placed;
}

Shape<double> coreShape(const Box2dPart& part) {
  Shape<double> shape;
  switch (part.kind) {
    case Box2dPart::Kind::Polygon: addPolygon(shape, part.points); break;
    case Box2dPart::Kind::Edge:
      // The wall's free side is the board's (outerWallsShape's order); its ends cannot be met.
      shape.segments.push_back(makeSegment(part.points.at(0), part.points.at(1)));
      break;
    case Box2dPart::Kind::Circle: shape.circles.push_back(CircleFeature<double>{part.centre, 0}); break;
  }
  return shape;
}

}  // namespace gizmo::verify
