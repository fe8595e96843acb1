#include "run_command.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "board_input.hpp"
#include "gizmo/core/math/precision.hpp"
#include "gizmo/io/diagnostics.hpp"

namespace gizmo::cli {
namespace {

void printHuman(const std::string& board, const RunOptions& o, const RunSummary& s, double wall) {
  std::printf("board      %s\n", board.c_str());
  std::printf("model      %s\nprecision  %s\ntime       %.17g s\n", o.model.c_str(), o.precision.c_str(), s.time);
  std::printf("events     %llu\n", static_cast<unsigned long long>(s.total));
  for (int k = 0; k < kEventKindCount; ++k)
    std::printf("  %-14s %llu\n", std::string(eventKindName(EventKind(k))).c_str(),
                static_cast<unsigned long long>(s.executed[std::size_t(k)]));
  std::printf("balls      %zu\n", s.balls.size());
  for (const BallState& b : s.balls)
    std::printf("  %-12s x=%-22.17g y=%-22.17g vx=%-22.17g vy=%-22.17g%s\n", b.name.c_str(), b.x, b.y, b.vx, b.vy,
                b.captured ? " captured" : "");
  std::printf("energy     %.17g (per unit mass, free balls)\n", s.energy);
  std::printf("wall       %.6f s\n", wall);
}

void printJson(const std::vector<std::string>& boardWarnings, const RunOptions& o, const RunSummary& s, double wall) {
  nlohmann::ordered_json events;
  for (int k = 0; k < kEventKindCount; ++k)
    events[std::string(eventKindName(EventKind(k)))] = s.executed[std::size_t(k)];
  events["total"] = s.total;
  nlohmann::ordered_json balls = nlohmann::ordered_json::array();
  for (const BallState& b : s.balls)
    balls.push_back({{"name", b.name}, {"x", b.x}, {"y", b.y}, {"vx", b.vx}, {"vy", b.vy}, {"captured", b.captured}});
  nlohmann::ordered_json out{{"model", o.model},     {"precision", o.precision}, {"time", s.time},
                             {"events", events},     {"balls", balls},           {"energy", s.energy},
                             {"wall_seconds", wall}, {"warnings", boardWarnings}};
  std::cout << out.dump(2) << '\n';
}

}  // namespace

int runCommand(const RunOptions& o) {
  CheckedRun run;
  int code = kExitOk;
  if (!checkRun(o, "run", run, code)) return code;
  const RunRequest& request = run.request;
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  try {
    summary = withPrecision(run.precision, [&]<class Real>() { return simulate<Real>(request); });
  } catch (const StallError& e) {
    std::cerr << "gizmo run: the simulation stalled: " << e.what() << '\n';
    return kExitCheckFailed;
  } catch (const IrrationalValue& e) {
    std::cerr << "gizmo run: an exact run cannot go on: it needs " << e.what() << '\n';
    return kExitCheckFailed;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  printRunSummary(run.boardName, run.boardWarnings, o, summary, wall);
  return kExitOk;
}

void printRunSummary(const std::string& board, const std::vector<std::string>& boardWarnings, const RunOptions& o,
                     const RunSummary& s, double wall) {
  if (o.json) printJson(boardWarnings, o, s, wall);
  else printHuman(board, o, s, wall);
}

}  // namespace gizmo::cli
