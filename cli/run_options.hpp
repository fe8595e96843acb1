#pragma once
// The options that describe a run (`gizmo run`, `gizmo record`), and their checking: a bad
// option is reported before anything is simulated or written.
#include <string>

#include "gizmo/core/math/precision.hpp"
#include "gizmo/core/run/run.hpp"

namespace CLI {
class App;
}

namespace gizmo::cli {

struct RunOptions {
  std::string board;  // empty: the built-in spec example
  double time = 10.0;
  std::string model = "ballistic";
  std::string precision = "double";
  double maxTick = 0.05;
  std::string keys;
  bool json = false;
};

// Adds the run options (board, --time, --model, --precision, --max-tick, --keys) to a subcommand;
// without --precision for a command that chooses its own scalars.
void addRunOptions(CLI::App& command, RunOptions& options, bool withPrecision = true);

struct CheckedRun {
  RunRequest request;
  PrecisionChoice precision;
  std::string boardName;
};

// Checks the options and reads the board and key script; on failure prints why (prefixed with
// the command's name) and returns the exit code in `exitCode`.
bool checkRun(const RunOptions& options, const std::string& command, CheckedRun& out, int& exitCode);

}  // namespace gizmo::cli
