#pragma once
// The replay player's data as JSON (docs/render.md): a run's arrays as base64, which run_data.js
// decodes, and the names of event kinds, rules and decisions. The player's page holds it
// (render_player_html.cpp), and so does the game page for a log it opens (web/play_module.cpp).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "render_run_track.hpp"

namespace gizmo::cli {

struct PlayerRun {
  std::string label;  // what the page calls the run (the log's file name)
  RunTrack track;
};

// One run as run_data.js's loadRun reads it.
nlohmann::ordered_json runJson(const PlayerRun& run);
// The names the player shows for event kinds, model rules and decision types.
nlohmann::ordered_json namesJson();

}  // namespace gizmo::cli
