// The core's lookups of a kind's data that the low headers declare (board_spec.hpp, shapes.hpp,
// grid_properties.hpp): they are defined here, where every kind's file is included, because each
// kind's file includes its gizmo's class, and the classes include those headers.
#include "gizmo/core/gizmo_kinds.hpp"

namespace gizmo {

// Every kind's file holds what CoreKindEntry asks for; the message names the kind and its file.
#define GIZMO_KIND_IS_COMPLETE(Name, stem)                                        \
  static_assert(CoreKindEntry<KindCore<GizmoType::Name>>,                        \
                "kind " #Name ": core/include/gizmo/core/kinds/" #stem ".hpp lacks part of what " \
                "CoreKindEntry (kinds/kind_core.hpp) asks of a kind's core file");
GIZMO_KINDS(GIZMO_KIND_IS_COMPLETE)
#undef GIZMO_KIND_IS_COMPLETE

int ownSide(GizmoType t) { return gizmoKind(t).side; }

bool isDiscGizmo(GizmoType t) { return gizmoKind(t).disc; }

}  // namespace gizmo
