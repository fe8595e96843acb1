#include "crosscheck_command.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "board_input.hpp"
#include "gizmo/verify/box2d3_run.hpp"
#include "gizmo/verify/box2d_crosscheck.hpp"
#include "gizmo/verify/box2d_mapping.hpp"
#include "gizmo/verify/box2d_time_of_impact.hpp"
#include "gizmo/verify/engine_trace.hpp"
#include "render_output.hpp"
#include "render_path_file.hpp"

namespace gizmo::cli {
namespace {

constexpr double kMinStep = 1e-5, kMaxStep = 0.1;

// A whole number text as a double, or nullopt (no trailing characters, finite).
std::optional<double> parseNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

// "0.01" or "1/60".
std::optional<double> parseStep(const std::string& text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return parseNumber(text);
  const std::optional<double> a = parseNumber(text.substr(0, slash)), b = parseNumber(text.substr(slash + 1));
  if (!a || !b || *b == 0) return std::nullopt;
  return *a / *b;
}

bool parseSteps(const std::string& list, double duration, std::vector<double>& out) {
  std::stringstream in(list);
  std::string item;
  double total = 0;
  while (std::getline(in, item, ',')) {
    const std::optional<double> dt = parseStepSize(item);
    if (!dt) {
      std::cerr << "gizmo crosscheck: --dt '" << item << "' is not a step size from 1e-5 to 0.1 s (a number or 1/N)\n";
      return false;
    }
    for (double d : out) {
      if (d == *dt) {
        std::cerr << "gizmo crosscheck: step size '" << item << "' is listed twice\n";
        return false;
      }
    }
    out.push_back(*dt);
    total += duration / *dt;
  }
  if (out.empty()) {
    std::cerr << "gizmo crosscheck: --dt lists no step size\n";
    return false;
  }
  if (total > kMaxBox2dSteps) {
    std::cerr << "gizmo crosscheck: --time and --dt ask for more than 1e7 Box2D steps\n";
    return false;
  }
  return true;
}

nlohmann::ordered_json optionalTime(const std::optional<double>& t) { return t ? nlohmann::ordered_json(*t) : nullptr; }

std::string levelName(double level) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", level);
  return buf;
}

nlohmann::ordered_json mappingJson() {
  using namespace verify;
  return {{"polygon_skin", kBox2dPolygonSkin},
          {"linear_slop", kBox2dLinearSlop},
          {"toi_target_depth", 3 * kBox2dLinearSlop},
          {"toi_tolerance", kBox2dToiTolerance},
          {"max_translation_per_step", kBox2dMaxTranslation},
          {"max_rotation_per_step", kBox2dMaxRotation}};
}

nlohmann::ordered_json pointJson(const Vec2<double>& p) { return nlohmann::ordered_json::array({p.x, p.y}); }

nlohmann::ordered_json partingJson(const std::optional<verify::PartingCheck>& parting) {
  if (!parting) return nullptr;
  nlohmann::ordered_json balls = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < parting->ours.size(); ++i)
    balls.push_back({{"ours", pointJson(parting->ours[i])},
                     {"engine", pointJson(parting->theirs[i])},
                     {"mpfr256", pointJson(parting->reference[i])}});
  return {{"time", parting->time},
          {"ours_off", parting->oursOff},
          {"engine_off", parting->theirsOff},
          {"mpfr256_agrees_with", parting->agreesWith == "ours" ? "us" : "engine"},
          {"balls", balls}};
}

// What the other side is, for the report: Box2D 2.4 run here, or a trace read from a file.
struct EngineSide {
  nlohmann::ordered_json json;  // its keys, merged into the report's object
  std::string text;             // its line of the text report
};

