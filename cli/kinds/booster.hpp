#pragma once
// How the pictures draw the booster (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Booster> {
  static constexpr Figure figure = Figure::Polygon;
  static constexpr std::string_view svgClass = "booster";
  static constexpr std::string_view colour = "#e0b830";
};

}  // namespace gizmo::cli
