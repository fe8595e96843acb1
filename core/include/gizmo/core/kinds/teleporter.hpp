#pragma once
// The teleporter, d-g-n/CS308-GizmoBall's addition (gizmos/teleporter.hpp): a disc that passes a
// ball to the teleporter it is connected to.
#include "gizmo/core/gizmos/teleporter.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Teleporter> {
  static constexpr std::string_view textCommand = "Teleporter";
  static constexpr std::string_view textUsage = "Teleporter NAME X Y";
  static constexpr std::string_view xmlElement = "teleporter";
  static constexpr std::string_view word = "teleporter";
  static constexpr std::string_view drawing = "teleporter";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
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
