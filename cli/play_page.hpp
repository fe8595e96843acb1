#pragma once
// The play page's HTML: the board (as the simulator reads it and as both pages draw it), the
// run's settings, the play module and the page's scripts, in one file that loads nothing.
#include <string>
#include <vector>

#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/core/board_spec.hpp"

namespace gizmo::cli {

struct PlayPage {
  std::string title;  // the board's file name
  BoardSpec board;
  std::vector<std::string> boardWarnings;  // the reader's, kept in every log the page writes
  MotionModel model = MotionModel::Ballistic;
  double maxTick = 0.05;
  std::string module;  // the play module's JavaScript (the WebAssembly inside it)
};

// Throws std::runtime_error when the module cannot be put into a script element whole.
std::string playHtml(const PlayPage& page);

}  // namespace gizmo::cli
