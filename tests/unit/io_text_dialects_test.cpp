// One test per row of the text reader's dialects table (core/io/src/text_dialects.cpp): a short
// board in that dialect, what the reader makes of it and the row's warning. Dropping a row makes
// its test fail; a new row comes with a test here.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gizmo/io/text_reader.hpp"
#include "io_test_util.hpp"

namespace gizmo::io {
namespace {

using test::formatted;

using test::read;

// Whether some warning of `r` starts with `prefix` ("b.txt:LINE:COLUMN: warning: …").
::testing::AssertionResult warned(const ReadResult& r, const std::string& prefix) {
  const std::vector<std::string> w = formatted(r.warnings);
  if (std::any_of(w.begin(), w.end(), [&](const std::string& s) { return s.rfind(prefix, 0) == 0; }))
    return ::testing::AssertionSuccess();
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  failure << "no warning starts with \"" << prefix << "\"; the warnings are:";
  for (const std::string& s : w) failure << "\n  " << s;
  return failure;
}

// A board whose gizmos the row keeps (`count` of them), with `warning`.
void expectGizmos(const std::string& board, std::size_t count, const std::string& warning) {
  const ReadResult r = read(board);
  EXPECT_EQ(r.board.gizmos.size(), count);
  EXPECT_TRUE(warned(r, warning));
}

TEST(TextDialects, ByteOrderMark) {
  expectGizmos("\xEF\xBB\xBFSquare S 1 1\n", 1,
               "b.txt:1:1: warning: the UTF-8 byte order mark at the start of the file is ignored");
}

TEST(TextDialects, CrLfLineEnds) {
  expectGizmos("Square S 1 1\r\nCircle C 3 3\r\n", 2,
               "b.txt:1:13: warning: Windows line ending (CR LF) read as a plain line end");
}

TEST(TextDialects, CrCrLfLineEnds) {
  expectGizmos("Square S 1 1\r\r\n", 1, "b.txt:1:13: warning: line ending CR CR LF");
}

TEST(TextDialects, CommentLines) {
  expectGizmos("# a board\nSquare S 1 1\n", 1,
               "b.txt:1:1: warning: '#' comment lines are not part of the standard format; ignored");
}

TEST(TextDialects, DgnSpinnerNamedByItsCell) {
  const ReadResult r = read("Spinner 7_12 7 12\nRotate 7_12\nSpinner S 3 3\n");
  ASSERT_EQ(r.board.gizmos.size(), 1u);  // NiklavsM's spinner only
  EXPECT_EQ(r.board.gizmos[0].name, "S");
  EXPECT_TRUE(warned(r, "b.txt:1:1: warning: 'Spinner' (d-g-n's spinner"));
  EXPECT_TRUE(warned(r, "b.txt:2:1: warning: 'Rotate' names '7_12'"));
}

TEST(TextDialects, KeywordsInAnotherCase) {
  const ReadResult r = read("square S 1 1\nKeyConnect KEY 32 DOWN S\n");
  EXPECT_EQ(r.board.gizmos.size(), 1u);
  ASSERT_EQ(r.board.keyConnections.size(), 1u);
  EXPECT_EQ(r.board.keyConnections[0].direction, KeyDirection::Down);
  EXPECT_TRUE(warned(r,
                     "b.txt:1:1: warning: 'square' is written 'Square' in the standard format; keywords are read "
                     "without regard to case (and 2 more like this)"));
}

TEST(TextDialects, AbsorberWithoutItsLowerRightCorner) {
  const ReadResult r = read("Absorber A 0 19\nConnect A A\nSquare S 1 1\n");
  ASSERT_EQ(r.board.gizmos.size(), 1u);
  EXPECT_EQ(r.board.gizmos[0].name, "S");
  EXPECT_TRUE(r.board.connections.empty());
  EXPECT_TRUE(warned(r, "b.txt:1:1: warning: this absorber has no lower-right corner"));
  EXPECT_TRUE(warned(r, "b.txt:2:1: warning: 'Connect' names 'A', the 'Absorber' that is left out"));
}

TEST(TextDialects, AnotherProgramsGizmoWithFewerValues) {
  expectGizmos("Portal P 3 3\nRotate P\nSquare S 1 1\n", 1,
               "b.txt:1:1: warning: Portal takes 5 values (Portal NAME X Y EXITX EXITY) but the line has 3; it is "
               "another program's portal, left out, and so are the commands that name 'P'");
}

TEST(TextDialects, WordAfterAGizmoOrBall) {
  const ReadResult r = read("LeftFlipper LF 9 14 false\nBall B 3 3 5.0 2.0 blue\n");
  EXPECT_EQ(r.board.gizmos.size(), 1u);
  ASSERT_EQ(r.board.balls.size(), 1u);
  EXPECT_EQ(r.board.balls[0].vx, 5.0);
  EXPECT_TRUE(warned(r, "b.txt:1:21: warning: the word 'false' after LeftFlipper NAME X Y is ignored"));
}

TEST(TextDialects, ConnectWithAnAction) {
  const ReadResult r = read("Square S 1 1\nCircle C 3 3\nConnect S C grow\n");
  ASSERT_EQ(r.board.connections.size(), 1u);
  EXPECT_EQ(r.board.connections[0].target, "C");
  EXPECT_TRUE(warned(r, "b.txt:3:13: warning: the action word 'grow' (MIT 6.170's"));
}

// A board of one gizmo, which the row places at x = `x` with `warning`.
void expectOneGizmoAt(const std::string& board, int x, const std::string& warning) {
  const ReadResult r = read(board);
  ASSERT_EQ(r.board.gizmos.size(), 1u);
  EXPECT_EQ(r.board.gizmos[0].x, x);
  EXPECT_TRUE(warned(r, warning));
}

TEST(TextDialects, ValuesAfterAGizmosOwn) {
  expectOneGizmoAt("Circle C 3 3 0.5\n", 3,
                   "b.txt:1:14: warning: what follows Circle NAME X Y (1 more, from '0.5') is ignored; it is placed "
                   "from its own values");
}

TEST(TextDialects, WholeNumbersWrittenAsDecimals) {
  expectOneGizmoAt("Square S 3.0 1\n", 3, "b.txt:1:10: warning: '3.0' is read as the whole number 3");
}

TEST(TextDialects, CoordinatesWithAFraction) {
  expectOneGizmoAt("RightFlipper RF 12.5 2\n", 12,
                   "b.txt:1:17: warning: '12.5' is not a whole number; the gizmo is placed in the cell it starts in, "
                   "12");
}

TEST(TextDialects, KeysByName) {
  const ReadResult r = read("Square S 1 1\nKeyConnect key Space down S\n");
  ASSERT_EQ(r.board.keyConnections.size(), 1u);
  EXPECT_EQ(r.board.keyConnections[0].key, 32);
  EXPECT_TRUE(warned(r, "b.txt:2:16: warning: the key 'Space' is read as the key code 32"));
}

TEST(TextDialects, KeysByANameNoProgramKnows) {
  const ReadResult r = read("Square S 1 1\nKeyConnect key spaghetti down S\n");
  EXPECT_TRUE(r.board.keyConnections.empty());
  EXPECT_TRUE(warned(r, "b.txt:2:16: warning: the key 'spaghetti' is neither a key code nor a key name"));
}

TEST(TextDialects, DirectionOnDown) {
  const ReadResult r = read("Square S 1 1\nKeyConnect key 32 ondown S\n");
  ASSERT_EQ(r.board.keyConnections.size(), 2u);
  EXPECT_EQ(r.board.keyConnections[0].direction, KeyDirection::Down);
  EXPECT_EQ(r.board.keyConnections[1].direction, KeyDirection::Up);
  EXPECT_TRUE(warned(r,
                     "b.txt:2:19: warning: 'ondown' is read as two connections, down and up: "
                     "ConfuddledPenguin/Gizmoball's reader"));
}

TEST(TextDialects, DirectionChange) {
  const ReadResult r = read("Square S 1 1\nKeyConnect key 32 change S\n");
  EXPECT_EQ(r.board.keyConnections.size(), 2u);
  EXPECT_TRUE(warned(r, "b.txt:2:19: warning: 'change' is read as two connections, down and up: jtax/Gizmoball-WJ2's"));
}

TEST(TextDialects, ConnectionsBeforeGizmos) {
  const ReadResult r = read("Connect S C\nKeyConnect key 32 down C\nSquare S 1 1\nCircle C 3 3\n");
  ASSERT_EQ(r.board.connections.size(), 1u);
  EXPECT_EQ(r.board.connections[0].source, "S");
  EXPECT_EQ(r.board.keyConnections.size(), 1u);
  EXPECT_TRUE(warned(r,
                     "b.txt:1:1: warning: this connection names a gizmo that is created further down; it is made "
                     "at the end of the file (and 1 more like this)"));
}

}  // namespace
}  // namespace gizmo::io
