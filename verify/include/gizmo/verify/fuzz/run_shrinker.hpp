#pragma once
// Smaller versions of a run, for shrinking a failing case down to a handful of gizmos. One list of
// candidates serves both shrinkers: rapidcheck's (the property tests wrap it with
// rc::shrinkable::shrinkRecur) and `gizmo fuzz`'s own greedy minimiser below.
#include <cstddef>
#include <functional>
#include <vector>

#include "gizmo/core/run/run.hpp"

namespace gizmo::verify::fuzz {

// Valid runs strictly simpler than `run`, boldest first: all the keys, half, then each; the same
// for gizmos (with their connections), balls (at least one stays), connections and key
// connections; then a shorter duration, no gravity, no friction, and balls at rest or on round
// coordinates. Each candidate passes checkBoardSpec.
std::vector<RunRequest> shrinkCandidates(const RunRequest& run);

struct Minimised {
  RunRequest run;
  std::size_t steps = 0;  // candidates accepted
  std::size_t tries = 0;  // times `fails` was called
};
// Greedy: takes the first candidate that still fails, and starts again from it, until none fails
// or `fails` has been called `budget` times.
Minimised minimise(const RunRequest& failing, const std::function<bool(const RunRequest&)>& fails, std::size_t budget);

}  // namespace gizmo::verify::fuzz
