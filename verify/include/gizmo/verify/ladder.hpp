#pragma once
// The precision ladder: one run (board, model, time, keys) at several scalars, each compared
// decision by decision with a reference run. docs/verification.md explains the measures.
#include <optional>
#include <string>
#include <vector>

#include "gizmo/core/math/precision.hpp"
#include "gizmo/core/run/run.hpp"

namespace gizmo::verify {

// Whether a run of this board can stay rational, decided before running it, and if not, why.
// Rational means: the classic model (straight motion, linear gaps against edges), μ₂ = 0 (no
// speed, so no square root, in the friction law), and only features whose normals are rational
// and whose contacts need no square root: axis-aligned edges. Corners, circles, 45° edges and
// swinging flippers may still be met; the run then stops where it first needs an irrational value.
struct SceneArithmetic {
  bool rationalPossible = false;
  std::string reason;  // why not, or what the run relies on
};
SceneArithmetic sceneArithmetic(const RunRequest& request);

struct PrecisionResult {
  std::string precision;  // the name as on the command line
  bool reference = false;
  std::uint64_t events = 0;    // executed
  std::uint64_t compared = 0;  // the events that change the board: all but recalculations
  double endTime = 0;
  std::string stopped;              // why the run ended early (an irrational value, a stall), or empty
  std::uint64_t horizonEvents = 0;  // leading compared events that agree with the reference's
  double horizonTime = 0;           // the reference's time of the first event that differs
  std::string difference;           // the two decisions there, in words
  bool agreesThroughout = false;    // every decision agreed, and both runs made the same number
  double maxTimeError = 0;          // over agreeing events: |t − t_ref|
  double maxPositionError = 0;      // over agreeing events: |p − p_ref| of the balls they touched
  double energyDrift = 0;           // |E − E_ref| after the last agreeing event, relative to E_ref
  double wallSeconds = 0;           // an unobserved run of the same request
  double eventsPerSecond = 0;
  double costRatio = 0;  // wall time / double's (0 when double was not run)
};

struct LadderOptions {
  RunRequest request;
  std::vector<PrecisionChoice> precisions;   // in the order to report
  std::optional<PrecisionChoice> reference;  // default: rational if the scene allows, else mpfr:256
  // Where the run cannot be exact throughout, certify the double run's decisions instead
  // (certify.hpp): the check goes on with certified arithmetic where exact arithmetic stops.
  bool certifyWhereInexact = true;
  // An exact run stops once the board time's numerator and denominator together have more
  // digits than this: they grow with every event, and so does the cost of each operation
  // (measured on fixtures/boards/verify/rational-squares.txt: 4 s of board time cost 1.3 s,
  // 6 s 43 s). The reference then falls back to mpfr:256.
  std::size_t exactDigits = 20000;
};

// The certificate of the double run, in counts (certify.hpp has the full report).
struct CertifiedSummary {
  std::uint64_t decisions = 0;
  std::uint64_t certified = 0;
  std::uint64_t notCertified = 0;  // e.g. near a swinging flipper
  std::uint64_t ties = 0;
  std::uint64_t wrong = 0;
  std::string firstWrong;  // the first wrong decision explained, if any
};

struct LadderReport {
  std::string reference;  // the precision every run was compared with
  SceneArithmetic scene;
  std::vector<std::string> notes;  // e.g. the rational run stopped, and the reference fell back
  std::vector<PrecisionResult> results;
  std::optional<CertifiedSummary> certified;  // when the run could not be exact throughout
};

// The ladder's default rungs: float, double, long-double, float128, bin50, bin100, mpfr:256,
// and rational when the scene may stay rational.
std::vector<PrecisionChoice> defaultLadder(const RunRequest& request);

LadderReport runLadder(const LadderOptions& options);

}  // namespace gizmo::verify
