#pragma once
// The play page's HTML: the board (as the simulator reads it and as both pages draw it), the
// run's settings, the play module and the page's scripts, in one file that loads nothing.
#include <string>

#include "play_data.hpp"

namespace gizmo::cli {

struct PlayPage {
  GameSettings game;
  std::string module;  // the play module's JavaScript (the WebAssembly inside it)
};

// Throws std::runtime_error when the module cannot be put into a script element whole.
std::string playHtml(const PlayPage& page);

}  // namespace gizmo::cli
