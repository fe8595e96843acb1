#pragma once
// The teleporter. What the fuzz generator and the verification checks know of it.
#include <vector>

#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Teleporter> {
  // Generated: half the circles become teleporters (docs/fuzzing.md).
  static constexpr bool generatedByConversion = true;
  static constexpr bool convertsFrom(GizmoType t) { return t == GizmoType::Circle; }
  static constexpr int oneIn = 2;
  static void converted(GizmoSpec& /*g*/, fuzz::SeededRandom& /*own*/) {}
  // Most of them get an exit: a connection to a teleporter (now and then themselves).
  static void afterConversions(BoardSpec& board, fuzz::SeededRandom& own) {
    std::vector<const GizmoSpec*> teleporters;
    for (const GizmoSpec& g : board.gizmos)
      if (g.type == GizmoType::Teleporter) teleporters.push_back(&g);
    for (const GizmoSpec* from : teleporters)
      if (!own.chance(5)) {
        const GizmoSpec* to = teleporters[std::size_t(own.whole(0, int(teleporters.size()) - 1))];
        board.connections.push_back(ConnectSpec{from->name, to->name, {}});
      }
  }
  static constexpr bool alwaysKeyed = false;
  static constexpr bool aimedAtCorner = false;
  static constexpr bool grazedAlongEdge = true;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = false;
  static constexpr std::string_view exactRunRefusal = "";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = false;
  // A teleport moves the ball to its exit, which may be higher.
  static constexpr RuleEnergy ruleEnergy(ModelRule /*teleported*/) { return {RuleEffect::Lifted}; }
};

}  // namespace gizmo::verify
