// A ball in a V of two still surfaces (docs/physics.md, "A ball in a V of two surfaces"): the
// geometry that recognises it, and the rule that brings such a ball to rest.
#include <gtest/gtest.h>

#include <cmath>

#include "gizmo/core/geometry/cradle.hpp"
#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using test::ballAt;
using test::build;
using test::emptyBoard;
using test::gizmoAt;
using test::Recorder;

const Vec2<double> kGravity(0, 25);  // y down

TEST(Cradle, GravityIsHeldOnlyInsideTheConeOfTheTwoNormals) {
  // The two upper slopes of a V, either order, any length.
  EXPECT_TRUE(gravityHeldBetween(Vec2<double>(1, -1), Vec2<double>(-1, -1), kGravity));
  EXPECT_TRUE(gravityHeldBetween(Vec2<double>(-3, -3), Vec2<double>(0.5, -0.5), kGravity));
  // Both normals lean one way: the ball rolls off that side.
  EXPECT_FALSE(gravityHeldBetween(Vec2<double>(1, -1), Vec2<double>(1, -0.1), kGravity));
  // Up lies on the edge of the cone (a floor and a wall): not strictly inside.
  EXPECT_FALSE(gravityHeldBetween(Vec2<double>(0, -1), Vec2<double>(1, 0), kGravity));
  // Parallel or opposite normals hold nothing; a V upside down holds nothing.
  EXPECT_FALSE(gravityHeldBetween(Vec2<double>(0, -1), Vec2<double>(0, -2), kGravity));
  EXPECT_FALSE(gravityHeldBetween(Vec2<double>(1, 0), Vec2<double>(-1, 0), kGravity));
  EXPECT_FALSE(gravityHeldBetween(Vec2<double>(1, 1), Vec2<double>(-1, 1), kGravity));
}

TEST(Cradle, OnlyAFeatureWithinReachOnItsFreeSideCounts) {
  Shape<double> shape;
  shape.segments.push_back(makeSegment(Vec2<double>(0, 10), Vec2<double>(4, 10)));  // normal (0, -1): free side above
  shape.circles.push_back(CircleFeature<double>{Vec2<double>(8, 10), 0.5});
  const double r = 0.25, reach = 1e-3;
  auto found = [&](const Vec2<double>& p) {
    return anyFeatureWithin(shape, p, r, reach, [](const Vec2<double>&) { return true; });
  };
  EXPECT_TRUE(found(Vec2<double>(2, 9.75)));     // touching the edge
  EXPECT_TRUE(found(Vec2<double>(2, 9.7495)));   // within reach above it
  EXPECT_FALSE(found(Vec2<double>(2, 9.7485)));  // beyond reach
  EXPECT_FALSE(found(Vec2<double>(2, 10.25)));   // behind the edge
  EXPECT_FALSE(found(Vec2<double>(4.1, 9.75)));  // past its end: its vertex's business
  EXPECT_TRUE(found(Vec2<double>(8, 9.2495)));   // within reach of the circle
  EXPECT_FALSE(found(Vec2<double>(8, 9.2485)));  // beyond it
  // The direction handed over: the edge's normal, or the offset from the circle's centre.
  Vec2<double> seen;
  anyFeatureWithin(shape, Vec2<double>(8.75, 10), r, reach, [&](const Vec2<double>& d) {
    seen = d;
    return true;
  });
  EXPECT_EQ(seen, Vec2<double>(0.75, 0));
}

// The ball of the next two tests, moving at 0.3 L/s beside circle C2 and, when `withC1`, in the
// V it makes with C1, with strong friction; watched by `rec` for `seconds`.
std::unique_ptr<GameBoard<double>> ballBesideCircles(bool withC1, Recorder<double>& rec, double seconds) {
  BoardSpec s = emptyBoard(25, 0.5, 0.5);
  if (withC1) s.gizmos.push_back(gizmoAt(GizmoType::Circle, "C1", 5, 10));
  s.gizmos.push_back(gizmoAt(GizmoType::Circle, "C2", 6, 10));
  s.balls.push_back(ballAt("B", 6.0, 9.93, 0.3, 0));
  auto board = build(s, MotionModel::Ballistic);
  board->setObserver(&rec);
  board->tick(seconds);
  return board;
}

