#pragma once
// What the board files, the messages and the drawings call each kind of gizmo, in one table: one
// row per kind, which the readers, the writers, the board check and the drawings look up instead
// of each keeping a switch of its own. A new kind is a new GizmoType and a new row here (its box
// side is ownSide's, in board_spec.hpp).
#include <string_view>

#include "gizmo/core/board_spec.hpp"

namespace gizmo {

struct GizmoKindInfo {
  GizmoType type;
  std::string_view textCommand;  // the text format's command ("LeftFlipper")
  std::string_view textUsage;    // its line, for messages; its word count is the command's
  std::string_view xmlElement;   // the XML format's element ("leftFlipper")
  std::string_view word;         // in messages ("left flipper")
  std::string_view drawing;      // the drawings' class ("left-flipper")
};

// In GizmoType's order. Booster and after are other programs' additions, spelled as the programs
// that invented them spell them (docs/board-files.md §2).
inline constexpr GizmoKindInfo kGizmoKinds[] = {
    {GizmoType::Square, "Square", "Square NAME X Y", "squareBumper", "square", "square"},
    {GizmoType::Circle, "Circle", "Circle NAME X Y", "circleBumper", "circle", "circle"},
    {GizmoType::Triangle, "Triangle", "Triangle NAME X Y", "triangleBumper", "triangle", "triangle"},
    {GizmoType::LeftFlipper, "LeftFlipper", "LeftFlipper NAME X Y", "leftFlipper", "left flipper", "left-flipper"},
    {GizmoType::RightFlipper, "RightFlipper", "RightFlipper NAME X Y", "rightFlipper", "right flipper", "right-flipper"},
    {GizmoType::Absorber, "Absorber", "Absorber NAME X1 Y1 X2 Y2", "absorber", "absorber", "absorber"},
    {GizmoType::Booster, "Booster", "Booster NAME X Y", "booster", "booster", "booster"},
    {GizmoType::Teleporter, "Teleporter", "Teleporter NAME X Y", "teleporter", "teleporter", "teleporter"},
    {GizmoType::Sink, "Sink", "Sink NAME X Y", "sink", "sink", "sink"},
    {GizmoType::Portal, "Portal", "Portal NAME X Y EXITX EXITY", "portal", "portal", "portal"},
    {GizmoType::Spinner, "Spinner", "Spinner NAME X Y", "spinner", "spinner", "spinner"},
    {GizmoType::Spawner, "Spawner", "Spawner NAME X Y", "spawner", "spawner", "spawner"},
};

// The kinds of the Gizmoball format itself, before the additions of other programs.
constexpr bool isStandardKind(GizmoType type) { return static_cast<int>(type) < static_cast<int>(GizmoType::Booster); }

// The row of a kind. Every GizmoType has one (checked at compile time below).
constexpr const GizmoKindInfo& gizmoKind(GizmoType type) { return kGizmoKinds[static_cast<int>(type)]; }

constexpr bool kindsInTypeOrder() {
  for (int i = 0; i < static_cast<int>(std::size(kGizmoKinds)); ++i)
    if (static_cast<int>(kGizmoKinds[i].type) != i) return false;
  return static_cast<int>(std::size(kGizmoKinds)) == static_cast<int>(GizmoType::Spawner) + 1;
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
