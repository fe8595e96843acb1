// `gizmo record`: run a board and write every decision to a replay log.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "board_input.hpp"
#include "gizmo/replay/replay.hpp"
#include "log_commands.hpp"
#include "run_command.hpp"

namespace gizmo::cli {

int recordCommand(const RecordOptions& o) {
  if (!o.from.empty()) return branchCommand(o);
  CheckedRun run;
  int code = kExitOk;
  if (!checkRun(o.run, "record", run, code)) return code;
  if (o.output.empty()) {
    std::cerr << "gizmo record: -o LOG is required\n";
    return kExitBadInput;
  }
  if (!recordable(run.precision)) {
    std::cerr << "gizmo record: " << precisionName(run.precision)
              << " runs cannot be recorded: the log has no encoding for them (use gizmo verify to compare them)\n";
    return kExitBadInput;
  }
  // The file is created only once the input is known to be good.
  const auto start = std::chrono::steady_clock::now();
  replay::RecordResult result;
  std::uint64_t bytes = 0, chunks = 0;
  try {
    replay::LogWriter writer(o.output);
    result = replay::recordRun(run.request, run.precision, writer, run.boardWarnings);
    bytes = writer.bytesWritten();
    chunks = writer.chunksWritten();
  } catch (const std::exception& e) {
    std::cerr << "gizmo record: " << e.what() << '\n';
    return kExitBadInput;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.completed) {
    std::cerr << "gizmo record: the simulation stopped: " << result.error << " (the log records it)\n";
    return kExitCheckFailed;
  }
  if (!o.run.json) {
    printRunSummary(run.boardName, run.boardWarnings, o.run, result.summary, wall);
    std::printf("log        %s: %llu bytes in %llu chunks, %.1f bytes per event\n", o.output.c_str(),
                static_cast<unsigned long long>(bytes), static_cast<unsigned long long>(chunks),
                result.summary.total ? double(bytes) / double(result.summary.total) : 0.0);
  } else {
    printRunSummary(run.boardName, run.boardWarnings, o.run, result.summary, wall);
  }
  return kExitOk;
}

}  // namespace gizmo::cli
