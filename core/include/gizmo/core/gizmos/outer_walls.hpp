#pragma once
// The four walls of the board, one gizmo named OuterWalls for triggering (docs/physics.md §1).
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"

namespace gizmo {

template <class Real>
class OuterWalls final : public AbstractGizmoWithPolygonalGeometry<Real> {
 public:
  OuterWalls() : AbstractGizmoWithPolygonalGeometry<Real>(kOuterWallsName, outerWallsShape<Real>(), Real(1)) {}
  const Shape<Real>* restingShape() const override { return &this->shape(); }
  GizmoKind kind() const override { return GizmoKind::OuterWalls; }
  GizmoSpec spec() const override { return GizmoSpec{}; }
  std::vector<std::string> propertyNames() const override { return {property::kName}; }
  std::optional<PropertyValue> property(std::string_view name) const override {
    if (name == property::kName) return PropertyValue(this->name());
    return std::nullopt;
  }
  bool setPropertyUnchecked(std::string_view, const PropertyValue&) override { return false; }
};

}  // namespace gizmo
