#pragma once
// How the pictures draw the spinner (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::Spinner> {
  static constexpr Figure figure = Figure::Cross;
  static constexpr std::string_view svgClass = "spinner";
  static constexpr std::string_view colour = "#b388ff";
};

}  // namespace gizmo::cli
