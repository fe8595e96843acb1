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

inline bool isFlipper(GizmoType t) { return t == GizmoType::LeftFlipper || t == GizmoType::RightFlipper; }

inline std::vector<std::string> gridPropertyNames(const GizmoSpec& s) {
  std::vector<std::string> names{property::kName, property::kX, property::kY};
  if (s.type == GizmoType::Absorber) {
    names.push_back(property::kWidth);
    names.push_back(property::kHeight);
  } else {
    names.push_back(property::kOrientation);
  }
  if (isFlipper(s.type)) names.push_back(property::kHandedness);
  return names;
}

inline std::optional<PropertyValue> gridProperty(const GizmoSpec& s, std::string_view name) {
  if (name == property::kName) return PropertyValue(s.name);
  if (name == property::kX) return PropertyValue(std::int64_t{s.x});
  if (name == property::kY) return PropertyValue(std::int64_t{s.y});
  if (name == property::kOrientation && s.type != GizmoType::Absorber) return PropertyValue(std::int64_t{s.orientation});
  if (name == property::kWidth && s.type == GizmoType::Absorber) return PropertyValue(std::int64_t{s.width});
  if (name == property::kHeight && s.type == GizmoType::Absorber) return PropertyValue(std::int64_t{s.height});
  if (name == property::kHandedness && isFlipper(s.type))
    return PropertyValue(std::string(s.type == GizmoType::LeftFlipper ? "left" : "right"));
  return std::nullopt;
}

// Writes one property into s; false when the name or the type of value does not fit.
inline bool setGridProperty(GizmoSpec& s, std::string_view name, const PropertyValue& value) {
  if (name == property::kName) {
    if (const std::string* text = std::get_if<std::string>(&value)) {
      s.name = *text;
      return true;
    }
    return false;
  }
  if (name == property::kHandedness && isFlipper(s.type)) {
    const std::string* text = std::get_if<std::string>(&value);
    if (!text || (*text != "left" && *text != "right")) return false;
    s.type = *text == "left" ? GizmoType::LeftFlipper : GizmoType::RightFlipper;
    return true;
  }
  const std::int64_t* n = std::get_if<std::int64_t>(&value);
  if (!n || *n < -1000000 || *n > 1000000) return false;
  const int v = static_cast<int>(*n);
  if (name == property::kX) s.x = v;
  else if (name == property::kY) s.y = v;
  else if (name == property::kOrientation && s.type != GizmoType::Absorber) s.orientation = v;
  else if (name == property::kWidth && s.type == GizmoType::Absorber) s.width = v;
  else if (name == property::kHeight && s.type == GizmoType::Absorber) s.height = v;
  else return false;
  return true;
}

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
