#pragma once
// The triangle bumper: placed by the generator's first draw, among the six standard kinds. What the
// fuzz generator and the verification checks know of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Triangle> {
  static constexpr bool generatedByConversion = false;
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
  static constexpr RuleEnergy ruleEnergy(ModelRule /*none: it records no rule*/) { return {}; }
};

}  // namespace gizmo::verify
