#pragma once
// The named invariants that every run must keep, checked by an observer while the run goes on
// (so any run can be watched: a test's, a fuzz case's, a user's board), and the function that
// runs a request under them.
//
// - no-tunnelling: no free ball is inside a gizmo or beyond a wall by more than
//   Bounds<Real>::overlap, at every executed event and at sampled instants between events.
// - energy: mechanical energy (board.energy()) never rises from one event to the next except by
//   what that event's flipper hits and absorber shots can supply, the documented minimum bounce
//   (½·restSpeed² per hit), and in the classic model the explicit step's own gain (see
//   docs/fuzzing.md); and a friction tick never speeds a ball up, and slows a moving one.
// - event-queue: board time never goes backwards; no event is scheduled before the present;
//   every removed or executed event was scheduled and still pending; the executed event is the
//   earliest pending one; the board's queue holds exactly the events the observer saw scheduled;
//   every moving free ball has a pending event that re-examines it within one maximum tick, and
//   every swinging flipper its stop.
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/geometry/flipper_time_of_impact.hpp"
#include "gizmo/core/run/run.hpp"

namespace gizmo::verify::fuzz {

enum class Invariant { NoTunnelling, Energy, EventQueue };
inline constexpr Invariant kAllInvariants[] = {Invariant::NoTunnelling, Invariant::Energy, Invariant::EventQueue};
std::string_view invariantName(Invariant i);

struct Violation {
  Invariant invariant = Invariant::EventQueue;
  std::string message;  // what broke, when, with exact values (hex floats)
  double time = 0;      // the board time at which it was seen
};

// How far rounding may carry a run past the exact model, per scalar: `overlap` in L (a ball's
// depth inside a gizmo or beyond a wall), `energy` relative to the board's energy scale.
template <class Real>
struct Bounds;
template <>
struct Bounds<double> {
  static constexpr double overlap = 1e-9;
  static constexpr double energy = 1e-11;
};
template <>
struct Bounds<long double> {
  static constexpr long double overlap = 1e-12L;
  static constexpr long double energy = 1e-14L;
};

// Watches one board: attach before the first tick (it reads the queue as built) and call
// finish() after the last. Keeps the first violation of each invariant that it checks.
template <class Real>
class InvariantChecker final : public BoardObserver<Real> {
 public:
  InvariantChecker(const GameBoard<Real>& board, std::vector<Invariant> checked);
  ~InvariantChecker() override;

  void eventScheduled(const Event<Real>& e) override;
  void eventRemoved(const Event<Real>& e) override;
  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>& outcome) override;
  void triggerFired(const Real& time, GizmoId, GizmoId) override { timePasses(time, "a trigger"); }
  void actionPerformed(const Real& time, GizmoId) override { timePasses(time, "an action"); }
  void inputApplied(const Real& time, int, KeyDirection) override { timePasses(time, "an input"); }
  void modelRuleApplied(const Real& time, ModelRule rule, GizmoId gizmo, GizmoId other) override;
  void tickBoundary(const Real& time) override;
  void finish();
  // A run that stopped with an error breaks every invariant checked.
  void runFailed(const std::string& what);

  const std::vector<Violation>& violations() const { return violations_; }
  std::uint64_t eventsChecked() const { return executed_; }

 private:
  struct Snapshot;
  bool checks(Invariant i) const;
  void fail(Invariant i, const std::string& message);
  void timePasses(const Real& time, const char* what);
  void checkOverlaps(const Real& time, const Snapshot& s, const char* when);
  void checkEnergy(const Event<Real>& e, const EventOutcome<Real>& outcome);
  void checkCoverage();
  void takeSnapshot();

  const GameBoard<Real>& board_;
  std::vector<Invariant> checked_;
  std::vector<Violation> violations_;
  std::uint64_t executed_ = 0;
  Real lastTime_{0};

  // event-queue: the pending events as seen through the observer, by sequence and in run order.
  struct RunsFirst {
    bool operator()(const Event<Real>& x, const Event<Real>& y) const { return runsBefore(x, y); }
  };
  std::map<std::uint64_t, Event<Real>> pending_;
  std::set<Event<Real>, RunsFirst> ordered_;

  // no-tunnelling: the fixed geometry, and the motion since the last event.
  struct Geometry;
  std::unique_ptr<Geometry> geometry_;
  std::unique_ptr<Snapshot> snapshot_;
  std::set<std::pair<GizmoId, GizmoId>> fired_;  // (absorber, ball) until the ball has left

  // energy: what the current event may add, gathered from its model rules.
  Real energyBefore_{0};
  Real allowance_{0};
  std::vector<GizmoId> released_;
  std::vector<std::pair<GizmoId, Real>> teleported_;  // each teleported ball, and its height before
};

struct InvariantRun {
  std::vector<Violation> violations;  // empty when every checked invariant held
  std::uint64_t events = 0;           // executed
  double energy = 0;                  // at the end
};
// Runs the request in Real with a checker watching.
template <class Real>
InvariantRun checkInvariants(const RunRequest& request, const std::vector<Invariant>& checked);

extern template class InvariantChecker<double>;
extern template InvariantRun checkInvariants<double>(const RunRequest&, const std::vector<Invariant>&);
extern template class InvariantChecker<long double>;
extern template InvariantRun checkInvariants<long double>(const RunRequest&, const std::vector<Invariant>&);

}  // namespace gizmo::verify::fuzz
