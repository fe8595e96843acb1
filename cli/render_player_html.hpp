#pragma once
// The replay player: one self-contained HTML page (its style, script and the run's data inside
// it; nothing fetched) that plays one run, or two runs of one board laid over each other, or one
// run with another engine's path over it.
#include <optional>
#include <string>
#include <vector>

#include "render_board_drawing.hpp"
#include "render_path_overlay.hpp"
#include "render_player_data.hpp"

namespace gizmo::cli {

// Where two runs part (gizmo diff's finding), for the page to mark.
struct Parting {
  double time = 0;
  std::string where;
  std::uint64_t matchedDecisions = 0;
  std::optional<std::uint64_t> firstEvents, secondEvents;  // events each run had executed by then
};

std::string playerHtml(const BoardDrawing& board, const std::vector<PlayerRun>& runs,
                       const std::optional<Parting>& parting, const PathOverlay* path = nullptr);

}  // namespace gizmo::cli
