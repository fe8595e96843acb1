#pragma once
// The trial's bouncer (tests/kinds/bouncer/core.hpp). What the fuzz generator and the verification
// checks know of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Bouncer> {
  // Generated: a fifth of the squares become bouncers.
  static constexpr bool generatedByConversion = true;
  static constexpr bool convertsFrom(GizmoType t) { return t == GizmoType::Square; }
  static constexpr int oneIn = 5;
  static void converted(GizmoSpec& /*g*/, fuzz::SeededRandom& /*own*/) {}
  static void afterConversions(BoardSpec& /*board*/, fuzz::SeededRandom& /*own*/) {}
  static constexpr bool alwaysKeyed = false;
  static constexpr bool aimedAtCorner = true;
  static constexpr bool grazedAlongEdge = false;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = false;
  static constexpr std::string_view exactRunRefusal =
      "has 45-degree edges, whose unit normals (sqrt(2)/2) are irrational";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = false;
  static constexpr RuleEnergy ruleEnergy(ModelRule /*none: it records no rule*/) { return {}; }
};

}  // namespace gizmo::verify
