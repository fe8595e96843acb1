// The sink (docs/physics.md, "Gizmos other programs added"): a ball that hits it is out of play
// for good, held at its centre; the hit fires the sink's triggers (reading and writing it:
// io_text_reader_test.cpp).
#include <gtest/gtest.h>

#include "gizmo/core/gizmos/sink.hpp"
#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using namespace test;

// A ball at (9.5, 10) falling at 10 L/s meets the sink's top face y = 12 when its centre is at
// 11.75: after 0.175 s, in both models (no gravity: each moves in a straight line).
TEST(Sink, AFallingBallIsTakenOutOfPlayAtItsCentre) {
  for (const MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    BoardSpec spec = emptyBoard(0, 0, 0);
    spec.gizmos.push_back(gizmoAt(GizmoType::Sink, "K", 9, 12));
    spec.balls.push_back(ballAt("B", 9.5, 10, 0, 10));
    auto board = build(spec, model);
    Recorder<double> rec;
    board->setObserver(&rec);
    board->tick(1.0);
    const GizmoId k = *board->find("K"), b = *board->find("B");
    const std::vector<Recorder<double>::Executed> hits = rec.ofKind(EventKind::Collision);
    ASSERT_EQ(hits.size(), 1u) << motionModelName(model);
    EXPECT_EQ(hits[0].event.a, k);
    EXPECT_NEAR(hits[0].event.time, 0.175, 1e-14);
    ASSERT_EQ(rec.countRule(SinkRule::Sunk), 1);
    EXPECT_EQ(rec.rules.front().second, k);
    const Ball<double>& ball = board->ballById(b);
    EXPECT_TRUE(ball.captured());
    EXPECT_EQ(ball.positionAt(board->now()), Vec2<double>(9.5, 12.5));
    EXPECT_EQ(ball.velocityAt(board->now()), Vec2<double>());
    EXPECT_EQ(board->energy(), 0.0);  // a ball out of play has none
  }
}

// Under gravity a sunk ball stays where the sink holds it, and a second ball that comes the same
// way is taken too: the first one, out of play, is in nobody's way.
TEST(Sink, ItTakesEveryBallAndHoldsThemForGood) {
  BoardSpec spec = emptyBoard(25, 0, 0);
  spec.gizmos.push_back(gizmoAt(GizmoType::Sink, "K", 9, 12));
  spec.balls.push_back(ballAt("B1", 9.5, 10, 0, 0));
  spec.balls.push_back(ballAt("B2", 9.5, 6, 0, 0));
  auto board = build(spec);
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(5.0);
  EXPECT_EQ(rec.countRule(SinkRule::Sunk), 2);
  EXPECT_EQ(rec.ofKind(EventKind::Collision).size(), 2u);
  for (const char* name : {"B1", "B2"}) {
    const Ball<double>& ball = board->ballById(*board->find(name));
    EXPECT_TRUE(ball.captured()) << name;
    EXPECT_EQ(ball.positionAt(board->now()), Vec2<double>(9.5, 12.5)) << name;
  }
}

// lheckemann's logic-gate boards connect sinks to other gizmos: the hit fires the sink's trigger.
TEST(Sink, TheHitFiresItsTriggers) {
  BoardSpec spec = emptyBoard(0, 0, 0);
  spec.gizmos.push_back(gizmoAt(GizmoType::Sink, "K", 9, 12));
  spec.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "F", 2, 2));
  spec.connections.push_back(ConnectSpec{"K", "F", {}});
  spec.balls.push_back(ballAt("B", 9.5, 10, 0, 10));
  auto board = build(spec);
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.2);
  const GizmoId k = *board->find("K"), f = *board->find("F");
  ASSERT_EQ(rec.triggers.size(), 1u);
  EXPECT_EQ(rec.triggers[0], std::make_pair(k, f));
  ASSERT_EQ(rec.actions.size(), 1u);
  EXPECT_EQ(rec.actions[0], f);
}

}  // namespace
}  // namespace gizmo
