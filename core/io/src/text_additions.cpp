#include "text_additions.hpp"

#include "parse_util.hpp"

namespace gizmo::io::detail {
namespace {

// SOURCES.md of the real-board collection (docs/board-files.md §2) says what each program does.
constexpr Addition kAdditions[] = {
    {"LeftSpinningFlipper", AdditionKind::Gizmo, "a spinning flipper", "lheckemann/gizmoball"},
    {"RightSpinningFlipper", AdditionKind::Gizmo, "a spinning flipper", "lheckemann/gizmoball"},
    {"Accelerator", AdditionKind::Gizmo, "a bumper that speeds the ball up", "course variants"},
    {"DeathSquare", AdditionKind::Gizmo, "a square that stops the ball", "d-g-n/CS308-GizmoBall"},
    {"Rhombus", AdditionKind::Gizmo, "a diamond bumper", "NiklavsM/Gizmoball"},
    {"Octagon", AdditionKind::Gizmo, "an octagonal bumper", "NiklavsM/Gizmoball"},
    {"Gate", AdditionKind::Gizmo, "a gate", "course variants"},
    {"Multiball", AdditionKind::Gizmo, "a gizmo that adds balls", "course variants"},
    {"Jezzmo", AdditionKind::Gizmo, "a growing wall", "MIT 6.170 staff examples (dwctsai/mit-6.170-gizmoball-3d)"},
    // JedBurrows' saver writes flippers as 'Flipper' (no side); its own reader has no case for the
    // word, so these flippers vanish when that program loads the file too.
    {"Flipper", AdditionKind::Gizmo, "a flipper without a side (its own program's reader drops it too)",
     "JedBurrows/CS308-GIzmoball"},
    {"Color", AdditionKind::Decoration, "a colour", "NiklavsM/Gizmoball, JedBurrows/CS308-GIzmoball"},
    {"Colour", AdditionKind::Decoration, "a colour", "highlightswitch/gizmoball"},
    {"Action", AdditionKind::Decoration, "an action that changes a gizmo's colour", "highlightswitch/gizmoball"},
    {"MouseConnect", AdditionKind::Input, "a mouse-button connection",
     "MIT 6.170 staff examples (dwctsai/mit-6.170-gizmoball-3d)"},
};

constexpr Addition kDgnSpinner{"Spinner", AdditionKind::Gizmo,
                               "d-g-n's spinner, a bar always turning at 6 pi rad/s, not NiklavsM's cross",
                               "d-g-n/CS308-GizmoBall"};

}  // namespace

const Addition& dgnSpinner() { return kDgnSpinner; }

const Addition* findAddition(std::string_view word) {
  const std::string lower = toLowerAscii(word);
  for (const Addition& a : kAdditions)
    if (toLowerAscii(a.word) == lower) return &a;
  return nullptr;
}

}  // namespace gizmo::io::detail
