// checkBoardSpec on boards built in code, as the simulator's property system will use it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gizmo/core/board_spec_check.hpp"

namespace gizmo {
namespace {

std::vector<std::string> messages(const BoardSpec& b) {
  std::vector<std::string> out;
  for (const SpecProblem& p : checkBoardSpec(b)) out.push_back(p.message);
  return out;
}

GizmoSpec square(const std::string& name, int x, int y, SourcePos where = {}) {
  return GizmoSpec{GizmoType::Square, name, x, y, 0, 1, 1, where};
}
BallSpec ball(const std::string& name, double x, double y, SourcePos where = {}) {
  return BallSpec{name, x, y, 0, 0, where};
}

TEST(CheckBoardSpec, AnEmptyBoardIsValid) { EXPECT_TRUE(checkBoardSpec(BoardSpec{}).empty()); }

TEST(CheckBoardSpec, NamingIsNotDecidedHere) {
  BoardSpec b;
  b.gizmos.push_back(square("Square(1,2)", 1, 1));
  b.balls.push_back(ball("a ball", 5, 5));
  EXPECT_TRUE(checkBoardSpec(b).empty());
}

TEST(CheckBoardSpec, BoardWideNumbers) {
  BoardSpec b;
  b.gravity = std::numeric_limits<double>::quiet_NaN();
  b.mu = -1;
  b.mu2 = std::numeric_limits<double>::infinity();
  EXPECT_EQ(messages(b), (std::vector<std::string>{"gravity is not a finite number",
                                                   "friction mu is -1; friction constants cannot be negative",
                                                   "friction mu2 is not a finite number"}));
  b = BoardSpec{};
  b.gravity = -1e7;
  EXPECT_EQ(messages(b), (std::vector<std::string>{"gravity -10000000 L/s^2 is beyond the limit of 1000000 L/s^2"}));
  EXPECT_TRUE(gravityProblem(-25).empty());
  EXPECT_TRUE(frictionProblem("mu", 0).empty());
}

TEST(CheckBoardSpec, Balls) {
  BoardSpec b;
  b.balls.push_back(BallSpec{"N", std::nan(""), 5, 0, 0, {}});
  b.balls.push_back(BallSpec{"V", 5, 5, std::numeric_limits<double>::infinity(), 0, {}});
  b.balls.push_back(BallSpec{"F", 10, 10, 0, -2e6, {}});
  b.balls.push_back(ball("O", 5, 0.2));
  EXPECT_EQ(
      messages(b),
      (std::vector<std::string>{
          "ball 'N' has a position that is not a finite number", "ball 'V' has a velocity that is not a finite number",
          "ball 'F' is too fast: its velocity (0, -2000000) L/s exceeds 1000000 L/s in x or y",
          "ball 'O' at (5, 0.2) is not inside the board: its centre must be at least 0.25 L from every wall"}));
  // Exactly touching the walls is inside.
  b.balls = {ball("A", 0.25, 0.25), ball("B", 19.75, 19.75)};
  EXPECT_TRUE(checkBoardSpec(b).empty());
}

TEST(CheckBoardSpec, GizmoShapes) {
  BoardSpec b;
  b.gizmos.push_back(GizmoSpec{GizmoType::Triangle, "T", 1, 1, 45, 1, 1, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::Absorber, "A", 0, 19, 90, 20, 1, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::Square, "S", 3, 3, 0, 2, 1, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::Absorber, "Z", 5, 5, 0, 3, 0, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::LeftFlipper, "L", 8, 8, 0, 1, 1, {}});
  EXPECT_EQ(messages(b),
            (std::vector<std::string>{"triangle 'T' has orientation 45; it must be 0, 90, 180 or 270",
                                      "absorber 'A' has orientation 90, but an absorber cannot be rotated",
                                      "square 'S' is 2 x 1 L, but every square is 1 x 1 L",
                                      "absorber 'Z' is 3 x 0 L; its width and height must each be at least 1",
                                      "left flipper 'L' is 1 x 1 L, but every left flipper is 2 x 2 L"}));
}

TEST(CheckBoardSpec, NamesAreUniqueAcrossBallsAndGizmos) {
  BoardSpec b;
  b.balls.push_back(ball("X", 5, 5));
  b.gizmos.push_back(square("X", 1, 1));
  b.gizmos.push_back(square("OuterWalls", 3, 3));
  b.balls.push_back(ball("OuterWalls", 10, 10));
  EXPECT_EQ(messages(b), (std::vector<std::string>{
                             "the name 'OuterWalls' is reserved for the outer walls; a ball cannot use it",
                             "square 'X' has the same name as the ball; names must be unique",
                             "the name 'OuterWalls' is reserved for the outer walls; a square cannot use it"}));
}

TEST(CheckBoardSpec, MovingAGizmoOntoAnother) {
  BoardSpec b;
  b.gizmos.push_back(GizmoSpec{GizmoType::Absorber, "A", 0, 18, 0, 20, 2, {18, 1}});
  b.gizmos.push_back(square("S", 5, 5, {3, 1}));
  EXPECT_TRUE(checkBoardSpec(b).empty());
  b.gizmos[1].y = 19;  // what the property system does when the user drags S
  const auto p = checkBoardSpec(b);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].message, "absorber 'A' overlaps square 'S' from line 3 (both occupy cell 5,19)");
  EXPECT_EQ(p[0].where.line, 18);
}

