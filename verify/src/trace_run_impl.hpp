#pragma once
// traceRun and timeRun for one scalar; included by the trace_run_*.cpp files only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "trace.hpp"

namespace gizmo::verify {

namespace detail {

template <class Real>
class TraceObserver final : public BoardObserver<Real> {
 public:
  TraceObserver(GameBoard<Real>& board, const Trace* reference, Trace* record, std::size_t exactDigits,
                const TraceExtras& extras)
      : board_(board), reference_(reference), record_(record), exactDigits_(exactDigits), extras_(extras) {
    tickBoundary(board.now());  // an instant at 0 is sampled before anything runs
  }

  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>& outcome) override {
    // A recalculation changes nothing on the board, it only predicts again; and where it falls
    // on a tick boundary exactly, rounding puts it before or after the tick at random. The
    // ladder compares the events that change the board.
    if constexpr (kExactScalar<Real>) checkDigits(e.time);
    if (e.kind == EventKind::Recalculate) return;
    ++compared_;
    TracePoint p;
    p.kind = e.kind;
    p.a = e.a;
    p.b = e.b;
    p.feature = e.feature;
    p.time = WideValue::of(e.time);
    for (const BallChange<Real>& c : outcome.balls()) {
      p.ball[p.ballCount] = c.ball;
      p.x[p.ballCount] = WideValue::of(c.position.x);
      p.y[p.ballCount] = WideValue::of(c.position.y);
      ++p.ballCount;
    }
    p.energy = WideValue::of(board_.energy());
    if (record_ != nullptr) record_->push_back(p);
    if (reference_ != nullptr) compare(p);
  }

  // The balls at every sampling instant this boundary reaches. An instant the run has passed
  // without a boundary on it cannot be sampled from here: that is a caller's error.
  void tickBoundary(const Real& now) override {
    if (extras_.samples == nullptr) return;
    const double t = toDouble(now);
    // Boundaries are counted as start + k·maxTick in the run's own scalar: they meet an instant
    // only to within that scalar's rounding (a float run's boundary at 2 s is 1e-7 s off), and
    // they are a whole tick apart, so the nearest boundary within a quarter tick is the instant's.
    const double slack = toDouble(board_.params().maxTick) / 4;
    for (; nextSample_ < extras_.sampleAt.size() && extras_.sampleAt[nextSample_] <= t + slack; ++nextSample_) {
      const double at = extras_.sampleAt[nextSample_];
      if (at < t - slack)
        throw std::invalid_argument("sampling instant " + std::to_string(at) + " s is not a tick boundary of the run");
      // The state at this boundary holds until the next event, so the path is evaluated at the
      // instant itself, the same value in every scalar.
      const Real instant = fromDouble<Real>(at);
      TraceSample sample;
      sample.time = at;
      for (GizmoId id : board_.ballIds()) {
        const Vec2<Real> p = board_.gizmo(id).asBall()->positionAt(instant);
        sample.x.push_back(WideValue::of(p.x));
        sample.y.push_back(WideValue::of(p.y));
      }
      sample.energy = WideValue::of(board_.energy());
      extras_.samples->push_back(std::move(sample));
    }
  }

  // Called when the run has ended: a run that made fewer or more events than the reference
  // parts from it where the shorter one ended.
  void finish(const Real& endTime) {
    if (reference_ == nullptr || parted_) return;
    if (agreement_.events < reference_->size()) {
      const TracePoint& r = reference_->at(agreement_.events);
      part(r.time.toDouble(), "the reference goes on with " + describe(r) + "; this run has ended");
    } else {
      agreement_.throughout = true;
      agreement_.time = toDouble(endTime);
    }
  }
  const Agreement& agreement() const { return agreement_; }
  const std::string& outgrown() const { return outgrown_; }
  std::uint64_t compared() const { return compared_; }

