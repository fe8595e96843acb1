// The play page: the game's data as JSON in one script element, then the play module, the board
// drawing, run data and timeline shared with the replay player, and the page's own script
// (docs/play.md).
#include "play_page.hpp"

#include <stdexcept>

#include "render_assets.hpp"
#include "render_output.hpp"

namespace gizmo::cli {
namespace {

using Json = nlohmann::ordered_json;

// A script's text inside a script element: "</script" would end the element early. JSON may
// say '<' as \u003c; the module's code must simply not hold it.
std::string scriptText(const std::string& code, const std::string& what) {
  if (code.find("</script") != std::string::npos || code.find("</SCRIPT") != std::string::npos)
    throw std::runtime_error(what + " holds \"</script\" and cannot be put into the page");
  return code;
}

}  // namespace

std::string playHtml(const PlayPage& p) {
  const Json data = gameJson(p.game);
  std::string json;
  for (char c : data.dump()) {
    if (c == '<') json += "\\u003c";
    else json += c;
  }
  // From the last marker to the first, so that no text put in can hold a marker still to fill.
  std::string page = kPlayHtml;
  replaceMarker(page, "{{script}}", std::string(kBoardViewJs) + kRunDataJs + kTimelineViewJs + kPlayJs);
  replaceMarker(page, "{{module}}", scriptText(p.module, "the play module"));
  replaceMarker(page, "{{data}}", json);
  replaceMarker(page, "{{style}}", kPlayCss);
  replaceMarker(page, "{{title}}", escapeHtml(p.game.title));
  return page;
}

}  // namespace gizmo::cli