TEST(CheckBoardSpec, ProblemsComeInSourceOrder) {
  BoardSpec b;
  b.balls.push_back(ball("late", 30, 5, {9, 1}));
  b.gizmos.push_back(GizmoSpec{GizmoType::Triangle, "T", 1, 1, 10, 1, 1, {4, 1}});
  b.connections.push_back(ConnectSpec{"nobody", "T", {2, 1}});
  b.keyConnections.push_back(KeyConnectSpec{99999, KeyDirection::Up, "T", {7, 3}});
  const auto p = checkBoardSpec(b);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0].where.line, 2);
  EXPECT_EQ(p[0].message, "connection source 'nobody' is not a gizmo on this board");
  EXPECT_EQ(p[1].where.line, 4);
  EXPECT_EQ(p[2].where.line, 7);
  EXPECT_EQ(p[2].where.column, 3);
  EXPECT_EQ(p[2].message, "key code 99999 is outside 0..65535");
  EXPECT_EQ(p[3].where.line, 9);
}

TEST(CheckBoardSpec, Connections) {
  BoardSpec b;
  b.gizmos.push_back(square("A", 1, 1));
  b.gizmos.push_back(square("B", 3, 3));
  b.balls.push_back(ball("Ball", 10, 10));
  b.connections = {{"A", "B", {}},    {"OuterWalls", "A", {}}, {"A", "B", {}},    {"Ball", "A", {}},
                   {"A", "Ball", {}}, {"A", "OuterWalls", {}}, {"A", "nope", {}}, {"outerWalls", "A", {}}};
  b.keyConnections = {
      {32, KeyDirection::Down, "A", {}}, {32, KeyDirection::Up, "A", {}}, {32, KeyDirection::Down, "A", {}}};
  EXPECT_EQ(messages(b),
            (std::vector<std::string>{
                "the connection from 'A' to 'B' is listed twice",
                "connection source 'Ball' is a ball; a ball triggers nothing",
                "connection target 'Ball' is a ball; a ball has no action",
                "connection target cannot be the outer walls: they have no action",
                "connection target 'nope' is not a gizmo on this board",
                "connection source 'outerWalls' is not a gizmo on this board (the outer walls are named OuterWalls)",
                "the key connection from key 32 down to 'A' is listed twice"}));
}

TEST(CheckBoardSpec, CapturedBalls) {
  BoardSpec b;
  b.gizmos.push_back(GizmoSpec{GizmoType::Absorber, "A", 2, 2, 0, 3, 3, {}});
  b.balls = {ball("P", 3, 3), ball("Q", 3.1, 3), ball("R", 4.75, 4.75)};
  EXPECT_TRUE(checkBoardSpec(b).empty());
  b.balls.push_back(ball("S", 4.8, 4.8));  // sticks out by 0.05
  EXPECT_EQ(messages(b), (std::vector<std::string>{"ball 'S' at (4.8, 4.8) overlaps absorber 'A'"}));
}

TEST(CheckBoardSpec, TooManyIsReportedAlone) {
  BoardSpec b;
  for (int i = 0; i < 10001; ++i) {
    std::string name = "S";
    name += std::to_string(i);
    b.gizmos.push_back(square(name, 1, 1, {i + 1, 1}));
  }
  const auto p = checkBoardSpec(b);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].message, "the board has 10001 gizmos; at most 10000 are allowed");
  EXPECT_EQ(p[0].where.line, 10001);
  b.gizmos.pop_back();
  EXPECT_EQ(checkBoardSpec(b).size(), 9999u);  // now every square overlaps the first
}

}  // namespace
}  // namespace gizmo
