#pragma once
// How the pictures draw the teleporter (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Teleporter> {
  static constexpr Figure figure = Figure::Disc;
  static constexpr std::string_view svgClass = "teleporter";
};

}  // namespace gizmo::cli
