#pragma once
// What a board reader returns when the board loads.
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/io/diagnostics.hpp"

namespace gizmo::io {

struct ReadResult {
  BoardSpec board;
  std::vector<Diagnostic> warnings;  // what was accepted leniently, sorted by position
};

}  // namespace gizmo::io
