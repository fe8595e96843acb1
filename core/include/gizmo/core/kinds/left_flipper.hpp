#pragma once
// The left flipper of the Gizmoball format: a capsule in a 2×2 box that swings about its pivot at
// the upper left.
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::LeftFlipper> {
  static constexpr std::string_view textCommand = "LeftFlipper";
  static constexpr std::string_view textUsage = "LeftFlipper NAME X Y";
  static constexpr std::string_view xmlElement = "leftFlipper";
  static constexpr std::string_view word = "left flipper";
  static constexpr std::string_view drawing = "left-flipper";
  static constexpr int side = 2;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Swings;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = true;
  static constexpr std::string_view handedness = "left";
  static constexpr auto rules = std::array{KindRule{FlipperRule::Blocked, "flipper-blocked"}};

  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    addFlipperAtRest(s, g);
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Flipper<Real>>(g);
  }
};

}  // namespace gizmo
