#pragma once
// What the board files, the messages and the drawings call each kind of gizmo, in one table: one
// row per kind, which the readers, the writers, the board check and the drawings look up instead
// of each keeping a switch of its own. The rows are read from the kinds' own files
// (kinds/STEM.hpp), in the order of the kind list (kinds/kind_list.hpp).
#include <array>
#include <string_view>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/kinds/all_kinds.hpp"  // generated from the kind list by cmake/GizmoKinds.cmake

namespace gizmo {

struct GizmoKindInfo {
  GizmoType type;
  std::string_view textCommand;  // the text format's command ("LeftFlipper")
  std::string_view textUsage;    // its line, for messages; its word count is the command's
  std::string_view xmlElement;   // the XML format's element ("leftFlipper")
  std::string_view word;         // in messages ("left flipper")
  std::string_view drawing;      // the drawings' class ("left-flipper")
  int side;                      // ownSide's
  bool disc;                     // isDiscGizmo's
  bool xmlOrientationAlways;     // the XML writer writes its orientation when it is 0 too
  std::string_view handedness;   // "left", "right", or empty
};

// Every kind's file holds what CoreKindEntry asks for; the message names the kind and its file.
#define GIZMO_KIND_IS_COMPLETE(Name, stem)                             \
  static_assert(CoreKindEntry<KindCore<GizmoType::Name>>,              \
                "kind " #Name ": core/include/gizmo/core/kinds/" #stem \
                ".hpp lacks part of what "                             \
                "CoreKindEntry (kinds/kind_core.hpp) asks of a kind's core file");
GIZMO_KINDS(GIZMO_KIND_IS_COMPLETE)
#undef GIZMO_KIND_IS_COMPLETE

template <GizmoType T>
requires CoreKindEntry<KindCore<T>>
constexpr GizmoKindInfo kindInfoOf() {
  using K = KindCore<T>;
  return {T,          K::textCommand, K::textUsage, K::xmlElement,           K::word,
          K::drawing, K::side,        K::disc,      K::xmlOrientationAlways, K::handedness};
}

// In GizmoType's order. Booster and after are other programs' additions, spelled as the programs
// that invented them spell them (docs/board-files.md §2).
inline constexpr std::array<GizmoKindInfo, kGizmoTypeCount> kGizmoKinds = {
#define GIZMO_KIND_ROW(Name, stem) kindInfoOf<GizmoType::Name>(),
    GIZMO_KINDS(GIZMO_KIND_ROW)
#undef GIZMO_KIND_ROW
};

// The kinds of the Gizmoball format itself, the first six lines of the kind list, before the
// additions of other programs.
inline constexpr int kStandardKindCount = 6;
constexpr bool isStandardKind(GizmoType type) { return static_cast<int>(type) < kStandardKindCount; }

// The row of a kind. Every GizmoType has one (checked at compile time below).
constexpr const GizmoKindInfo& gizmoKind(GizmoType type) { return kGizmoKinds[static_cast<int>(type)]; }

constexpr bool kindsInTypeOrder() {
  for (int i = 0; i < static_cast<int>(std::size(kGizmoKinds)); ++i)
    if (static_cast<int>(kGizmoKinds[i].type) != i) return false;
  return true;
}
static_assert(kindsInTypeOrder(), "kGizmoKinds must hold one row per GizmoType, in its order");

// The number of words of a kind's text line: its command's token count.
constexpr std::size_t textTokens(const GizmoKindInfo& k) {
  std::size_t words = 0;
  bool inWord = false;
  for (char c : k.textUsage) {
    if (c != ' ' && !inWord) ++words;
    inWord = c != ' ';
  }
  return words;
}

// The kind an XML element names, exactly as spelled; nullptr for none.
constexpr const GizmoKindInfo* gizmoKindByXmlElement(std::string_view element) {
  for (const GizmoKindInfo& k : kGizmoKinds)
    if (k.xmlElement == element) return &k;
  return nullptr;
}

}  // namespace gizmo
