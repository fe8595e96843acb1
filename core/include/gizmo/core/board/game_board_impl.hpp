#pragma once
// GameBoard's member definitions. Included only by the explicit instantiations in core/src,
// one scalar per translation unit; everyone else includes game_board.hpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/geometry/cradle.hpp"
#include "gizmo/core/gizmos/outer_walls.hpp"

namespace gizmo {

namespace detail {
// Events in one burst beyond which the board declares a stall rather than loop for ever. A
// burst is a run of events each at most kBurstGap after the one before: a chain of events at
// one instant, or a Zeno chain whose steps rounding has shrunk to nothing. No board makes a
// million of them legitimately (the jam rule settles a wedge within 64 hits per 10⁻⁶ s).
inline constexpr std::uint64_t kMaxEventsInBurst = 1000000;
inline constexpr double kBurstGap = 1e-9;
// Widening of a ball's swept box, in L: far above rounding, far below any gap that matters.
inline constexpr double kBroadPhaseMargin = 1e-6;
// Above this many cells a ball's box is wide (GameBoard::wideBalls_): a ball crossing four cells
// each way in one prediction horizon.
inline constexpr int kWideCells = 16;
// The grid cell holding coordinate v, clamped to the board. Compared before converting, so
// that truncation is the floor (v >= 0), and no value (huge, NaN) converts out of range:
// std::floor costs a library call on a target without SSE4.1, and this runs for every box.
inline int cellOf(double v) {
  if (!(v >= 0)) return 0;
  if (v >= double(kBoardSize - 1)) return kBoardSize - 1;
  return static_cast<int>(v);
}
}  // namespace detail

template <class Real>
typename GameBoard<Real>::CellRange GameBoard<Real>::cellsOf(const Box<Real>& b) {
  return CellRange{detail::cellOf(toDouble(b.lo.x)), detail::cellOf(toDouble(b.hi.x)), detail::cellOf(toDouble(b.lo.y)),
                   detail::cellOf(toDouble(b.hi.y))};
}

template <class Real>
bool GameBoard<Real>::isWide(const CellRange& c) {
  return (c.x1 - c.x0 + 1) * (c.y1 - c.y0 + 1) > detail::kWideCells;
}

// Moves a ball's entries in the ball grid to the cells its new box covers, or to the wide balls
// (none when captured).
template <class Real>
void GameBoard<Real>::placeBall(GizmoId id, bool inGrid) {
  const std::size_t i = static_cast<std::size_t>(id);
  CellRange& old = ballCells_[i];
  const CellRange now = inGrid ? cellsOf(boxes_[i]) : CellRange{0, -1, 0, -1};
  // Most moves stay within the same cells (the order within a cell or among the wide balls does
  // not matter: the candidates taken from them are sorted by id).
  if (now == old) return;
  if (isWide(old)) {
    std::erase(wideBalls_, id);
  } else {
    for (int y = old.y0; y <= old.y1; ++y)
      for (int x = old.x0; x <= old.x1; ++x) std::erase(ballGrid_[std::size_t(y * kBoardSize + x)], id);
  }
  old = now;
  if (isWide(old)) {
    wideBalls_.push_back(id);
  } else {
    for (int y = old.y0; y <= old.y1; ++y)
      for (int x = old.x0; x <= old.x1; ++x) ballGrid_[std::size_t(y * kBoardSize + x)].push_back(id);
  }
}

// Visits every free ball listed in a cell that the box covers, and every wide ball: a superset of
// the balls whose boxes overlap it (boxes that overlap share a cell, since cellsOf is monotone),
// with repeats. The caller checks the overlap.
template <class Real>
template <class Visit>
void GameBoard<Real>::forEachBallNear(const Box<Real>& box, Visit visit) const {
  const CellRange c = cellsOf(box);
  for (int y = c.y0; y <= c.y1; ++y)
    for (int x = c.x0; x <= c.x1; ++x)
      for (GizmoId ballId : ballGrid_[std::size_t(y * kBoardSize + x)]) visit(ballId);
  for (GizmoId ballId : wideBalls_) visit(ballId);
}

// Whether a still gizmo other than `except` (the walls, listed in no cell, or one listed in the
// cells around p) has a feature within `reach` of a ball centred at p that `accept` takes, given
// the direction from the feature towards the ball (geometry/cradle.hpp's anyFeatureWithin).
template <class Real>
template <class Accept>
bool GameBoard<Real>::stillFeatureNear(const Vec2<Real>& p, const Real& reach, GizmoId except, Accept accept) const {
  const Real r = Ball<Real>::radius();
  auto near = [&](GizmoId g) {
    if (g == except) return false;
    const Shape<Real>* shape = gizmos_[std::size_t(g)]->restingShape();
    return shape && anyFeatureWithin(*shape, p, r, reach, accept);
  };
  if (near(outerWallsId())) return true;
  const CellRange c = cellsOf(Box<Real>::around(p, r + reach));
  for (int y = c.y0; y <= c.y1; ++y)
    for (int x = c.x0; x <= c.x1; ++x)
      for (GizmoId g : grid_[std::size_t(y * kBoardSize + x)])
        if (near(g)) return true;
  return false;
}

template <class Real>
GameBoard<Real>::GameBoard(const PhysicsParams<Real>& params) : params_(params) {
  add(std::make_unique<OuterWalls<Real>>());
}

template <class Real>
GameBoard<Real>::~GameBoard() = default;

template <class Real>
Real GameBoard<Real>::infinity() const {
  return Real(std::numeric_limits<double>::max());
}

template <class Real>
GizmoId GameBoard<Real>::add(std::unique_ptr<AbstractGizmo<Real>> gizmo) {
  if (spawned_ > 0) throw std::logic_error("a board that has spawned balls takes no more gizmos");
  built_ = false;
  return join(std::move(gizmo));
}

template <class Real>
GizmoId GameBoard<Real>::join(std::unique_ptr<AbstractGizmo<Real>> gizmo) {
  const GizmoId id = static_cast<GizmoId>(gizmos_.size());
  gizmo->setId(id);
  if (gizmo->asBall()) balls_.push_back(id);
  gizmos_.push_back(std::move(gizmo));
  triggerTargets_.emplace_back();
  return id;
}

template <class Real>
GizmoId GameBoard<Real>::addSpawnedBall(const Vec2<Real>& p) {
  std::vector<std::string> names;
  for (std::size_t g = 0; g < gizmos_.size() - spawned_; ++g) names.push_back(gizmos_[g]->name());
  auto ball = std::make_unique<Ball<Real>>(spawnedBallName(static_cast<long long>(gizmos_.size()), names), p, Vec2<Real>());
  ball->setState(now_, p, Vec2<Real>(), params_);
  ++spawned_;
  return join(std::move(ball));
}

template <class Real>
void GameBoard<Real>::setSpawnedCount(std::size_t count) {
  while (spawned_ > count) {
    gizmos_.pop_back();
    balls_.pop_back();
    triggerTargets_.pop_back();
    --spawned_;
  }
  while (spawned_ < count) addSpawnedBall(Vec2<Real>());
  built_ = false;
}

template <class Real>
GizmoId GameBoard<Real>::spawnBall(const Vec2<Real>& p) {
  for (auto& g : gizmos_) {
    const GizmoId id = g->handBackRetiredBall();
    if (id == kNoGizmo) continue;
    ballById(id).release(now_, p, Vec2<Real>(), params_);
    markForRecompute(id);
    return id;
  }
  if (spawned_ >= kMaxSpawnedBalls) return kNoGizmo;
  // A new ball: the per-gizmo tables grow by one, the predictions made so far stand.
  const GizmoId id = addSpawnedBall(p);
  const std::size_t n = gizmos_.size();
  ballIndex_.push_back(std::int32_t(balls_.size() - 1));
  formColliders(n - 1);
  ballCells_.push_back(CellRange{0, -1, 0, -1});
  boxes_.push_back(gizmos_.back()->bounds());
  validUntil_.push_back(infinity());
  stamp_.push_back(0);
  candidateSet_.reset(n);
  markForRecompute(id);
  return id;
}

template <class Real>
void GameBoard<Real>::connect(GizmoId source, GizmoId target) {
  triggerTargets_.at(static_cast<std::size_t>(source)).push_back(target);
}

template <class Real>
void GameBoard<Real>::keyConnect(int key, KeyDirection direction, GizmoId target) {
  keyTargets_[{key, static_cast<int>(direction)}].push_back(target);
}

template <class Real>
std::optional<GizmoId> GameBoard<Real>::find(std::string_view name) const {
  for (const auto& g : gizmos_)
    if (g->name() == name) return g->id();
  return std::nullopt;
}

template <class Real>
Ball<Real>& GameBoard<Real>::ballById(GizmoId id) {
  Ball<Real>* b = gizmo(id).asBall();
  if (!b) throw std::logic_error("gizmo " + std::to_string(id) + " is not a ball");
  return *b;
}


template <class Real>
Real GameBoard<Real>::energy() const {
  Real e(0);
  const Real half = Real(1) / Real(2);
  for (GizmoId id : balls_) {
    const Ball<Real>& b = *gizmos_[static_cast<std::size_t>(id)]->asBall();
    if (b.captured()) continue;
    const Vec2<Real> v = b.velocityAt(now_), p = b.positionAt(now_);
    e += half * lengthSquared(v) + params_.gravity * (Real(kBoardSize) - p.y);
  }
  return e;
}

template <class Real>
bool GameBoard<Real>::roomForBall(const Vec2<Real>& p, GizmoId ball, GizmoId ignore) const {
  const Real r = Ball<Real>::radius(), size(kBoardSize);
  if (p.x - r < Real(0) || size < p.x + r || p.y - r < Real(0) || size < p.y + r) return false;
  const Box<Real> box = Box<Real>::around(p, r);
  for (std::size_t g = 1; g < gizmos_.size(); ++g) {  // the walls (id 0) are checked above
    if (GizmoId(g) == ball || GizmoId(g) == ignore) continue;
    if (const Ball<Real>* other = gizmos_[g]->asBall()) {
      if (!other->captured() && lengthSquared(Vec2<Real>(other->positionAt(now_) - p)) < Real(4) * r * r) return false;
      continue;
    }
    const Box<Real> o = gizmos_[g]->bounds();
    if (box.lo.x < o.hi.x && o.lo.x < box.hi.x && box.lo.y < o.hi.y && o.lo.y < box.hi.y) return false;
  }
  return true;
}

// The other surface is looked for among the gizmos listed in the cells around the ball, and the
// walls (listed in none). Within a minimum bounce's rise, restSpeed²/(2|g|): the farthest the
// bounce that the rule replaces would lift the ball off the surface it struck. (A reach of
// settleRise rested more piles, and made a ball cradled against a flipper that its own hit
// triggered rest and wake every 0.4 ns: campaign seed 3162277660, case 99.) A ball at rest
// (docs/physics.md, "Piles") is a still surface too: a circle of the ball's radius (every ball is
// a candidate; a board holds few enough that the grid is not worth it here).
template <class Real>
bool GameBoard<Real>::cradled(GizmoId ball, const Vec2<Real>& p, const Vec2<Real>& normal, GizmoId by) const {
  if (params_.gravity == Real(0) || !isGizmoId(by)) return false;
  if (!gizmos_[std::size_t(by)]->restingShape() && !ballAtRest(by)) return false;
  const Vec2<Real> gravity(Real(0), params_.gravity);
  const Real r = Ball<Real>::radius();
  const Real rise = params_.restSpeed * params_.restSpeed / (Real(2) * absOf(params_.gravity));
  if (stillFeatureNear(p, rise, by, [&](const Vec2<Real>& towardsBall) {
        return gravityHeldBetween(towardsBall, normal, gravity);
      }))
    return true;
  // Between two balls at rest the reach is settleRise: no gizmo's action is in the V, and the
  // V of two balls of a floor row is so flat that a ball falling into it strikes one side, then
  // the other, long before either is within a minimum bounce's rise of it while it touches the
  // first (many-balls: such a ball struck its two sides about 150 times per 1/60 s before it rested).
  const Real ballRise = ballAtRest(by) ? params_.settleRise : rise;
  for (GizmoId other : balls_) {
    if (other == by || other == ball || !ballAtRest(other)) continue;
    const Vec2<Real> d = p - gizmos_[std::size_t(other)]->asBall()->positionAt(now_);
    const Real most = Real(2) * r + ballRise, dist2 = lengthSquared(d);
    if (Real(0) < dist2 && !(most * most < dist2) && gravityHeldBetween(d, normal, gravity)) return true;
  }
  return false;
}

// The line is followed from ball to ball (the nearest slow one ahead, within 30° of m; ties to
// the lower id) and ends when a still gizmo or the walls lie ahead within settleRise. Slow: a
// speed that would rise less than settleRise against gravity. Products and comparisons only.
template <class Real>
bool GameBoard<Real>::boxedAlong(GizmoId ball, const Vec2<Real>& start, const Vec2<Real>& m, GizmoId behind) const {
  if (params_.gravity == Real(0)) return false;
  const Real r = Ball<Real>::radius();
  const Real reach = params_.settleRise;
  const Real slow2 = Real(2) * params_.settleRise * absOf(params_.gravity);
  // `towards` points from an obstacle to the ball: the obstacle lies ahead, within 30° of m.
  auto ahead = [&](const Vec2<Real>& towards) {
    const Real along = -dot(towards, m);
    return Real(0) < along && !(Real(4) * along * along < Real(3) * lengthSquared(towards));
  };
  const Real most = Real(2) * r + reach;
  GizmoId current = ball;
  Vec2<Real> p = start;
  // Each link advances along m by at least √3·r, so a line is shorter than the board is wide;
  // the count of balls bounds it whatever the geometry.
  for (std::size_t links = 0; links <= balls_.size(); ++links) {
    if (stillFeatureNear(p, reach, kNoGizmo, ahead)) return true;
    GizmoId next = kNoGizmo;
    Vec2<Real> nextAt;
    Real nearest2(0);
    forEachBallNear(Box<Real>::around(p, most + r), [&](GizmoId other) {
      if (other == current || other == behind || other == ball) return;
      const Ball<Real>& o = *gizmos_[std::size_t(other)]->asBall();
      if (o.captured() || !(lengthSquared(o.velocityAt(now_)) < slow2)) return;
      const Vec2<Real> q = o.positionAt(now_);
      const Real dist2 = lengthSquared(Vec2<Real>(q - p));
      if (most * most < dist2 || !ahead(Vec2<Real>(p - q))) return;
      if (next == kNoGizmo || dist2 < nearest2 || (dist2 == nearest2 && other < next)) {
        next = other;
        nextAt = q;
        nearest2 = dist2;
      }
    });
    if (next == kNoGizmo) return false;
    current = next;
    p = nextAt;
  }
  return false;
}

template <class Real>
bool GameBoard<Real>::ballAtRest(GizmoId id) const {
  const Ball<Real>* b = gizmos_[std::size_t(id)]->asBall();
  return b && !b->captured() && b->resting();
}

template <class Real>
std::vector<CollisionPair> GameBoard<Real>::collisionPairs() {
  rebuild();
  std::vector<CollisionPair> pairs;
  for (std::size_t a = 0; a < gizmos_.size(); ++a)
    for (std::size_t b = a + 1; b < gizmos_.size(); ++b) {
      const PairRole r = formPair(*gizmos_[a], *gizmos_[b]);
      if (r == PairRole::FirstCollides) pairs.push_back({GizmoId(a), GizmoId(b)});
      if (r == PairRole::SecondCollides) pairs.push_back({GizmoId(b), GizmoId(a)});
    }
  return pairs;
}

// Each pair's collider is fixed: asked in id order, the first gizmo that can collide.
// The table is formed for the gizmos from `known` on; the rows and columns of those before it
// are kept (a spawned ball adds a row and a column, and the table's width changes with it).
template <class Real>
void GameBoard<Real>::formColliders(std::size_t known) {
  const std::size_t n = gizmos_.size();
  std::vector<Collider> table(balls_.size() * n, Collider::None);
  for (std::size_t i = 0; i < balls_.size() && std::size_t(balls_[i]) < known; ++i)
    std::copy_n(colliders_.begin() + std::ptrdiff_t(i * known), known, table.begin() + std::ptrdiff_t(i * n));
  colliders_.swap(table);
  for (std::size_t i = 0; i < balls_.size(); ++i)
    for (std::size_t g = 0; g < n; ++g) {
      const std::size_t b = static_cast<std::size_t>(balls_[i]);
      if (g == b || (g < known && b < known)) continue;
      const std::size_t lo = std::min(g, b), hi = std::max(g, b);
      const PairRole r = formPair(*gizmos_[lo], *gizmos_[hi]);
      if (r == PairRole::None) continue;
      colliders_[i * n + g] = (r == PairRole::FirstCollides ? lo : hi) == b ? Collider::Ball : Collider::Other;
    }
}

// Forms the pairs and the broad-phase grid, and predicts everything afresh.
template <class Real>
void GameBoard<Real>::rebuild() {
  if (built_) return;
  const std::size_t n = gizmos_.size();
  ballIndex_.assign(n, -1);
  for (std::size_t i = 0; i < balls_.size(); ++i) ballIndex_[static_cast<std::size_t>(balls_[i])] = std::int32_t(i);
  formColliders(0);
  for (auto& cell : grid_) cell.clear();
  for (auto& cell : ballGrid_) cell.clear();
  wideBalls_.clear();
  ballCells_.assign(n, CellRange{0, -1, 0, -1});
  for (std::size_t g = 1; g < n; ++g) {  // the walls (id 0) are checked against the edges instead
    if (gizmos_[g]->asBall()) continue;
    const CellRange c = cellsOf(gizmos_[g]->bounds());
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x) grid_[std::size_t(y * kBoardSize + x)].push_back(GizmoId(g));
  }
  boxes_.assign(n, Box<Real>{});
  for (std::size_t g = 0; g < n; ++g) boxes_[g] = gizmos_[g]->bounds();
  validUntil_.assign(n, infinity());
  stamp_.assign(n, 0);
  candidateSet_.reset(n);
  queue_.clear();
  recompute_.clear();
  built_ = true;
  for (std::size_t g = 0; g < n; ++g) recompute_.push_back(GizmoId(g));
  recomputePending();
}

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
    if (e.kind == EventKind::EndOfTick) break;
  }
  if (observer_) observer_->tickBoundary(now_);
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
      auto it = keyTargets_.find({e.feature, static_cast<int>(dir)});
      if (it != keyTargets_.end())
        for (GizmoId target : it->second) performAction(target);
      break;
    }
    case EventKind::Recalculate:
      recompute_.push_back(e.a);
      break;
    case EventKind::EndOfTick:
      break;
  }
  releaseContactsOfStarted();
  wakeWhatRestsOnStarted();
}

