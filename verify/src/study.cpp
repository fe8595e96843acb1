// The study's runs: each method on each scene, timed over repeats and compared with the scene's
// reference run (study_compare.hpp).
#include "gizmo/verify/study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

#include "gizmo/verify/box2d3_run.hpp"
#include "gizmo/verify/box2d_crosscheck.hpp"
#include "gizmo/verify/study_suite.hpp"
#include "study_compare.hpp"

namespace gizmo::verify {
namespace {

// An exact run is never part of the study: its budget is irrelevant.
constexpr std::size_t kNoExactBudget = std::numeric_limits<std::size_t>::max();
const PrecisionChoice kReferencePrecision{Precision::Mpfr, 256};

bool isReferencePrecision(const PrecisionChoice& p) { return precisionName(p) == precisionName(kReferencePrecision); }

std::string formatTick(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

// The scene's sampling instants, and the check that each is a tick boundary of every run.
std::vector<double> samplingInstants(const StudyScene& scene, const StudyPlan& plan) {
  std::vector<double> ticks = plan.classicTicks;
  ticks.push_back(plan.ballisticTick);
  for (double h : ticks) {
    const double k = scene.sampleEvery / h;
    if (std::fabs(k - std::round(k)) > 1e-6)
      throw StudyInputError("scene " + scene.name + ": SAMPLE_EVERY " + formatTick(scene.sampleEvery) +
                            " s is not a multiple of the maximum tick length " + formatTick(h) +
                            " s: the run could not be sampled at its tick boundaries");
  }
  std::vector<double> instants;
  for (std::int64_t k = 0;; ++k) {
    const double t = double(k) * scene.sampleEvery;
    if (t > scene.request.duration * (1 + 1e-12)) break;
    instants.push_back(t);
  }
  return instants;
}

Spread costSpread(const std::vector<double>& seconds, double per) {
  std::vector<double> scaled;
  for (double s : seconds) scaled.push_back(per > 0 ? s / per : 0);
  return Spread::of(scaled);
}

void setCost(MethodResult& r, const std::vector<double>& seconds, double boardSeconds) {
  r.wallSeconds = Spread::of(seconds);
  r.secondsPerBoardSecond = costSpread(seconds, boardSeconds);
  r.secondsPerEvent = costSpread(seconds, double(r.events));
}

void setErrors(MethodResult& r, const RunErrors& e, std::size_t referenceCollisions, std::size_t collisions) {
  r.positionError = e.positionError;
  r.positionErrorMedian = e.positionErrorMedian;
  r.divergedAt = e.divergedAt;
  r.referenceCollisions = referenceCollisions;
  r.collisions = collisions;
  r.matched = e.matched;
  r.eventTimeError = e.eventTimeError;
  r.meanEventTimeError = e.meanEventTimeError;
  r.firstWrongTime = e.firstWrongTime;
  r.firstWrong = e.firstWrong;
  r.energyDrift = e.energyDrift;
}

class SceneRunner {
 public:
  SceneRunner(const StudyScene& scene, const StudyPlan& plan, StudyProgress progress)
      : scene_(scene), plan_(plan), progress_(progress), instants_(samplingInstants(scene, plan)) {}

  std::vector<MethodResult> run() {
    // The ballistic model first: its mpfr:256 run is the reference of every method. Then the
    // classic model from its smallest tick up: that tick's mpfr:256 run is the classic model's
    // own finest run, which the coarser ticks converge to.
    runOurGroup(MotionModel::Ballistic, plan_.ballisticTick);
    std::vector<double> ticks = plan_.classicTicks;
    std::sort(ticks.begin(), ticks.end());
    for (double h : ticks) runOurGroup(MotionModel::Classic, h);
    for (double dt : plan_.box2dSteps)
      for (bool v3 : {false, true})
        for (bool bullet : {true, false}) runBox2dMethod(dt, bullet, v3);
    std::vector<MethodResult> ordered;
    for (const StudyMethod& m : plan_.methods()) ordered.push_back(results_.at(m.label()));
    return ordered;
  }

 private:
  // One model at one tick, at every precision: mpfr:256 first, whose trace the others' decisions
  // are compared with (the precision ladder's horizon).
  void runOurGroup(MotionModel model, double tick) {
    RunRequest request = scene_.request;
    request.model = model;
    request.maxTick = tick;
    const MethodFamily family = model == MotionModel::Ballistic ? MethodFamily::Ballistic : MethodFamily::Classic;
    Trace own;
    std::vector<TraceSample> ownSamples;
    {
      MethodResult& r = traceOurs(StudyMethod{family, kReferencePrecision, tick}, request, nullptr, &own, ownSamples);
      if (family == MethodFamily::Ballistic) reference_ = studyRunOf(own, ownSamples, scene_.request.board);
      if (family == MethodFamily::Classic && !classicFinest_) classicFinest_ = ownSamples;
      finish(r, studyRunOf(own, ownSamples, scene_.request.board), ownSamples);
      r.horizonEvents = own.size();  // the run every other precision of the group is compared with
      r.horizonTime = request.duration;
    }
    for (const PrecisionChoice& p : plan_.precisions) {
      if (isReferencePrecision(p)) continue;
      std::vector<TraceSample> samples;
      Trace trace;
      MethodResult& r = traceOurs(StudyMethod{family, p, tick}, request, &own, &trace, samples);
      finish(r, studyRunOf(trace, samples, scene_.request.board), samples);
    }
  }

  MethodResult& traceOurs(const StudyMethod& method, const RunRequest& request, const Trace* own, Trace* record,
                          std::vector<TraceSample>& samples) {
    if (progress_) progress_(scene_.name, method.label());
    MethodResult& r = results_[method.label()];
    r.scene = scene_.name;
    r.method = method;
    r.reference = method.family == MethodFamily::Ballistic && isReferencePrecision(method.precision);
    TraceExtras extras;
    extras.sampleAt = instants_;
    extras.samples = &samples;
    extras.stopAtDifference = false;
    const TracedRun traced = traceAt(method.precision, request, own, record, kNoExactBudget, extras);
    r.stopped = traced.stopped;
    r.events = traced.events;
    if (own != nullptr) {
      r.horizonEvents = traced.agreement.events;
      r.horizonTime = traced.agreement.time;
      r.horizonDifference = traced.agreement.difference;
    }
    std::vector<double> seconds;
    for (int k = 0; k < plan_.repeats; ++k) {
      std::uint64_t events = 0;
      seconds.push_back(timeAt(method.precision, request, std::numeric_limits<std::uint64_t>::max(), events));
      // A run is a function of its input: every repeat makes the same events as the traced run.
      if (events != r.events && r.stopped.empty())
        r.stopped = "not deterministic: a repeat made " + std::to_string(events) + " events, the traced run " +
                    std::to_string(r.events);
    }
    setCost(r, seconds, request.duration);
    return r;
  }

  void finish(MethodResult& r, const StudyRun& run, const std::vector<TraceSample>& samples) {
    setErrors(r, compareWithReference(reference_, run, scene_.request.duration, matchWindow(0)),
              reference_.collisions.size(), run.collisions.size());
    if (r.method.family == MethodFamily::Classic && classicFinest_)
      r.convergenceError = largestPositionDistance(*classicFinest_, samples);
  }

  // Box2D 2.4 in process, or v3 by the node program (a board it cannot run, or a machine without
  // node or the package, leaves the method stopped, saying why).
  void runBox2dMethod(double dt, bool bullet, bool v3) {
    const MethodFamily family = v3 ? (bullet ? MethodFamily::Box2dV3 : MethodFamily::Box2dV3NoBullet)
                                   : (bullet ? MethodFamily::Box2d : MethodFamily::Box2dNoBullet);
    const StudyMethod method{family, PrecisionChoice{}, dt};
    if (progress_) progress_(scene_.name, method.label());
    MethodResult& r = results_[method.label()];
    r.scene = scene_.name;
    r.method = method;
    Box2dOptions options;
    options.dt = dt;
    options.bullet = bullet;
    if (v3) {
      if (std::optional<std::string> why = box2d3CannotModel(scene_.request.board)) r.stopped = *why;
      else if (std::optional<std::string> missing = box2d3Unavailable()) r.stopped = "not run: " + *missing;
      // A v3 run is a node program stepped over a pipe, a request and a reply a step: at the
      // fine steps those dominate, and under the sanitizers the quick study took ten times its
      // old length. The quick plan runs v3 at its coarsest step with bullets, once (a node start
      // each); the full plan runs it all.
      if (r.stopped.empty() && plan_.quick && (dt != plan_.box2dSteps.front() || !bullet))
        r.stopped = "left out of the quick plan, which runs Box2D v3 at its coarsest step with bullets only";
      if (!r.stopped.empty()) return;
    }
    std::vector<double> seconds;
    RunRecord first;
    const int repeats = v3 && plan_.quick ? 1 : plan_.repeats;
    try {
      for (int k = 0; k < repeats; ++k) {
        RunRecord record = v3 ? runBox2d3(scene_.request, options).run.record : runBox2d(scene_.request, options);
        seconds.push_back(record.wallSeconds);
        if (k == 0) first = std::move(record);
        else if (record.collisions.size() != first.collisions.size() && r.stopped.empty())
          r.stopped = "not deterministic: the repeats made different numbers of collisions";
      }
    } catch (const std::exception& e) {
      r.stopped = std::string("the Box2D run failed: ") + e.what();
      return;
    }
    r.events = first.steps;
    setCost(r, seconds, scene_.request.duration);
    const StudyRun run = studyRunOf(first, instants_, scene_.request.board.balls.size());
    setErrors(r, compareWithReference(reference_, run, scene_.request.duration, matchWindow(dt)),
              reference_.collisions.size(), run.collisions.size());
  }

  const StudyScene& scene_;
  const StudyPlan& plan_;
  StudyProgress progress_;
  std::vector<double> instants_;
  StudyRun reference_;
  std::optional<std::vector<TraceSample>> classicFinest_;
  std::map<std::string, MethodResult> results_;
};

}  // namespace

const char* familyName(MethodFamily family) {
  switch (family) {
    case MethodFamily::Ballistic: return "ballistic";
    case MethodFamily::Classic: return "classic";
    case MethodFamily::Box2d: return "box2d";
    case MethodFamily::Box2dNoBullet: return "box2d-no-bullet";
    case MethodFamily::Box2dV3: return "box2d-v3";
    case MethodFamily::Box2dV3NoBullet: return "box2d-v3-no-bullet";
  }
  return "?";
}

bool isBox2dFamily(MethodFamily family) {
  return family == MethodFamily::Box2d || family == MethodFamily::Box2dNoBullet || isBox2dV3Family(family);
}

bool isBox2dV3Family(MethodFamily family) {
  return family == MethodFamily::Box2dV3 || family == MethodFamily::Box2dV3NoBullet;
}

std::string StudyMethod::label() const {
  switch (family) {
    case MethodFamily::Ballistic: return "ballistic " + precisionName(precision);
    case MethodFamily::Classic: return "classic h=" + formatTick(tick) + " " + precisionName(precision);
    case MethodFamily::Box2d:
    case MethodFamily::Box2dNoBullet:
    case MethodFamily::Box2dV3:
    case MethodFamily::Box2dV3NoBullet: {
      // Step sizes are 1/N of a second: say so, as Box2D's users do.
      const double n = 1 / tick;
      const std::string step =
          std::fabs(n - std::round(n)) < 1e-9 ? "1/" + formatTick(std::round(n)) : formatTick(tick);
      return std::string(familyName(family)) + " dt=" + step;
    }
  }
  return "?";
}

StudyPlan StudyPlan::full() {
  StudyPlan p;
  for (const char* name : {"float", "double", "long-double", "float128", "bin50", "bin100", "mpfr:256"})
    p.precisions.push_back(*parsePrecision(name));
  p.classicTicks = {0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 0.0005};
  p.box2dSteps = {1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480, 1.0 / 960, 1.0 / 1920};
  p.repeats = 5;
  return p;
}

StudyPlan StudyPlan::quickPlan() {
  StudyPlan p;
  for (const char* name : {"float", "double", "long-double", "mpfr:256"}) p.precisions.push_back(*parsePrecision(name));
  p.classicTicks = {0.05, 0.005, 0.0005};
  p.box2dSteps = {1.0 / 60, 1.0 / 240, 1.0 / 960};
  p.repeats = 3;
  p.quick = true;
  return p;
}

std::vector<StudyMethod> StudyPlan::methods() const {
  std::vector<StudyMethod> out;
  for (const PrecisionChoice& p : precisions) out.push_back(StudyMethod{MethodFamily::Ballistic, p, ballisticTick});
  for (double h : classicTicks)
    for (const PrecisionChoice& p : precisions) out.push_back(StudyMethod{MethodFamily::Classic, p, h});
  for (double dt : box2dSteps)
    for (MethodFamily f :
         {MethodFamily::Box2d, MethodFamily::Box2dNoBullet, MethodFamily::Box2dV3, MethodFamily::Box2dV3NoBullet})
      out.push_back(StudyMethod{f, PrecisionChoice{}, dt});
  return out;
}

Spread Spread::of(std::vector<double> values) {
  Spread s;
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  s.min = values.front();
  s.max = values.back();
  s.median = n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
  return s;
}

bool MethodResult::failed() const {
  return !stopped.empty() || positionError > kFailDistance || firstWrongTime.has_value();
}

void checkStudy(const std::vector<StudyScene>& scenes, const StudyPlan& plan) {
  if (std::none_of(plan.precisions.begin(), plan.precisions.end(), isReferencePrecision))
    throw StudyInputError("the study's precisions must include mpfr:256, the reference");
  for (const StudyScene& s : scenes) samplingInstants(s, plan);
}

StudyReport runStudy(const std::vector<StudyScene>& scenes, const StudyPlan& plan, StudyProgress progress) {
  checkStudy(scenes, plan);
  StudyReport report;
  report.plan = plan;
  report.box2dVersion = box2dVersion();
  for (const StudyScene& s : scenes) report.scenes.push_back(SceneReport{s, SceneRunner(s, plan, progress).run()});
  return report;
}

}  // namespace gizmo::verify
