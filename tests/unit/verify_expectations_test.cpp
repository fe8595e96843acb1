// The user's expectations about a board (verify/fuzz/expectations.hpp): the file's grammar with
// its located errors, and each kind on a board where it holds and one where it fails.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gizmo/verify/fuzz/expectations.hpp"
#include "support/board_builder.hpp"

namespace gizmo::verify::fuzz {
namespace {

using test::ballAt;
using test::gizmoAt;

RunRequest runOf(BoardSpec board, double duration) {
  RunRequest r;
  r.board = std::move(board);
  r.model = MotionModel::Ballistic;
  r.duration = duration;
  return r;
}

// The failures of one expectation line on a run (empty: it holds).
std::vector<ExpectationFailure> check(const RunRequest& run, const std::string& line) {
  return checkExpectations(run, parseExpectations(line, "board.expect"));
}

std::string parseError(const std::string& text) {
  try {
    parseExpectations(text, "my.expect");
  } catch (const ExpectationError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Expectations, EachKindIsReadWithItsValues) {
  const std::vector<Expectation> e = parseExpectations(
      "# the level's rules\n"
      "reaches A within 30\n"
      "\n"
      "avoids 2 3 5.5 8 ball B   # the gap\n"
      "rests-at-most 5\n"
      "hit G at-least 2 within 60\n"
      "stays-on-board ball B\n",
      "level.expect");
  ASSERT_EQ(e.size(), 5u);
  EXPECT_EQ(e[0].kind, ExpectationKind::Reaches);
  EXPECT_EQ(e[0].gizmo, "A");
  EXPECT_EQ(e[0].seconds, 30.0);
  EXPECT_EQ(e[0].ball, "");
  EXPECT_EQ(e[0].source, "level.expect:2");
  EXPECT_EQ(e[1].kind, ExpectationKind::Avoids);
  EXPECT_EQ(e[1].x1, 5.5);
  EXPECT_EQ(e[1].y1, 8.0);
  EXPECT_EQ(e[1].ball, "B");
  EXPECT_EQ(e[2].kind, ExpectationKind::RestsAtMost);
  EXPECT_EQ(e[3].kind, ExpectationKind::Hit);
  EXPECT_EQ(e[3].count, 2);
  EXPECT_EQ(e[3].seconds, 60.0);
  EXPECT_EQ(e[4].kind, ExpectationKind::StaysOnBoard);
  EXPECT_EQ(e[4].source, "level.expect:7");
  EXPECT_EQ(expectationHorizon(e), 60.0);
}

TEST(Expectations, AMalformedLineIsRefusedWithItsFileAndLine) {
  EXPECT_EQ(parseError("reaches A within 30\nreaches A in 30\n"), "my.expect:2: expected 'within', not 'in'");
  EXPECT_EQ(parseError("reaches A within soon\n"), "my.expect:1: the time must be a number, not 'soon'");
  EXPECT_EQ(parseError("reaches A within -1\n"), "my.expect:1: the time must be more than 0 s, not -1");
  EXPECT_EQ(parseError("reaches A within\n"), "my.expect:1: missing the time after 'within'");
  EXPECT_EQ(parseError("avoids 5 3 2 8\n"), "my.expect:1: the rectangle X0 Y0 X1 Y1 needs X0 < X1 and Y0 < Y1");
  EXPECT_EQ(parseError("hit G at-least 0 within 5\n"),
            "my.expect:1: the number of hits must be a whole number of at least 1, not '0'");
  EXPECT_EQ(parseError("stays-on-board B\n"), "my.expect:1: expected 'ball', not 'B'");
  EXPECT_EQ(parseError("rests-at-most 5 ball B again\n"),
            "my.expect:1: unexpected 'again' after the end of the expectation");
  EXPECT_EQ(parseError("\n\nfloats\n").rfind("my.expect:3: 'floats' is no expectation; one of: reaches", 0), 0u);
  EXPECT_EQ(parseError("# nothing\n").rfind("my.expect: no expectation in the file", 0), 0u);
}

TEST(Expectations, ANameTheBoardLacksIsAnError) {
  BoardSpec board = test::emptyBoard(25);
  board.balls.push_back(ballAt("B", 5.5, 5.5));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "S", 5, 10));
  const RunRequest run = runOf(board, 1);
  EXPECT_THROW(check(run, "reaches A within 3"), ExpectationError);
  EXPECT_THROW(check(run, "reaches S within 3"), ExpectationError);  // not an absorber
  EXPECT_THROW(check(run, "stays-on-board ball C"), ExpectationError);
  EXPECT_THROW(check(run, "stays-on-board ball S"), ExpectationError);  // not a ball
  EXPECT_THROW(check(run, "hit T at-least 1 within 1"), ExpectationError);
}

// A ball dropped from rest at (5.5, 5.5) under gravity 25 onto an absorber along the floor: its
// bottom meets the absorber's top (y = 19) when 13.25 = 12.5 t², at t = 1.0296 s.
BoardSpec dropOntoAbsorber() {
  BoardSpec board = test::emptyBoard(25);
  board.balls.push_back(ballAt("B", 5.5, 5.5));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "A", 0, 19, 0, 20, 1));
  return board;
}

