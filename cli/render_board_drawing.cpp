// Board shapes for pictures, from the simulator's geometry (see render_board_drawing.hpp).
#include "render_board_drawing.hpp"

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "kinds/drawing_registry.hpp"

namespace gizmo::cli {

// Each class is a literal of kGizmoKinds, so its view ends in a terminating null.
const char* drawingTypeName(GizmoType type) { return gizmoKind(type).drawing.data(); }

namespace {

nlohmann::ordered_json point(const Vec2<double>& p) { return nlohmann::ordered_json::array({p.x, p.y}); }

}  // namespace

BoardDrawing drawingOf(const BoardSpec& board) {
  BoardDrawing drawing;
  drawing.balls = board.balls;
  for (const GizmoSpec& g : board.gizmos) {
    GizmoDrawing d;
    d.name = g.name;
    d.type = g.type;
    const Shape<double> shape = restShape<double>(g);
    const Figure figure = figureOf(g.type);  // each kind's drawing file says (cli/kinds/STEM.hpp)
    if (figure == Figure::Flipper) {
      const FlipperLayout layout = flipperLayout(g.type, g.orientation);
      d.pivot = Vec2<double>(g.x + layout.pivot.x, g.y + layout.pivot.y);
      d.restQuarter = layout.restQuarter;
      d.endQuarter = layout.endQuarter;
      d.forwardSign = layout.forwardSign;
      d.length = kFlipperLength;
      d.radius = kFlipperRadius;
    } else if (figure == Figure::Disc) {
      d.centre = shape.circles.front().centre;
      d.radius = shape.circles.front().radius;
    } else if (figure == Figure::Cross) {
      d.centre = Vec2<double>(g.x + 1, g.y + 1);
      d.length = kSpinnerArmLength;
      d.radius = kSpinnerArmRadius;
      d.rate = kSpinnerTurnRate;
    } else if (figure == Figure::CellOutline) {
      // Nothing meets it: its cell is drawn as an outline.
      d.polygon = {Vec2<double>(g.x, g.y), Vec2<double>(g.x + 1, g.y), Vec2<double>(g.x + 1, g.y + 1),
                   Vec2<double>(g.x, g.y + 1)};
    } else {
      // A polygon's vertices are its zero-radius corner circles, in the order of its edges.
      for (const CircleFeature<double>& corner : shape.circles) d.polygon.push_back(corner.centre);
    }
    drawing.gizmos.push_back(d);
  }
  return drawing;
}

nlohmann::ordered_json drawingJson(const BoardDrawing& drawing) {
  nlohmann::ordered_json gizmos = nlohmann::ordered_json::array();
  for (const GizmoDrawing& d : drawing.gizmos) {
    const Figure figure = figureOf(d.type);
    nlohmann::ordered_json g{{"name", d.name},
                             {"type", drawingTypeName(d.type)},
                             {"figure", figureName(figure)},
                             {"colour", colourOf(d.type)}};
    if (figure == Figure::Flipper) {
      g["pivot"] = point(d.pivot);
      g["rest_quarter"] = d.restQuarter;
      g["end_quarter"] = d.endQuarter;
      g["forward_sign"] = d.forwardSign;
      g["length"] = d.length;
      g["radius"] = d.radius;
    } else if (figure == Figure::Disc) {
      g["centre"] = point(d.centre);
      g["radius"] = d.radius;
    } else if (figure == Figure::Cross) {
      g["centre"] = point(d.centre);
      g["length"] = d.length;
      g["radius"] = d.radius;
      g["rate"] = d.rate;
    } else {
      nlohmann::ordered_json polygon = nlohmann::ordered_json::array();
      for (const Vec2<double>& p : d.polygon) polygon.push_back(point(p));
      g["polygon"] = polygon;
    }
    gizmos.push_back(g);
  }
  return {{"size", drawing.size}, {"ball_radius", drawing.ballRadius}, {"gizmos", gizmos}};
}

}  // namespace gizmo::cli
