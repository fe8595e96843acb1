// The study's data as CSV (one row per scene and method) and JSON (everything, with the findings).
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gizmo/verify/study_findings.hpp"
#include "gizmo/verify/study_output.hpp"

namespace gizmo::verify {
namespace {

std::string number(double v) { return studyNumber(v); }
std::string optionalNumber(const std::optional<double>& v) { return v ? number(*v) : ""; }

std::string field(const std::string& text) { return studyCsvField(text); }

nlohmann::ordered_json spread(const Spread& s) { return {{"median", s.median}, {"min", s.min}, {"max", s.max}}; }

template <class T>
nlohmann::ordered_json optionalJson(const std::optional<T>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

bool onFront(const std::vector<ChartPoint>& front, std::size_t index) {
  for (const ChartPoint& p : front)
    if (p.result == index) return true;
  return false;
}

}  // namespace

std::string studyCsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string studyCsv(const StudyReport& report) {
  std::ostringstream out;
  out << "scene,stress,method,family,precision,tick,reference,stopped,failed,events,wall_seconds_median,"
         "wall_seconds_min,wall_seconds_max,seconds_per_board_second,seconds_per_event,position_error,"
         "position_error_median,diverged_at,collisions,reference_collisions,matched,event_time_error,"
         "mean_event_time_error,first_wrong_time,energy_drift,horizon_events,horizon_time,convergence_error,pareto\n";
  for (const SceneReport& s : report.scenes) {
    const std::vector<ChartPoint> front = paretoFront(chartPoints(s));
    for (std::size_t i = 0; i < s.results.size(); ++i) {
      const MethodResult& r = s.results[i];
      const bool box2d = isBox2dFamily(r.method.family);
      out << field(s.scene.name) << ',' << (s.scene.stress ? 1 : 0) << ',' << field(r.method.label()) << ','
          << familyName(r.method.family) << ',' << (box2d ? "" : precisionName(r.method.precision)) << ','
          << number(r.method.tick) << ',' << (r.reference ? 1 : 0) << ',' << field(r.stopped) << ','
          << (r.failed() ? 1 : 0) << ',' << r.events << ',' << number(r.wallSeconds.median) << ','
          << number(r.wallSeconds.min) << ',' << number(r.wallSeconds.max) << ','
          << number(r.secondsPerBoardSecond.median) << ',' << number(r.secondsPerEvent.median) << ','
          << number(r.positionError) << ',' << number(r.positionErrorMedian) << ',' << optionalNumber(r.divergedAt)
          << ',' << r.collisions << ',' << r.referenceCollisions << ',' << r.matched << ',' << number(r.eventTimeError)
          << ',' << number(r.meanEventTimeError) << ',' << optionalNumber(r.firstWrongTime) << ','
          << number(r.energyDrift) << ',' << (r.horizonEvents ? std::to_string(*r.horizonEvents) : "") << ','
          << optionalNumber(r.horizonTime) << ',' << optionalNumber(r.convergenceError) << ','
          << (onFront(front, i) ? 1 : 0) << '\n';
    }
  }
  return out.str();
}

std::string studyJson(const StudyReport& report) {
  const StudyPlan& p = report.plan;
  nlohmann::ordered_json precisions = nlohmann::ordered_json::array();
  for (const PrecisionChoice& c : p.precisions) precisions.push_back(precisionName(c));
  nlohmann::ordered_json scenes = nlohmann::ordered_json::array();
  nlohmann::ordered_json box2d = nlohmann::ordered_json::array();
  for (const SceneReport& s : report.scenes) {
    const std::vector<ChartPoint> front = paretoFront(chartPoints(s));
    nlohmann::ordered_json results = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < s.results.size(); ++i) {
      const MethodResult& r = s.results[i];
      results.push_back({{"method", r.method.label()},
                         {"family", familyName(r.method.family)},
                         {"precision", precisionName(r.method.precision)},
                         {"tick", r.method.tick},
                         {"reference", r.reference},
                         {"stopped", r.stopped},
                         {"failed", r.failed()},
                         {"events", r.events},
                         {"wall_seconds", spread(r.wallSeconds)},
                         {"seconds_per_board_second", spread(r.secondsPerBoardSecond)},
                         {"seconds_per_event", spread(r.secondsPerEvent)},
                         {"position_error", r.positionError},
                         {"position_error_median", r.positionErrorMedian},
                         {"diverged_at", optionalJson(r.divergedAt)},
                         {"collisions", r.collisions},
                         {"reference_collisions", r.referenceCollisions},
                         {"matched", r.matched},
                         {"event_time_error", r.eventTimeError},
                         {"mean_event_time_error", r.meanEventTimeError},
                         {"first_wrong_time", optionalJson(r.firstWrongTime)},
                         {"first_wrong", r.firstWrong},
                         {"energy_drift", r.energyDrift},
                         {"horizon_events", optionalJson(r.horizonEvents)},
                         {"horizon_time", optionalJson(r.horizonTime)},
                         {"horizon_difference", r.horizonDifference},
                         {"convergence_error", optionalJson(r.convergenceError)},
                         {"pareto", onFront(front, i)}});
    }
    nlohmann::ordered_json fails = nlohmann::ordered_json::object();
    if (s.scene.stress)
      for (MethodFamily f : {MethodFamily::Ballistic, MethodFamily::Classic, MethodFamily::Box2d,
                             MethodFamily::Box2dNoBullet, MethodFamily::Box2dV3, MethodFamily::Box2dV3NoBullet})
        fails[familyName(f)] = failsFrom(s, f);
    scenes.push_back({{"name", s.scene.name},
                      {"board", s.scene.board},
                      {"note", s.scene.note},
                      {"stress", s.scene.stress},
                      {"duration", s.scene.request.duration},
                      {"sample_every", s.scene.sampleEvery},
                      {"fails", fails},
                      {"results", results}});
    if (const auto c = compareBallisticDoubleWithBox2d(s))
      box2d.push_back({{"scene", c->scene},
                       {"ours_cost", c->oursCost},
                       {"ours_error", c->oursError},
                       {"speedup_at_equal_error", c->speedupAtEqualError},
                       {"speedup_is_bound", c->speedupIsBound},
                       {"accuracy_gain_at_equal_cost", c->accuracyGainAtEqualCost},
                       {"accuracy_gain_is_bound", c->accuracyGainIsBound}});
  }
  nlohmann::ordered_json out{{"reference", "ballistic mpfr:256"},
                             {"fail_distance", kFailDistance},
                             {"box2d_version", report.box2dVersion},
                             {"plan",
                              {{"quick", p.quick},
                               {"precisions", precisions},
                               {"classic_ticks", p.classicTicks},
                               {"ballistic_tick", p.ballisticTick},
                               {"box2d_steps", p.box2dSteps},
                               {"repeats", p.repeats}}},
                             {"scenes", scenes},
                             {"ballistic_double_against_box2d", box2d}};
  return out.dump(2) + "\n";
}

}  // namespace gizmo::verify
