#pragma once
// How the pictures draw the teleporter (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Teleporter> {
  static constexpr Figure figure = Figure::Disc;
  static constexpr std::string_view svgClass = "teleporter";
  static constexpr std::string_view colour = "#2bb3c0";
};

}  // namespace gizmo::cli
