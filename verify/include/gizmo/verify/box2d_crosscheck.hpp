#pragma once
// `gizmo crosscheck`: one board run by our simulator (double) and by Box2D at each step size,
// collisions matched (same ball, same gizmo, nearest time within a window), and for each step
// size what agreed, what either side missed, how far the trajectories and the energy drifted
// apart, and what each cost (docs/verification.md, "Cross-checking against Box2D").
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "gizmo/verify/box2d_world.hpp"

namespace gizmo::verify {

struct CrosscheckOptions {
  RunRequest request;
  std::vector<double> steps{1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480};
  Box2dOptions box2d;  // its dt is replaced by each of `steps`
  bool keepBox2dSamples = false;  // hand each step size's Box2D samples back (for a path file)
};

// A collision that only one side made: the first of them, for the report.
struct UnmatchedCollision {
  std::string side;  // "ours" (Box2D missed it) or "box2d" (we did not make it)
  CollisionRecord collision;
};

inline constexpr std::array<double, 3> kDivergenceLevels{0.01, 0.1, 1.0};

struct StepComparison {
  double dt = 0;
  double end = 0;                       // the run's length (both sides ran on by the window)
  double matchWindow = 0;               // seconds: collisions further apart never match
  std::uint64_t steps = 0;
  std::size_t box2dCollisions = 0;
  std::size_t matched = 0;
  std::size_t missedByBox2d = 0;        // ours, unmatched
  std::size_t missedByUs = 0;           // Box2D's, unmatched
  double maxTimeError = 0;              // over matched: |t_box2d − t_ours|
  double meanTimeError = 0;
  double maxPositionError = 0;          // over matched: |p_box2d − p_ours|, L
  std::size_t matchedWithinToi = 0;     // matched with a position error within Box2D's TOI target + tolerance
  std::optional<UnmatchedCollision> firstUnmatched;
  std::uint64_t speedCappedSteps = 0;     // counted over the run and the window after it,
  std::uint64_t rotationCappedSteps = 0;  // as is wallSeconds
  double maxDivergence = 0;             // max over samples and balls of |p_box2d − p_ours|
  std::array<std::optional<double>, kDivergenceLevels.size()> divergenceFrom;  // first time above each level
  std::vector<std::pair<double, double>> divergence;  // (time, max distance), at most 50 evenly spread samples
  double energyEnd = 0;                 // Box2D's, at the end
  double maxEnergyDifference = 0;       // max over samples of |E_box2d − E_ours| / max(|E_ours|, |E_start|)
  double wallSeconds = 0;
  // Box2D's balls after each step, from time 0 to the end and the window after it; only with
  // CrosscheckOptions::keepBox2dSamples.
  std::vector<TrajectorySample> box2dSamples;
};

struct CrosscheckReport {
  std::size_t ourCollisions = 0;
  std::uint64_t ourEvents = 0;
  double ourWallSeconds = 0;   // an unobserved run of the same request
  double energyStart = 0;
  double ourEnergyEnd = 0;
  std::vector<StepComparison> steps;
};

// The window within which two collisions of the same pair can match, at step size dt, and how
// far apart the ball's centres may be.
double matchWindow(double dt);
inline constexpr double kMatchDistance = 1.0;

CrosscheckReport crosscheck(const CrosscheckOptions& options);

// The record of our own run (double, the request's model), as runBox2d's; `events` gets the
// number of executed events.
RunRecord runOurs(const RunRequest& request, std::uint64_t& events);

// A run's sample at time t, interpolated linearly between the samples around it, which are
// taken every dt from time 0 (Box2D's steps).
TrajectorySample interpolate(const std::vector<TrajectorySample>& samples, double dt, double t);

// Matches two collision lists: pairs of indices (ours, Box2D's), the closest in time first,
// within `window` seconds and kMatchDistance.
std::vector<std::pair<std::size_t, std::size_t>> matchCollisions(const std::vector<CollisionRecord>& ours,
                                                                 const std::vector<CollisionRecord>& box2d,
                                                                 double window);

}  // namespace gizmo::verify