TEST(Expectations, ReachesHoldsWhenTheBallIsCapturedInTimeAndSaysWhereItWasOtherwise) {
  const RunRequest run = runOf(dropOntoAbsorber(), 0.1);
  EXPECT_TRUE(check(run, "reaches A within 1.1").empty());
  EXPECT_TRUE(check(run, "reaches A within 2 ball B").empty());
  const std::vector<ExpectationFailure> f = check(run, "reaches A within 1");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].time, 1.0);
  // At t = 1 the ball has fallen 12.5 L: its centre is at y = 18.
  EXPECT_EQ(f[0].message, "board.expect:1: ball B did not reach A within 1 s: at t = 1 s it was at (5.5, 18)");
}

TEST(Expectations, AvoidsFailsAtTheInstantTheCentreEntersTheRectangle) {
  const RunRequest run = runOf(dropOntoAbsorber(), 1);
  EXPECT_TRUE(check(run, "avoids 7 0 9 20").empty());  // beside its fall
  // The rectangle from y = 10: the centre falls 4.5 L to it, at t = sqrt(4.5 / 12.5) = 0.6 s.
  const std::vector<ExpectationFailure> f = check(run, "avoids 5 10 6 12");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(f[0].time, 0.6, 1e-12);
  EXPECT_NE(f[0].message.find("ball B entered the rectangle (5, 10) to (6, 12) at t = 0.6"), std::string::npos)
      << f[0].message;
}

TEST(Expectations, RestsAtMostFailsForABallLyingStillOutsideAnAbsorber) {
  BoardSpec board = test::emptyBoard(25);
  board.balls.push_back(ballAt("B", 10.5, 19.75));  // on the floor
  const std::vector<ExpectationFailure> f = check(runOf(board, 2), "rests-at-most 1");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_GT(f[0].time, 1.0);
  EXPECT_LE(f[0].time, 1.05);  // seen at the first tick boundary after a second of rest
  EXPECT_NE(f[0].message.find("ball B has rested at (10.5, 19.75) outside an absorber since t = 0 s"),
            std::string::npos)
      << f[0].message;
  // A ball captured by an absorber rests inside it, which the expectation allows; so does a ball
  // that keeps moving (no gravity, bouncing between the walls).
  EXPECT_TRUE(check(runOf(dropOntoAbsorber(), 3), "rests-at-most 1").empty());
  BoardSpec moving = test::emptyBoard(0);
  moving.balls.push_back(ballAt("B", 10.5, 10.5, 7, 0));
  EXPECT_TRUE(check(runOf(moving, 3), "rests-at-most 1").empty());
}

TEST(Expectations, HitCountsTheStrikesOnTheGizmoWithinItsTime) {
  // No gravity: the ball moves down at 10 L/s onto a square whose top is at y = 10, from y = 5,
  // strikes it at t = 0.475 s, meets the top wall at t = 1.425 s and strikes it again at 2.375 s.
  BoardSpec board = test::emptyBoard(0);
  board.balls.push_back(ballAt("B", 5.5, 5, 0, 10));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "S", 5, 10));
  const RunRequest run = runOf(board, 0.1);
  EXPECT_TRUE(check(run, "hit S at-least 1 within 1").empty());
  EXPECT_TRUE(check(run, "hit S at-least 2 within 2.4").empty());
  const std::vector<ExpectationFailure> f = check(run, "hit S at-least 2 within 2.3");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].message, "board.expect:1: S was hit 1 times within 2.3 s, fewer than 2");
  EXPECT_EQ(check(run, "hit S at-least 1 within 0.4").size(), 1u);
}

TEST(Expectations, StaysOnBoardFailsForABallASinkTakes) {
  BoardSpec board = test::emptyBoard(25);
  board.balls.push_back(ballAt("B", 5.5, 5.5));
  board.balls.push_back(ballAt("C", 15.5, 5.5));
  board.gizmos.push_back(gizmoAt(GizmoType::Sink, "K", 5, 18));
  const RunRequest run = runOf(board, 2);
  EXPECT_TRUE(check(run, "stays-on-board ball C").empty());
  const std::vector<ExpectationFailure> f = check(run, "stays-on-board");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NE(f[0].message.find("ball B was taken out of play by K at t = "), std::string::npos) << f[0].message;
}

}  // namespace
}  // namespace gizmo::verify::fuzz
