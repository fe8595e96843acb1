#pragma once
// Internal to gizmo::io: key names that some programs write in KeyConnect instead of a key code
// ("Space", "Q", "Delete": lejhy/Gizmoball passes the word to JavaFX's KeyCode.getKeyCode; others
// write Java's VK_ names or the browsers' key names and codes).
#include <optional>
#include <string_view>

namespace gizmo::io::detail {

// The Java key code (java.awt.event.KeyEvent.VK_*, which JavaFX's KeyCode shares for these keys)
// of a key's name as Java ("VK_SPACE"), JavaFX ("Space", "BACK_SPACE", "DIGIT1") or a browser
// ("ArrowLeft", "KeyA", "ShiftLeft") writes it, any case; nullopt for any other word.
std::optional<int> keyCodeOfName(std::string_view name);

}  // namespace gizmo::io::detail
