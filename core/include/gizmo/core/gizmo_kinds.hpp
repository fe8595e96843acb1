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
  int side;                      // ownSide's; 0: sized by its board line's corners, never turned
  bool exitCell;                 // its board line names an exit cell (a portal)
  KindMotion motion;             // still, swings or turns (kinds/kind_core.hpp)
  bool holdsPlacedBalls;         // a ball placed at rest inside it starts held (the absorber)
  bool disc;                     // isDiscGizmo's
  bool xmlOrientationAlways;     // the XML writer writes its orientation when it is 0 too
  std::string_view handedness;   // "left", "right", or empty
};

// Whether every rule a kind's file names has a code that a record holds and that none of the
// board's own rules has, a name, and no code or name that another rule has with a different
// meaning (the two flippers name one rule, which is fine): its code is in logs, its name in the
// logs' readings.
template <GizmoType T>
constexpr bool rulesAreItsOwn() {
  for (const KindRule& mine : KindCore<T>::rules) {
    if (static_cast<int>(mine.rule) >= kModelRuleCodeCount || !boardRuleName(mine.rule).empty() || mine.name.empty())
      return false;
    for (int code = 0; code < kModelRuleCodeCount; ++code)
      if (boardRuleName(static_cast<ModelRule>(code)) == mine.name) return false;
    bool agree = true;
    forEachKind([&]<GizmoType U>(KindTag<U>) {
      for (const KindRule& other : KindCore<U>::rules)
        if ((other.rule == mine.rule) != (other.name == mine.name)) agree = false;
    });
    if (!agree) return false;
  }
  return true;
}

// Every kind's file holds what CoreKindEntry asks for, and its rules are its own; the messages
// name the kind and its file.
#define GIZMO_KIND_IS_COMPLETE(Name, stem)                                            \
  static_assert(CoreKindEntry<KindCore<GizmoType::Name>>,                             \
                "kind " #Name ": core/include/gizmo/core/kinds/" #stem                \
                ".hpp lacks part of what "                                            \
                "CoreKindEntry (kinds/kind_core.hpp) asks of a kind's core file");    \
  static_assert(rulesAreItsOwn<GizmoType::Name>(),                                    \
                "kind " #Name ": a rule that core/include/gizmo/core/kinds/" #stem    \
                ".hpp names has no name, a code beyond 15 or one of the board's own " \
                "(board/model_rule.hpp), or the code or name of another rule");
GIZMO_KINDS(GIZMO_KIND_IS_COMPLETE)
#undef GIZMO_KIND_IS_COMPLETE

template <GizmoType T>
requires CoreKindEntry<KindCore<T>>
constexpr GizmoKindInfo kindInfoOf() {
  using K = KindCore<T>;
  return {T,
          K::textCommand,
          K::textUsage,
          K::xmlElement,
          K::word,
          K::drawing,
          K::side,
          K::exitCell,
          K::motion,
          K::holdsPlacedBalls,
          K::disc,
          K::xmlOrientationAlways,
          K::handedness};
}

// In GizmoType's order. The kinds after the standard ones (kStandardKindCount below) are other
// programs' additions, spelled as the programs that invented them spell them (docs/board-files.md §2).
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

// Whether a kind's size is a property its board line gives (side 0: the absorber's corners); such
// a kind is never turned.
constexpr bool sizedByLine(GizmoType type) { return gizmoKind(type).side == 0; }

// Whether a kind swings like a flipper (its gizmo is a Flipper).
constexpr bool swings(GizmoType type) { return gizmoKind(type).motion == KindMotion::Swings; }
// Whether a kind turns like a spinner (its gizmo is a Spinner).
constexpr bool turns(GizmoType type) { return gizmoKind(type).motion == KindMotion::Turns; }

// How a gizmo on the board moves: its kind's motion, Still for a ball and the outer walls.
constexpr KindMotion motionOf(GizmoKind kind) {
  const int type = static_cast<int>(kind) - static_cast<int>(gizmoKindOf(GizmoType(0)));
  return type >= 0 && type < kGizmoTypeCount ? kGizmoKinds[type].motion : KindMotion::Still;
}

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
