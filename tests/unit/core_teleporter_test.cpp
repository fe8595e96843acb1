// The teleporter and the portal (docs/physics.md, "Gizmos other programs added"): their exits,
// the pass through computed by hand, and where each is a plain circle bumper instead.
#include <gtest/gtest.h>

#include "gizmo/core/gizmos/teleporter.hpp"
#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using namespace test;

// Teleporter A in cell (4, 10), centre (4.5, 10.5); B in cell (14, 4), centre (14.5, 4.5). A ball
// at (1.5, 10.5) moving right at 10 L/s touches A when its centre is 0.75 short of A's centre,
// at (3.75, 10.5), after 0.225 s. It leaves B opposite that point, at (14.5 + 0.75, 4.5), still
// at (10, 0), so 0.075 s later it is at (16, 4.5).
BoardSpec twoTeleporters(const char* exit) {
  BoardSpec spec = emptyBoard(0, 0, 0);
  spec.gizmos.push_back(gizmoAt(GizmoType::Teleporter, "A", 4, 10));
  spec.gizmos.push_back(gizmoAt(GizmoType::Teleporter, "B", 14, 4));
  if (exit) spec.connections.push_back(ConnectSpec{"A", exit, {}});
  spec.balls.push_back(ballAt("K", 1.5, 10.5, 10, 0));
  return spec;
}

TEST(Teleporter, APassThroughByHand) {
  auto board = build(twoTeleporters("B"));
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.3);
  const GizmoId a = *board->find("A"), k = *board->find("K");
  ASSERT_EQ(rec.ofKind(EventKind::Collision).size(), 1u);
  EXPECT_EQ(rec.ofKind(EventKind::Collision)[0].event.a, a);
  EXPECT_DOUBLE_EQ(rec.ofKind(EventKind::Collision)[0].event.time, 0.225);
  ASSERT_EQ(rec.countRule(TeleporterRule::Teleported), 1);
  EXPECT_EQ(rec.rules[0], std::make_pair(TeleporterRule::Teleported, a));
  const Ball<double>& ball = board->ballById(k);
  EXPECT_EQ(ball.velocityAt(board->now()), Vec2<double>(10, 0));
  EXPECT_NEAR(ball.positionAt(board->now()).x, 16, 1e-12);
  EXPECT_EQ(ball.positionAt(board->now()).y, 4.5);
}

// Its own exit: the ball comes out of the far side of the same disc, at (5.25, 10.5).
TEST(Teleporter, ItsOwnExitLetsTheBallThrough) {
  auto board = build(twoTeleporters("A"));
  board->tick(0.3);
  const Ball<double>& ball = board->ballById(*board->find("K"));
  EXPECT_EQ(ball.velocityAt(board->now()), Vec2<double>(10, 0));
  EXPECT_NEAR(ball.positionAt(board->now()).x, 6.0, 1e-12);
}

// Without an exit, or with a square beside the exit in the way, it is a circle bumper: the ball
// bounces straight back.
TEST(Teleporter, WithoutARoomyExitItIsACircleBumper) {
  BoardSpec blocked = twoTeleporters("B");
  blocked.gizmos.push_back(gizmoAt(GizmoType::Square, "S", 15, 4));
  for (const BoardSpec& spec : {twoTeleporters(nullptr), blocked}) {
    auto board = build(spec);
    Recorder<double> rec;
    board->setObserver(&rec);
    board->tick(0.3);
    EXPECT_EQ(rec.countRule(TeleporterRule::Teleported), 0);
    const Ball<double>& ball = board->ballById(*board->find("K"));
    EXPECT_EQ(ball.velocityAt(board->now()), Vec2<double>(-10, 0));
    EXPECT_NEAR(ball.positionAt(board->now()).x, 3.0, 1e-12);
  }
}

