#pragma once
// How the pictures draw the sink (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Sink> {
  static constexpr Figure figure = Figure::Polygon;
  static constexpr std::string_view svgClass = "sink";
  static constexpr std::string_view colour = "#55556a";
};

}  // namespace gizmo::cli
