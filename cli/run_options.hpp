#pragma once
// The options that describe a run (`gizmo run`, `gizmo record`), and their checking: a bad
// option is reported before anything is simulated or written.
#include <string>
#include <vector>

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
  bool strict = false;  // refuse a board that would be read leniently
};

// Adds the run options (board, --time, --model, --precision, --max-tick, --keys) to a subcommand;
// without --precision for a command that chooses its own scalars.
void addRunOptions(CLI::App& command, RunOptions& options, bool withPrecision = true);
// --strict alone, for a command that reads a board without the run options (render).
void addStrictOption(CLI::App& command, bool& strict);

struct CheckedRun {
  RunRequest request;
  PrecisionChoice precision;
  std::string boardName;
  std::vector<std::string> boardWarnings;  // what the reader read leniently (io::format lines)
};

// The options' own values (model, precision, --time, --max-tick) checked and read, the board and
// key script left alone; on failure prints why, prefixed with the command's name.
struct CheckedOptions {
  MotionModel model = MotionModel::Ballistic;
  PrecisionChoice precision;
};
bool checkRunOptions(const RunOptions& options, const std::string& command, CheckedOptions& out);

// Checks the options and reads the board and key script; on failure prints why (prefixed with
// the command's name) and returns the exit code in `exitCode`.
bool checkRun(const RunOptions& options, const std::string& command, CheckedRun& out, int& exitCode);

}  // namespace gizmo::cli
