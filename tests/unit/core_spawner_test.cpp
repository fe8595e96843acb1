// The spawner (docs/physics.md, "Gizmos other programs added"): a cell that nothing meets, whose
// action puts a ball at rest at its centre: a ball a sink holds if there is one, else a new ball
// of the board, which saved states carry.
#include <gtest/gtest.h>

#include <cmath>

#include "gizmo/core/gizmos/sink.hpp"
#include "gizmo/core/gizmos/spawner.hpp"
#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using namespace test;

// Spawner P in cell (5, 5), centre (5.5, 5.5), fired by key 32 going down.
BoardSpec keyedSpawner(double gravity) {
  BoardSpec spec = emptyBoard(gravity, 0, 0);
  spec.gizmos.push_back(gizmoAt(GizmoType::Spawner, "P", 5, 5));
  spec.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "P", {}});
  return spec;
}

std::size_t count(const Recorder<double>& rec, ModelRule rule) {
  std::size_t n = 0;
  for (const auto& [r, g] : rec.rules) n += r == rule;
  return n;
}

TEST(Spawner, AKeyPutsANewBallAtRestAtItsCentre) {
  auto board = build(keyedSpawner(25));
  Recorder<double> rec;
  board->setObserver(&rec);
  board->scheduleInput(0.1, 32, KeyDirection::Down);
  board->tick(0.3);
  ASSERT_EQ(board->ballIds().size(), 1u);
  const GizmoId id = board->ballIds()[0];
  EXPECT_EQ(id, 2);  // after the walls and the spawner
  const Ball<double>& ball = board->ballById(id);
  EXPECT_EQ(ball.name(), "Spawned2");
  EXPECT_EQ(count(rec, SpawnerRule::Spawned), 1u);
  // At rest at (5.5, 5.5) at t = 0.1, then 0.2 s of falling: ½ · 25 · 0.2² = 0.5 L lower.
  EXPECT_DOUBLE_EQ(ball.positionAt(0.1).y, 5.5);
  EXPECT_NEAR(ball.positionAt(board->now()).x, 5.5, 1e-15);
  EXPECT_NEAR(ball.positionAt(board->now()).y, 6.0, 1e-12);
  EXPECT_NEAR(ball.velocityAt(board->now()).y, 5.0, 1e-12);
}

TEST(Spawner, ABallStillAtItsCentreBlocksTheNextOne) {
  auto board = build(keyedSpawner(0));
  Recorder<double> rec;
  board->setObserver(&rec);
  board->scheduleInput(0.1, 32, KeyDirection::Down);
  board->scheduleInput(0.2, 32, KeyDirection::Down);
  board->tick(0.3);
  EXPECT_EQ(board->ballIds().size(), 1u);
  EXPECT_EQ(count(rec, SpawnerRule::Spawned), 1u);
  EXPECT_EQ(count(rec, SpawnerRule::Blocked), 1u);
}

TEST(Spawner, BallsPassThroughIt) {
  BoardSpec spec = keyedSpawner(0);
  spec.balls.push_back(ballAt("B", 2, 5.5, 10, 0));
  auto board = build(spec);
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.5);
  EXPECT_TRUE(rec.ofKind(EventKind::Collision).empty());
  EXPECT_NEAR(board->ballById(*board->find("B")).positionAt(board->now()).x, 7, 1e-12);
}

