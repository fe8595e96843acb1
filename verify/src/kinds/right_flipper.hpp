#pragma once
// The right flipper: placed by the generator's first draw, among the six standard kinds, always
// with a key connection so that it swings. What the fuzz generator and the verification checks know
// of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::RightFlipper> {
  static constexpr bool generatedByConversion = false;
  static constexpr bool alwaysKeyed = true;
  static constexpr bool aimedAtCorner = false;
  static constexpr bool grazedAlongEdge = true;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = true;
  static constexpr std::string_view exactRunRefusal = "";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = false;
  // A pinch stops it where it is: nothing gained.
  static constexpr RuleEnergy ruleEnergy(ModelRule /*blocked*/) { return {}; }
};

}  // namespace gizmo::verify
