#pragma once
// The triangle bumper of the Gizmoball format: the right angle at the upper left at rest, turned by
// its orientation.
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Triangle> {
  static constexpr std::string_view textCommand = "Triangle";
  static constexpr std::string_view textUsage = "Triangle NAME X Y";
  static constexpr std::string_view xmlElement = "triangleBumper";
  static constexpr std::string_view word = "triangle";
  static constexpr std::string_view drawing = "triangle";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = true;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array<KindRule, 0>{};

  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    addTurnedTriangle(s, g, 0);
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<GridBumper<Real>>(g);
  }
};

}  // namespace gizmo
