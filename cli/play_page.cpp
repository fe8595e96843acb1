// The play page: the game's data as JSON in one script element, then the play module, the board
// drawing shared with the replay player, and the page's own script (docs/play.md).
#include "play_page.hpp"

#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "gizmo/io/board_writer.hpp"
#include "render_assets.hpp"
#include "render_board_drawing.hpp"
#include "render_output.hpp"

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
  for (const auto& [code, targets] : keys) out.push_back({{"code", code}, {"down", targets.first}, {"up", targets.second}});
  return out;
}

// A script's text inside a script element: "</script" would end the element early. JSON may
// say '<' as \u003c; the module's code must simply not hold it.
std::string scriptText(const std::string& code, const std::string& what) {
  if (code.find("</script") != std::string::npos || code.find("</SCRIPT") != std::string::npos)
    throw std::runtime_error(what + " holds \"</script\" and cannot be put into the page");
  return code;
}

}  // namespace

std::string playHtml(const PlayPage& p) {
  const Json data{{"format", 1},
                  {"title", p.title},
                  {"model", std::string(motionModelName(p.model))},
                  {"max_tick", p.maxTick},
                  {"board_text", io::writeTextBoard(p.board)},
                  {"board_warnings", p.boardWarnings},
                  {"keys", keysJson(p.board)},
                  {"board", drawingJson(drawingOf(p.board))}};
  std::string json;
  for (char c : data.dump()) {
    if (c == '<') json += "\\u003c";
    else json += c;
  }
  // From the last marker to the first, so that no text put in can hold a marker still to fill.
  std::string page = kPlayHtml;
  replaceMarker(page, "{{script}}", std::string(kBoardViewJs) + kPlayJs);
  replaceMarker(page, "{{module}}", scriptText(p.module, "the play module"));
  replaceMarker(page, "{{data}}", json);
  replaceMarker(page, "{{style}}", kPlayCss);
  replaceMarker(page, "{{title}}", escapeHtml(p.title));
  return page;
}

}  // namespace gizmo::cli
