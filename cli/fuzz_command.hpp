#pragma once
// `gizmo fuzz`: the properties of docs/fuzzing.md on generated runs (a campaign, sharded if
// asked), on variations of a board or log the user brings (`gizmo fuzz BOARD`, with their own
// expectations), the merge of sharded campaigns' results, or the properties on one given run
// (--check, the command each failure's folder holds).
#include <cstdint>
#include <string>
#include <vector>

#include "gizmo/verify/fuzz/variations.hpp"
#include "run_options.hpp"

namespace gizmo::cli {

struct FuzzOptions {
  std::string property = "all";
  std::uint64_t count = 100;
  std::uint64_t seed = 1;
  unsigned jobs = 1;
  std::string shard;       // "K/N"; empty: the whole campaign
  std::string out;         // results folder; empty: failures are only printed
  double wallSeconds = 0;  // --budget: stop starting cases after this long (0: no limit)
  std::size_t shrinkBudget = 100;
  bool logCases = false;                // --log-cases: a line as each case starts and ends
  std::vector<std::string> merge;       // --merge DIR...: merge these results folders
  std::string check;                    // --check BOARD: check one run instead of generating
  std::string board;                    // BOARD: a campaign of variations of this board file or replay log
  RunOptions run;                       // --keys, --model, --max-tick, --time for --check and BOARD
  std::string expect;                   // --expect FILE: the user's expectations, with --check or BOARD
  verify::fuzz::VariationOptions vary;  // --vary-*: the variations of BOARD's run
  bool json = false;                    // --json: the campaign's result as one JSON object
  // Which run options were given (a log's own model, tick, duration and keys stand otherwise).
  bool boardTimeGiven = false, keysGiven = false, modelGiven = false, maxTickGiven = false, precisionGiven = false;
};
int fuzzCommand(const FuzzOptions& options);
// The property names, comma-separated, for the help text.
std::string fuzzPropertyList();

}  // namespace gizmo::cli
