#pragma once
// `gizmo play`: one self-contained page in which a person plays a board with the keyboard, the
// simulator running in the page as WebAssembly, and saves the game as a replay log that
// `gizmo replay` checks. docs/play.md.
#include <string>

namespace gizmo::cli {

struct PlayOptions {
  std::string board;   // empty: the built-in spec example
  std::string output;  // the page, .html
  std::string model = "ballistic";
  // Board time moves in whole ticks (docs/play.md), so the tick is also the step in which the page
  // shows the board: a hundredth of a second draws smoothly at 60 frames a second.
  double maxTick = 0.01;
  std::string module;  // the play module (gizmo-play.js); empty: $GIZMO_PLAY_MODULE, else the build's
  bool strict = false;
};
int playCommand(const PlayOptions& options);

}  // namespace gizmo::cli
