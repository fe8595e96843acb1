#pragma once
// A game's data as the play page reads it (docs/play.md): the board as the simulator reads it
// (canonical text) and as both pages draw it, the keys it listens to, the model and the tick.
// `gizmo play` puts it into the page it writes (play_page.cpp); the play module makes it again
// for a log the page opens (web/play_module.cpp), so that the page plays that log's board.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/core/board_spec.hpp"

namespace gizmo::cli {

struct GameSettings {
  std::string title;  // the board's file name, or the log's
  BoardSpec board;
  std::vector<std::string> boardWarnings;  // the reader's, kept in every log the page writes
  MotionModel model = MotionModel::Ballistic;
  double maxTick = 0.05;
};

nlohmann::ordered_json gameJson(const GameSettings& game);

}  // namespace gizmo::cli
