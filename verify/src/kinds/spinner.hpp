#pragma once
// The spinner. What the fuzz generator and the verification checks know of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Spinner> {
  // Generated: a third of the flippers become spinners (keeping the key connection a flipper is
  // given) (docs/fuzzing.md).
  static constexpr bool generatedByConversion = true;
  static constexpr bool convertsFrom(GizmoType t) {
    return t == GizmoType::LeftFlipper || t == GizmoType::RightFlipper;
  }
  static constexpr int oneIn = 3;
  static void converted(GizmoSpec& /*g*/, fuzz::SeededRandom& /*own*/) {}
  static void afterConversions(BoardSpec& /*board*/, fuzz::SeededRandom& /*own*/) {}
  static constexpr bool alwaysKeyed = true;
  static constexpr bool aimedAtCorner = false;
  static constexpr bool grazedAlongEdge = true;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = false;
  // No exact run: its arms' angles are irrational.
  static constexpr std::string_view exactRunRefusal = "turns through angles whose sines and cosines are irrational";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = false;
  // A pinch stops it where it is: nothing gained.
  static constexpr RuleEnergy ruleEnergy(ModelRule /*blocked*/) { return {}; }
};

}  // namespace gizmo::verify
