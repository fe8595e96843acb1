// `gizmo replay`: run a log's board again and compare every decision, or show one moment of it.
#include <cstdio>
#include <iostream>

#include "board_input.hpp"
#include "log_commands.hpp"
#include "log_view.hpp"

namespace gizmo::cli {
namespace {

int seek(const replay::OpenedLog& log, const ReplayOptions& o) {
  replay::SeekTarget target;
  if (o.event) target.events = static_cast<std::uint64_t>(*o.event);
  if (o.at) {
    if (!(*o.at >= 0) || !(*o.at <= log.header.duration)) {
      std::cerr << "gizmo replay: --at must be a time within the run (0 to " << log.header.duration << " s)\n";
      return kExitBadInput;
    }
    target.time = *o.at + 0.0;  // −0 is 0
  }
  replay::StateView s;
  try {
    s = replay::seekLog(log, target);
  } catch (const std::out_of_range& e) {
    std::cerr << "gizmo replay: " << o.log << ": " << e.what() << '\n';
    return kExitBadInput;
  }
  if (o.json) std::cout << stateJson(s).dump(2) << '\n';
  else printState(o.event ? "after event " + std::to_string(*o.event) : "at the requested time", s);
  return kExitOk;
}

int compare(const replay::OpenedLog& log, const ReplayOptions& o) {
  const replay::ReplayReport r =
      replay::replayLog(log, o.everyRecord ? replay::ReplayMethod::Records : replay::ReplayMethod::Digests);
  const char* compared = r.byDigests ? "chunk digests and keyframes" : "every record";
  if (o.json) {
    nlohmann::ordered_json j{{"identical", r.identical},
                             {"events", r.events},
                             {"note", r.note},
                             {"board_warnings", log.header.boardWarnings}};
    if (log.header.parent)
      j["branch"] = {{"parent_digest", log.header.parent->parentDigest}, {"event", log.header.parent->event}};
    if (r.identical) j["compared"] = compared;
    if (!r.identical) {
      j["where"] = r.where;
      j["decisions_identical"] = r.decisions;
      if (r.logDecision) j["log_decision"] = decisionJson(*r.logDecision, log.gizmoNames);
      if (r.runDecision) j["run_decision"] = decisionJson(*r.runDecision, log.gizmoNames);
      if (r.logState) j["log_state"] = stateJson(*r.logState);
      if (r.runState) j["run_state"] = stateJson(*r.runState);
    }
    std::cout << j.dump(2) << '\n';
    return r.identical ? kExitOk : kExitCheckFailed;
  }
  if (r.identical) {
    std::printf("identical: %llu events replay exactly as recorded (%s, %s; compared: %s)\n",
                static_cast<unsigned long long>(r.events), log.header.precision.c_str(),
                std::string(motionModelName(log.header.model)).c_str(), compared);
    if (!r.note.empty()) std::printf("note: %s\n", r.note.c_str());
    if (log.header.parent)
      std::printf(
          "note: a branch log, taken at event %llu of the log whose checksum is %016llx; its events are "
          "counted from that log's start\n",
          static_cast<unsigned long long>(log.header.parent->event),
          static_cast<unsigned long long>(log.header.parent->parentDigest));
    if (!log.header.boardWarnings.empty())
      std::printf(
          "note: the board was read leniently (%zu warnings, above): this is a run of the board as read, "
          "not of the file as written\n",
          log.header.boardWarnings.size());
    return kExitOk;
  }
  std::printf("DIFFERENT: %s\n", r.where.c_str());
  if (r.logDecision || r.runDecision)
    std::printf("after %llu identical decisions and %llu events\n", static_cast<unsigned long long>(r.decisions),
                static_cast<unsigned long long>(r.events));
  std::printf("log: %s\n", r.logDecision ? decisionLine(*r.logDecision, log.gizmoNames, true).c_str() : "(ends here)");
  std::printf("run: %s\n", r.runDecision ? decisionLine(*r.runDecision, log.gizmoNames, true).c_str() : "(ends here)");
  if (r.logState) printState("log state", *r.logState);
  if (r.runState) printState("run state", *r.runState);
  return kExitCheckFailed;
}

}  // namespace

int replayCommand(const ReplayOptions& o) {
  if (o.at && o.event) {
    std::cerr << "gizmo replay: give --at or --event, not both\n";
    return kExitBadInput;
  }
  if (o.event && *o.event < 0) {
    std::cerr << "gizmo replay: --event must be a number of events, 0 or more\n";
    return kExitBadInput;
  }
  int code = kExitOk;
  const std::optional<replay::OpenedLog> log = openLogFor("replay", o.log, code);
  if (!log) return code;
  try {
    const int result = o.at || o.event ? seek(*log, o) : compare(*log, o);
    std::fflush(stdout);
    return finishWithCutOffLogs("replay", result, {&*log}, {o.log});
  } catch (const std::exception& e) {
    std::cerr << "gizmo replay: " << o.log << ": " << e.what() << '\n';
    return kExitBadInput;
  }
}

}  // namespace gizmo::cli
