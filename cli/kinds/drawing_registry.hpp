#pragma once
// Every kind's drawing file, checked against DrawingKindEntry (an incomplete file fails to compile
// with the kind's name), and the lookups the pictures make.
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

}  // namespace gizmo::cli
