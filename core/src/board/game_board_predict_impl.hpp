#pragma once
// GameBoard: recomputation (the seed's steps 3b–3c): the events of the gizmos an event changed
// are removed, each moving ball is swept up to its horizon, and its pairs with the candidates the
// broad phase finds are predicted again.
// Included only by the explicit instantiations (core/src/instantiate.hpp).
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "gizmo/core/board/game_board.hpp"

namespace gizmo {

// The seed's steps 3b–3c (docs/physics.md, "The event loop"): remove every event of the gizmos
// to recompute, then predict their pairs again.
template <class Real>
void GameBoard<Real>::recomputePending() {
  if (recompute_.empty()) return;
  // Swapped, not moved: both buffers keep their capacity, so a recompute allocates nothing.
  std::vector<GizmoId>& todo = recomputing_;
  todo.clear();
  todo.swap(recompute_);
  std::sort(todo.begin(), todo.end());
  todo.erase(std::unique(todo.begin(), todo.end()), todo.end());

  for (GizmoId g : todo)
    queue_.removeInvolving(g, [&](const Event<Real>& e) {
      if (observer_) observer_->eventRemoved(e);
    });

  // Where each recomputed gizmo can be until its predictions run out. A moving ball of the
  // classic model is swept below, as it comes, up to the earliest event queued by then.
  const bool untilNextEvent = params_.model == MotionModel::Classic;
  ++stampNow_;
  for (GizmoId g : todo) {
    const std::size_t i = static_cast<std::size_t>(g);
    stamp_[i] = stampNow_;  // marks membership of `todo`
    if (Ball<Real>* b = gizmos_[i]->asBall()) {
      if (b->captured() || b->resting()) sweepBall(g, infinity());
      else if (!untilNextEvent) sweepBall(g, ballHorizon(*b));
    } else {
      const std::optional<Real> until = gizmos_[i]->predictionHorizon();
      validUntil_[i] = until ? *until : infinity();
    }
  }
  const std::uint32_t inTodo = stampNow_;

  for (GizmoId g : todo) {
    AbstractGizmo<Real>& G = *gizmos_[static_cast<std::size_t>(g)];
    if (Ball<Real>* b = G.asBall()) {
      if (b->captured()) continue;
      if (untilNextEvent && !b->resting()) sweepBall(g, classicHorizon(*b));
      scheduleBallEvents(*b);
      gatherCandidates(g, candidates_);
      for (GizmoId other : candidates_) {
        const bool otherInTodo = stamp_[static_cast<std::size_t>(other)] == inTodo;
        // A pair with both sides recomputed is predicted once: from the ball when the other
        // side is not a ball; of two balls, from the lower id, or, when balls are swept as they
        // come, from the higher (the lower one's box is final by then).
        if (otherInTodo && gizmos_[static_cast<std::size_t>(other)]->asBall() &&
            (untilNextEvent ? g < other : other < g))
          continue;
        computePair(g, other);
      }
    } else {
      G.scheduleOwnEvents(*this);
      const Box<Real> reach = G.bounds();
      candidates_.clear();
      broadPhase_.forEachBallNear(reach, [&](GizmoId ballId) {
        const std::size_t bi = static_cast<std::size_t>(ballId);
        if (stamp_[bi] != inTodo && boxes_[bi].overlaps(reach)) candidateSet_.insert(ballId);
      });
      candidateSet_.drainInto(candidates_);
      for (GizmoId ballId : candidates_) computePair(ballId, g);
    }
  }
}

// Sets where a ball can be until `until` (its box, listed in the ball grid) and that its
// predictions hold until then.
template <class Real>
void GameBoard<Real>::sweepBall(GizmoId id, const Real& until) {
  const std::size_t i = static_cast<std::size_t>(id);
  const Ball<Real>& b = *gizmos_[i]->asBall();
  validUntil_[i] = until;
  if (until < infinity())
    boxes_[i] = sweptBox(b.trajectoryAt(now_), Real(until - now_), Ball<Real>::radius(),
                         fromDouble<Real>(detail::kBroadPhaseMargin));
  else boxes_[i] = b.bounds();
  broadPhase_.placeBall(id, boxes_[i], !b.captured());
}

// The classic model's horizon (docs/physics.md, "The classic model's horizon"): every event that
// takes time steps every moving ball (advanceTo) and so predicts its pairs again, and a prediction
// past the earliest event already queued would be removed unrun. On a busy board events come
// every few microseconds, and a sweep to the maximum tick's end met every gizmo and ball of the
// board. A ball that coverUntilNextEvent extends is swept at least as far as a ballistic ball
// (sweepSpan), so that it is not extended again at the next event, and to the tick's end the
// second time in one call, so that the rounds end.
template <class Real>
Real GameBoard<Real>::classicHorizon(const Ball<Real>& b) {
  const Real full = now_ + params_.maxTick;
  if (queue_.empty()) return full;
  const Real next = minOf(full, queue_.top().time);
  if (!covering_) return next;
  std::uint32_t& extended = extendedIn_[static_cast<std::size_t>(b.id())];
  if (extended == coverNow_) return full;
  extended = coverNow_;
  return minOf(full, maxOf(next, Real(now_ + sweepSpan(b))));
}

// Before each event of the classic model. After an event that took no time, or one that left a
// ball's velocity as it was (no gravity, no friction), the earliest event can lie past the
// horizon of a ball that was not recomputed: such a ball is predicted again, no time passing,
// to find what a longer sweep would have found. Predicting it again removes its events, and the
// earliest event can then come later than another ball's horizon: hence the rounds. Each ball is
// swept at least to the earliest event queued when its turn comes (its events were removed
// before), so none of the round falls short at once; a ball that falls short again in the same
// call is swept to the end of the maximum tick, where its recalculation event lies, so it falls
// short no more, and the rounds end.
template <class Real>
void GameBoard<Real>::coverUntilNextEvent() {
  const Real full = now_ + params_.maxTick;
  if (++coverNow_ == 0) {  // a wrapped count would find old marks
    std::fill(extendedIn_.begin(), extendedIn_.end(), 0u);
    coverNow_ = 1;
  }
  covering_ = true;
  while (!queue_.empty()) {
    const Real next = minOf(queue_.top().time, full);
    for (GizmoId id : balls_) {
      const Ball<Real>& b = *gizmos_[static_cast<std::size_t>(id)]->asBall();
      if (!b.resting() && validUntil_[static_cast<std::size_t>(id)] < next) recompute_.push_back(id);
    }
    if (recompute_.empty()) break;
    recomputePending();
  }
  covering_ = false;
}

// How far ahead a moving ball's pairs are predicted: the maximum tick length, or its next
// friction tick when that comes first, since the tick changes its velocity and every prediction
// past it would be removed unrun (on a board with friction most events are friction ticks).
template <class Real>
Real GameBoard<Real>::ballHorizon(Ball<Real>& b) const {
  const Real horizon = now_ + sweepSpan(b);
  if (!frictionTicks()) return horizon;
  return minOf(horizon, frictionTickTime(b));
}

// How long a fast ball is swept for: the maximum tick, halved until the ball's path over it
// reaches no further than kSweepReach (its speed's part and gravity's part each within half of
// it; products and comparisons, so that an exact scalar decides it too). At thousands of L/s a
// whole tick's sweep covers the board, and every prediction of the ball then pairs it with every
// other ball, where its next hit is among its neighbours.
template <class Real>
Real GameBoard<Real>::sweepSpan(const Ball<Real>& b) const {
  const Real half = fromDouble<Real>(detail::kSweepReach / 2);
  const Real v2 = lengthSquared(b.velocityAt(now_));
  const Real g = params_.gravity < Real(0) ? Real(-params_.gravity) : params_.gravity;
  Real h = params_.maxTick;
  for (int k = 0; k < 40; ++k) {
    const Real fall = g * h * h / Real(2);
    if (!(half * half < v2 * h * h) && !(half < fall)) break;
    h = h / Real(2);
  }
  return h;
}

template <class Real>
bool GameBoard<Real>::frictionTicks() const {
  return params_.model == MotionModel::Ballistic && (params_.mu != Real(0) || params_.mu2 != Real(0));
}

// The ball's own events: friction ticks, the end of a sliding contact, and the seed's
// recalculate-collision-time event at the prediction horizon.
template <class Real>
void GameBoard<Real>::scheduleBallEvents(Ball<Real>& b) {
  if (b.resting()) return;
  const GizmoId id = b.id();
  const Real horizon = params_.model == MotionModel::Classic ? now_ + params_.maxTick : now_ + sweepSpan(b);
  // Each of these events recomputes the ball; when one comes by the horizon, a recalculate
  // event would always be removed before it runs, and is not scheduled.
  bool recomputedInTime = false;
  if (frictionTicks()) {
    const Real t = frictionTickTime(b);
    schedule(EventKind::FrictionTick, t, id, kNoGizmo, -1);
    recomputedInTime = !(horizon < t);
  }
  if (const std::optional<Real> end = b.contactEndTime(now_, horizon)) {
    schedule(EventKind::ContactEnd, *end, id, kNoGizmo, -1);
    recomputedInTime = true;
  }
  if (!recomputedInTime) schedule(EventKind::Recalculate, horizon, id, kNoGizmo, -1);
}

// The first friction time k·h after now on the global grid.
template <class Real>
Real GameBoard<Real>::frictionTickTime(Ball<Real>& b) const {
  const Real& h = params_.frictionStep;
  std::int64_t& k = b.nextFrictionIndex;
  if (Real(k) * h <= now_) k = static_cast<std::int64_t>(toDouble(Real(now_ / h)));
  while (Real(k) * h <= now_) ++k;
  while (k > 1 && now_ < Real(k - 1) * h) --k;
  return Real(k) * h;
}

// Broad phase: fixed gizmos in the grid cells the ball's swept box covers whose bounds overlap
// it, the walls when the box reaches an edge, and the balls whose boxes overlap it. Ordered by
// id so that scheduling order is deterministic.
template <class Real>
void GameBoard<Real>::gatherCandidates(GizmoId ballId, std::vector<GizmoId>& out) {
  out.clear();
  const Box<Real>& box = boxes_[static_cast<std::size_t>(ballId)];
  // The walls are the board's edges, so they meet only a box that reaches an edge (touching
  // counts, as in overlaps()). Most predictions of a ball away from the edges need no pair with
  // them, on the spec example as on a crowded board.
  const Real zero(0), side(kBoardSize);
  if ((int(box.lo.x <= zero) | int(box.lo.y <= zero) | int(side <= box.hi.x) | int(side <= box.hi.y)) != 0)
    candidateSet_.insert(outerWallsId());
  broadPhase_.forEachFixedNear(box, [&](GizmoId g) {
    if (boxes_[static_cast<std::size_t>(g)].overlaps(box)) candidateSet_.insert(g);
  });
  broadPhase_.forEachBallNear(box, [&](GizmoId other) {
    if (other != ballId && boxes_[static_cast<std::size_t>(other)].overlaps(box)) candidateSet_.insert(other);
  });
  candidateSet_.drainInto(out);
}

// The seed's step 3c: predict one pair. A collision within both sides' horizons becomes a
// collision event; anything later is found again when either side is next recomputed (the
// ball's own recalculate event bounds that wait by the maximum tick length).
template <class Real>
void GameBoard<Real>::computePair(GizmoId ballId, GizmoId other) {
  const GizmoId collider = colliderOf(ballId, other);
  if (collider == kNoGizmo) return;
  const Real limit = minOf(validUntil_[std::size_t(ballId)], validUntil_[std::size_t(other)]);
  // Neither side can move (or the gizmo moves for ever, and bounds its own search).
  if (!(limit < infinity()) && !gizmos_[std::size_t(other)]->movesForEver()) return;
  const GizmoId collidee = collider == ballId ? other : ballId;
  auto predict = [&] {
    return gizmos_[std::size_t(collider)]->timeUntilCollision(*gizmos_[std::size_t(collidee)], now_, limit, params_);
  };
  std::optional<Contact<Real>> c;
  if constexpr (kExactScalar<Real>) {
    try {
      c = predict();
    } catch (const IrrationalValue& e) {  // say where the exact run needed it
      throw IrrationalValue(std::string(e.what()) + ", for the contact of " + gizmos_[std::size_t(collider)]->name() +
                            " with " + gizmos_[std::size_t(collidee)]->name());
    }
  } else {
    c = predict();
  }
  if (c) schedule(c->kind, c->time, collider, collidee, c->feature);
}

}  // namespace gizmo