// Two circle bumpers side by side make a V on top, where a ball touches both at W = (6, 10.5 −
// √(0.75² − 0.5²)). A ball set moving in it is trapped (climbing out takes 3 L/s); friction takes
// its bounces down to the minimum bounce, which would then rattle it between the circles for as
// long as the run lasts. It comes to rest instead, touching one circle and within the minimum
// bounce's rise, restSpeed²/(2g) = 2e-6 L, of the other: within rise / sin(83.6°) of W, the angle
// between the normals there. Ballistic only: the classic model's step gains up to ½g²dt² per
// step and throws the ball out of so shallow a V (the seed's method; docs/physics.md §6).
TEST(Cradle, ABallRattlingInTheVOfTwoCirclesComesToRestThere) {
  Recorder<double> rec;
  const auto board = ballBesideCircles(true, rec, 60.0);
  EXPECT_EQ(rec.countRule(ModelRule::Wedged), 1);
  const Ball<double>& ball = board->ballById(*board->find("B"));
  EXPECT_EQ(ball.velocityAt(board->now()), Vec2<double>());
  const Vec2<double> w(6, 10.5 - std::sqrt(0.75 * 0.75 - 0.5 * 0.5));
  const double rise = 0.01 * 0.01 / (2 * 25);
  EXPECT_LE(length(Vec2<double>(ball.positionAt(board->now()) - w)), rise / std::sin(83.6 * M_PI / 180));
}

// The same ball in the same place without the second circle: one round surface holds nothing,
// and the ball rolls off it (no rule applies).
TEST(Cradle, OneCircleAloneIsNoV) {
  Recorder<double> rec;
  const auto board = ballBesideCircles(false, rec, 5.0);
  EXPECT_EQ(rec.countRule(ModelRule::Wedged), 0);
  EXPECT_GT(board->ballById(*board->find("B")).positionAt(board->now()).y, 11.0);
}

// A ball that slides down a triangle's slope into a still flipper's side rests in that V
// (`Wedged`: the two-segment rule). When the flipper swings away, nothing holds the ball up any
// more: it wakes and slides on down the slope. Before, it hung in the air where it had rested.
// Ballistic only: in the classic model the ball, dropped onto the slope, bounces out of the V.
TEST(Cradle, ABallRestingAgainstAFlipperWakesWhenTheFlipperSwingsAway) {
  for (const MotionModel model : {MotionModel::Ballistic}) {
    BoardSpec s = emptyBoard(25, 0.5, 0.5);
    s.gizmos.push_back(gizmoAt(GizmoType::Triangle, "T", 6, 12, 180));  // slope from (7, 12) down to (6, 13)
    s.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "F", 4, 11));   // its side at x = 6 while still
    s.balls.push_back(ballAt("B", 6.3, 12.2));
    s.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "F", {}});
    auto board = build(s, model);
    board->tick(19.0);
    const Ball<double>& ball = board->ballById(*board->find("B"));
    ASSERT_TRUE(ball.wedged()) << motionModelName(model);
    const Vec2<double> rest = ball.positionAt(board->now());
    EXPECT_NEAR(rest.x, 6.25, 1e-9) << motionModelName(model);
    board->scheduleInput(20.0, 32, KeyDirection::Down);
    board->tick(1.05);
    EXPECT_FALSE(ball.wedged()) << motionModelName(model);
    board->tick(1.0);
    EXPECT_GT(ball.positionAt(board->now()).y, rest.y + 0.5) << motionModelName(model);
  }
}

}  // namespace
}  // namespace gizmo
