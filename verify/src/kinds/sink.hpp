#pragma once
// The sink. What the fuzz generator and the verification checks know of it.
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Sink> {
  // Generated: a quarter of the squares become sinks (docs/fuzzing.md).
  static constexpr bool generatedByConversion = true;
  static constexpr bool convertsFrom(GizmoType t) { return t == GizmoType::Square; }
  static constexpr int oneIn = 4;
  static void converted(GizmoSpec& /*g*/, fuzz::SeededRandom& /*own*/) {}
  static void afterConversions(BoardSpec& /*board*/, fuzz::SeededRandom& /*own*/) {}
  static constexpr bool alwaysKeyed = false;
  static constexpr bool aimedAtCorner = true;
  static constexpr bool grazedAlongEdge = true;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = false;
  static constexpr std::string_view exactRunRefusal = "";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = false;
  // A sunk ball leaves play with its energy.
  static constexpr RuleEnergy ruleEnergy(ModelRule /*sunk*/) { return {}; }
};

}  // namespace gizmo::verify
