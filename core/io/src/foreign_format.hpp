#pragma once
// Internal to gizmo::io: files that other Gizmoball programs wrote in formats of their own (JSON,
// Java serialisation, key=value lines, pixel-coordinate maps, 3-D boards, other dialects). They
// are refused with one message that says what the file looks like, rather than with a parse error
// on its first line.
#include <optional>
#include <string>
#include <string_view>

namespace gizmo::io::detail {

// "this looks like a JSON file, not a Gizmoball board (...)", or nullopt when the content may be
// a board of the text format. Decided on strong signs only: a valid text board never matches.
std::optional<std::string> foreignFormat(std::string_view content);

}  // namespace gizmo::io::detail
