#pragma once
// The sink, an addition of other programs (gizmos/sink.hpp): a square that takes the balls it meets
// out of play.
#include "gizmo/core/gizmos/sink.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Sink> {
  static constexpr std::string_view textCommand = "Sink";
  static constexpr std::string_view textUsage = "Sink NAME X Y";
  static constexpr std::string_view xmlElement = "sink";
  static constexpr std::string_view word = "sink";
  static constexpr std::string_view drawing = "sink";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = true;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array{KindRule{SinkRule::Sunk, "sunk"}};

  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    const AtCell<Real> at{g};
    addPolygon(s, {at(0, 0), at(1, 0), at(1, 1), at(0, 1)});
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Sink<Real>>(g);
  }
};

}  // namespace gizmo
