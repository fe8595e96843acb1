#pragma once
// The text board format (docs/board-files.md §2, "The text format", says what is accepted).
#include <string>
#include <string_view>

#include "gizmo/io/read_result.hpp"

namespace gizmo::io {

// Reads a whole text board. Throws InputError listing every error (file:line:column) when any
// statement is wrong or the resulting board fails checkBoardSpec: a board loads whole or not at all.
ReadResult readTextBoard(std::string_view content, const std::string& fileName);

}  // namespace gizmo::io
