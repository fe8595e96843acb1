#pragma once
// The seed's GameBoard: a composite of gizmos (the ball among them), the triggers between
// them, and the discrete-event queue that simulates them, kept between ticks.
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gizmo/core/board/board_state.hpp"
#include "gizmo/core/board/broad_phase.hpp"
#include "gizmo/core/board/collision_pairs.hpp"
#include "gizmo/core/board/event_queue.hpp"
#include "gizmo/core/board/id_set.hpp"
#include "gizmo/core/board/observer.hpp"
#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/core/board/triggers.hpp"
#include "gizmo/core/gizmos/abstract_gizmo.hpp"
#include "gizmo/core/gizmos/ball.hpp"

namespace gizmo {

// Stopped instead of looping for ever: too many events with (next to) no board time between
// them.
class StallError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <class Real>
class GameBoard final : private BoardAccess<Real> {
 public:
  explicit GameBoard(const PhysicsParams<Real>& params = PhysicsParams<Real>());
  ~GameBoard() override;
  GameBoard(const GameBoard&) = delete;
  GameBoard& operator=(const GameBoard&) = delete;

  // --- building ---------------------------------------------------------------------------------
  GizmoId add(std::unique_ptr<AbstractGizmo<Real>> gizmo);
  void connect(GizmoId source, GizmoId target);
  void keyConnect(int key, KeyDirection direction, GizmoId target);

  // --- running ----------------------------------------------------------------------------------
  // Seed: simulate `time` seconds, in ticks no longer than the maximum tick length.
  void tick(const Real& time);
  // The ticks first, first + 1, … of a span of ticks that began at `start`: tick k ends at
  // start + k·maxTick (counted, not summed), the last at `end`. tick(time) is the span from now
  // to now + time; a run resumed from a saved state carries on its span where it stopped.
  void tickSpan(const Real& start, std::int64_t first, const Real& end);

  // Stops a run early, for looking at a moment of it: before the first event later than
  // `time`, or once `events` events have run in all. A stopped board is not meant to go on.
  struct RunLimit {
    std::uint64_t events = std::numeric_limits<std::uint64_t>::max();
    std::optional<Real> time;
  };
  void setRunLimit(const RunLimit& limit) {
    limit_ = limit;
    limited_ = true;
  }
  bool stopped() const { return stopped_; }

  // Everything that changes as the board runs (board_state.hpp). restoreState puts a saved
  // state back onto a board built from the same spec with the same inputs; it checks that the
  // state fits the board and throws StateError if not (the board is then not to be used).
  BoardState<Real> saveState() const;
  void restoreState(const BoardState<Real>& state);
  // A key pressed or released at board time `time` (≥ now): key triggers perform their actions
  // then, in the queue's order. Inputs are part of a run's data.
  void scheduleInput(const Real& time, int key, KeyDirection direction);

  void setObserver(BoardObserver<Real>* observer) { observer_ = observer; }

  // --- looking at it --------------------------------------------------------------------------------
  const Real& now() const override { return now_; }
  const PhysicsParams<Real>& params() const override { return params_; }
  std::size_t gizmoCount() const { return gizmos_.size(); }
  AbstractGizmo<Real>& gizmo(GizmoId id) { return *gizmos_.at(static_cast<std::size_t>(id)); }
  const AbstractGizmo<Real>& gizmo(GizmoId id) const { return *gizmos_.at(static_cast<std::size_t>(id)); }
  std::optional<GizmoId> find(std::string_view name) const;
  const std::vector<GizmoId>& ballIds() const { return balls_; }
  Ball<Real>& ballById(GizmoId id) override;
  static constexpr GizmoId outerWallsId() { return 0; }

  // Seed: the collision pairs, formed once per board change from canCollideWith.
  std::vector<CollisionPair> collisionPairs();
  // Live events, earliest first.
  std::vector<Event<Real>> pendingEvents() const { return queue_.snapshot(); }
  const std::array<std::uint64_t, kEventKindCount>& executedCounts() const { return executed_; }
  std::uint64_t executedTotal() const { return executedTotal_; }

  // Mechanical energy per unit mass: ½|v|² + g (20 − y), summed over free balls.
  Real energy() const;

  // The property system with the board's checks: a gizmo may not be moved onto another or off
  // the board. On refusal returns the reason and changes nothing.
  std::optional<std::string> setProperty(GizmoId id, std::string_view name, const PropertyValue& value);

  BoardSpec toSpec() const;

 private:
  // BoardAccess, for the gizmos.
  void markForRecompute(GizmoId id) override { recompute_.push_back(id); }
  void schedule(EventKind kind, const Real& time, GizmoId a, GizmoId b, std::int32_t feature) override;
  void reportRule(ModelRule rule, GizmoId gizmo, GizmoId other) override {
    if (observer_) observer_->modelRuleApplied(now_, rule, gizmo, other);
  }
  void releaseContactsOn(GizmoId g) override { starting_.push_back(g); }
  bool roomForBall(const Vec2<Real>& p, GizmoId ball, GizmoId ignore) const override;
  bool cradled(GizmoId ball, const Vec2<Real>& p, const Vec2<Real>& normal, GizmoId by) const override;
  bool boxedAlong(GizmoId ball, const Vec2<Real>& p, const Vec2<Real>& m, GizmoId behind) const override;
  bool ballAtRest(GizmoId id) const;
  bool jammed() const override { return collisionsInWindow_ > kJamThreshold; }
  GizmoId spawnBall(const Vec2<Real>& p) override;

