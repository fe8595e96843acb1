#pragma once
// How the pictures draw the square (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Square> {
  static constexpr Figure figure = Figure::Polygon;
  static constexpr std::string_view svgClass = "square";
  static constexpr std::string_view colour = "#d9534f";
};

}  // namespace gizmo::cli
