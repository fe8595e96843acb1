#pragma once
// Every kind's drawing file, checked against DrawingKindEntry (an incomplete file fails to compile
// with the kind's name), and the lookups the pictures make.
#include <string_view>

#include "gizmo/core/kinds/kind_core.hpp"
#include "kinds/all_drawing_kinds.hpp"  // generated from the kind list by cmake/GizmoKinds.cmake
#include "kinds/kind_drawing.hpp"

namespace gizmo::cli {

#define GIZMO_DRAWING_KIND_IS_COMPLETE(Name, stem)              \
  static_assert(DrawingKindEntry<KindDrawing<GizmoType::Name>>, \
                "kind " #Name ": cli/kinds/" #stem              \
                ".hpp lacks part of what DrawingKindEntry (cli/kinds/kind_drawing.hpp) asks");
GIZMO_KINDS(GIZMO_DRAWING_KIND_IS_COMPLETE)
#undef GIZMO_DRAWING_KIND_IS_COMPLETE

inline Figure figureOf(GizmoType t) {
  return visitKind(t, []<GizmoType T>(KindTag<T>) { return KindDrawing<T>::figure; });
}

// Each class is a literal, so its view ends in a terminating null.
inline const char* svgClassOf(GizmoType t) {
  return visitKind(t, []<GizmoType T>(KindTag<T>) { return KindDrawing<T>::svgClass.data(); });
}

inline std::string_view colourOf(GizmoType t) {
  return visitKind(t, []<GizmoType T>(KindTag<T>) { return KindDrawing<T>::colour; });
}

// The figure's name in the drawing's JSON, by which render/board_view.js draws it.
inline const char* figureName(Figure f) {
  switch (f) {
    case Figure::Polygon: return "polygon";
    case Figure::Disc: return "disc";
    case Figure::Flipper: return "flipper";
    case Figure::Cross: return "cross";
    case Figure::CellOutline: return "cell-outline";
  }
  return "polygon";  // not reached: every figure is a case
}

// The style sheet has one rule per class, so kinds that share a class (both flippers) must agree
// on its figure and colour.
consteval bool sharedClassesAgree() {
  struct Entry {
    std::string_view svgClass;
    Figure figure;
    std::string_view colour;
  };
  const Entry entries[] = {
#define GIZMO_DRAWN_ENTRY(Name, stem) \
  {KindDrawing<GizmoType::Name>::svgClass, KindDrawing<GizmoType::Name>::figure, KindDrawing<GizmoType::Name>::colour},
      GIZMO_KINDS(GIZMO_DRAWN_ENTRY)
#undef GIZMO_DRAWN_ENTRY
  };
  for (const Entry& a : entries)
    for (const Entry& b : entries)
      if (a.svgClass == b.svgClass && (a.figure != b.figure || a.colour != b.colour)) return false;
  return true;
}
static_assert(sharedClassesAgree(), "two kinds share an SVG class (cli/kinds/STEM.hpp) but not its figure or colour");

}  // namespace gizmo::cli
