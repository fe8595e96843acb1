#pragma once
// The speed/accuracy study (docs/verification.md, "The speed/accuracy study"): every method —
// the classic model at several maximum tick lengths and the ballistic model, each at every rung
// of the precision ladder, and Box2D at several step sizes with and without bullets — run on
// every scene of a suite, its cost measured over repeats and its errors against one reference
// run per scene.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gizmo/core/math/precision.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/study_bench.hpp"

namespace gizmo::verify {

// One scene of the suite (study_suite.hpp reads them).
struct StudyScene {
  std::string name;
  std::string board;       // the board file as the manifest names it
  RunRequest request;      // its duration is the scene's (the model is set per method)
  double sampleEvery = 0;  // ball positions are compared every this many seconds, from 0
  bool stress = false;     // a scene where methods are known to struggle: in the stability map
  std::string note;        // what the scene is for, in a few words
};

// Box2d: Box2D 2.4, linked in; Box2dV3: Box2D v3, run by the node program (box2d3_run.hpp).
enum class MethodFamily { Ballistic, Classic, Box2d, Box2dNoBullet, Box2dV3, Box2dV3NoBullet };
const char* familyName(MethodFamily family);
bool isBox2dFamily(MethodFamily family);  // either engine, bullets or not
bool isBox2dV3Family(MethodFamily family);

// One way to simulate a scene.
struct StudyMethod {
  MethodFamily family = MethodFamily::Ballistic;
  PrecisionChoice precision;  // ours only
  double tick = 0.05;         // the maximum tick length (ours), or the step size (Box2D)
  std::string label() const;  // e.g. "classic h=0.005 double", "box2d-no-bullet dt=1/240", "box2d-v3 dt=1/60"
};

// What a study runs: the methods, and how often each run is timed.
struct StudyPlan {
  std::vector<PrecisionChoice> precisions;  // must include mpfr:256, the reference
  std::vector<double> classicTicks;         // decreasing; the last is the convergence reference's
  double ballisticTick = 0.05;              // only places end-of-tick events in the ballistic model
  std::vector<double> box2dSteps;           // decreasing
  int repeats = 3;
  bool quick = false;  // scenes run for their quick duration
  static StudyPlan full();
  static StudyPlan quickPlan();  // finishes in a couple of minutes on two cores
  std::vector<StudyMethod> methods() const;
};

// A value measured over repeats.
struct Spread {
  double median = 0, min = 0, max = 0;
  static Spread of(std::vector<double> values);
};

// One method on one scene. Errors are against the scene's reference run (the ballistic model at
// mpfr:256); a simulation is deterministic, so they are the same at every repeat (the study
// checks this for our runs by comparing the first two repeats' event counts) and their spread
// is over the sampling instants instead.
struct MethodResult {
  std::string scene;
  StudyMethod method;
  bool reference = false;  // this run is the reference
  std::string stopped;     // why the run ended early, if it did: it then counts as failed

  // Cost: wall time of an unobserved run, over the repeats.
  std::uint64_t events = 0;  // executed events (ours) or steps (Box2D)
  Spread wallSeconds;
  Spread secondsPerBoardSecond;
  Spread secondsPerEvent;

  // Ball positions at the sampling instants: the largest distance over the balls at each
  // instant; its maximum and median over the instants, and the first instant above kFailDistance.
  double positionError = 0;
  double positionErrorMedian = 0;
  std::optional<double> divergedAt;
  // Collisions matched with the reference's (same ball and gizmo, nearest in time within the
  // window): the largest and mean time error over those matched before the first unmatched one.
  std::size_t collisions = 0, referenceCollisions = 0, matched = 0;
  double eventTimeError = 0;
  double meanEventTimeError = 0;
  // The first collision either run made that the other did not: the first wrong decision.
  std::optional<double> firstWrongTime;
  std::string firstWrong;
  // |E − E_ref| / max(|E_ref|, |E_ref(0)|), largest over the sampling instants.
  double energyDrift = 0;
  // Ours only: the precision ladder against the same model and tick at mpfr:256 (where rounding
  // first changes a decision), and for the classic model its distance to its own finest run
  // (classic, the smallest tick, mpfr:256): the model's convergence, not its error.
  std::optional<std::uint64_t> horizonEvents;
  std::optional<double> horizonTime;
  std::string horizonDifference;
  std::optional<double> convergenceError;

  bool failed() const;
};

// Above this distance (L) from the reference a ball is on another path: the method has failed.
inline constexpr double kFailDistance = 0.1;

struct SceneReport {
  StudyScene scene;
  std::vector<MethodResult> results;  // in the plan's method order
};

struct StudyReport {
  StudyPlan plan;
  std::string box2dVersion;
  std::vector<SceneReport> scenes;
  // gizmo_bench's figures (`gizmo study --bench`), charted beside the runs; none: no Kernels part.
  BenchResults bench;
};

// Called before each method runs, for progress output.
using StudyProgress = void (*)(const std::string& scene, const std::string& method);

// Throws StudyInputError when the plan or a scene cannot be run: the plan has no mpfr:256, or a
// scene's sampling interval is not a multiple of every maximum tick length. runStudy checks
// this first, so that bad input leaves no partial output.
void checkStudy(const std::vector<StudyScene>& scenes, const StudyPlan& plan);

StudyReport runStudy(const std::vector<StudyScene>& scenes, const StudyPlan& plan, StudyProgress progress = nullptr);

}  // namespace gizmo::verify
