#pragma once
// How the pictures draw the triangle (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Triangle> {
  static constexpr Figure figure = Figure::Polygon;
  static constexpr std::string_view svgClass = "triangle";
  static constexpr std::string_view colour = "#3e7cd6";
};

}  // namespace gizmo::cli
