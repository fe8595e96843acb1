#pragma once
// `gizmo crosscheck`: one board run by our simulator (double) and by another engine (Box2D at
// each step size, or any engine's run read from a trace: engine_trace.hpp), collisions matched
// (same ball, same gizmo, nearest time within a window), and for each run of the engine what
// agreed, what either side missed, how far the trajectories and the energy drifted apart, which
// side an mpfr:256 run agrees with where they part, and what each cost (docs/verification.md,
// "Cross-checking against Box2D" and "Any engine's run").
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "gizmo/verify/box2d_world.hpp"

namespace gizmo::verify {

struct CrosscheckOptions {
  RunRequest request;
  std::vector<double> steps{1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480};
  Box2dOptions box2d;             // its dt is replaced by each of `steps`
  bool keepBox2dSamples = false;  // hand each step size's Box2D samples back (for a path file)
};

// A collision that only one side made: the first of them, for the report.
struct UnmatchedCollision {
  std::string side;  // "ours" (the engine missed it) or "theirs" (we did not make it)
  CollisionRecord collision;
};

// Where the paths part (the first of our tick boundaries at which some ball is more than 0.1 L
// from the engine's), and which side a run of the same request at mpfr:256 agrees with there:
// the balls' largest distance from it on each side.
struct PartingCheck {
  double time = 0;
  std::vector<Vec2<double>> ours, theirs, reference;  // every ball, in the board's order
  double oursOff = 0, theirsOff = 0;                  // max over balls of |p − p_mpfr256|
  std::string agreesWith;                             // "ours" or "theirs" (the nearer; ours on a tie)
};
inline constexpr double kPartingLevel = 0.1;  // L: one of kDivergenceLevels

inline constexpr std::array<double, 3> kDivergenceLevels{0.01, 0.1, 1.0};

struct StepComparison {
  double dt = 0;
  double end = 0;          // the run's length (both sides ran on by the window)
  double matchWindow = 0;  // seconds: collisions further apart never match
  std::uint64_t steps = 0;
  bool collisionsCompared = true;  // false: the engine reported no contacts (a trace may not)
  std::size_t theirCollisions = 0;
  std::size_t matched = 0;
  std::size_t missedByThem = 0;  // ours, unmatched
  std::size_t missedByUs = 0;    // the engine's, unmatched
  double maxTimeError = 0;       // over matched: |t_box2d − t_ours|
  double meanTimeError = 0;
  double maxPositionError = 0;       // over matched: |p_box2d − p_ours|, L
  std::size_t matchedWithinToi = 0;  // matched with a position error within Box2D's TOI target + tolerance
  std::optional<UnmatchedCollision> firstUnmatched;
  std::uint64_t speedCappedSteps = 0;     // counted over the run and the window after it,
  std::uint64_t rotationCappedSteps = 0;  // as is wallSeconds
  double maxDivergence = 0;               // max over samples and balls of |p_box2d − p_ours|
  std::array<std::optional<double>, kDivergenceLevels.size()> divergenceFrom;  // first time above each level
  std::optional<PartingCheck> parting;                // at divergenceFrom's kPartingLevel, when the paths part
  std::vector<std::pair<double, double>> divergence;  // (time, max distance), at most 50 evenly spread samples
  double energyEnd = 0;                               // the engine's, at the end
  double maxEnergyDifference = 0;  // max over samples of |E_theirs − E_ours| / max(|E_ours|, |E_start|)
  double wallSeconds = 0;          // the engine's (a trace's own figure, 0 when it gives none)
  // Box2D's balls after each step, from time 0 to the end and the window after it; only with
  // CrosscheckOptions::keepBox2dSamples.
  std::vector<TrajectorySample> box2dSamples;
};

struct CrosscheckReport {
  std::size_t ourCollisions = 0;
  std::uint64_t ourEvents = 0;
  double ourWallSeconds = 0;  // an unobserved run of the same request
  double energyStart = 0;
  double ourEnergyEnd = 0;
  std::vector<StepComparison> steps;
};

// The window within which two collisions of the same pair can match, at step size dt, and how
// far apart the ball's centres may be.
double matchWindow(double dt);
inline constexpr double kMatchDistance = 1.0;

CrosscheckReport crosscheck(const CrosscheckOptions& options);

// The same report for runs of another engine made elsewhere (each a RunRecord with its largest
// step size): our run, each compared with it, and the partings checked at mpfr:256. Collisions are
// compared only when `withCollisions` (the engine reported its contacts).
struct EngineRun {
  RunRecord record;
  double dt = 0;  // its largest step: the match window's step
  bool withCollisions = true;
};
CrosscheckReport crosscheckRuns(const RunRequest& request, const std::vector<EngineRun>& runs);

// The record of our own run (double, the request's model), as runBox2d's; `events` gets the
// number of executed events.
RunRecord runOurs(const RunRequest& request, std::uint64_t& events);

// A run's sample at time t, interpolated linearly between the samples around it (their times in
// increasing order from time 0; after the last, the last).
TrajectorySample interpolate(const std::vector<TrajectorySample>& samples, double t);

// Matches two collision lists: pairs of indices (ours, Box2D's), the closest in time first,
// within `window` seconds and kMatchDistance.
std::vector<std::pair<std::size_t, std::size_t>> matchCollisions(const std::vector<CollisionRecord>& ours,
                                                                 const std::vector<CollisionRecord>& box2d,
                                                                 double window);

}  // namespace gizmo::verify
