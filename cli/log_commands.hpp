#pragma once
// The replay log's commands: record a run, replay a log (or look at one moment of it), dump its
// decisions, and find where two logs part.
#include <optional>
#include <string>

#include "run_options.hpp"

namespace gizmo::cli {

struct RecordOptions {
  RunOptions run;
  std::string output;
  // A branch (--from LOG): go on from a moment of LOG, at a board time or after a number of events.
  std::string from;
  std::optional<double> at;
  std::optional<long long> event;
  bool timeGiven = false;  // --time: the board time the branch runs to (default: LOG's)
};
int recordCommand(const RecordOptions& options);
// `gizmo record --from` (branch_command.cpp).
int branchCommand(const RecordOptions& options);

struct ReplayOptions {
  std::string log;
  std::optional<double> at;
  std::optional<long long> event;
  bool json = false;
  bool everyRecord = false;  // compare record by record, not by chunk digests
};
int replayCommand(const ReplayOptions& options);

struct DumpOptions {
  std::string log;
  bool json = false;
  bool exact = false;
  std::string kind;
  std::string gizmo;
  std::optional<double> from, to;
};
int dumpCommand(const DumpOptions& options);

struct DiffOptions {
  std::string first, second;
  bool summary = false;
  bool json = false;
  int context = 3;
};
int diffCommand(const DiffOptions& options);

}  // namespace gizmo::cli
