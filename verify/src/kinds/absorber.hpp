#pragma once
// The absorber: placed by the generator's first draw, among the six standard kinds, at any size.
// What the fuzz generator and the verification checks know of it.
#include "gizmo/core/gizmos/absorber.hpp"
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Absorber> {
  static constexpr bool generatedByConversion = false;
  static constexpr bool alwaysKeyed = false;
  static constexpr bool aimedAtCorner = true;
  static constexpr bool grazedAlongEdge = true;
  static constexpr bool restedOnTop = true;
  static constexpr bool touchedBesideCapsule = false;
  static constexpr std::string_view exactRunRefusal = "";
  static constexpr bool box2dModels = true;
  static constexpr bool box2dSensor = true;
  // Its shot fires the ball with all its energy from inside its box; a capture takes it all.
  static constexpr RuleEnergy ruleEnergy(ModelRule r) {
    return r == AbsorberRule::Released ? RuleEnergy{RuleEffect::Fired} : RuleEnergy{};
  }
};

}  // namespace gizmo::verify
