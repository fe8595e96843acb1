#pragma once
// What every kind's core file (kinds/STEM.hpp) defines, and how shared code reaches it: a
// specialisation of KindCore per kind, visited through a switch that the kind list generates. No
// registration at run time: every lookup is a switch or a constant, compiled where it is used.
#include <array>
#include <concepts>
#include <memory>
#include <span>
#include <string_view>
#include <utility>

#include "gizmo/core/board/model_rule.hpp"
#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/features.hpp"
#include "gizmo/core/kinds/kind_list.hpp"

namespace gizmo {

template <class Real>
class AbstractGizmo;

// How a kind's outline moves, for the code that draws, saves, checks or models a gizmo in motion
// by what it does rather than by its name: it stays still; it swings like a flipper (a capsule
// about its pivot between two stops: the kind's gizmo is a Flipper, gizmos/flipper.hpp); or it
// turns like a spinner (a cross turning at kSpinnerTurnRate while on: a Spinner, gizmos/spinner.hpp).
enum class KindMotion { Still, Swings, Turns };

// A model rule that a kind records, and its name: the word that `gizmo dump`, the player and the
// fuzz reports print, and that `gizmo dump --only` takes. Its code (board/model_rule.hpp) is
// declared by the kind's behaviour class, as AbsorberRule::Captured in gizmos/absorber.hpp.
struct KindRule {
  ModelRule rule;
  std::string_view name;
};

// Each kind's core description, specialised in its own file (kinds/STEM.hpp).
template <GizmoType T>
struct KindCore;

// A kind as a type, for the generic code that visits every kind.
template <GizmoType T>
struct KindTag {
  static constexpr GizmoType type = T;
};

// What a kind's core file must hold; kind_registry.cpp checks every kind against it, so that an
// incomplete file fails to compile with the kind's name in the message.
template <class K>
concept CoreKindEntry = requires(Shape<double>& shape, const GizmoSpec& spec) {
  // Its names: the text command and its line (for messages; the line's word count is the
  // command's), the XML element, the word in messages, the drawing's class.
  { K::textCommand } -> std::convertible_to<std::string_view>;
  { K::textUsage } -> std::convertible_to<std::string_view>;
  { K::xmlElement } -> std::convertible_to<std::string_view>;
  { K::word } -> std::convertible_to<std::string_view>;
  { K::drawing } -> std::convertible_to<std::string_view>;
  // Its box: the side of its square box in L (0: its size is a property, as an absorber's, which
  // its board line gives by its lower-right corner; such a kind is never turned).
  { K::side } -> std::convertible_to<int>;
  // Whether its board line names an exit cell after its own (a portal's EX EY, exitX and exitY).
  { K::exitCell } -> std::convertible_to<bool>;
  // How its outline moves (KindMotion above).
  { K::motion } -> std::convertible_to<KindMotion>;
  // Whether a ball a board file places at rest inside its box starts held by it (the absorber:
  // its gizmo is an Absorber, which holds it); a moving ball there is an error.
  { K::holdsPlacedBalls } -> std::convertible_to<bool>;
  // A disc of radius 0.5 in its cell (the pictures and the fuzz checker draw and test it so).
  { K::disc } -> std::convertible_to<bool>;
  // Whether the XML writer writes its orientation attribute when it is 0 too (as the programs
  // that write the element do); otherwise only when it is not 0.
  { K::xmlOrientationAlways } -> std::convertible_to<bool>;
  // Its handedness property ("left", "right"), empty for a kind without one.
  { K::handedness } -> std::convertible_to<std::string_view>;
  // The model rules that only this kind records, each with its name in logs' readings
  // (board/model_rule.hpp); gizmo_kinds.hpp checks them against every other rule.
  {std::span<const KindRule>(K::rules)};
  // Its outline at rest, in board coordinates (what restShape returns for it).
  K::template addRestShape<double>(shape, spec);
  // The gizmo the board builds for it.
  { K::template build<double>(spec) } -> std::same_as<std::unique_ptr<AbstractGizmo<double>>>;
};

// Calls f(KindTag<T>{}) for the kind t: one switch, generated from the kind list.
template <class F>
constexpr decltype(auto) visitKind(GizmoType t, F&& f) {
  switch (t) {
#define GIZMO_KIND_CASE(Name, stem) \
  case GizmoType::Name: return std::forward<F>(f)(KindTag<GizmoType::Name>{});
    GIZMO_KINDS(GIZMO_KIND_CASE)
#undef GIZMO_KIND_CASE
  }
  return std::forward<F>(f)(KindTag<GizmoType(0)>{});  // not reached: every GizmoType is a case
}

// Calls f(KindTag<T>{}) for every kind, in the list's order.
template <class F>
constexpr void forEachKind(F&& f) {
#define GIZMO_KIND_CALL(Name, stem) f(KindTag<GizmoType::Name>{});
  GIZMO_KINDS(GIZMO_KIND_CALL)
#undef GIZMO_KIND_CALL
}

}  // namespace gizmo