 private:
  void compare(const TracePoint& p) {
    if (parted_) return;
    if (agreement_.events >= reference_->size()) {  // the reference ended here
      part(p.time.toDouble(), "this run goes on with " + describe(p) + "; the reference has ended");
      return;
    }
    const TracePoint& r = (*reference_)[agreement_.events];
    const bool same = p.kind == r.kind && p.a == r.a && p.b == r.b && p.feature == r.feature &&
                      p.ballCount == r.ballCount && p.ball == r.ball;
    if (!same) {
      part(r.time.toDouble(), "the reference: " + describe(r) + "; this run: " + describe(p));
      return;
    }
    agreement_.maxTimeError = std::max(agreement_.maxTimeError, distance(p.time, r.time));
    for (std::uint8_t i = 0; i < p.ballCount; ++i)
      agreement_.maxPositionError = std::max(agreement_.maxPositionError, distance(p.x[i], p.y[i], r.x[i], r.y[i]));
    const double energyScale = std::fabs(r.energy.toDouble());
    const double energyError = distance(p.energy, r.energy);
    agreement_.energyDrift = energyScale > 0 ? energyError / energyScale : energyError;
    ++agreement_.events;
  }
  void checkDigits(const Real& time) {
    const mpq_srcptr q = time.backend().data();
    const std::size_t digits = mpz_sizeinbase(mpq_numref(q), 10) + mpz_sizeinbase(mpq_denref(q), 10);
    if (digits <= exactDigits_ || !outgrown_.empty()) return;
    outgrown_ = "stopped after " + std::to_string(board_.executedTotal()) + " events: the exact board time has " +
                std::to_string(digits) + " digits, beyond the budget of " + std::to_string(exactDigits_);
    board_.setRunLimit(typename GameBoard<Real>::RunLimit{board_.executedTotal(), std::nullopt});
  }

  std::string describe(const TracePoint& p) const {
    auto name = [&](GizmoId id) {
      return id >= 0 && std::size_t(id) < board_.gizmoCount() ? board_.gizmo(id).name() : std::string("-");
    };
    char time[32];
    std::snprintf(time, sizeof time, "%.17g", p.time.toDouble());
    std::string text = std::string(eventKindName(p.kind)) + " at " + time;
    if (p.kind == EventKind::Input) return text + " (key " + std::to_string(p.feature) + ")";
    if (p.a != kNoGizmo) text += " " + name(p.a);
    if (p.b != kNoGizmo) text += " with " + name(p.b);
    if (p.kind == EventKind::Collision) text += " feature " + std::to_string(p.feature);
    return text;
  }
  void part(double time, std::string difference) {
    parted_ = true;
    agreement_.time = time;
    agreement_.difference = std::move(difference);
    // Nothing after the first difference is compared: stop the run at the next event.
    if (extras_.stopAtDifference)
      board_.setRunLimit(typename GameBoard<Real>::RunLimit{board_.executedTotal(), std::nullopt});
  }

  GameBoard<Real>& board_;
  const Trace* reference_;
  Trace* record_;
  std::size_t exactDigits_;
  const TraceExtras& extras_;
  std::size_t nextSample_ = 0;
  std::string outgrown_;  // why an exact run was stopped, if it was
  Agreement agreement_;
  std::uint64_t compared_ = 0;
  bool parted_ = false;
};

}  // namespace detail

template <class Real>
TracedRun traceRun(const RunRequest& request, const Trace* reference, Trace* record, std::size_t exactDigits,
                   const TraceExtras& extras) {
  TracedRun result;
  std::unique_ptr<GameBoard<Real>> board;
  try {
    board = prepareRun<Real>(request);
  } catch (const IrrationalValue& e) {
    result.stopped = std::string("needs an irrational value before the first event: ") + e.what();
    return result;
  }
  detail::TraceObserver<Real> observer(*board, reference, record, exactDigits, extras);
  board->setObserver(&observer);
  try {
    continueRun(*board, request, 0);
  } catch (const IrrationalValue& e) {
    result.stopped =
        "needs an irrational value after " + std::to_string(board->executedTotal()) + " events: " + e.what();
  } catch (const std::exception& e) {
    result.stopped = std::string("the run failed: ") + e.what();
  }
  if (!observer.outgrown().empty()) result.stopped = observer.outgrown();
  observer.finish(board->now());
  result.events = board->executedTotal();
  result.compared = observer.compared();
  result.endTime = toDouble(board->now());
  result.agreement = observer.agreement();
  return result;
}

template <class Real>
double timeRun(const RunRequest& request, std::uint64_t maxEvents, std::uint64_t& events) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<GameBoard<Real>> board;
  try {
    board = prepareRun<Real>(request);
    board->setRunLimit(typename GameBoard<Real>::RunLimit{maxEvents, std::nullopt});
    continueRun(*board, request, 0);
  } catch (const std::exception&) {
    // The traced run reports why; the time is that of the part that ran.
  }
  events = board ? board->executedTotal() : 0;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

#define GIZMO_INSTANTIATE_TRACE_RUN(Real)                                                                      \
  template TracedRun traceRun<Real>(const RunRequest&, const Trace*, Trace*, std::size_t, const TraceExtras&); \
  template double timeRun<Real>(const RunRequest&, std::uint64_t, std::uint64_t&);

}  // namespace gizmo::verify
