#pragma once
// The booster. What the fuzz generator and the verification checks know of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Booster> {
  // Generated: half the triangles become boosters (docs/fuzzing.md).
  static constexpr bool generatedByConversion = true;
  static constexpr bool convertsFrom(GizmoType t) { return t == GizmoType::Triangle; }
  static constexpr int oneIn = 2;
  static void converted(GizmoSpec& /*g*/, fuzz::SeededRandom& /*own*/) {}
  static void afterConversions(BoardSpec& /*board*/, fuzz::SeededRandom& /*own*/) {}
  static constexpr bool alwaysKeyed = false;
  static constexpr bool aimedAtCorner = true;
  static constexpr bool grazedAlongEdge = true;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = false;
  // No exact run: its face's normal is irrational.
  static constexpr std::string_view exactRunRefusal =
      "has a 45-degree edge, whose unit normal (sqrt(2)/2) is irrational";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = false;
  // It doubles the speed of the ball it reflects.
  static constexpr RuleEnergy ruleEnergy(ModelRule /*boosted*/) { return {RuleEffect::SpeedScaled, 2}; }
};

}  // namespace gizmo::verify
