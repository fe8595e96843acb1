#pragma once
// GameBoard: the event loop (the seed's tick procedure, docs/physics.md "The event loop"), what
// each event does, the triggers' actions, and the contacts released when a gizmo starts to move.
// Included only by the explicit instantiations (core/src/instantiate.hpp).
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "gizmo/core/board/game_board.hpp"

namespace gizmo {

namespace detail {
// Events in one burst beyond which the board declares a stall rather than loop for ever. A
// burst is a run of events each at most kBurstGap after the one before: a chain of events at
// one instant, or a Zeno chain whose steps rounding has shrunk to nothing. No board makes a
// million of them legitimately (the jam rule settles a wedge within 64 hits per 10⁻⁶ s).
inline constexpr std::uint64_t kMaxEventsInBurst = 1000000;
inline constexpr double kBurstGap = 1e-9;
}  // namespace detail

template <class Real>
void GameBoard<Real>::scheduleInput(const Real& time, int key, KeyDirection direction) {
  if (time < now_) throw std::invalid_argument("input scheduled before the present");
  // Kept in time order; equal times stay in the order given.
  auto at = std::upper_bound(inputs_.begin() + std::ptrdiff_t(nextInput_), inputs_.end(), time,
                             [](const Real& t, const PendingInput& in) { return t < in.time; });
  inputs_.insert(at, PendingInput{time, key, direction});
}

// Tick ends are counted from the start (start + k·maxTick), not summed, so that a long tick
// ends exactly at start + time.
template <class Real>
void GameBoard<Real>::tick(const Real& time) {
  const Real start = now_;
  tickSpan(start, 1, start + time);
}

template <class Real>
void GameBoard<Real>::tickSpan(const Real& start, std::int64_t first, const Real& end) {
  rebuild();
  if (!(now_ < end) || stopped_) return;
  for (std::int64_t k = first;; ++k) {
    const Real next = start + Real(k) * params_.maxTick;
    if (!(next < end)) {
      tickUntil(end);
      return;
    }
    tickUntil(next);
    if (stopped_) return;
  }
}

// The seed's steps 2–4 (docs/physics.md, "The event loop"): an end-of-tick event, then the
// earliest event until that one is reached.
template <class Real>
void GameBoard<Real>::tickUntil(const Real& end) {
  schedule(EventKind::EndOfTick, end, kNoGizmo, kNoGizmo, -1);
  while (nextInput_ < inputs_.size() && !(end < inputs_[nextInput_].time)) {
    const PendingInput& in = inputs_[nextInput_++];
    schedule(EventKind::Input, in.time, kNoGizmo, static_cast<GizmoId>(in.direction), in.key);
  }
  for (;;) {
    if (params_.model == MotionModel::Classic) coverUntilNextEvent();
    if (limited_ && (limit_.events <= executedTotal_ || (limit_.time && *limit_.time < queue_.top().time))) {
      stopped_ = true;
      return;
    }
    const Event<Real> e = queue_.pop();
    advanceTo(e.time);
    execute(e);
    recomputePending();
    if (!starting_.empty() && instantOver(e)) {
      releaseContactsOfStarted();
      noteBallsThatLeftRest();  // those the releases woke
      recomputePending();
    }
    // After the releases, whose balls may come back to rest at this instant too.
    if (!leftRest_.empty() && instantOver(e)) {
      wakeWhatRestsOnLeftRest();
      recomputePending();
    }
    if (e.kind == EventKind::EndOfTick) break;
  }
  if (observer_) observer_->tickBoundary(now_);
}

// Whether nothing more happens at the present instant after e. A tick's end closes the instant
// regardless, so that nothing is pending where states are taken; what the releases there schedule
// at that time begins the next tick.
template <class Real>
bool GameBoard<Real>::instantOver(const Event<Real>& e) {
  return e.kind == EventKind::EndOfTick || now_ < queue_.top().time;
}

// The seed's step 3a (docs/physics.md, "The event loop"): every gizmo simulated up to the
// event. Ballistic balls and flippers move along closed forms anchored at their last change, so
// only the classic model steps anything.
template <class Real>
void GameBoard<Real>::advanceTo(const Real& t) {
  if (!(fromDouble<Real>(detail::kBurstGap) < Real(t - now_))) {
    if (++eventsInBurst_ > detail::kMaxEventsInBurst)
      throw StallError("more than " + std::to_string(detail::kMaxEventsInBurst) +
                       " events, each within 1e-9 s of the one before, by board time " + std::to_string(toDouble(t)));
  } else {
    eventsInBurst_ = 0;
  }
  if (params_.model == MotionModel::Classic && now_ < t) {
    const Real dt = t - now_;
    for (GizmoId id : balls_)
      if (gizmos_[static_cast<std::size_t>(id)]->tick(dt, *this)) recompute_.push_back(id);
  }
  now_ = t;
}

template <class Real>
void GameBoard<Real>::execute(const Event<Real>& e) {
  ++executed_[static_cast<std::size_t>(e.kind)];
  ++executedTotal_;
  if (!observer_) {
    applyEvent(e);
    return;
  }
  // The report: each ball the event names, before and after. The balls are found once, by the
  // ball index rather than a virtual call, and the report is built only when someone listens.
  EventOutcome<Real> outcome;
  std::array<const Ball<Real>*, 2> touched{};
  auto before = [&](GizmoId id) {
    if (!isBallId(id)) return;
    const Ball<Real>& b = static_cast<const Ball<Real>&>(*gizmos_[std::size_t(id)]);
    touched[outcome.count] = &b;
    outcome.add(BallChange<Real>{id, b.positionAt(now_), b.velocityAt(now_), Vec2<Real>()});
  };
  before(e.a);
  if (e.b != e.a && e.kind != EventKind::Input) before(e.b);
  applyEvent(e);
  for (std::size_t i = 0; i < outcome.count; ++i) outcome.changes[i].velocityAfter = touched[i]->velocityAt(now_);
  observer_->eventExecuted(e, outcome);
}

// What one event does to the board; the gizmos it changes go on the list to recompute.
template <class Real>
void GameBoard<Real>::applyEvent(const Event<Real>& e) {
  switch (e.kind) {
    case EventKind::Collision:
    case EventKind::Leave: {
      if (e.kind == EventKind::Collision) {
        if (fromDouble<Real>(kJamWindow) < Real(now_ - jamWindowStart_)) {
          jamWindowStart_ = now_;
          collisionsInWindow_ = 0;
        }
        ++collisionsInWindow_;
      }
      AbstractGizmo<Real>& collider = gizmo(e.a);
      AbstractGizmo<Real>& collidee = gizmo(e.b);
      collider.collide(collidee, Contact<Real>{e.time, e.feature, e.kind}, *this);
      if (e.kind == EventKind::Collision) {
        fireTriggersOf(e.a);
        fireTriggersOf(e.b);
      }
      recompute_.push_back(e.a);
      recompute_.push_back(e.b);
      break;
    }
    case EventKind::ContactEnd: {
      Ball<Real>& b = ballById(e.a);
      const Vec2<Real> p = b.positionAt(now_), v = b.velocityAt(now_);
      b.leaveContact(*this);
      b.setState(now_, p, v, params_);
      recompute_.push_back(e.a);
      break;
    }
    case EventKind::FlipperStop:
      gizmo(e.a).handleOwnEvent(e, *this);
      recompute_.push_back(e.a);
      break;
    case EventKind::FrictionTick: {
      Ball<Real>& b = ballById(e.a);
      const Vec2<Real> p = b.positionAt(now_);
      Vec2<Real> v = Ball<Real>::frictionApplied(b.velocityAt(now_), params_.frictionStep, params_);
      const bool settled = b.settlesOnLevel(v, params_);
      if (settled) v = Vec2<Real>();
      b.setState(now_, p, v, params_);
      ++b.nextFrictionIndex;
      reportRule(ModelRule::FrictionApplied, e.a, kNoGizmo);
      if (settled) reportRule(ModelRule::Settled, e.a, b.contact()->gizmo);
      recompute_.push_back(e.a);
      break;
    }
    case EventKind::Input: {
      const KeyDirection dir = static_cast<KeyDirection>(e.b);
      if (observer_) observer_->inputApplied(now_, e.feature, dir);
      for (GizmoId target : triggers_.keyTargets(e.feature, dir)) performAction(target);
      break;
    }
    case EventKind::Recalculate: recompute_.push_back(e.a); break;
    case EventKind::EndOfTick: break;
  }
  noteBallsThatLeftRest();
}

// The balls of recompute_ that left rest since the last look, with where they rested.
template <class Real>
void GameBoard<Real>::noteBallsThatLeftRest() {
  for (const GizmoId id : recompute_) {
    if (!isBallId(id)) continue;
    Ball<Real>& b = static_cast<Ball<Real>&>(*gizmos_[std::size_t(id)]);
    if (b.takeStartedMoving()) leftRest_.push_back(LeftRest{id, b.positionAt(now_)});
  }
}

// A ball that left rest wakes every ball at rest that it may hold up (docs/physics.md, "Piles"):
// one within settleRise of it (the reach of a V of two balls), with the mover on gravity's side of
// it. A woken ball leaves rest in turn, so a pile wakes from the bottom up. A ball that only
// touches the mover from beside or below wakes too when gravity leans on the mover at all: it
// costs a few events (it settles again), where missing one would leave it hanging in the air.
// As a gizmo's release (releaseContactsOfStarted), this waits until nothing more happens at the
// instant, the events of the balls those releases woke included, and a ball back at rest where it
// rested then never moved and wakes nothing: a spinner's arm struck a
// ball wedged against a flipper, which woke a ball wedged above it and came to rest again at
// once; the woken ball fell back onto the spinner 0.78 ns later, whose hit started the spinner
// and struck the first ball again, for ever (campaign seed 2612061238, case 1209).
template <class Real>
void GameBoard<Real>::wakeWhatRestsOnLeftRest() {
  const Real r = Ball<Real>::radius();
  const Real reach = Real(2) * r + params_.settleRise;
  const Vec2<Real> gravity(Real(0), params_.gravity);
  for (std::size_t i = 0; i < leftRest_.size(); ++i) {
    const LeftRest left = leftRest_[i];  // a copy: the loop appends what it wakes
    const Ball<Real>& mover = *gizmos_[std::size_t(left.ball)]->asBall();
    if (mover.resting() && !mover.captured() && mover.positionAt(now_) == left.from) continue;
    for (GizmoId id : balls_) {
      Ball<Real>& b = *gizmos_[static_cast<std::size_t>(id)]->asBall();
      if (!b.wedged() || b.captured()) continue;
      const Vec2<Real> d = left.from - b.positionAt(now_);
      if (reach * reach < lengthSquared(d) || !(Real(0) < dot(d, gravity))) continue;
      b.wake(*this, left.ball);
      recompute_.push_back(id);
      if (b.takeStartedMoving()) leftRest_.push_back(LeftRest{id, b.positionAt(now_)});
    }
  }
  leftRest_.clear();
}

template <class Real>
void GameBoard<Real>::fireTriggersOf(GizmoId source) {
  if (!gizmo(source).hasTrigger()) return;
  // Copied: an action never changes connections, but the board must not depend on that.
  const std::vector<GizmoId> targets = triggers_.targetsOf(source);
  for (GizmoId target : targets) {
    if (observer_) observer_->triggerFired(now_, source, target);
    performAction(target);
  }
}

// Seed: fireTrigger. Actions never fire their own gizmo's trigger (no chaining).
template <class Real>
void GameBoard<Real>::performAction(GizmoId target) {
  if (observer_) observer_->actionPerformed(now_, target);
  gizmo(target).fireTrigger(*this);
}

template <class Real>
void GameBoard<Real>::schedule(EventKind kind, const Real& time, GizmoId a, GizmoId b, std::int32_t feature) {
  Event<Real> e;
  e.time = time;
  e.kind = kind;
  e.a = a;
  e.b = b;
  e.feature = feature;
  e.sequence = queue_.push(e);
  if (observer_) observer_->eventScheduled(e);
}

// BoardAccess::releaseContactsOn, once the instant is over (before the first later event, or at
// the tick's end): each gizmo that started to move and is still in motion, in the order they
// started. A gizmo started and stopped again within one instant never moved, though the two may
// be different events: a spinner connected to itself, started by one ball's hit and stopped at
// once by its hit on a second ball it touches, woke a ball wedged on it at each start, which fell
// back and started it again 1.8·10⁻⁹ s later, for ever (campaign seed 4123105625, case 1684).
template <class Real>
void GameBoard<Real>::releaseContactsOfStarted() {
  for (const GizmoId g : starting_)
    if (gizmos_[static_cast<std::size_t>(g)]->inMotionAt(now_)) releaseContactsNow(g);
  starting_.clear();
}

template <class Real>
void GameBoard<Real>::releaseContactsNow(GizmoId g) {
  // "Beside": the ball's box within the broad phase's margin of g's box. A wedged ball rests
  // against a second surface besides the one it slides on or was struck by, and that surface
  // may be g: a ball sliding down a triangle's slope into a still flipper's side rests there,
  // and hung in the air after the flipper swung away (found on a cradle rule's board).
  const Box<Real> held = gizmos_[static_cast<std::size_t>(g)]->bounds();
  const Real reach = Ball<Real>::radius() + fromDouble<Real>(detail::kBroadPhaseMargin);
  for (GizmoId id : balls_) {
    Ball<Real>& b = *gizmos_[static_cast<std::size_t>(id)]->asBall();
    if (b.contact() && b.contact()->gizmo == g) {
      const Vec2<Real> p = b.positionAt(now_), v = b.velocityAt(now_);
      b.leaveContact(*this);
      b.setState(now_, p, v, params_);
      recompute_.push_back(id);
      continue;
    }
    if (!b.wedged() || b.captured() || !Box<Real>::around(b.positionAt(now_), reach).overlaps(held)) continue;
    b.wake(*this, g);
    recompute_.push_back(id);
  }
}

}  // namespace gizmo
