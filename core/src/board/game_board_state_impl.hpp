#pragma once
// GameBoard's saved states (board_state.hpp): taking one, and putting one back after checking
// that it can belong to this board. Included only by the explicit instantiations in core/src.
#include "gizmo/core/board/game_board.hpp"

namespace gizmo {

template <class Real>
BoardState<Real> GameBoard<Real>::saveState() const {
  if (!built_) throw std::logic_error("a board's state is saved once it has started");
  BoardState<Real> s;
  s.now = now_;
  s.executedTotal = executedTotal_;
  s.executed = executed_;
  s.eventsInBurst = eventsInBurst_;
  s.jamWindowStart = jamWindowStart_;
  s.collisionsInWindow = collisionsInWindow_;
  s.nextInput = nextInput_;
  s.events = queue_.liveInSequenceOrder();
  s.nextSequence = queue_.nextSequence();
  s.boxes = boxes_;
  s.validUntil = validUntil_;
  s.gizmos.resize(gizmos_.size());
  for (std::size_t g = 0; g < gizmos_.size(); ++g) gizmos_[g]->saveState(s.gizmos[g]);
  return s;
}

// An event the board could have scheduled: known kind, the right kinds of gizmos, no earlier
// than now. Executing anything else could touch a gizmo through the wrong interface.
template <class Real>
void GameBoard<Real>::checkRestoredEvent(const Event<Real>& e, const BoardState<Real>& state) const {
  auto fail = [&](const std::string& why) {
    throw StateError("queued event " + std::to_string(e.sequence) + " (" + std::string(eventKindName(e.kind)) +
                     "): " + why);
  };
  if (static_cast<int>(e.kind) >= kEventKindCount) fail("unknown kind");
  if (e.sequence >= state.nextSequence) fail("sequence number not yet handed out");
  if (e.time < state.now) fail("earlier than the present");
  switch (e.kind) {
    case EventKind::Collision: {
      if (!isGizmoId(e.a) || !isGizmoId(e.b) || e.a == e.b) fail("not a pair of gizmos");
      const GizmoId ball = isBallId(e.a) ? e.a : e.b, other = ball == e.a ? e.b : e.a;
      if (!isBallId(ball)) fail("no ball involved");
      if (colliderOf(ball, other) != e.a) fail("not the collider of a formed pair");
      break;
    }
    case EventKind::Leave:
      if (!isGizmoId(e.a) || !gizmos_[std::size_t(e.a)]->makesEventKind(e.kind) || !isBallId(e.b))
        fail("not an absorber and a ball");
      break;
    case EventKind::ContactEnd:
    case EventKind::FrictionTick:
    case EventKind::Recalculate:
      if (!isBallId(e.a)) fail("not a ball");
      break;
    case EventKind::FlipperStop:
      if (!isGizmoId(e.a) || !gizmos_[std::size_t(e.a)]->makesEventKind(e.kind)) fail("not a flipper");
      break;
    case EventKind::Input:
      if (e.a != kNoGizmo || (e.b != 0 && e.b != 1)) fail("not a key press or release");
      break;
    case EventKind::EndOfTick:
      if (e.a != kNoGizmo || e.b != kNoGizmo) fail("names a gizmo");
      break;
  }
}

template <class Real>
void GameBoard<Real>::restoreState(const BoardState<Real>& s) {
  // The pairs and the grid come from the spec; the predictions made now are replaced below.
  // Balls spawned as the board ran are part of the state: the count of gizmos past the built
  // ones says how many there were, and only a board with a spawner can have any.
  const std::size_t built = gizmos_.size() - spawned_;
  if (s.gizmos.size() < built || s.boxes.size() != s.gizmos.size() || s.validUntil.size() != s.gizmos.size())
    throw StateError("the state is of a board with " + std::to_string(s.gizmos.size()) + " gizmos, this one has " +
                     std::to_string(built));
  const std::size_t spawned = s.gizmos.size() - built;
  const bool spawner =
      std::any_of(gizmos_.begin(), gizmos_.end(), [](const auto& g) { return g->spawnPosition().has_value(); });
  if (spawned > 0 && (!spawner || spawned > kMaxSpawnedBalls))
    throw StateError("the state has " + std::to_string(spawned) + " spawned balls, more than this board can have");
  if (spawned != spawned_) setSpawnedCount(spawned);
  BoardObserver<Real>* const observer = observer_;
  observer_ = nullptr;
  rebuild();
  observer_ = observer;

  const std::size_t n = gizmos_.size();
  if (s.nextInput > inputs_.size()) throw StateError("more inputs applied than the run has");
  std::uint64_t sum = 0;
  for (std::uint64_t c : s.executed) sum += c;
  if (sum != s.executedTotal) throw StateError("executed events do not add up");
  std::uint64_t previous = 0;
  for (std::size_t i = 0; i < s.events.size(); ++i) {
    if (i > 0 && s.events[i].sequence <= previous) throw StateError("queued events out of scheduling order");
    previous = s.events[i].sequence;
    checkRestoredEvent(s.events[i], s);
  }

  struct Ids final : GizmoIdCheck {
    const GameBoard& board;
    explicit Ids(const GameBoard& b) : board(b) {}
    bool isGizmo(std::int64_t id) const override { return board.isGizmoId(id); }
    bool isBall(std::int64_t id) const override { return board.isBallId(id); }
  } ids(*this);
  for (std::size_t g = 0; g < n; ++g) {
    GizmoStateReader<Real> in(s.gizmos[g]);
    gizmos_[g]->restoreState(in, ids);
    in.expectEnd();
  }

  now_ = s.now;
  executed_ = s.executed;
  executedTotal_ = s.executedTotal;
  eventsInBurst_ = s.eventsInBurst;
  jamWindowStart_ = s.jamWindowStart;
  collisionsInWindow_ = s.collisionsInWindow;
  nextInput_ = static_cast<std::size_t>(s.nextInput);
  queue_.restore(s.events, s.nextSequence);
  boxes_ = s.boxes;
  validUntil_ = s.validUntil;
  for (GizmoId id : balls_)
    broadPhase_.placeBall(id, boxes_[std::size_t(id)], !gizmos_[std::size_t(id)]->asBall()->captured());
  recompute_.clear();
  starting_.clear();  // both empty between instants, where states are taken
  leftRest_.clear();
  stopped_ = false;
}

}  // namespace gizmo
