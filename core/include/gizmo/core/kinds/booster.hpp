#pragma once
// The booster, d-g-n/CS308-GizmoBall's addition (gizmos/booster.hpp): a triangle that doubles the
// speed of the ball it reflects.
#include "gizmo/core/gizmos/booster.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Booster> {
  static constexpr std::string_view textCommand = "Booster";
  static constexpr std::string_view textUsage = "Booster NAME X Y";
  static constexpr std::string_view xmlElement = "booster";
  static constexpr std::string_view word = "booster";
  static constexpr std::string_view drawing = "booster";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = true;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array{KindRule{BoosterRule::Boosted, "boosted"}};

  // At rest its right angle is at the lower left (d-g-n's BoosterGizmo.java): the triangle turned
  // three quarters.
  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    addTurnedTriangle(s, g, 3);
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Booster<Real>>(g);
  }
};

}  // namespace gizmo