EngineSide box2dSide(const verify::CrosscheckOptions& options) {
  EngineSide side;
  side.json = {{"engine", "box2d-2.4"},
               {"box2d_version", verify::box2dVersion()},
               {"bullet", options.box2d.bullet},
               {"continuous", options.box2d.continuous},
               {"restitution_threshold", options.box2d.restitutionThreshold},
               {"velocity_iterations", options.box2d.velocityIterations},
               {"position_iterations", options.box2d.positionIterations},
               {"mapping", mappingJson()}};
  char text[512];
  std::snprintf(
      text, sizeof text,
      "box2d      %s, bullets %s, continuous %s, restitution threshold %g m/s, %d velocity / %d position iterations\n"
      "mapping    polygons inset by the %g L skin; Box2D's time of impact stops %g L past contact (+- %g);\n"
      "           at most %g L and %g rad per step\n",
      verify::box2dVersion().c_str(), options.box2d.bullet ? "on" : "off", options.box2d.continuous ? "on" : "off",
      options.box2d.restitutionThreshold, options.box2d.velocityIterations, options.box2d.positionIterations,
      verify::kBox2dPolygonSkin, 3 * verify::kBox2dLinearSlop, verify::kBox2dToiTolerance, verify::kBox2dMaxTranslation,
      verify::kBox2dMaxRotation);
  side.text = text;
  return side;
}

EngineSide box2d3Side(const verify::Box2dOptions& options, const std::string& name) {
  EngineSide side;
  side.json = {{"engine", "box2d-v3"},
               {"box2d_version", name},
               {"bullet", options.bullet},
               {"continuous", options.continuous},
               {"restitution_threshold", options.restitutionThreshold},
               {"sub_steps", verify::kBox2d3SubSteps},
               {"mapping", mappingJson()}};
  char text[512];
  std::snprintf(
      text, sizeof text,
      "box2d v3   %s under node, bullets %s, continuous %s, restitution threshold %g m/s, %d sub-steps\n"
      "mapping    the same bodies and shapes as Box2D 2.4's (polygons inset by the %g L skin, rounded by it)\n",
      name.c_str(), options.bullet ? "on" : "off", options.continuous ? "on" : "off", options.restitutionThreshold,
      verify::kBox2d3SubSteps, verify::kBox2dPolygonSkin);
  side.text = text;
  return side;
}

EngineSide traceSide(const std::string& path, const verify::EngineTrace& trace) {
  EngineSide side;
  side.json = {{"engine", "trace"},
               {"trace", path},
               {"trace_engine", trace.engine},
               {"contacts_reported", trace.run.withCollisions}};
  side.text = "engine     " + trace.engine + ", from the trace " + path + " (" +
              (trace.run.withCollisions ? "contacts reported" : "no contacts reported: paths only") + ")\n";
  return side;
}

