#pragma once
// The bouncer, a kind that only the trial of docs/design.md's "Adding a gizmo" registers
// (tests/kinds/run.sh copies this file to core/include/gizmo/core/kinds/bouncer.hpp in a copy of
// the tree): a diamond whose corners are the midpoints of its cell's sides. Its behaviour class is
// here too, so that the kind is this one file in the core: a bumper, since the diamond only reflects.
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"
#include "gizmo/core/kinds/kind_core.hpp"
#include "gizmo/core/kinds/outline_parts.hpp"

namespace gizmo {

template <class Real>
class Bouncer final : public GridBumper<Real> {
 public:
  explicit Bouncer(const GizmoSpec& spec) : GridBumper<Real>(spec) {}
};

template <>
struct KindCore<GizmoType::Bouncer> {
  static constexpr std::string_view textCommand = "Bouncer";
  static constexpr std::string_view textUsage = "Bouncer NAME X Y";
  static constexpr std::string_view xmlElement = "bouncer";
  static constexpr std::string_view word = "bouncer";
  static constexpr std::string_view drawing = "bouncer";
  static constexpr int side = 1;
  static constexpr bool exitCell = false;
  static constexpr KindMotion motion = KindMotion::Still;
  static constexpr bool holdsPlacedBalls = false;
  static constexpr bool disc = false;
  static constexpr bool xmlOrientationAlways = false;
  static constexpr std::string_view handedness = "";
  static constexpr auto rules = std::array<KindRule, 0>{};

  // A diamond looks the same turned by a quarter: the orientation changes nothing.
  template <class Real>
  static void addRestShape(Shape<Real>& s, const GizmoSpec& g) {
    const AtCell<Real> at{g};
    addPolygon(s, {at(0.5, 0), at(1, 0.5), at(0.5, 1), at(0, 0.5)});
  }

  template <class Real>
  static std::unique_ptr<AbstractGizmo<Real>> build(const GizmoSpec& g) {
    return std::make_unique<Bouncer<Real>>(g);
  }
};

}  // namespace gizmo
