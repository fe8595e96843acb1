#pragma once
// What every kind's verify file (verify/src/kinds/STEM.hpp) defines: how the fuzz generator makes
// it, and what the checks that cannot take it say about it. The generated header
// kinds/all_verify_kinds.hpp (cmake/GizmoKinds.cmake) includes every kind's file; the shared code
// reads a kind's entry through visitKind (gizmo/core/kinds/kind_core.hpp).
#include <concepts>
#include <string_view>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/verify/fuzz/seeded_random.hpp"

namespace gizmo::verify {

template <GizmoType T>
struct KindVerify;

// A kind that the generator makes by converting gizmos of another kind, drawn after the standard
// kinds are placed (verify/src/fuzz/run_generator.cpp, `additions`): a gizmo of a kind that
// `convertsFrom` accepts becomes this kind with a chance of one in `oneIn`. The conversions run
// in the kind list's order, each over the whole board, drawing from the additions' own stream,
// so that boards without the base kinds keep every draw they had.
template <class K>
concept GeneratedByConversion = requires(GizmoSpec& g, BoardSpec& board, fuzz::SeededRandom& own) {
  { K::convertsFrom(GizmoType{}) } -> std::convertible_to<bool>;
  { K::oneIn } -> std::convertible_to<int>;
  // Draws what a converted gizmo needs besides its type (a portal's exit cell).
  K::converted(g, own);
  // Runs once after the kind's conversions (a teleporter's connections).
  K::afterConversions(board, own);
};

// What one of a kind's rules (KindCore::rules) may do to the energy of the ball it names (the
// rule's other gizmo), beyond what the event's own reflection does, for the fuzz invariants' energy
// check (verify/src/fuzz/invariants.cpp).
enum class RuleEffect {
  Kept,         // nothing more: the rule keeps energy or takes it (a capture, a pinch, a sink)
  Fired,        // the ball leaves with all its energy from inside the gizmo's outline, which
                // overlaps it until the gizmo's Leave event (an absorber's shot)
  Brought,      // the ball comes into play with all its energy (a spawn)
  Lifted,       // the ball moves, reported before it does, and may gain the height between (a teleport)
  SpeedScaled,  // the ball's speed is multiplied by speedFactor, reported before it is: ½|v|² may
                // rise by (speedFactor² − 1)·½|v|² (a boost)
};

struct RuleEnergy {
  RuleEffect effect = RuleEffect::Kept;
  int speedFactor = 1;
};

template <class K>
concept VerifyKindEntry = requires {
  // Generation: whether the generator converts gizmos into it (GeneratedByConversion), whether
  // it gives the gizmo a key connection always (flippers, spinners, spawners: so that they act),
  // and which of the generator's aimed balls pick it: at a corner, grazing the top or bottom edge
  // of its cell, resting on its top, touching its capsule at rest.
  { K::generatedByConversion } -> std::convertible_to<bool>;
  { K::alwaysKeyed } -> std::convertible_to<bool>;
  { K::aimedAtCorner } -> std::convertible_to<bool>;
  { K::grazedAlongEdge } -> std::convertible_to<bool>;
  { K::restedOnTop } -> std::convertible_to<bool>;
  { K::touchedBesideCapsule } -> std::convertible_to<bool>;
  // The exact (rational) run of the precision ladder: why it cannot take this kind, after the
  // kind's word and the gizmo's name; empty when it can (verify/src/ladder.cpp).
  { K::exactRunRefusal } -> std::convertible_to<std::string_view>;
  // Whether the Box2D bridge models it (verify/src/box2d_mapping.cpp reports it by name if not).
  { K::box2dModels } -> std::convertible_to<bool>;
  // Whether the bridge makes it a Box2D sensor, which reports the balls that enter and leave it
  // while the core decides what happens to them: its gizmo must be an Absorber, whose capture and
  // shot the bridge's driver calls (verify/src/box2d_driver.cpp).
  { K::box2dSensor } -> std::convertible_to<bool>;
  // What each of its rules does to energy (RuleEffect above); asked only of its own rules.
  { K::ruleEnergy(ModelRule{}) } -> std::convertible_to<RuleEnergy>;
}
&&(!K::generatedByConversion || GeneratedByConversion<K>);

}  // namespace gizmo::verify
