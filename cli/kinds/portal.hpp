#pragma once
// How the pictures draw the portal (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Portal> {
  static constexpr Figure figure = Figure::Disc;
  static constexpr std::string_view svgClass = "portal";
  static constexpr std::string_view colour = "#7b5cd6";
};

}  // namespace gizmo::cli
