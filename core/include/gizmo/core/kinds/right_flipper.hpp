#pragma once
// The right flipper of the Gizmoball format: the left flipper's mirror image, its pivot at the
// upper right.
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::RightFlipper> {
  static constexpr std::string_view textCommand = "RightFlipper";
  static constexpr std::string_view textUsage = "RightFlipper NAME X Y";
  static constexpr std::string_view xmlElement = "rightFlipper";
  static constexpr std::string_view word = "right flipper";
  static constexpr std::string_view drawing = "right-flipper";
  static constexpr int side = 2;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Swings;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = true;
  static constexpr std::string_view handedness = "right";
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
