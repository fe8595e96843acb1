#include "verify_command.hpp"

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "board_input.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/replay.hpp"
#include "gizmo/verify/certify.hpp"
#include "gizmo/verify/ladder.hpp"
#include "log_view.hpp"

namespace gizmo::cli {
namespace {

bool parseList(const std::string& list, std::vector<PrecisionChoice>& out) {
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    const std::optional<PrecisionChoice> p = parsePrecision(name);
    if (!p) {
      std::cerr << "gizmo verify: unknown precision '" << name << "' (" << kPrecisionNames << ")\n";
      return false;
    }
    for (const PrecisionChoice& q : out) {
      if (precisionName(q) == precisionName(*p)) {
        std::cerr << "gizmo verify: precision '" << name << "' is listed twice\n";
        return false;
      }
    }
    out.push_back(*p);
  }
  if (out.empty()) {
    std::cerr << "gizmo verify: --precisions lists no precision\n";
    return false;
  }
  return true;
}

void printHuman(const std::string& board, const VerifyOptions& o, const verify::LadderReport& r) {
  std::printf("board      %s\n", board.c_str());
  std::printf("model      %s, %.6g s, max tick %.6g s\n", o.run.model.c_str(), o.run.time, o.run.maxTick);
  std::printf("exact      %s: %s\n", r.scene.rationalPossible ? "possible" : "not possible", r.scene.reason.c_str());
  std::printf("reference  %s\n", r.reference.c_str());
  for (const std::string& n : r.notes) std::printf("note       %s\n", n.c_str());
  if (r.certified) {
    const verify::CertifiedSummary& c = *r.certified;
    std::printf(
        "certified  the double run's decisions: %llu of %llu certified, %llu not certified, %llu ties, %llu wrong\n",
        static_cast<unsigned long long>(c.certified), static_cast<unsigned long long>(c.decisions),
        static_cast<unsigned long long>(c.notCertified), static_cast<unsigned long long>(c.ties),
        static_cast<unsigned long long>(c.wrong));
    if (!c.firstWrong.empty()) std::printf("           first: %s\n", c.firstWrong.c_str());
  }
  std::printf("\n%-12s %9s %9s %12s %10s %10s %10s %9s %11s %9s\n", "precision", "compared", "horizon", "horizon t/s",
              "max dt", "max dpos", "energy", "wall s", "events/s", "x double");
  for (const verify::PrecisionResult& p : r.results) {
    std::printf("%-12s %9llu %9llu %12.6g %10.3g %10.3g %10.3g %9.4f %11.4g %9.3g%s\n", p.precision.c_str(),
                static_cast<unsigned long long>(p.compared), static_cast<unsigned long long>(p.horizonEvents),
                p.horizonTime, p.maxTimeError, p.maxPositionError, p.energyDrift, p.wallSeconds, p.eventsPerSecond,
                p.costRatio,
                p.reference          ? "  (reference)"
                : p.agreesThroughout ? "  (agrees throughout)"
                                     : "");
    if (!p.difference.empty()) std::printf("  first difference: %s\n", p.difference.c_str());
    if (!p.stopped.empty()) std::printf("  stopped: %s\n", p.stopped.c_str());
  }
}

nlohmann::ordered_json certifiedJson(const std::optional<verify::CertifiedSummary>& c) {
  if (!c) return nullptr;
  return {{"decisions", c->decisions}, {"certified", c->certified}, {"not_certified", c->notCertified},
          {"ties", c->ties},           {"wrong", c->wrong},         {"first_wrong", c->firstWrong}};
}

void printJson(const CheckedRun& run, const VerifyOptions& o, const verify::LadderReport& r) {
  nlohmann::ordered_json precisions = nlohmann::ordered_json::array();
  for (const verify::PrecisionResult& p : r.results) {
    precisions.push_back({{"precision", p.precision},
                          {"reference", p.reference},
                          {"events", p.events},
                          {"compared_events", p.compared},
                          {"end_time", p.endTime},
                          {"stopped", p.stopped},
                          {"horizon_events", p.horizonEvents},
                          {"horizon_time", p.horizonTime},
                          {"first_difference", p.difference},
                          {"agrees_throughout", p.agreesThroughout},
                          {"max_time_error", p.maxTimeError},
                          {"max_position_error", p.maxPositionError},
                          {"energy_drift", p.energyDrift},
                          {"wall_seconds", p.wallSeconds},
                          {"events_per_second", p.eventsPerSecond},
                          {"cost_ratio_to_double", p.costRatio}});
  }
  nlohmann::ordered_json out{{"board", run.boardName},
                             {"warnings", run.boardWarnings},
                             {"model", o.run.model},
                             {"time", o.run.time},
                             {"max_tick", o.run.maxTick},
                             {"reference", r.reference},
                             {"exact_possible", r.scene.rationalPossible},
                             {"exact_reason", r.scene.reason},
                             {"notes", r.notes},
                             {"certified", certifiedJson(r.certified)},
                             {"precisions", precisions}};
  std::cout << out.dump(2) << '\n';
}

// `gizmo verify LOG --certify`: exit 1 when a decision is proven wrong.
int certifyCommand(const VerifyOptions& o) {
  if (o.run.board.empty()) {
    std::cerr << "gizmo verify: --certify checks a recorded run: give its log (gizmo record -o LOG)\n";
    return kExitBadInput;
  }
  int code = kExitOk;
  const std::optional<replay::OpenedLog> log = openLogFor("verify", o.run.board, code);
  if (!log) return code;
  verify::CertifyReport report;
  try {
    // The certificate is about the run the log records: first make sure that re-simulating it
    // gives exactly the logged decisions.
    const replay::ReplayReport replayed = replay::replayLog(*log);
    if (!replayed.identical) {
      std::cerr << "gizmo verify: " << o.run.board << ": the log does not replay identically (" << replayed.where
                << "); see gizmo replay\n";
      return kExitCheckFailed;
    }
    report = verify::certifyLog(*log);
  } catch (const replay::FormatError& e) {
    std::cerr << "gizmo verify: " << o.run.board << ": " << e.what() << '\n';
    return kExitBadInput;
  } catch (const verify::CertifyError& e) {
    std::cerr << "gizmo verify: " << o.run.board << ": " << e.what() << '\n';
    return kExitBadInput;
  }
  if (o.run.json) std::cout << verify::certifyReportJson(report) << '\n';
  else verify::printCertifyReport(std::cout, report);
  return finishWithCutOffLogs("verify", report.wrong.empty() ? kExitOk : kExitCheckFailed, {&*log}, {o.run.board});
}

}  // namespace

int verifyCommand(const VerifyOptions& o) {
  if (o.certify) return certifyCommand(o);
  CheckedRun run;
  int code = kExitOk;
  if (!checkRun(o.run, "verify", run, code)) return code;
  verify::LadderOptions options;
  options.request = run.request;
  options.exactDigits = o.exactDigits;
  if (o.precisions.empty()) {
    options.precisions = verify::defaultLadder(run.request);
  } else if (!parseList(o.precisions, options.precisions)) {
    return kExitBadInput;
  }
  if (!o.reference.empty()) {
    options.reference = parsePrecision(o.reference);
    if (!options.reference) {
      std::cerr << "gizmo verify: unknown reference precision '" << o.reference << "' (" << kPrecisionNames << ")\n";
      return kExitBadInput;
    }
  }
  const verify::LadderReport report = verify::runLadder(options);
  if (o.run.json) printJson(run, o, report);
  else printHuman(run.boardName, o, report);
  return kExitOk;
}

}  // namespace gizmo::cli
