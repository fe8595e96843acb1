#pragma once
// How the pictures draw the circle (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Circle> {
  static constexpr Figure figure = Figure::Disc;
  static constexpr std::string_view svgClass = "circle";
  static constexpr std::string_view colour = "#3fae5a";
};

}  // namespace gizmo::cli
