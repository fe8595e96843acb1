#pragma once
// The registry of gizmo kinds: one line per kind, X(Name, stem), in GizmoType's order. Name is the
// kind's GizmoType and GizmoKind enumerator; stem names its files, one per layer that needs one:
// core/include/gizmo/core/kinds/STEM.hpp, verify/src/kinds/STEM.hpp and cli/kinds/STEM.hpp
// (docs/design.md, "Adding a gizmo"). The enumerators' values are the lines' places and are kept
// nowhere outside a build: logs hold the board as text and rules by their own codes. The order
// still counts twice: the first six lines are the standard kinds (kStandardKindCount), and the
// fuzz generator converts gizmos into the other kinds in the list's order, so a new kind goes at
// the end to leave every board generated before it as it was. cmake/GizmoKinds.cmake reads this
// file at configure time to include every kind's files; a line whose file is missing stops the
// configure step.
#define GIZMO_KINDS(X)           \
  X(Square, square)              \
  X(Circle, circle)              \
  X(Triangle, triangle)          \
  X(LeftFlipper, left_flipper)   \
  X(RightFlipper, right_flipper) \
  X(Absorber, absorber)          \
  X(Booster, booster)            \
  X(Teleporter, teleporter)      \
  X(Sink, sink)                  \
  X(Portal, portal)              \
  X(Spinner, spinner)            \
  X(Spawner, spawner)
