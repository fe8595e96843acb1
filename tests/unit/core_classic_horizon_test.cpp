// The classic model's horizon (docs/physics.md, "The classic model's horizon (decided)"): a
// recomputed ball is predicted only up to the earliest event queued, and before each event every
// moving ball whose horizon that event passes is predicted again. The boards here make that
// happen at every tick: a ball that a step leaves at the velocity it had (falling at its terminal
// speed under strong friction, or moving with no force at all) is not recomputed by the step, so
// its horizon is often another ball's event, which can be removed before it runs. A prediction
// missed there lets a ball through a wall: every ball must be on the board at every tick's end,
// and must have met a wall by the end.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using test::ballAt;
using test::build;
using test::emptyBoard;
using test::Recorder;

void runChecked(const BoardSpec& s, double tick, double seconds, const std::string& what) {
  auto board = build(s, MotionModel::Classic, tick);
  Recorder<double> rec;
  board->setObserver(&rec);
  const double lo = 0.25 - 1e-9, hi = 19.75 + 1e-9;
  for (int k = 0; k * tick < seconds; ++k) {
    board->tick(tick);
    for (const BallSpec& spec : s.balls) {
      const Vec2<double> p = board->ballById(*board->find(spec.name)).positionAt(board->now());
      ASSERT_TRUE(lo <= p.x && p.x <= hi && lo <= p.y && p.y <= hi)
          << what << ": ball " << spec.name << " at (" << p.x << ", " << p.y << ") after t = " << board->now();
    }
  }
  std::set<GizmoId> metAWall;
  for (const auto& e : rec.ofKind(EventKind::Collision))
    if (e.event.a == board->outerWallsId() || e.event.b == board->outerWallsId())
      metAWall.insert(e.event.a == board->outerWallsId() ? e.event.b : e.event.a);
  for (const BallSpec& spec : s.balls)
    EXPECT_TRUE(metAWall.count(*board->find(spec.name))) << what << ": ball " << spec.name << " never met a wall";
}

// Fuzz case 898 of seed 3302773171 is the first board: two balls falling at their terminal speed
// (friction 5 and 5), one of them onto the floor, which it passed when its horizon was the other
// ball's recalculation and that was moved later by the other's own extension.
TEST(ClassicHorizon, BallsFallingAtTerminalSpeedMeetTheFloor) {
  for (const double gravity : {24.067580009148458, 5.0, 60.0, 250.0})
    for (const double tick : {0.05, 0.01, 0.003}) {
      BoardSpec s = emptyBoard(gravity, 5, 5);
      s.balls.push_back(ballAt("B26", 18.5, 5.918560312366653));
      s.balls.push_back(ballAt("B27", 14.5, 18.408332124036104));
      s.balls.push_back(ballAt("C", 3.25, 12.3));
      s.balls.push_back(ballAt("D", 9.75, 16.1, 0, -1));
      runChecked(s, tick, 30, "gravity " + std::to_string(gravity) + ", tick " + std::to_string(tick));
    }
}

// No force: no step ever changes a velocity, so only a ball's own events recompute it.
TEST(ClassicHorizon, BallsWithoutForcesStayOnTheBoard) {
  for (const double tick : {0.05, 0.01}) {
    BoardSpec s = emptyBoard(0, 0, 0);
    s.balls.push_back(ballAt("A", 2.5, 2.5, 3.1, 0.7));
    s.balls.push_back(ballAt("B", 17.5, 4.5, -0.9, 2.3));
    s.balls.push_back(ballAt("C", 10.25, 10.25, 0, -7.3));
    s.balls.push_back(ballAt("D", 6.5, 16.5, 11.9, 0.01));
    s.balls.push_back(ballAt("E", 14.0, 18.0, -0.3, -0.2));
    runChecked(s, tick, 60, "no forces, tick " + std::to_string(tick));
  }
}

}  // namespace
}  // namespace gizmo
