#pragma once
// How the pictures draw the absorber (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Absorber> {
  static constexpr Figure figure = Figure::Polygon;
  static constexpr std::string_view svgClass = "absorber";
  static constexpr std::string_view colour = "#b05cc4";
};

}  // namespace gizmo::cli
