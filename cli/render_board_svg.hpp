#pragma once
// A still picture of a board as SVG: the walls and every gizmo at rest, the balls where they
// start, and optionally one run's ball paths (true parabolas, as quadratic Bézier curves) with
// the points where they collided.
#include <string>

#include "render_board_drawing.hpp"
#include "render_run_track.hpp"

namespace gizmo::cli {

std::string boardSvg(const BoardDrawing& board, const RunTrack* trace);

}  // namespace gizmo::cli
