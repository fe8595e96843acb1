#pragma once
// GameBoard: building the board (adding gizmos and connections, forming the pairs and the broad
// phase), growing it by a spawned ball as it runs, changing a property, and writing it back as a
// spec.
// Included only by the explicit instantiations (core/src/instantiate.hpp).
#include <memory>
#include <string>
#include <vector>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/gizmos/outer_walls.hpp"

namespace gizmo {

template <class Real>
GameBoard<Real>::GameBoard(const PhysicsParams<Real>& params) : params_(params) {
  add(std::make_unique<OuterWalls<Real>>());
}

template <class Real>
GameBoard<Real>::~GameBoard() = default;

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
  triggers_.addSource();
  return id;
}

template <class Real>
GizmoId GameBoard<Real>::addSpawnedBall(const Vec2<Real>& p) {
  std::vector<std::string> names;
  for (std::size_t g = 0; g < gizmos_.size() - spawned_; ++g) names.push_back(gizmos_[g]->name());
  auto ball =
      std::make_unique<Ball<Real>>(spawnedBallName(static_cast<long long>(gizmos_.size()), names), p, Vec2<Real>());
  ball->setState(now_, p, Vec2<Real>(), params_);
  ++spawned_;
  return join(std::move(ball));
}

template <class Real>
void GameBoard<Real>::setSpawnedCount(std::size_t count) {
  while (spawned_ > count) {
    gizmos_.pop_back();
    balls_.pop_back();
    triggers_.removeLastSource();
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
  colliders_.form(gizmos_, balls_, n - 1);
  broadPhase_.grow();
  boxes_.push_back(gizmos_.back()->bounds());
  validUntil_.push_back(infinity());
  stamp_.push_back(0);
  extendedIn_.push_back(0);
  candidateSet_.reset(n);
  markForRecompute(id);
  return id;
}

template <class Real>
void GameBoard<Real>::connect(GizmoId source, GizmoId target) {
  triggers_.connect(source, target);
}

template <class Real>
void GameBoard<Real>::keyConnect(int key, KeyDirection direction, GizmoId target) {
  triggers_.keyConnect(key, direction, target);
}

template <class Real>
std::vector<CollisionPair> GameBoard<Real>::collisionPairs() {
  rebuild();
  return collisionPairsOf(gizmos_);
}

// Forms the pairs and the broad-phase grid, and predicts everything afresh.
template <class Real>
void GameBoard<Real>::rebuild() {
  if (built_) return;
  const std::size_t n = gizmos_.size();
  ballIndex_.assign(n, -1);
  for (std::size_t i = 0; i < balls_.size(); ++i) ballIndex_[static_cast<std::size_t>(balls_[i])] = std::int32_t(i);
  colliders_.form(gizmos_, balls_, 0);
  broadPhase_.reset(n);
  for (std::size_t g = 1; g < n; ++g)  // the walls (id 0) are checked against the edges instead
    if (!gizmos_[g]->asBall()) broadPhase_.addFixed(GizmoId(g), gizmos_[g]->bounds());
  boxes_.assign(n, Box<Real>{});
  for (std::size_t g = 0; g < n; ++g) boxes_[g] = gizmos_[g]->bounds();
  validUntil_.assign(n, infinity());
  stamp_.assign(n, 0);
  extendedIn_.assign(n, 0);
  candidateSet_.reset(n);
  queue_.clear();
  recompute_.clear();
  built_ = true;
  for (std::size_t g = 0; g < n; ++g) recompute_.push_back(GizmoId(g));
  recomputePending();
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
  triggers_.forEachConnection([&](GizmoId source, GizmoId target) {
    spec.connections.push_back(ConnectSpec{gizmo(source).name(), gizmo(target).name(), SourcePos{}});
  });
  triggers_.forEachKeyConnection([&](int key, KeyDirection direction, GizmoId target) {
    spec.keyConnections.push_back(KeyConnectSpec{key, direction, gizmo(target).name(), SourcePos{}});
  });
  return spec;
}

}  // namespace gizmo
