#pragma once
// The circle bumper: placed by the generator's first draw, among the six standard kinds. The aimed
// ball that grazes a cell's edge never picks it (it has no edge there). What the fuzz generator and
// the verification checks know of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Circle> {
  static constexpr bool generatedByConversion = false;
  static constexpr bool alwaysKeyed = false;
  static constexpr bool aimedAtCorner = false;
  static constexpr bool grazedAlongEdge = false;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = false;
  static constexpr std::string_view exactRunRefusal = "";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = false;
  static constexpr RuleEnergy ruleEnergy(ModelRule /*none: it records no rule*/) { return {}; }
};

}  // namespace gizmo::verify
