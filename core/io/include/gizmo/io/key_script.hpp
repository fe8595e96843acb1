#pragma once
// Key scripts: timed key presses and releases that drive a run. One input per line,
// "TIME down|up KEYCODE" (e.g. "1.25 down 32"); '#' comment lines and blank lines are allowed.
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/board_spec.hpp"

namespace gizmo::io {

struct KeyInput {
  double time = 0;  // seconds of board time, finite, >= 0, non-decreasing through the script
  KeyDirection direction = KeyDirection::Down;
  int key = 0;  // 0..65535
  SourcePos where;
};

// Throws InputError listing every error (file:line:column).
std::vector<KeyInput> readKeyScript(std::string_view content, const std::string& fileName);
// Reads the file first (same file checks as readBoardFile).
std::vector<KeyInput> readKeyScriptFile(const std::string& path);

}  // namespace gizmo::io
