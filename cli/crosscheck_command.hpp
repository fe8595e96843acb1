#pragma once
// `gizmo crosscheck`: a board run by our simulator and by Box2D at several step sizes, or by any
// engine whose run is read from a trace (--trace), compared collision by collision; or, with
// --toi-sweeps, our times of impact against b2TimeOfImpact on seeded random single contacts.
#include <cstdint>
#include <optional>
#include <string>

#include "run_options.hpp"

namespace gizmo::cli {

inline constexpr const char* kDefaultCrosscheckSteps = "1/60,1/120,1/240,1/480";

struct CrosscheckCommandOptions {
  RunOptions run;
  std::string steps = kDefaultCrosscheckSteps;  // --dt: comma-separated seconds, each a number or 1/N
  std::string engine = "box2d-2.4";             // or box2d-v3 (the node program, verify/box2d3)
  bool noBullet = false;
  bool noContinuous = false;
  double restitutionThreshold = 0;
  int toiSweeps = 0;             // > 0: the time-of-impact survey instead of whole runs
  std::uint64_t seed = 1;        // the survey's seed
  std::string pathOut;           // writes Box2D's ball paths here (one step size only): render_path_file.hpp
  std::string traceOut;          // Box2D v3's program writes its run here as a trace (one step size only)
  std::string trace;             // another engine's run (JSON lines: engine_trace.hpp) instead of Box2D's
  std::string box2dOptionGiven;  // the first Box2D option given on the command line (refused with --trace)
};
int crosscheckCommand(const CrosscheckCommandOptions& options);

// A Box2D step size, "0.01" or "1/60", from 1e-5 to 0.1 s; nullopt for anything else.
std::optional<double> parseStepSize(const std::string& text);
// Box2D steps one command may ask for, summed over its step sizes.
inline constexpr double kMaxBox2dSteps = 1e7;

}  // namespace gizmo::cli
