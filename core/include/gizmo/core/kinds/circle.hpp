#pragma once
// The circle bumper of the Gizmoball format: a disc of radius 0.5 in its cell.
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Circle> {
  static constexpr std::string_view textCommand = "Circle";
  static constexpr std::string_view textUsage = "Circle NAME X Y";
  static constexpr std::string_view xmlElement = "circleBumper";
  static constexpr std::string_view word = "circle";
  static constexpr std::string_view drawing = "circle";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = true;
  static constexpr bool xmlOrientationAlways = false;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array<KindRule, 0>{};

  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    const AtCell<Real> at{g};
    s.circles.push_back(CircleFeature<Real>{at(0.5, 0.5), fromDouble<Real>(0.5)});
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<GridBumper<Real>>(g);
  }
};

}  // namespace gizmo