void printRunsJson(const CheckedRun& run, const CrosscheckCommandOptions& o, const EngineSide& engine,
                   const verify::CrosscheckReport& r) {
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (const verify::StepComparison& s : r.steps) {
    nlohmann::ordered_json above = nlohmann::ordered_json::object();
    for (std::size_t l = 0; l < verify::kDivergenceLevels.size(); ++l)
      above[levelName(verify::kDivergenceLevels[l])] = optionalTime(s.divergenceFrom[l]);
    nlohmann::ordered_json first = nullptr;
    if (s.firstUnmatched) {
      const verify::CollisionRecord& c = s.firstUnmatched->collision;
      first = {{"missed_by", s.firstUnmatched->side == "ours" ? "engine" : "us"},
               {"time", c.time},
               {"ball", c.ball},
               {"other", c.other},
               {"x", c.position.x},
               {"y", c.position.y}};
    }
    nlohmann::ordered_json series = nlohmann::ordered_json::array();
    for (const auto& [t, d] : s.divergence) series.push_back({t, d});
    steps.push_back({{"dt", s.dt},
                     {"match_window", s.matchWindow},
                     {"steps", s.steps},
                     {"collisions_compared", s.collisionsCompared},
                     {"collisions", s.theirCollisions},
                     {"matched", s.matched},
                     {"missed_by_engine", s.missedByThem},
                     {"missed_by_us", s.missedByUs},
                     {"max_time_error", s.maxTimeError},
                     {"mean_time_error", s.meanTimeError},
                     {"max_position_error", s.maxPositionError},
                     {"matched_within_toi", s.matchedWithinToi},
                     {"first_unmatched", first},
                     {"speed_capped_steps", s.speedCappedSteps},
                     {"rotation_capped_steps", s.rotationCappedSteps},
                     {"max_divergence", s.maxDivergence},
                     {"divergence_above", above},
                     {"parting", partingJson(s.parting)},
                     {"divergence", series},
                     {"energy_end", s.energyEnd},
                     {"max_energy_difference", s.maxEnergyDifference},
                     {"wall_seconds", s.wallSeconds}});
  }
  nlohmann::ordered_json out{{"board", run.boardName},
                             {"warnings", run.boardWarnings},
                             {"model", o.run.model},
                             {"time", o.run.time},
                             {"max_tick", o.run.maxTick}};
  out.update(engine.json);
  out["ours"] = {{"collisions", r.ourCollisions},
                 {"events", r.ourEvents},
                 {"wall_seconds", r.ourWallSeconds},
                 {"energy_start", r.energyStart},
                 {"energy_end", r.ourEnergyEnd}};
  out["steps"] = steps;
  if (!o.pathOut.empty()) out["path_out"] = o.pathOut;
  if (!o.traceOut.empty()) out["trace_out"] = o.traceOut;
  std::cout << out.dump(2) << '\n';
}

void printRunsText(const CheckedRun& run, const CrosscheckCommandOptions& o, const EngineSide& engine,
                   const verify::CrosscheckReport& r) {
  std::printf("board      %s\n", run.boardName.c_str());
  std::printf("ours       %s, double, %.6g s: %zu collisions, %llu events, %.4f s wall, energy %.6g -> %.6g\n",
              o.run.model.c_str(), o.run.time, r.ourCollisions, static_cast<unsigned long long>(r.ourEvents),
              r.ourWallSeconds, r.energyStart, r.ourEnergyEnd);
  std::fputs(engine.text.c_str(), stdout);
  if (!o.pathOut.empty())
    std::printf("path       %s: Box2D's ball centres after every step (gizmo render LOG -o run.html --compare %s)\n",
                o.pathOut.c_str(), o.pathOut.c_str());
  if (!o.traceOut.empty())
    std::printf("trace out  %s: the v3 program's own run, as a trace (gizmo crosscheck BOARD --trace %s)\n",
                o.traceOut.c_str(), o.traceOut.c_str());
  std::printf("\n%-10s %7s %6s %7s %8s %8s %10s %10s %9s %6s %7s %9s %9s %9s %8s\n", "dt", "steps", "engine", "matched",
              "missed", "missed", "max dt", "mean dt", "max dpos", "in-toi", "capped", "div>0.1", "max div", "dE/E",
              "wall s");
  std::printf("%-10s %7s %6s %7s %8s %8s\n", "", "", "hits", "", "by engine", "by us");
  for (const verify::StepComparison& s : r.steps) {
    char dt[32], diverged[32];
    std::snprintf(dt, sizeof dt, "%.6g", s.dt);
    if (s.divergenceFrom[1]) std::snprintf(diverged, sizeof diverged, "%.4g s", *s.divergenceFrom[1]);
    else std::snprintf(diverged, sizeof diverged, "never");
    if (s.collisionsCompared)
      std::printf("%-10s %7llu %6zu %7zu %8zu %8zu %10.3g %10.3g %9.3g %6zu %7llu %9s %9.3g %9.3g %8.4f\n", dt,
                  static_cast<unsigned long long>(s.steps), s.theirCollisions, s.matched, s.missedByThem, s.missedByUs,
                  s.maxTimeError, s.meanTimeError, s.maxPositionError, s.matchedWithinToi,
                  static_cast<unsigned long long>(s.speedCappedSteps + s.rotationCappedSteps), diverged,
                  s.maxDivergence, s.maxEnergyDifference, s.wallSeconds);
    else
      std::printf("%-10s %7llu %6s %7s %8s %8s %10s %10s %9s %6s %7llu %9s %9.3g %9.3g %8.4f\n", dt,
                  static_cast<unsigned long long>(s.steps), "-", "-", "-", "-", "-", "-", "-", "-",
                  static_cast<unsigned long long>(s.speedCappedSteps + s.rotationCappedSteps), diverged,
                  s.maxDivergence, s.maxEnergyDifference, s.wallSeconds);
    if (s.firstUnmatched) {
      const verify::CollisionRecord& c = s.firstUnmatched->collision;
      std::printf("  first unmatched: %s hit of %s on %s at t = %.6g s, (%.4f, %.4f)\n",
                  s.firstUnmatched->side == "ours" ? "our" : "the engine's", c.ball.c_str(), c.other.c_str(), c.time,
                  c.position.x, c.position.y);
    }
    if (s.parting)
      std::printf("  paths part at t = %.6g s: mpfr:256 agrees with %s (ours %.3g L off, the engine's %.3g L)\n",
                  s.parting->time, s.parting->agreesWith == "ours" ? "us" : "the engine", s.parting->oursOff,
                  s.parting->theirsOff);
  }
}

