#pragma once
// Internal to gizmo::io: the placements that other programs accept and the core's board checks
// do not (a ball on a wall, a ball inside an absorber but moving, things that overlap), read the
// way that keeps the rest of the board: each repair is a warning (docs/board-files.md §2).
#include <set>
#include <string>

#include "gizmo/core/board_spec.hpp"
#include "parse_util.hpp"

namespace gizmo::io::detail {

// Moves balls that stick out of the board inside it, captures balls whose centre lies in an
// absorber, then leaves out the later of two overlapping things (and the connections of a gizmo
// left out) until checkBoardSpec finds no overlap. What is not a placement problem is left for
// checkBoardSpec to report.
void repairPlacements(BoardSpec& board, Reporter& rep);

// Drops every connection and key connection that names one of `gone` (left out of the board),
// each with a warning.
void dropConnectionsTo(BoardSpec& board, const std::set<std::string>& gone, Reporter& rep);

}  // namespace gizmo::io::detail
