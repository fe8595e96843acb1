// The player page: the run's arrays as base64 inside a JSON block, then the embedded script that
// reads them (see render_player_html.hpp and docs/render.md for the layout).
#include "render_player_html.hpp"

#include "render_assets.hpp"
#include "render_output.hpp"
#include "render_player_data.hpp"

namespace gizmo::cli {
namespace {

using Json = nlohmann::ordered_json;

// Another engine's path: per ball the kept sample times and positions (x, y interleaved), and
// where it parts from our run.
Json pathJson(const PathOverlay& path) {
  Json balls = Json::array();
  for (const OverlayBall& b : path.balls) {
    std::vector<double> p;
    for (const Vec2<double>& at : b.p) p.insert(p.end(), {at.x, at.y});
    balls.push_back({{"name", b.name}, {"count", b.t.size()}, {"t", base64Of(b.t)}, {"p", base64Of(p)}});
  }
  Json parting = nullptr;
  if (path.parting) {
    const PathParting& p = *path.parting;
    parting = {{"time", p.time},
               {"ball", p.ball},
               {"distance", p.distance},
               {"ours", {p.ours.x, p.ours.y}},
               {"theirs", {p.theirs.x, p.theirs.y}}};
  }
  return {{"label", path.label},           {"engine", path.engine}, {"dt", path.dt},     {"tolerance", path.tolerance},
          {"threshold", kPartingDistance}, {"balls", balls},        {"parting", parting}};
}

}  // namespace

std::string playerHtml(const BoardDrawing& board, const std::vector<PlayerRun>& runs,
                       const std::optional<Parting>& parting, const PathOverlay* path) {
  Json data{{"format", 1}, {"names", namesJson()}, {"board", drawingJson(board)}, {"runs", Json::array()}};
  for (const PlayerRun& run : runs) data["runs"].push_back(runJson(run));
  if (parting) {
    data["parting"] = {{"time", parting->time},
                       {"where", parting->where},
                       {"matched_decisions", parting->matchedDecisions},
                       {"first_events", parting->firstEvents ? Json(*parting->firstEvents) : Json()},
                       {"second_events", parting->secondEvents ? Json(*parting->secondEvents) : Json()}};
  }
  if (path) data["path"] = pathJson(*path);
  // Inside a script element "</script" or "<!--" would end or confuse it; '<' only occurs
  // within JSON strings, where \u003c means the same.
  std::string json;
  for (char c : data.dump()) {
    if (c == '<') json += "\\u003c";
    else json += c;
  }
  std::string page = kPlayerHtml;
  std::string title = runs.empty() ? "gizmo run" : runs.front().label;
  if (runs.size() > 1) title += " vs " + runs[1].label;
  if (path) title += " vs " + path->label;
  replaceMarker(page, "{{title}}", escapeHtml(title));
  replaceMarker(page, "{{style}}", kPlayerCss);
  replaceMarker(page, "{{data}}", json);
  replaceMarker(page, "{{script}}", std::string(kBoardViewJs) + kRunDataJs + kTimelineViewJs + kPlayerJs);
  return page;
}

}  // namespace gizmo::cli
