#include "gizmo/verify/ladder.hpp"

#include <algorithm>
#include <limits>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/verify/certify.hpp"
#include "kinds/verify_registry.hpp"
#include "trace.hpp"

namespace gizmo::verify {

SceneArithmetic sceneArithmetic(const RunRequest& request) {
  SceneArithmetic s;
  if (request.model != MotionModel::Classic) {
    s.reason = "the ballistic model meets surfaces at the roots of quadratics, which need square roots";
    return s;
  }
  if (request.board.mu2 != 0) {
    s.reason = "mu2 is not 0: the friction law needs the speed |v|, a square root";
    return s;
  }
  // A kind the exact run cannot take says why in its own file (verify/src/kinds/STEM.hpp).
  for (const GizmoSpec& g : request.board.gizmos) {
    const std::string_view refusal = verifyFact(g.type, [](auto k) { return k.exactRunRefusal; });
    if (!refusal.empty()) {
      s.reason = std::string(gizmoTypeWord(g.type)) + " " + g.name + " " + std::string(refusal);
      return s;
    }
  }
  s.rationalPossible = true;
  s.reason =
      "classic model, mu2 = 0, axis-aligned edges: exact unless a ball meets a corner, a circle or a "
      "swinging flipper";
  return s;
}

std::vector<PrecisionChoice> defaultLadder(const RunRequest& request) {
  std::vector<PrecisionChoice> ladder;
  for (const char* name : {"float", "double", "long-double", "float128", "bin50", "bin100", "mpfr:256"})
    ladder.push_back(*parsePrecision(name));
  if (sceneArithmetic(request).rationalPossible) ladder.push_back(*parsePrecision("rational"));
  return ladder;
}

TracedRun traceAt(const PrecisionChoice& p, const RunRequest& request, const Trace* reference, Trace* record,
                  std::size_t exactDigits, const TraceExtras& extras) {
  return withPrecision(p,
                       [&]<class Real>() { return traceRun<Real>(request, reference, record, exactDigits, extras); });
}

double timeAt(const PrecisionChoice& p, const RunRequest& request, std::uint64_t maxEvents, std::uint64_t& events) {
  return withPrecision(p, [&]<class Real>() { return timeRun<Real>(request, maxEvents, events); });
}

namespace {

TracedRun traceAt(const PrecisionChoice& p, const LadderOptions& o, const Trace* reference, Trace* record) {
  return traceAt(p, o.request, reference, record, o.exactDigits);
}

bool samePrecision(const PrecisionChoice& a, const PrecisionChoice& b) { return precisionName(a) == precisionName(b); }

}  // namespace

LadderReport runLadder(const LadderOptions& options) {
  LadderReport report;
  report.scene = sceneArithmetic(options.request);

  // The reference: the one asked for, else the cheapest exact arithmetic the scene allows, else
  // MPFR at 256 bits.
  const PrecisionChoice mpfr256 = *parsePrecision("mpfr:256");
  PrecisionChoice reference =
      options.reference.value_or(report.scene.rationalPossible ? *parsePrecision("rational") : mpfr256);
  Trace trace;
  TracedRun referenceRun = traceAt(reference, options, nullptr, &trace);
  if (!referenceRun.stopped.empty() && !options.reference && reference.kind == Precision::Rational) {
    report.notes.push_back("the rational run " + referenceRun.stopped + "; the reference is mpfr:256 instead");
    reference = mpfr256;
    trace.clear();
    referenceRun = traceAt(reference, options, nullptr, &trace);
  }
  if (!referenceRun.stopped.empty())
    report.notes.push_back("the reference run (" + precisionName(reference) +
                           ") stopped early: " + referenceRun.stopped);
  report.reference = precisionName(reference);
  std::optional<CertifyReport> certified;
  if (options.certifyWhereInexact && reference.kind != Precision::Rational) certified = certifyRun(options.request);
  if (certified) {
    const CertifyReport& c = *certified;
    CertifiedSummary summary;
    summary.decisions = c.decisions;
    summary.certified = c.certified();
    for (std::uint64_t n : c.uncertifiedByReason) summary.notCertified += n;
    summary.ties = c.ties.size();
    summary.wrong = c.wrong.size();
    if (!c.wrong.empty()) summary.firstWrong = wrongDecisionLine(c.wrong.front());
    report.certified = summary;
  }

  // The cost of a run over as many events as its traced run made (an exact run that outgrew
  // its budget is timed to the same point).
  std::uint64_t doubleEvents = 0;
  const double doubleSeconds =
      timeAt(*parsePrecision("double"), options.request, std::numeric_limits<std::uint64_t>::max(), doubleEvents);
  for (const PrecisionChoice& p : options.precisions) {
    PrecisionResult r;
    r.precision = precisionName(p);
    TracedRun run;
    if (samePrecision(p, reference)) {
      r.reference = true;
      run = referenceRun;
      run.agreement.events = trace.size();
      run.compared = trace.size();
      run.agreement.time = run.endTime;
      run.agreement.throughout = true;
    } else {
      run = traceAt(p, options, &trace, nullptr);
    }
    r.stopped = run.stopped;
    r.compared = run.compared;
    r.horizonEvents = run.agreement.events;
    r.horizonTime = run.agreement.time;
    r.difference = run.agreement.difference;
    r.agreesThroughout = run.agreement.throughout;
    r.maxTimeError = run.agreement.maxTimeError;
    r.maxPositionError = run.agreement.maxPositionError;
    r.energyDrift = run.agreement.energyDrift;
    const bool exact = p.kind == Precision::Rational;
    r.wallSeconds =
        timeAt(p, options.request, exact ? run.events : std::numeric_limits<std::uint64_t>::max(), r.events);
    r.endTime = run.endTime;
    r.eventsPerSecond = r.wallSeconds > 0 ? double(r.events) / r.wallSeconds : 0;
    r.costRatio = doubleSeconds > 0 ? r.wallSeconds / doubleSeconds : 0;
    report.results.push_back(r);
  }
  return report;
}

}  // namespace gizmo::verify
