#pragma once
// What every kind's drawing file (cli/kinds/STEM.hpp) defines: which figure the pictures draw for
// it (render_board_drawing.cpp, render_board_svg.cpp, and render/board_view.js, which reads the
// figure, its fields and its colour from the drawing's JSON), the SVG class of that figure, and
// its colour (the SVG's style sheet is written from the kinds' colours, in the list's order). The
// generated header kinds/all_drawing_kinds.hpp (cmake/GizmoKinds.cmake) includes every kind's file.
#include <concepts>
#include <string_view>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/kinds/kind_core.hpp"

namespace gizmo::cli {

// The figures a picture knows. A new kind picks one; a new figure is new drawing code.
enum class Figure {
  Polygon,      // its outline at rest (restShape's corners), filled
  Disc,         // the disc of its outline
  Flipper,      // a capsule that swings about its pivot (flipperLayout)
  Cross,        // the spinner's turning cross
  CellOutline,  // the outline of its cell: nothing meets it
};

template <GizmoType T>
struct KindDrawing;

template <class K>
concept DrawingKindEntry = requires {
  { K::figure } -> std::convertible_to<Figure>;
  // The class of its SVG element: the drawing's class of its core file, or one a figure shares
  // ("flipper" for both flippers).
  { K::svgClass } -> std::convertible_to<std::string_view>;
  // "#rrggbb": the fill of a polygon or disc, the stroke of the other figures. Kinds that share a
  // class share its figure and colour (drawing_registry.hpp checks).
  { K::colour } -> std::convertible_to<std::string_view>;
};

}  // namespace gizmo::cli
