#pragma once
// The square bumper of the Gizmoball format: a 1×1 square, coefficient of reflection 1.
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Square> {
  static constexpr std::string_view textCommand = "Square";
  static constexpr std::string_view textUsage = "Square NAME X Y";
  static constexpr std::string_view xmlElement = "squareBumper";
  static constexpr std::string_view word = "square";
  static constexpr std::string_view drawing = "square";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = false;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array<KindRule, 0>{};

  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    const AtCell<Real> at{g};
    addPolygon(s, {at(0, 0), at(1, 0), at(1, 1), at(0, 1)});
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<GridBumper<Real>>(g);
  }
};

}  // namespace gizmo
