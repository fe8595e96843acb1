#pragma once
// The portal, rgallagher27/308gizmoball's addition: the teleporter's disc with its exit given as a
// cell (gizmos/teleporter.hpp). It records the teleporter's rule, Teleported.
#include "gizmo/core/gizmos/teleporter.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Portal> {
  static constexpr std::string_view textCommand = "Portal";
  static constexpr std::string_view textUsage = "Portal NAME X Y EXITX EXITY";
  static constexpr std::string_view xmlElement = "portal";
  static constexpr std::string_view word = "portal";
  static constexpr std::string_view drawing = "portal";
  static constexpr int side = 1;
  static constexpr bool exitCell = true;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = true;
  static constexpr bool xmlOrientationAlways = false;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array{KindRule{TeleporterRule::Teleported, "teleported"}};

  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    const AtCell<Real> at{g};
    s.circles.push_back(CircleFeature<Real>{at(0.5, 0.5), fromDouble<Real>(0.5)});
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Teleporter<Real>>(g);
  }
};

}  // namespace gizmo
