#pragma once
// How the pictures draw the spawner (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Spawner> {
  static constexpr Figure figure = Figure::CellOutline;
  static constexpr std::string_view svgClass = "spawner";
  static constexpr std::string_view colour = "#7fa8c9";
};

}  // namespace gizmo::cli
