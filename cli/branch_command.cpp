// `gizmo record --from LOG (--at T | --event N)`: take a log's run over at a moment and go on
// with new key input, into a branch log (replay.hpp: recordBranch).
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "board_input.hpp"
#include "log_commands.hpp"
#include "log_view.hpp"
#include "run_command.hpp"

namespace gizmo::cli {
namespace {

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  return a == b || std::filesystem::equivalent(a, b, error);
}

}  // namespace

int branchCommand(const RecordOptions& o) {
  const std::string prefix = "gizmo record: ";
  if (o.at.has_value() == o.event.has_value()) {
    std::cerr << prefix << "--from needs the moment to branch at: --at T or --event N\n";
    return kExitBadInput;
  }
  if (o.event && *o.event < 0) {
    std::cerr << prefix << "--event must be a number of events, 0 or more\n";
    return kExitBadInput;
  }
  if (o.at && !(*o.at >= 0)) {
    std::cerr << prefix << "--at must be a board time, 0 or more\n";
    return kExitBadInput;
  }
  if (sameFile(o.from, o.output)) {
    std::cerr << prefix << o.output << ": the branch log would overwrite its parent\n";
    return kExitBadInput;
  }
  replay::BranchRequest request;
  if (o.event) request.at.events = static_cast<std::uint64_t>(*o.event);
  if (o.at) request.at.time = *o.at + 0.0;  // −0 is 0
  if (o.timeGiven) {
    if (!(o.run.time >= 0) || o.run.time > 1e7) {
      std::cerr << prefix << "--time must be a number of seconds from 0 to 1e7\n";
      return kExitBadInput;
    }
    request.duration = o.run.time;
  }
  try {
    request.keys = loadKeys(o.run.keys);
  } catch (const std::exception& e) {
    std::cerr << prefix << e.what() << '\n';
    return kExitBadInput;
  }
  int code = kExitOk;
  const std::optional<replay::OpenedLog> parent = openLogFor("record", o.from, code);
  if (!parent) return code;

  // The file is created when the branch is known to be good (recordBranch checks everything
  // before it writes the header); one that fails after that is removed.
  replay::BranchResult result;
  replay::LogWriter writer(o.output);
  try {
    result = replay::recordBranch(*parent, request, writer);
  } catch (const std::exception& e) {
    std::cerr << prefix << o.from << ": " << e.what() << '\n';
    if (writer.bytesWritten() > 0) std::remove(o.output.c_str());
    return kExitBadInput;
  }
  const std::uint64_t bytes = writer.bytesWritten(), chunks = writer.chunksWritten();
  if (!result.record.completed) {
    std::cerr << prefix << "the simulation stopped: " << result.record.error << " (the log records it)\n";
    return kExitCheckFailed;
  }
  if (o.run.json) {
    nlohmann::ordered_json j{{"parent", o.from},
                             {"parent_digest", result.origin.parentDigest},
                             {"branch_event", result.origin.event},
                             {"branch_time", result.time.value},
                             {"start_event", result.startEvents},
                             {"keys_left_out", result.keysLeftOut},
                             {"events", result.record.summary.total},
                             {"time", result.record.summary.time},
                             {"bytes", bytes},
                             {"chunks", chunks}};
    std::cout << j.dump(2) << '\n';
    return kExitOk;
  }
  std::printf(
      "branch     of %s at event %llu, time %.17g (%s); the log starts at event %llu, the tick boundary "
      "before it\n",
      o.from.c_str(), static_cast<unsigned long long>(result.origin.event), result.time.value, result.time.text.c_str(),
      static_cast<unsigned long long>(result.startEvents));
  if (result.keysLeftOut > 0)
    std::printf("keys       %zu of the key script's keys come before the branch point and are left out\n",
                result.keysLeftOut);
  std::printf("run        to %.17g s: %llu events in all\n", result.record.summary.time,
              static_cast<unsigned long long>(result.record.summary.total));
  std::printf("log        %s: %llu bytes in %llu chunks\n", o.output.c_str(), static_cast<unsigned long long>(bytes),
              static_cast<unsigned long long>(chunks));
  return kExitOk;
}

}  // namespace gizmo::cli