// A ball that leaves rest wakes every ball at rest that it may hold up (docs/physics.md,
// "Piles"): one within settleRise of it (the reach of a V of two balls), with the mover on
// gravity's side of it. A woken ball leaves rest in turn, so a pile wakes from the bottom up. A
// ball that only touches the mover from beside or below wakes too when gravity leans on the mover
// at all: it costs a few events (it settles again), where missing one would leave it hanging in
// the air.
template <class Real>
void GameBoard<Real>::wakeWhatRestsOnStarted() {
  const Real r = Ball<Real>::radius();
  const Real reach = Real(2) * r + params_.settleRise;
  const Vec2<Real> gravity(Real(0), params_.gravity);
  for (std::size_t i = 0; i < recompute_.size(); ++i) {
    if (!isBallId(recompute_[i])) continue;
    Ball<Real>& mover = static_cast<Ball<Real>&>(*gizmos_[std::size_t(recompute_[i])]);
    if (!mover.takeStartedMoving()) continue;
    const Vec2<Real> below = mover.positionAt(now_);
    for (GizmoId id : balls_) {
      Ball<Real>& b = *gizmos_[static_cast<std::size_t>(id)]->asBall();
      if (!b.wedged() || b.captured()) continue;
      const Vec2<Real> d = below - b.positionAt(now_);
      if (reach * reach < lengthSquared(d) || !(Real(0) < dot(d, gravity))) continue;
      b.wake(*this, mover.id());
      recompute_.push_back(id);
    }
  }
}

