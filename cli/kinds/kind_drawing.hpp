#pragma once
// What every kind's drawing file (cli/kinds/STEM.hpp) defines: which figure the pictures draw for
// it (render_board_drawing.cpp, render_board_svg.cpp, and render/board_view.js, which reads the
// figure's fields from the drawing's JSON) and the SVG class of that figure. The generated header
// kinds/all_drawing_kinds.hpp (cmake/GizmoKinds.cmake) includes every kind's file.
//
// The colours stay in one place each, keyed by the drawing's class (kinds/STEM.hpp in core: its
// `drawing`): the SVG's style sheet (render_board_svg.cpp) and board_view.js's fills. Moving a
// colour into a kind's file would reorder the style sheet, and so change every picture `gizmo
// render` writes, which must stay the same bytes; the page's script reads the class it is given.
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
};

}  // namespace gizmo::cli
