#pragma once
// How a gizmo becomes Box2D bodies and shapes (docs/verification.md, "Cross-checking against
// Box2D"), as plain data: this header does not include Box2D, so the time-of-impact check, the
// world builder and the tests read the one mapping. 1 L = 1 m, board coordinates as they are
// (y down, gravity +y: Box2D has no preferred up).
//
// Box2D rounds every polygon and edge by a skin of b2_polygonRadius. The mapping insets each
// polygon and moves each wall edge outwards by that skin, so that Box2D's faces lie exactly on
// ours; only the corners differ (rounded with radius skin instead of sharp).
#include <optional>
#include <string>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/features.hpp"

namespace gizmo::verify {

// Box2D 2.4's compiled-in constants (b2_common.h), restated because the comparisons account
// for them; tests/unit/verify_box2d_test.cpp checks them against the library's.
inline constexpr double kBox2dLinearSlop = 0.005;
inline constexpr double kBox2dPolygonSkin = 2 * kBox2dLinearSlop;  // b2_polygonRadius
inline constexpr double kBox2dMaxTranslation = 2.0;                // per step (b2_maxTranslation)
inline constexpr double kBox2dMaxRotation = 1.5707963267948966;    // per step, π/2 (b2_maxRotation)

// b2TimeOfImpact stops when the distance between the two shapes' cores (the shapes without
// their radii) comes within `tolerance` of this target: 3 linear slops inside contact.
inline double box2dToiTarget(double totalRadius) {
  const double t = totalRadius - 3 * kBox2dLinearSlop;
  return t > kBox2dLinearSlop ? t : kBox2dLinearSlop;
}
inline constexpr double kBox2dToiTolerance = 0.25 * kBox2dLinearSlop;

// One Box2D shape: a convex polygon's core (vertices clockwise on screen, rounded by `radius`,
// the skin), a circle (centre, radius), or an edge (two points, rounded by the skin).
struct Box2dPart {
  enum class Kind { Polygon, Circle, Edge };
  Kind kind = Kind::Circle;
  std::vector<Vec2<double>> points;  // polygon vertices or the edge's ends
  Vec2<double> centre;               // circle
  double radius = 0;                 // circle radius, or the skin
};

// One body. Parts are in the body's own frame; the body stands at `origin` turned by `angle`
// (radians, from +x towards +y, as Box2D's angle in these coordinates).
struct Box2dBody {
  std::string name;  // the gizmo's name; OuterWalls for the walls
  GizmoType type = GizmoType::Square;
  bool walls = false;
  bool kinematic = false;  // a flipper or a spinner: turned on the core's schedule about its pivot
  bool sensor = false;     // an absorber: reports overlaps, our code captures
  double restitution = 1;  // the gizmo's coefficient of reflection
  Vec2<double> origin;
  double angle = 0;
  std::vector<Box2dPart> parts;
};

// Why the bridge cannot model the board, or nothing: the commands ask before they run Box2D.
std::optional<std::string> box2dCannotModel(const BoardSpec& board);
// The body of a gizmo (flippers at rest: the origin is the pivot, the axis along the body's +x);
// std::invalid_argument for a gizmo the bridge cannot model.
Box2dBody box2dBodyOf(const GizmoSpec& gizmo);
// The four walls as edges on one static body.
Box2dBody box2dOuterWalls();

// The part in board coordinates for a body standing at origin, turned by a whole number of
// quarter turns (exact).
Box2dPart placePart(const Box2dPart& part, const Vec2<double>& origin, int quarterTurns);

// The part's core as features our time-of-impact functions take (a polygon's edges and
// vertices, an edge's segment, a circle's centre as a circle of radius 0): Box2D's time of
// impact is the moment the ball's centre comes within box2dToiTarget of this core.
Shape<double> coreShape(const Box2dPart& part);

}  // namespace gizmo::verify
