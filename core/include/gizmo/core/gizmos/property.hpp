#pragma once
// The seed's properties system: each gizmo exposes typed values by name (name, position,
// orientation, velocity, size, handedness) for the editor, the readers and the tests.
#include <cstdint>
#include <string>
#include <variant>

namespace gizmo {

// Whole numbers for grid positions, orientation and sizes; doubles for a ball's centre and
// velocity (board files hold doubles); text for names and handedness.
using PropertyValue = std::variant<std::int64_t, double, std::string>;

namespace property {
inline constexpr const char* kName = "name";
inline constexpr const char* kX = "x";
inline constexpr const char* kY = "y";
inline constexpr const char* kOrientation = "orientation";
inline constexpr const char* kVx = "vx";
inline constexpr const char* kVy = "vy";
inline constexpr const char* kWidth = "width";
inline constexpr const char* kHeight = "height";
inline constexpr const char* kHandedness = "handedness";
}  // namespace property

}  // namespace gizmo
