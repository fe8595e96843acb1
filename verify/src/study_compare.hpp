#pragma once
// What the study compares of a run, whichever method made it, and the comparison with the
// scene's reference run: ball positions and energy at fixed instants, and collisions matched as
// the Box2D cross-check matches them.
#include <optional>
#include <string>
#include <vector>

#include "gizmo/verify/box2d_world.hpp"
#include "trace.hpp"

namespace gizmo::verify {

struct StudyRun {
  std::vector<CollisionRecord> collisions;  // in time order
  std::vector<WideValue> collisionTimes;    // the same times, held wide (ours in their own scalar)
  std::vector<TraceSample> samples;         // at the scene's instants
};

// Our run from its trace: every collision (an absorber's capture included) named as Box2D's are.
StudyRun studyRunOf(const Trace& trace, std::vector<TraceSample> samples, const BoardSpec& board);
// Box2D's run: its samples interpolated at the instants (its steps need not fall on them).
StudyRun studyRunOf(const RunRecord& record, const std::vector<double>& instants, std::size_t balls);

struct RunErrors {
  double positionError = 0, positionErrorMedian = 0;
  std::optional<double> divergedAt;
  std::size_t matched = 0;
  double eventTimeError = 0, meanEventTimeError = 0;
  std::optional<double> firstWrongTime;
  std::string firstWrong;
  double energyDrift = 0;
};

// The errors of run against reference over [0, end]. Collisions match within `window` seconds;
// one in the last window before the end that found no partner is not counted as wrong (its
// partner may lie just past the end).
RunErrors compareWithReference(const StudyRun& reference, const StudyRun& run, double end, double window);

// The largest distance between the balls of two runs over their common sampling instants.
double largestPositionDistance(const std::vector<TraceSample>& a, const std::vector<TraceSample>& b);

}  // namespace gizmo::verify
