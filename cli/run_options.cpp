#include "run_options.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>

#include "board_input.hpp"

namespace gizmo::cli {

void addRunOptions(CLI::App& command, RunOptions& o, bool withPrecision) {
  command.add_option("board", o.board, "Board file, XML or text (default: the specification's example, built in)");
  command.add_option("--time", o.time, "Seconds of board time to simulate")->capture_default_str();
  command.add_option("--model", o.model, "Motion model: ballistic or classic")->capture_default_str();
  if (withPrecision)
    command.add_option("--precision", o.precision, std::string("Scalar: ") + kPrecisionNames)->capture_default_str();
  command.add_option("--max-tick", o.maxTick, "Maximum tick length, seconds")->capture_default_str();
  command.add_option("--keys", o.keys, "Key script: one 'TIME down|up KEYCODE' per line");
  addStrictOption(command, o.strict);
}

void addStrictOption(CLI::App& command, bool& strict) {
  command.add_flag("--strict", strict,
                   "Refuse a board that is not read exactly as written (what would be a warning is an error, exit 2)");
}

bool checkRunOptions(const RunOptions& o, const std::string& command, CheckedOptions& out) {
  const std::string prefix = "gizmo " + command + ": ";
  std::optional<MotionModel> model;
  if (o.model == "ballistic") model = MotionModel::Ballistic;
  if (o.model == "classic") model = MotionModel::Classic;
  if (!model) {
    std::cerr << prefix << "unknown model '" << o.model << "' (ballistic or classic)\n";
    return false;
  }
  const std::optional<PrecisionChoice> precision = parsePrecision(o.precision);
  if (!precision) {
    std::cerr << prefix << "unknown precision '" << o.precision << "' (" << kPrecisionNames << ")\n";
    return false;
  }
  if (!builtHere(*precision)) {
    std::cerr << prefix << notBuiltHereMessage(*precision) << '\n';
    return false;
  }
  if (!(o.time >= 0) || !std::isfinite(o.time) || o.time > 1e7) {
    std::cerr << prefix << "--time must be a number of seconds from 0 to 1e7\n";
    return false;
  }
  if (!(o.maxTick > 0) || !std::isfinite(o.maxTick) || o.maxTick > 10) {
    std::cerr << prefix << "--max-tick must be a number of seconds above 0 and at most 10\n";
    return false;
  }
  out.model = *model;
  out.precision = *precision;
  return true;
}

bool checkRun(const RunOptions& o, const std::string& command, CheckedRun& out, int& exitCode) {
  exitCode = kExitBadInput;
  CheckedOptions checked;
  if (!checkRunOptions(o, command, checked)) return false;
  try {
    LoadedBoard board = loadBoard(o.board, o.strict);
    out.request.board = std::move(board.spec);
    out.boardName = board.name;
    out.boardWarnings = std::move(board.warnings);
    out.request.keys = loadKeys(o.keys);
  } catch (const io::InputError& e) {
    std::cerr << e.what() << '\n';
    return false;
  }
  out.request.model = checked.model;
  out.request.maxTick = o.maxTick;
  out.request.duration = o.time;
  out.precision = checked.precision;
  exitCode = kExitOk;
  return true;
}

}  // namespace gizmo::cli