int toiSurveyCommand(const CrosscheckCommandOptions& o) {
  const std::vector<verify::SweepKindSurvey> survey = verify::surveySweeps(o.seed, o.toiSweeps);
  if (o.run.json) {
    nlohmann::ordered_json kinds = nlohmann::ordered_json::array();
    for (const verify::SweepKindSurvey& k : survey)
      kinds.push_back({{"kind", std::string(verify::sweepKindName(k.kind))},
                       {"sweeps", k.sweeps},
                       {"ours_hits", k.oursHits},
                       {"box2d_hits", k.box2dHits},
                       {"max_difference", k.maxDifference},
                       {"min_depth", k.minDepth},
                       {"max_depth", k.maxDepth},
                       {"findings", k.findingCount},
                       {"finding_examples", k.findings}});
    nlohmann::ordered_json out{{"seed", o.seed},
                               {"sweeps_per_kind", o.toiSweeps},
                               {"box2d_version", verify::box2dVersion()},
                               {"mapping", mappingJson()},
                               {"kinds", kinds}};
    std::cout << out.dump(2) << '\n';
    return kExitOk;
  }
  std::printf("seed %llu, %d straight sweeps per kind: our time of impact against b2TimeOfImpact (Box2D %s)\n",
              static_cast<unsigned long long>(o.seed), o.toiSweeps, verify::box2dVersion().c_str());
  std::printf("Box2D stops when the cores are within target +- tolerance: %g L past contact +- %g L\n\n",
              3 * verify::kBox2dLinearSlop, verify::kBox2dToiTolerance);
  std::printf("%-20s %7s %9s %10s %12s %22s %9s\n", "kind", "sweeps", "our hits", "box2d hits", "max |dt| s",
              "depth min..max L", "findings");
  for (const verify::SweepKindSurvey& k : survey)
    std::printf("%-20s %7d %9d %10d %12.3g %10.5f..%-10.5f %9d\n", std::string(verify::sweepKindName(k.kind)).c_str(),
                k.sweeps, k.oursHits, k.box2dHits, k.maxDifference, k.minDepth, k.maxDepth, k.findingCount);
  for (const verify::SweepKindSurvey& k : survey)
    for (const std::string& f : k.findings) std::printf("finding: %s\n", f.c_str());
  return kExitOk;
}