// The exit is the first teleporter a teleporter is connected to; other connections trigger as
// usual.
TEST(Teleporter, TheFirstTeleporterConnectedIsTheExit) {
  BoardSpec spec = twoTeleporters(nullptr);
  spec.gizmos.push_back(gizmoAt(GizmoType::Square, "S", 10, 15));
  spec.gizmos.push_back(gizmoAt(GizmoType::Teleporter, "C", 10, 2));
  spec.connections.push_back(ConnectSpec{"A", "S", {}});
  spec.connections.push_back(ConnectSpec{"A", "B", {}});
  spec.connections.push_back(ConnectSpec{"A", "C", {}});
  auto board = build(spec);
  const auto& a = dynamic_cast<const Teleporter<double>&>(board->gizmo(*board->find("A")));
  EXPECT_EQ(a.exit(), board->find("B"));
  EXPECT_EQ(a.exitPosition(Vec2<double>(3.75, 10.5)), Vec2<double>(15.25, 4.5));
  const auto& c = dynamic_cast<const Teleporter<double>&>(board->gizmo(*board->find("C")));
  EXPECT_EQ(c.exit(), std::nullopt);
}

// Portal A in cell (4, 10), exit cell (14, 4) given by the board file: the same pass as a
// teleporter A connected to a teleporter B in that cell, with nothing in the exit cell but the
// ball that comes out there.
BoardSpec portal(int exitX, int exitY) {
  BoardSpec spec = emptyBoard(0, 0, 0);
  GizmoSpec a = gizmoAt(GizmoType::Portal, "A", 4, 10);
  a.exitX = exitX;
  a.exitY = exitY;
  spec.gizmos.push_back(a);
  spec.balls.push_back(ballAt("K", 1.5, 10.5, 10, 0));
  return spec;
}

TEST(Portal, APassThroughByHand) {
  auto board = build(portal(14, 4));
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.3);
  const GizmoId a = *board->find("A");
  EXPECT_EQ(board->gizmo(a).kind(), GizmoKind::Portal);
  ASSERT_EQ(rec.ofKind(EventKind::Collision).size(), 1u);
  EXPECT_DOUBLE_EQ(rec.ofKind(EventKind::Collision)[0].event.time, 0.225);
  ASSERT_EQ(rec.countRule(TeleporterRule::Teleported), 1);
  EXPECT_EQ(rec.rules[0], std::make_pair(TeleporterRule::Teleported, a));
  const Ball<double>& ball = board->ballById(*board->find("K"));
  EXPECT_EQ(ball.velocityAt(board->now()), Vec2<double>(10, 0));
  EXPECT_NEAR(ball.positionAt(board->now()).x, 16, 1e-12);
  EXPECT_EQ(ball.positionAt(board->now()).y, 4.5);
}

// A connection does not change a portal's exit; a gizmo in the exit cell's way makes the portal
// a circle bumper.
TEST(Portal, ItsExitIsTheCellItsLineNames) {
  BoardSpec connected = portal(14, 4);
  connected.gizmos.push_back(gizmoAt(GizmoType::Teleporter, "T", 2, 2));
  connected.connections.push_back(ConnectSpec{"A", "T", {}});
  auto board = build(connected);
  const auto& a = dynamic_cast<const Teleporter<double>&>(board->gizmo(*board->find("A")));
  EXPECT_EQ(a.exit(), std::nullopt);
  EXPECT_TRUE(a.hasExit());
  EXPECT_EQ(a.exitPosition(Vec2<double>(3.75, 10.5)), Vec2<double>(15.25, 4.5));

  BoardSpec blocked = portal(14, 4);
  blocked.gizmos.push_back(gizmoAt(GizmoType::Square, "S", 15, 4));
  auto bumper = build(blocked);
  Recorder<double> rec;
  bumper->setObserver(&rec);
  bumper->tick(0.3);
  EXPECT_EQ(rec.countRule(TeleporterRule::Teleported), 0);
  EXPECT_EQ(bumper->ballById(*bumper->find("K")).velocityAt(bumper->now()), Vec2<double>(-10, 0));
}

}  // namespace
}  // namespace gizmo
