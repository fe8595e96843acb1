#pragma once
// The absorber of the Gizmoball format: a rectangle of any size that captures balls and fires them
// upward.
#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Absorber> {
  static constexpr std::string_view textCommand = "Absorber";
  static constexpr std::string_view textUsage = "Absorber NAME X1 Y1 X2 Y2";
  static constexpr std::string_view xmlElement = "absorber";
  static constexpr std::string_view word = "absorber";
  static constexpr std::string_view drawing = "absorber";
  static constexpr int side = 0;  // its box is what its file says
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = true;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = false;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules =
      std::array{KindRule{AbsorberRule::Captured, "captured"}, KindRule{AbsorberRule::Released, "released"}};

  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    const AtCell<Real> at{g};
    addPolygon(s, {at(0, 0), at(g.width, 0), at(g.width, g.height), at(0, g.height)});
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Absorber<Real>>(g);
  }
};

}  // namespace gizmo