// Box2D's run at the one step size asked for, as a path file (render_path_file.hpp), written
// whole before the report is printed, so that a failed write leaves neither.
bool writePath(const CheckedRun& run, const CrosscheckCommandOptions& o, const verify::CrosscheckOptions& options,
               const verify::CrosscheckReport& report) {
  verify::Box2dOptions box2d = options.box2d;
  box2d.dt = report.steps.front().dt;
  // Only the board's file name: the path file may travel to another machine.
  const std::string boardName = std::filesystem::path(run.boardName).filename().string();
  const PathFile file = box2dPathFile(run.request, boardName, box2d, report.steps.front().box2dSamples);
  try {
    writeFileWhole(o.pathOut, pathFileText(file));
  } catch (const std::exception& e) {
    std::cerr << "gizmo crosscheck: " << e.what() << '\n';
    return false;
  }
  return true;
}

// --engine box2d-v3: the scene run by the node program at each step size, stepped by the driver
// and compared as a trace is; with --trace-out (one step size), the program also writes its run
// as a trace, whole before the report is printed.
int box2d3Command(const CheckedRun& run, const CrosscheckCommandOptions& o, const verify::CrosscheckOptions& options) {
  if (const std::optional<std::string> why = verify::box2d3CannotModel(run.request.board)) {
    std::cerr << "gizmo crosscheck: " << *why << '\n';
    return kExitBadInput;
  }
  if (const std::optional<std::string> why = verify::box2d3Unavailable()) {
    std::cerr << "gizmo crosscheck: --engine box2d-v3: " << *why << '\n';
    return kExitBadInput;
  }
  double longestWindow = 0;
  for (double dt : options.steps) longestWindow = std::max(longestWindow, verify::matchWindow(dt));
  RunRequest longer = run.request;
  longer.duration += longestWindow;
  std::vector<verify::EngineRun> runs;
  std::string name;
  try {
    for (double dt : options.steps) {
      verify::Box2dOptions b = options.box2d;
      b.dt = dt;
      verify::EngineTrace trace = verify::runBox2d3(longer, b, o.traceOut);
      trace.run.dt = dt;
      name = trace.engine;
      runs.push_back(std::move(trace.run));
    }
  } catch (const std::runtime_error& e) {
    std::cerr << "gizmo crosscheck: " << e.what() << '\n';
    return kExitBadInput;
  }
  const verify::CrosscheckReport report = verify::crosscheckRuns(run.request, runs);
  const EngineSide engine = box2d3Side(options.box2d, name);
  if (o.run.json) printRunsJson(run, o, engine, report);
  else printRunsText(run, o, engine, report);
  return kExitOk;
}

// --trace FILE: another engine's run, read whole before anything is printed, and compared as
// Box2D's runs are.
int traceCommand(const CrosscheckCommandOptions& o) {
  if (!o.box2dOptionGiven.empty()) {
    std::cerr << "gizmo crosscheck: " << o.box2dOptionGiven << " sets up a Box2D run, not the reading of --trace\n";
    return kExitBadInput;
  }
  CheckedRun run;
  int code = kExitOk;
  if (!checkRun(o.run, "crosscheck", run, code)) return code;
  std::optional<verify::EngineTrace> trace;
  try {
    trace = verify::readEngineTraceFile(o.trace, run.request.board, run.request.duration);
  } catch (const verify::EngineTraceError& e) {
    std::cerr << "gizmo crosscheck: " << e.what() << '\n';
    return kExitBadInput;
  }
  const verify::CrosscheckReport report = verify::crosscheckRuns(run.request, {trace->run});
  const EngineSide engine = traceSide(o.trace, *trace);
  if (o.run.json) printRunsJson(run, o, engine, report);
  else printRunsText(run, o, engine, report);
  return kExitOk;
}

}  // namespace

std::optional<double> parseStepSize(const std::string& text) {
  const std::optional<double> dt = parseStep(text);
  if (!dt || !(*dt >= kMinStep && *dt <= kMaxStep)) return std::nullopt;
  return dt;
}