template <class Real>
void GameBoard<Real>::fireTriggersOf(GizmoId source) {
  if (!gizmo(source).hasTrigger()) return;
  // Copied: an action never changes connections, but the board must not depend on that.
  const std::vector<GizmoId> targets = triggerTargets_[static_cast<std::size_t>(source)];
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

// BoardAccess::releaseContactsOn, once the event's actions are done: each gizmo that started to
// move and is still in motion, in the order they started.
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
      if (b->captured() || b->resting())
        sweepBall(g, infinity());
      else if (!untilNextEvent)
        sweepBall(g, ballHorizon(*b));
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
      if (untilNextEvent && !b->resting()) sweepBall(g, nextEventHorizon());
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
      forEachBallNear(reach, [&](GizmoId ballId) {
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
  else
    boxes_[i] = b.bounds();
  placeBall(id, !b.captured());
}

// The classic model's horizon (docs/physics.md, "The event loop"): every event that takes time
// steps every moving ball (advanceTo) and so predicts its pairs again, and a prediction past the
// earliest event already queued would be removed unrun. On a busy board events come every few
// microseconds, and a sweep to the maximum tick's end met every gizmo and ball of the board.
template <class Real>
Real GameBoard<Real>::nextEventHorizon() {
  const Real horizon = now_ + params_.maxTick;
  if (queue_.empty() || sweepFullTick_) return horizon;
  return minOf(horizon, queue_.top().time);
}

// Before each event of the classic model. After an event that took no time, or one that left a
// ball's velocity as it was (no gravity, no friction), the earliest event can lie past the
// horizon of a ball that was not recomputed: such a ball is predicted again, no time passing,
// to find what a longer sweep would have found. Predicting it again removes its events, and the
// earliest event can then come later than another ball's horizon: hence the rounds. A ball
// predicted again here is swept to the end of the maximum tick, where its recalculation event
// lies, so it needs no second round, and the rounds end.
template <class Real>
void GameBoard<Real>::coverUntilNextEvent() {
  const Real full = now_ + params_.maxTick;
  sweepFullTick_ = true;
  while (!queue_.empty()) {
    const Real next = minOf(queue_.top().time, full);
    for (GizmoId id : balls_) {
      const Ball<Real>& b = *gizmos_[static_cast<std::size_t>(id)]->asBall();
      if (!b.resting() && validUntil_[static_cast<std::size_t>(id)] < next) recompute_.push_back(id);
    }
    if (recompute_.empty()) break;
    recomputePending();
  }
  sweepFullTick_ = false;
}

// How far ahead a moving ball's pairs are predicted: the maximum tick length, or its next
// friction tick when that comes first, since the tick changes its velocity and every prediction
// past it would be removed unrun (on a board with friction most events are friction ticks).
template <class Real>
Real GameBoard<Real>::ballHorizon(Ball<Real>& b) const {
  const Real horizon = now_ + params_.maxTick;
  if (!frictionTicks()) return horizon;
  return minOf(horizon, frictionTickTime(b));
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
  const Real horizon = now_ + params_.maxTick;
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
  const CellRange c = cellsOf(box);
  for (int y = c.y0; y <= c.y1; ++y)
    for (int x = c.x0; x <= c.x1; ++x)
      for (GizmoId g : grid_[std::size_t(y * kBoardSize + x)])
        if (boxes_[static_cast<std::size_t>(g)].overlaps(box)) candidateSet_.insert(g);
  forEachBallNear(box, [&](GizmoId other) {
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

template <class Real>
std::optional<std::string> GameBoard<Real>::setProperty(GizmoId id, std::string_view name, const PropertyValue& value) {
  AbstractGizmo<Real>& g = gizmo(id);
  const std::optional<PropertyValue> old = g.property(name);
  if (!old) return "gizmo '" + g.name() + "' has no property '" + std::string(name) + "'";
  if (!g.setPropertyUnchecked(name, value)) return "value of the wrong kind for property '" + std::string(name) + "'";
  const std::vector<SpecProblem> problems = checkBoardSpec(toSpec());
  if (!problems.empty()) {
    g.setPropertyUnchecked(name, *old);
    return problems.front().message;
  }
  built_ = false;
  return std::nullopt;
}

template <class Real>
BoardSpec GameBoard<Real>::toSpec() const {
  BoardSpec spec;
  spec.gravity = toDouble(params_.gravity);
  spec.mu = toDouble(params_.mu);
  spec.mu2 = toDouble(params_.mu2);
  for (const auto& g : gizmos_) {
    if (const Ball<Real>* b = g->asBall()) spec.balls.push_back(b->ballSpec(now_));
    else if (g->id() != outerWallsId()) spec.gizmos.push_back(g->spec());
  }
  for (std::size_t s = 0; s < triggerTargets_.size(); ++s)
    for (GizmoId t : triggerTargets_[s])
      spec.connections.push_back(ConnectSpec{gizmos_[s]->name(), gizmo(t).name(), SourcePos{}});
  for (const auto& [key, targets] : keyTargets_)
    for (GizmoId t : targets)
      spec.keyConnections.push_back(
          KeyConnectSpec{key.first, static_cast<KeyDirection>(key.second), gizmo(t).name(), SourcePos{}});
  return spec;
}

}  // namespace gizmo