  GizmoId join(std::unique_ptr<AbstractGizmo<Real>> gizmo);
  // Spawned balls come after every gizmo the board was built with (ids never move): a state
  // with more or fewer of them than the board has now sets the count before it is restored.
  void setSpawnedCount(std::size_t count);
  GizmoId addSpawnedBall(const Vec2<Real>& p);
  void rebuild();
  void checkRestoredEvent(const Event<Real>& e, const BoardState<Real>& state) const;
  bool isGizmoId(std::int64_t id) const { return id >= 0 && std::uint64_t(id) < gizmos_.size(); }
  bool isBallId(std::int64_t id) const { return isGizmoId(id) && ballIndex_[std::size_t(id)] >= 0; }
  void tickUntil(const Real& end);
  void advanceTo(const Real& t);
  void execute(const Event<Real>& e);
  void applyEvent(const Event<Real>& e);
  bool instantOver(const Event<Real>& e);
  void releaseContactsOfStarted();
  void noteBallsThatLeftRest();
  void wakeWhatRestsOnLeftRest();
  void releaseContactsNow(GizmoId g);
  void fireTriggersOf(GizmoId source);
  void performAction(GizmoId target) override;
  void recomputePending();
  void scheduleBallEvents(Ball<Real>& ball);
  void computePair(GizmoId ball, GizmoId other);
  void gatherCandidates(GizmoId ball, std::vector<GizmoId>& out);
  Real ballHorizon(Ball<Real>& b) const;
  Real sweepSpan(const Ball<Real>& b) const;
  void sweepBall(GizmoId ball, const Real& until);
  Real classicHorizon(const Ball<Real>& b);
  void coverUntilNextEvent();
  bool frictionTicks() const;
  template <class Accept>
  bool stillFeatureNear(const Vec2<Real>& p, const Real& reach, GizmoId except, Accept accept) const;
  Real frictionTickTime(Ball<Real>& ball) const;
  Real infinity() const;

  PhysicsParams<Real> params_;
  Real now_{0};
  std::vector<std::unique_ptr<AbstractGizmo<Real>>> gizmos_;
  std::vector<GizmoId> balls_;
  std::size_t spawned_ = 0;  // the last gizmos: balls that spawners added as the board ran
  Triggers triggers_;
  struct PendingInput {
    Real time;
    int key;
    KeyDirection direction;
  };
  std::vector<PendingInput> inputs_;  // not yet queued, in time order
  std::size_t nextInput_ = 0;

  // Built once per board change.
  bool built_ = false;
  std::vector<std::int32_t> ballIndex_;  // gizmo id → index into balls_, or −1
  ColliderTable<Real> colliders_;
  GizmoId colliderOf(GizmoId ball, GizmoId other) const {
    return colliders_.colliderOf(std::size_t(ballIndex_[std::size_t(ball)]), ball, other);
  }
  BroadPhase<Real> broadPhase_;
  std::vector<Box<Real>> boxes_;      // per gizmo: where it can be until validUntil_
  std::vector<Real> validUntil_;      // per gizmo: its predictions hold until then
  std::vector<std::uint32_t> stamp_;  // marks the gizmos of the current recomputation
  std::uint32_t stampNow_ = 0;
  // coverUntilNextEvent: whether it runs, a number for each call, and per gizmo the call that
  // last extended it (a ball extended a second time in one call is swept to the tick's end).
  bool covering_ = false;
  std::uint32_t coverNow_ = 0;
  std::vector<std::uint32_t> extendedIn_;

  EventQueue<Real> queue_;
  std::vector<GizmoId> recompute_;
  // Gizmos that started to move during the present instant; empty between instants.
  std::vector<GizmoId> starting_;
  // Balls that left rest during the present instant, each with where it rested; empty between
  // instants (wakeWhatRestsOnLeftRest).
  struct LeftRest {
    GizmoId ball;
    Vec2<Real> from;
  };
  std::vector<LeftRest> leftRest_;
  std::vector<GizmoId> recomputing_;  // recomputePending's working list, kept for its capacity
  std::vector<GizmoId> candidates_;
  IdSet candidateSet_;  // gathers candidates_ in id order, without repeats
  std::array<std::uint64_t, kEventKindCount> executed_{};
  std::uint64_t executedTotal_ = 0;
  RunLimit limit_;
  bool limited_ = false;
  bool stopped_ = false;
  std::uint64_t eventsInBurst_ = 0;
  // The jam rule: more than kJamThreshold collisions within kJamWindow seconds of board time
  // (counted from the first of them) leave no rebound.
  Real jamWindowStart_{0};
  std::uint64_t collisionsInWindow_ = 0;
  static constexpr std::uint64_t kJamThreshold = 64;
  static constexpr double kJamWindow = 1e-6;
  BoardObserver<Real>* observer_ = nullptr;
};

}  // namespace gizmo

// Compiled once per scalar in core/src (instantiate_*.cpp).
namespace gizmo {
extern template class GameBoard<float>;
extern template class GameBoard<double>;
extern template class GameBoard<long double>;
#if GIZMO_HAS_MULTIPRECISION
extern template class GameBoard<Float128>;
extern template class GameBoard<MpfrReal>;
#endif
}  // namespace gizmo