int crosscheckCommand(const CrosscheckCommandOptions& o) {
  if (!(o.restitutionThreshold >= 0 && o.restitutionThreshold <= 1000)) {
    std::cerr << "gizmo crosscheck: --restitution-threshold must be from 0 to 1000 m/s\n";
    return kExitBadInput;
  }
  if (o.toiSweeps < 0 || o.toiSweeps > 1000000) {
    std::cerr << "gizmo crosscheck: --toi-sweeps must be from 0 to 1000000\n";
    return kExitBadInput;
  }
  if (o.toiSweeps > 0 && !o.pathOut.empty()) {
    std::cerr << "gizmo crosscheck: --path-out writes the path of a whole run, not of --toi-sweeps\n";
    return kExitBadInput;
  }
  if (o.engine != "box2d-2.4" && o.engine != "box2d-v3") {
    std::cerr << "gizmo crosscheck: --engine '" << o.engine << "' is not box2d-2.4 or box2d-v3\n";
    return kExitBadInput;
  }
  if (o.engine == "box2d-v3" && o.toiSweeps > 0) {
    std::cerr << "gizmo crosscheck: --toi-sweeps compares b2TimeOfImpact, which Box2D 2.4 has and box2d3-wasm does not "
                 "expose: use --engine box2d-2.4\n";
    return kExitBadInput;
  }
  if (o.engine == "box2d-v3" && !o.pathOut.empty()) {
    std::cerr << "gizmo crosscheck: --path-out writes Box2D 2.4's path: use --engine box2d-2.4\n";
    return kExitBadInput;
  }
  if (!o.traceOut.empty() && !o.trace.empty()) {
    std::cerr
        << "gizmo crosscheck: --trace-out writes Box2D v3's run as a trace and --trace reads one: give one of them\n";
    return kExitBadInput;
  }
  if (!o.traceOut.empty() && o.engine != "box2d-v3") {
    std::cerr << "gizmo crosscheck: --trace-out is written by the Box2D v3 program: use --engine box2d-v3\n";
    return kExitBadInput;
  }
  if (o.toiSweeps > 0) return toiSurveyCommand(o);
  if (!o.trace.empty()) return traceCommand(o);
  CheckedRun run;
  int code = kExitOk;
  if (!checkRun(o.run, "crosscheck", run, code)) return code;
  if (const std::optional<std::string> why = verify::box2dCannotModel(run.request.board)) {
    std::cerr << "gizmo crosscheck: " << *why << '\n';
    return kExitBadInput;
  }
  verify::CrosscheckOptions options;
  options.request = run.request;
  options.steps.clear();
  if (!parseSteps(o.steps, o.run.time, options.steps)) return kExitBadInput;
  options.box2d.bullet = !o.noBullet;
  options.box2d.continuous = !o.noContinuous;
  options.box2d.restitutionThreshold = o.restitutionThreshold;
  if (!o.traceOut.empty() && options.steps.size() != 1) {
    std::cerr
        << "gizmo crosscheck: --trace-out writes the run of one step size: give --dt one (for example --dt 1/240)\n";
    return kExitBadInput;
  }
  if (o.engine == "box2d-v3") return box2d3Command(run, o, options);
  if (!o.pathOut.empty() && options.steps.size() != 1) {
    std::cerr
        << "gizmo crosscheck: --path-out writes the path of one step size: give --dt one (for example --dt 1/240)\n";
    return kExitBadInput;
  }
  options.keepBox2dSamples = !o.pathOut.empty();
  const verify::CrosscheckReport report = verify::crosscheck(options);
  if (!o.pathOut.empty() && !writePath(run, o, options, report)) return kExitBadInput;
  const EngineSide engine = box2dSide(options);
  if (o.run.json) printRunsJson(run, o, engine, report);
  else printRunsText(run, o, engine, report);
  return kExitOk;
}

}  // namespace gizmo::cli
