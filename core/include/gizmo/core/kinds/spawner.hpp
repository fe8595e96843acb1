#pragma once
// The spawner, an addition of other programs (gizmos/spawner.hpp): a cell nothing meets, whose
// action puts a ball at its centre.
#include "gizmo/core/gizmos/spawner.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <>
struct KindCore<GizmoType::Spawner> {
  static constexpr std::string_view textCommand = "Spawner";
  static constexpr std::string_view textUsage = "Spawner NAME X Y";
  static constexpr std::string_view xmlElement = "spawner";
  static constexpr std::string_view word = "spawner";
  static constexpr std::string_view drawing = "spawner";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = false;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules =
      std::array{KindRule{SpawnerRule::Spawned, "spawned"}, KindRule{SpawnerRule::Blocked, "spawn-blocked"}};

  // Nothing meets it: balls pass through its cell.
  template <class Real>
  static void addRestShape(Shape<Real>& /*s*/, const GizmoSpec& /*g*/) {}

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Spawner<Real>>(g);
  }
};

}  // namespace gizmo
