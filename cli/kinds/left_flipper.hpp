#pragma once
// How the pictures draw the left flipper (cli/kinds/kind_drawing.hpp).
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

template <>
struct KindDrawing<GizmoType::LeftFlipper> {
  static constexpr Figure figure = Figure::Flipper;
  // Both flippers share the class "flipper".
  static constexpr std::string_view svgClass = "flipper";
  static constexpr std::string_view colour = "#f0a030";
};

}  // namespace gizmo::cli
