// A game's data for the play page (play_data.hpp).
#include "play_data.hpp"

#include <map>

#include "gizmo/io/board_writer.hpp"
#include "render_board_drawing.hpp"

namespace gizmo::cli {
namespace {

using Json = nlohmann::ordered_json;

// The keys the board listens to, each with the gizmos it moves when pressed and when released.
Json keysJson(const BoardSpec& board) {
  std::map<int, std::pair<std::vector<std::string>, std::vector<std::string>>> keys;
  for (const KeyConnectSpec& k : board.keyConnections) {
    auto& [down, up] = keys[k.key];
    (k.direction == KeyDirection::Down ? down : up).push_back(k.target);
  }
  Json out = Json::array();
  for (const auto& [code, targets] : keys)
    out.push_back({{"code", code}, {"down", targets.first}, {"up", targets.second}});
  return out;
}

}  // namespace

nlohmann::ordered_json gameJson(const GameSettings& g) {
  return Json{{"format", 1},
              {"title", g.title},
              {"model", std::string(motionModelName(g.model))},
              {"max_tick", g.maxTick},
              {"board_text", io::writeTextBoard(g.board)},
              {"board_warnings", g.boardWarnings},
              {"keys", keysJson(g.board)},
              {"board", drawingJson(drawingOf(g.board))}};
}

}  // namespace gizmo::cli
