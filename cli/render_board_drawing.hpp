#pragma once
// A board as shapes to draw, taken from the core's own geometry (shapes.hpp) so that pictures
// show exactly what the simulator collides with: polygons for squares, triangles and absorbers,
// circles for circle bumpers, and each flipper's pivot and swing.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo::cli {

struct GizmoDrawing {
  std::string name;
  GizmoType type = GizmoType::Square;
  std::vector<Vec2<double>> polygon;  // squares, triangles, absorbers: vertices clockwise on screen
  Vec2<double> centre;                // circles: centre and radius; spinners: centre, arm length and radius
  double radius = 0;
  // Flippers: the pivot centre, the bar's direction at rest and at the end of the forward swing
  // (quarter turns θ = q·π/2 from +x toward +y), the sign of ω on the forward swing, the bar's
  // length (pivot centre to tip centre) and its half-width.
  Vec2<double> pivot;
  int restQuarter = 0, endQuarter = 0, forwardSign = 0;
  double length = 0;
  double rate = 0;  // spinners: the turning rate, rad/s
};

struct BoardDrawing {
  double size = kBoardSize;
  double ballRadius = kBallRadius;
  std::vector<GizmoDrawing> gizmos;
  std::vector<BallSpec> balls;  // where each ball starts
};

// The word for a gizmo type in a drawing's JSON and as a picture's CSS class ("left-flipper").
const char* drawingTypeName(GizmoType type);

BoardDrawing drawingOf(const BoardSpec& board);
nlohmann::ordered_json drawingJson(const BoardDrawing& drawing);

}  // namespace gizmo::cli
