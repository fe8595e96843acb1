#pragma once
// Internal to gizmo::io: key names that some programs write in KeyConnect instead of a key code
// ("Space", "Q", "Delete": lejhy/Gizmoball passes the word to JavaFX's KeyCode.getKeyCode).
#include <optional>
#include <string_view>

namespace gizmo::io::detail {

// The Java key code (java.awt.event.KeyEvent.VK_*, which JavaFX's KeyCode shares for these keys)
// of a key name as JavaFX writes it (KeyCode.getName(): "Space", "A", "Delete", "F1"), any case;
// nullopt for any other word.
std::optional<int> keyCodeOfName(std::string_view name);

}  // namespace gizmo::io::detail
