#pragma once
// `gizmo crosscheck`: a board run by our simulator and by Box2D at several step sizes, compared
// collision by collision; or, with --toi-sweeps, our times of impact against b2TimeOfImpact on
// seeded random single contacts.
#include <cstdint>
#include <string>

#include "run_options.hpp"

namespace gizmo::cli {

inline constexpr const char* kDefaultCrosscheckSteps = "1/60,1/120,1/240,1/480";

struct CrosscheckCommandOptions {
  RunOptions run;
  std::string steps = kDefaultCrosscheckSteps;  // --dt: comma-separated seconds, each a number or 1/N
  bool noBullet = false;
  double restitutionThreshold = 0;
  int toiSweeps = 0;       // > 0: the time-of-impact survey instead of whole runs
  std::uint64_t seed = 1;  // the survey's seed
};
int crosscheckCommand(const CrosscheckCommandOptions& options);

}  // namespace gizmo::cli
