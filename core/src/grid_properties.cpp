// The property system of the gizmos on the grid (gizmos/grid_properties.hpp), read from each
// kind's file: whether its size is a property (side 0) and its handedness.
#include "gizmo/core/gizmos/grid_properties.hpp"

#include "gizmo/core/gizmo_kinds.hpp"

namespace gizmo {
namespace {

bool sizeIsProperty(GizmoType t) { return gizmoKind(t).side == 0; }
bool hasHandedness(GizmoType t) { return !gizmoKind(t).handedness.empty(); }

}  // namespace

std::vector<std::string> gridPropertyNames(const GizmoSpec& s) {
  std::vector<std::string> names{property::kName, property::kX, property::kY};
  if (sizeIsProperty(s.type)) {
    names.push_back(property::kWidth);
    names.push_back(property::kHeight);
  } else {
    names.push_back(property::kOrientation);
  }
  if (hasHandedness(s.type)) names.push_back(property::kHandedness);
  return names;
}

std::optional<PropertyValue> gridProperty(const GizmoSpec& s, std::string_view name) {
  const bool sized = sizeIsProperty(s.type);
  if (name == property::kName) return PropertyValue(s.name);
  if (name == property::kX) return PropertyValue(std::int64_t{s.x});
  if (name == property::kY) return PropertyValue(std::int64_t{s.y});
  if (name == property::kOrientation && !sized) return PropertyValue(std::int64_t{s.orientation});
  if (name == property::kWidth && sized) return PropertyValue(std::int64_t{s.width});
  if (name == property::kHeight && sized) return PropertyValue(std::int64_t{s.height});
  if (name == property::kHandedness && hasHandedness(s.type))
    return PropertyValue(std::string(gizmoKind(s.type).handedness));
  return std::nullopt;
}

bool setGridProperty(GizmoSpec& s, std::string_view name, const PropertyValue& value) {
  if (name == property::kName) {
    if (const std::string* text = std::get_if<std::string>(&value)) {
      s.name = *text;
      return true;
    }
    return false;
  }
  if (name == property::kHandedness && hasHandedness(s.type)) {
    // The other hand is another kind (a left flipper made right is a right flipper).
    const std::string* text = std::get_if<std::string>(&value);
    if (!text || text->empty()) return false;
    for (const GizmoKindInfo& k : kGizmoKinds)
      if (k.handedness == *text) {
        s.type = k.type;
        return true;
      }
    return false;
  }
  const bool sized = sizeIsProperty(s.type);
  const std::int64_t* n = std::get_if<std::int64_t>(&value);
  if (!n || *n < -1000000 || *n > 1000000) return false;
  const int v = static_cast<int>(*n);
  if (name == property::kX) s.x = v;
  else if (name == property::kY) s.y = v;
  else if (name == property::kOrientation && !sized) s.orientation = v;
  else if (name == property::kWidth && sized) s.width = v;
  else if (name == property::kHeight && sized) s.height = v;
  else return false;
  return true;
}

}  // namespace gizmo
