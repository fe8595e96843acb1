#pragma once
// How the pictures draw the trial's bouncer (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Bouncer> {
  static constexpr Figure figure = Figure::Polygon;
  static constexpr std::string_view svgClass = "bouncer";
  static constexpr std::string_view colour = "#2a9d8f";
};

}  // namespace gizmo::cli
