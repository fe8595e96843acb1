#pragma once
// `gizmo render`: a log as a self-contained HTML replay player, or a board as an SVG picture
// (optionally with one run's ball paths). docs/render.md.
#include <optional>
#include <string>

namespace gizmo::cli {

struct RenderOptions {
  std::string input;    // a log (player or picture) or a board file (picture); empty: the built-in board
  std::string output;   // ends in .html (player) or .svg (picture)
  std::string compare;  // player: a second log of the same board, a path file, or box2d:STEP, laid over the first
  std::string trace;    // picture: a log whose ball paths are drawn
  std::optional<double> tolerance;  // L: ball pieces closer than this to the one before are left out
  bool strict = false;              // a board file read leniently is refused
};
int renderCommand(const RenderOptions& options);

// By default the drawn paths stay within a thousandth of L of the rebuilt ones: a tenth of a
// pixel on a board drawn 2000 pixels wide.
inline constexpr double kDefaultRenderTolerance = 1e-3;

}  // namespace gizmo::cli
