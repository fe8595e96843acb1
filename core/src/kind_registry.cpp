// The core's lookups of a kind's data that the low headers declare (board_spec.hpp, shapes.hpp):
// they are defined here, where every kind's file is included, because each kind's file includes
// its gizmo's class, and the classes include those headers. gizmo_kinds.hpp checks every kind's
// file against CoreKindEntry.
#include "gizmo/core/gizmo_kinds.hpp"

namespace gizmo {

int ownSide(GizmoType t) { return gizmoKind(t).side; }

bool isDiscGizmo(GizmoType t) { return gizmoKind(t).disc; }

}  // namespace gizmo
