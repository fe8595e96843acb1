#pragma once
// The spawner. What the fuzz generator and the verification checks know of it.
#include "gizmo/core/gizmos/spawner.hpp"
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

template <>
struct KindVerify<GizmoType::Spawner> {
  // Generated: a third of the sinks become spawners, each given a key connection so that it spawns
  // (docs/fuzzing.md).
  static constexpr bool generatedByConversion = true;
  static constexpr bool convertsFrom(GizmoType t) { return t == GizmoType::Sink; }
  static constexpr int oneIn = 3;
  static void converted(GizmoSpec& /*g*/, fuzz::SeededRandom& /*own*/) {}
  static void afterConversions(BoardSpec& /*board*/, fuzz::SeededRandom& /*own*/) {}
  static constexpr bool alwaysKeyed = true;
  static constexpr bool aimedAtCorner = false;
  static constexpr bool grazedAlongEdge = true;
  static constexpr bool restedOnTop = false;
  static constexpr bool touchedBesideCapsule = false;
  static constexpr std::string_view exactRunRefusal = "";
  // The Box2D bridge would need bodies added to the world as the board runs, which it does not
  // do yet: refused by name rather than compared as something else.
  static constexpr bool box2dModels = false;
  static constexpr bool box2dSensor = false;
  // A spawned ball comes into play with all its energy, as a fired one does.
  static constexpr RuleEnergy ruleEnergy(ModelRule r) {
    return r == SpawnerRule::Spawned ? RuleEnergy{RuleEffect::Brought} : RuleEnergy{};
  }
};

}  // namespace gizmo::verify
