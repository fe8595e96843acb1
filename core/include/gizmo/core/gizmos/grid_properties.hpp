#pragma once
// Properties of a gizmo that sits on the grid (everything but the ball and the walls), read
// from and written to its plain-data description.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/gizmos/property.hpp"

namespace gizmo {

// The properties of a gizmo on the grid: its name and cell, then its orientation, or its width and
// height for a kind whose size is a property (a kind whose `side` is 0), and its handedness for a
// kind that has one (kinds/STEM.hpp). Defined in core/src/grid_properties.cpp, where every kind's
// file is included.
std::vector<std::string> gridPropertyNames(const GizmoSpec& s);
std::optional<PropertyValue> gridProperty(const GizmoSpec& s, std::string_view name);
// Writes one property into s; false when the name or the type of value does not fit.
bool setGridProperty(GizmoSpec& s, std::string_view name, const PropertyValue& value);

// A gizmo that stands on the grid and is described by a GizmoSpec: the property system for
// every such gizmo, over whichever gizmo base it extends. `placed()` tells the gizmo its spec
// changed (it lays out its shape again).
template <class Base>
class GridPlaced : public Base {
 public:
  GizmoSpec spec() const override {
    GizmoSpec s = spec_;
    s.name = this->name();
    return s;
  }
  std::vector<std::string> propertyNames() const override { return gridPropertyNames(spec_); }
  std::optional<PropertyValue> property(std::string_view name) const override { return gridProperty(spec(), name); }
  bool setPropertyUnchecked(std::string_view name, const PropertyValue& value) override {
    GizmoSpec s = spec();
    if (!setGridProperty(s, name, value)) return false;
    spec_ = s;
    this->rename(s.name);
    placed();
    return true;
  }

 protected:
  template <class... BaseArgs>
  explicit GridPlaced(const GizmoSpec& spec, BaseArgs&&... args) : Base(std::forward<BaseArgs>(args)...), spec_(spec) {}
  const GizmoSpec& placement() const { return spec_; }
  virtual void placed() = 0;

 private:
  GizmoSpec spec_;
};

}  // namespace gizmo
