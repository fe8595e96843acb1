#pragma once
// The portal. What the fuzz generator and the verification checks know of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Portal> {
  // Generated: a third of the teleporters become portals, each with an exit cell anywhere on the
  // board (docs/fuzzing.md).
  static constexpr bool generatedByConversion = true;
  static constexpr bool convertsFrom(GizmoType t) { return t == GizmoType::Teleporter; }
  static constexpr int oneIn = 3;
  static void converted(GizmoSpec& g, fuzz::SeededRandom& own) {
    g.exitX = own.whole(0, kBoardSize - 1);
    g.exitY = own.whole(0, kBoardSize - 1);
  }
  static void afterConversions(BoardSpec& /*board*/, fuzz::SeededRandom& /*own*/) {}
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