// A ball falls onto sink K, whose trigger fires the spawner: the spawner takes the ball the sink
// holds, so the board keeps its one ball, now at the spawner's centre.
TEST(Spawner, ItTakesTheBallASinkHoldsBeforeAddingOne) {
  BoardSpec spec = keyedSpawner(25);
  spec.gizmos.push_back(gizmoAt(GizmoType::Sink, "K", 10, 10));
  spec.connections.push_back(ConnectSpec{"K", "P", {}});
  spec.balls.push_back(ballAt("B", 10.5, 5));
  auto board = build(spec);
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.7);  // it meets the sink's top (centre at y = 9.75) after sqrt(2 · 4.75 / 25) s
  const double hit = std::sqrt(2 * 4.75 / 25);
  ASSERT_EQ(count(rec, SinkRule::Sunk), 1u);
  ASSERT_EQ(count(rec, SpawnerRule::Spawned), 1u);
  ASSERT_EQ(board->ballIds().size(), 1u);
  const Ball<double>& ball = board->ballById(*board->find("B"));
  EXPECT_FALSE(ball.captured());
  const double fallen = 0.5 * 25 * (0.7 - hit) * (0.7 - hit);
  EXPECT_NEAR(ball.positionAt(board->now()).x, 5.5, 1e-12);
  EXPECT_NEAR(ball.positionAt(board->now()).y, 5.5 + fallen, 1e-9);
}

// The spawned balls are part of a saved state: restored onto a new board, or onto the same board
// after it spawned more, the run goes on as it did.
TEST(Spawner, SavedStatesCarryTheSpawnedBalls) {
  const BoardSpec spec = keyedSpawner(25);
  auto schedule = [](GameBoard<double>& b) {
    for (double t : {0.1, 0.5, 0.9}) b.scheduleInput(t, 32, KeyDirection::Down);
  };
  auto original = build(spec);
  schedule(*original);
  original->tick(0.05);
  const BoardState<double> before = original->saveState();
  original->tick(0.25);
  const BoardState<double> after = original->saveState();
  original->tick(0.9);
  ASSERT_EQ(original->ballIds().size(), 3u);
  auto positions = [](const GameBoard<double>& b) {
    std::vector<std::pair<std::string, double>> out;
    for (GizmoId id : b.ballIds()) out.emplace_back(b.gizmo(id).name(), b.gizmo(id).asBall()->positionAt(b.now()).y);
    return out;
  };
  const auto expected = positions(*original);

  auto fresh = build(spec);
  schedule(*fresh);
  fresh->restoreState(after);
  EXPECT_EQ(fresh->ballIds().size(), 1u);
  fresh->tick(0.9);
  EXPECT_EQ(positions(*fresh), expected);

  original->restoreState(before);  // back to before the first spawn: the three balls go
  EXPECT_EQ(original->ballIds().size(), 0u);
  original->tick(1.15);
  EXPECT_EQ(positions(*original), expected);
}

// Fired by every hit on the walls, the spawner's balls make more hits and more balls: it adds
// kMaxSpawnedBalls and no more, and says so each time after.
TEST(Spawner, AddsAtMostItsLimitOfNewBalls) {
  BoardSpec spec = keyedSpawner(25);
  spec.connections.push_back(ConnectSpec{kOuterWallsName, "P", {}});
  spec.balls.push_back(ballAt("B", 2, 2, 20, 0));
  auto board = build(spec);
  Recorder<double> rec;
  board->setObserver(&rec);
  for (int second = 0; second < 120 && board->ballIds().size() <= kMaxSpawnedBalls; ++second) board->tick(1);
  ASSERT_EQ(board->ballIds().size(), 1 + kMaxSpawnedBalls);
  const std::size_t blocked = count(rec, SpawnerRule::Blocked);
  board->tick(2);
  EXPECT_EQ(board->ballIds().size(), 1 + kMaxSpawnedBalls);
  EXPECT_EQ(count(rec, SpawnerRule::Spawned), kMaxSpawnedBalls);
  EXPECT_GT(count(rec, SpawnerRule::Blocked), blocked);
}

TEST(Spawner, ABoardWithoutOneRefusesAStateWithSpawnedBalls) {
  auto spawning = build(keyedSpawner(25));
  spawning->scheduleInput(0.1, 32, KeyDirection::Down);
  spawning->tick(0.2);
  const BoardState<double> state = spawning->saveState();
  BoardSpec squares = keyedSpawner(25);
  squares.gizmos[0].type = GizmoType::Square;
  auto board = build(squares);
  EXPECT_THROW(board->restoreState(state), StateError);
}

}  // namespace
}  // namespace gizmo
