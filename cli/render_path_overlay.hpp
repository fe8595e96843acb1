#pragma once
// Another engine's path laid over our run in the player: each ball's polyline through the
// engine's step positions (between two steps a Box2D body moves in a straight line at constant
// speed, so the polyline is its motion), thinned to what a viewer can see, and the first moment
// the two runs are further apart than kPartingDistance (docs/render.md, "Our run against Box2D's").
#include <optional>
#include <string>
#include <vector>

#include "render_path_file.hpp"
#include "render_run_track.hpp"

namespace gizmo::cli {

// Further apart than this, the runs have parted: a tenth of L. It is the level at which
// `gizmo crosscheck` reports `divergence_above` 0.1, so the page and the report agree; it lies
// above what the mapping itself gives every collision (Box2D stops 0.015 L past contact, up to
// 0.031 L at corners) and below a ball's radius (0.25 L), so that on the board the two balls are
// visibly apart where the mark is.
inline constexpr double kPartingDistance = 0.1;

struct OverlayBall {
  std::string name;
  std::vector<double> t;
  std::vector<Vec2<double>> p;
};

struct PathParting {
  double time = 0;
  std::string ball;
  double distance = 0;  // at that moment, L
  Vec2<double> ours, theirs;
};

struct PathOverlay {
  std::string label;   // what the page calls the path (its file name, or the step size asked for)
  std::string engine;  // the path file's engine line
  double dt = 0;
  double tolerance = 0;
  std::vector<OverlayBall> balls;
  std::optional<PathParting> parting;
};

// The path's samples thinned (a sample is left out when the straight line between the kept ones
// around it, travelled at constant speed as the player draws it, stays within `tolerance` L of
// it at its own time), up to the end of our run, and the runs' parting measured on every sample
// against our run as the player draws it. Each ball of the path must be a ball of the run.
PathOverlay overlayOf(const PathFile& path, const std::string& label, const RunTrack& ours, double tolerance);

// The indices of the samples that stay (the first and last always do).
std::vector<std::size_t> thinnedSamples(const std::vector<PathSample>& samples, double tolerance);

}  // namespace gizmo::cli
