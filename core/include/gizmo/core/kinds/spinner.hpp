#pragma once
// The spinner, NiklavsM/Gizmoball's addition (gizmos/spinner.hpp): a cross of two capsules in a 2×2
// box that turns while toggled on.
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Spinner> {
  static constexpr std::string_view textCommand = "Spinner";
  static constexpr std::string_view textUsage = "Spinner NAME X Y";
  static constexpr std::string_view xmlElement = "spinner";
  static constexpr std::string_view word = "spinner";
  static constexpr std::string_view drawing = "spinner";
  static constexpr int side = 2;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Turns;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = false;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array{KindRule{SpinnerRule::Blocked, "spinner-blocked"}};

  // A cross looks the same turned by any whole quarter: the orientation changes nothing.
  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    const AtCell<Real> at{g};
    addSpinnerCross(s, at(1, 1), Vec2<Real>(Real(1), Real(0)));
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Spinner<Real>>(g);
  }
};

}  // namespace gizmo
