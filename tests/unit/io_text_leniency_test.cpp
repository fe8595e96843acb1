// What the text reader reads leniently, one test per leniency (docs/board-files.md §2): each gives
// one warning per kind and file, at its first place, and --strict (refuseLeniency) refuses it with
// that position. The constructs are those of real boards that other Gizmoball programs wrote.
#include <gtest/gtest.h>

#include <string>

#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/text_reader.hpp"
#include "io_test_util.hpp"

namespace gizmo::io {
namespace {

using test::errorsOf;
using test::formatted;

using test::read;
std::vector<std::string> warnings(const std::string& s) { return formatted(read(s).warnings); }
std::string firstError(const std::string& s) {
  const std::vector<std::string> e = errorsOf([&] { read(s); });
  return e.empty() ? std::string() : e.front();
}
std::vector<std::string> strict(const std::string& s) {
  return errorsOf([&] { refuseLeniency(read(s)); });
}

TEST(TextReaderLeniency, CrCrLfLineEnds) {
  const ReadResult r = read("Square S 1 1\r\r\nCircle C 3 3\r\r\n");
  EXPECT_EQ(r.board.gizmos.size(), 2u);
  ASSERT_EQ(formatted(r.warnings).size(), 1u);
  EXPECT_EQ(formatted(r.warnings)[0],
            "b.txt:1:13: warning: line ending CR CR LF (a CR LF file saved again through a CR LF conversion) read as "
            "a plain line end (and 1 more like this)");
  // A CR inside a line is still refused.
  EXPECT_EQ(firstError("Square S 1 1\rSquare T 2 2\n"), "b.txt:1:13: error: unexpected control character (byte 0x0D)");
}

TEST(TextReaderLeniency, NamesOutsideTheStandardAreRenamed) {
  const ReadResult r =
      read("Ball Ball(126,121) 6.3 6.05 -3 0\nSquare 054ba281-d896 1 1\nConnect 054ba281-d896 054ba281-d896\n");
  EXPECT_EQ(r.board.balls[0].name, "Ball_126_121_");
  EXPECT_EQ(r.board.gizmos[0].name, "054ba281_d896");
  ASSERT_EQ(r.board.connections.size(), 1u);
  EXPECT_EQ(r.board.connections[0].source, "054ba281_d896");
  EXPECT_EQ(formatted(r.warnings)[0],
            "b.txt:1:6: warning: 'Ball(126,121)' is not a standard name (names use only letters, digits and _); the "
            "ball is named 'Ball_126_121_' (later commands that name 'Ball(126,121)' mean it) (and 1 more like this)");
  // A renamed name never takes one the file uses.
  const ReadResult taken = read("Square S_1 1 1\nSquare S-1 3 3\n");
  EXPECT_EQ(taken.board.gizmos[1].name, "S_1_2");
}

TEST(TextReaderLeniency, NamesGivenTwiceAreNumbered) {
  const ReadResult r = read(
      "Ball B 2 2 0 0\nBall B 4 4 0 0\nBall B 6 6 0 0\nSquare S 10 10\nConnect S S\nSquare S 12 12\n"
      "Connect S S\n");
  ASSERT_EQ(r.board.balls.size(), 3u);
  EXPECT_EQ(r.board.balls[1].name, "B_2");
  EXPECT_EQ(r.board.balls[2].name, "B_3");
  // A later command names the latest object of that name.
  ASSERT_EQ(r.board.connections.size(), 2u);
  EXPECT_EQ(r.board.connections[1].source, "S_2");
  EXPECT_EQ(formatted(r.warnings)[0],
            "b.txt:2:6: warning: the name 'B' is already used by the ball created on line 1; this ball is named 'B_2' "
            "(later commands that name 'B' mean it) (and 2 more like this)");
  EXPECT_EQ(strict("Ball B 2 2 0 0\nBall B 4 4 0 0\n").front().substr(0, 60),
            "b.txt:2:6: error: the name 'B' is already used by the ball c");
}

TEST(TextReaderLeniency, AdditionsAreLeftOutByName) {
  const ReadResult r = read(
      "Square S 1 1\nDeathSquare K 5 5\nGate P 7 7\nConnect S K\nConnect K S\nKeyConnect key 32 down P\n"
      "Rotate P\ncolor S #ff0000\nMouseConnect left-click press S\n");
  EXPECT_EQ(r.board.gizmos.size(), 1u);
  EXPECT_TRUE(r.board.connections.empty());
  EXPECT_TRUE(r.board.keyConnections.empty());
  const std::vector<std::string> w = formatted(r.warnings);
  ASSERT_EQ(w.size(), 5u);
  EXPECT_EQ(w[0],
            "b.txt:2:1: warning: 'DeathSquare' (a square that stops the ball, from d-g-n/CS308-GizmoBall) is "
            "not a gizmo this simulator knows; it is left out, and so are the commands that name 'K'");
  EXPECT_EQ(
      w[2],
      "b.txt:4:1: warning: 'Connect' names 'K', the 'DeathSquare' that is left out; the command is ignored (and 3 "
      "more like this)");
  EXPECT_EQ(w[3],
            "b.txt:8:1: warning: 'color' lines (a colour, from NiklavsM/Gizmoball, JedBurrows/CS308-GIzmoball) do "
            "not change how the board plays; ignored");
  EXPECT_EQ(w[4],
            "b.txt:9:1: warning: 'MouseConnect' (a mouse-button connection, from MIT 6.170 staff examples "
            "(dwctsai/mit-6.170-gizmoball-3d)) is an input this simulator does not have; the line is ignored");
  // A word that no program gives a meaning is left out too, by name (io_board_rules_test.cpp); a
  // file of nothing else is no board.
  EXPECT_EQ(firstError("Kircle C 3 4\n").substr(0, 57), "b.txt:1:1: error: no line of this file is a command of th");
}

TEST(TextReaderLeniency, OndownAndChangeAreDownAndUp) {
  for (const std::string word : {"ondown", "change"}) {
    const ReadResult r = read("LeftFlipper F 1 1\nKeyConnect Key 32 " + word + " F\n");
    ASSERT_EQ(r.board.keyConnections.size(), 2u) << word;
    EXPECT_EQ(r.board.keyConnections[0].direction, KeyDirection::Down);
    EXPECT_EQ(r.board.keyConnections[1].direction, KeyDirection::Up);
    EXPECT_EQ(r.board.keyConnections[1].key, 32);
  }
  EXPECT_EQ(warnings("LeftFlipper F 1 1\nKeyConnect key 32 ondown F\n")[0].substr(0, 75),
            "b.txt:2:19: warning: 'ondown' is read as two connections, down and up: Conf");
}

TEST(TextReaderLeniency, KeyNames) {
  const ReadResult r = read(
      "Absorber A 0 19 20 20\nKeyConnect key Space down A\nKeyConnect key Q up A\n"
      "KeyConnect key Delete down A\nKeyConnect key F1 down A\n");
  ASSERT_EQ(r.board.keyConnections.size(), 4u);
  EXPECT_EQ(r.board.keyConnections[0].key, 32);
  EXPECT_EQ(r.board.keyConnections[1].key, 81);
  EXPECT_EQ(r.board.keyConnections[2].key, 127);
  EXPECT_EQ(r.board.keyConnections[3].key, 112);
  EXPECT_EQ(formatted(r.warnings)[0],
            "b.txt:2:16: warning: the key 'Space' is read as the key code 32 (programs write Java's, JavaFX's or the "
            "browsers' key names; the standard format writes the code) (and 3 more like this)");
  // A word that names no key: the connection is left out.
  const ReadResult spaghetti = read("Absorber A 0 19 20 20\nKeyConnect key spaghetti down A\n");
  EXPECT_TRUE(spaghetti.board.keyConnections.empty());
  EXPECT_EQ(formatted(spaghetti.warnings).at(0),
            "b.txt:2:16: warning: the key 'spaghetti' is neither a key code nor a key name this reader knows; the "
            "connection is left out");
}

TEST(TextReaderLeniency, FractionalCellsAndTrailingWords) {
  const ReadResult r = read("RightFlipper RF 12.5 2\nLeftFlipper LF 9 14 false\nBall B 3 3 5 0 blue\n");
  EXPECT_EQ(r.board.gizmos[0].x, 12);
  EXPECT_EQ(r.board.balls[0].vx, 5.0);
  const std::vector<std::string> w = formatted(r.warnings);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0],
            "b.txt:1:17: warning: '12.5' is not a whole number; the gizmo is placed in the cell it starts in, 12");
  EXPECT_EQ(w[1].substr(0, 60), "b.txt:2:21: warning: the word 'false' after LeftFlipper NAME");
  // A number after what places a gizmo is ignored too, with the general warning
  // (io_board_rules_test.cpp); two extra words after a Connect are an error.
  EXPECT_EQ(warnings("Circle C 3 1 1\n").at(0).substr(0, 45), "b.txt:1:14: warning: what follows Circle NAME");
  EXPECT_NE(firstError("Square S 1 1\nConnect S S x y\n"), "");
}

TEST(TextReaderLeniency, ConnectionsToUnknownOrLaterNames) {
  const ReadResult r = read("Connect C1 T2\nCircle C1 2 3\nTriangle T2 5 5\nKeyConnect key 32 down LF92\n");
  ASSERT_EQ(r.board.connections.size(), 1u);  // made at the end, where both exist
  EXPECT_TRUE(r.board.keyConnections.empty());
  const std::vector<std::string> w = formatted(r.warnings);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0],
            "b.txt:1:1: warning: this connection names a gizmo that is created further down; it is made at the "
            "end of the file");
  EXPECT_EQ(w[1], "b.txt:4:1: warning: there is no gizmo named 'LF92' in the file; the connection is ignored");
}

TEST(TextReaderLeniency, PlacementsOtherProgramsAccept) {
  // A ball on the wall is moved inside; one inside an absorber is captured; the later of two
  // overlapping things is left out, and a gizmo's connections go with it.
  const ReadResult r = read(
      "Ball B0 0 0 1 1\nAbsorber A 0 19 20 20\nBall B1 19 19 20 20\nSquare S 5 5\n"
      "Circle C 5 5\nConnect S C\nBall D 8 8 0 0\nBall E 8 8 0 0\n");
  ASSERT_EQ(r.board.balls.size(), 3u);
  EXPECT_EQ(r.board.balls[0].x, 0.25);
  EXPECT_EQ(r.board.balls[0].y, 0.25);
  EXPECT_EQ(r.board.balls[1].x, 19.0);
  EXPECT_EQ(r.board.balls[1].y, 19.25);
  EXPECT_EQ(r.board.balls[1].vx, 0.0);
  EXPECT_EQ(r.board.gizmos.size(), 2u);
  EXPECT_TRUE(r.board.connections.empty());
  EXPECT_EQ(formatted(r.warnings).size(), 4u);
  // A gizmo off the board is left out (io_board_rules_test.cpp).
  EXPECT_TRUE(read("Absorber A 3 19 23 20\n").board.gizmos.empty());
}

TEST(TextReaderLeniency, WrittenBackItLoadsStrictlyAndRunsTheSameDecisions) {
  const std::string file =
      "Ball Ball(1,2) 5 5 3 -2\r\nBall Ball(1,2) 9 9 -4 1\r\nSquare S-1 2.5 12\r\n"
      "LeftFlipper F 10 15 false\r\nKeyConnect Key Space ondown F\r\nSink K 1 1\r\nConnect K F\r\n"
      "Absorber A 0 19 20 20\r\nConnect S-1 A\r\nBall B 10 19.2 0 5\r\n";
  const ReadResult lenient = read(file);
  ASSERT_FALSE(lenient.warnings.empty());
  const ReadResult again = readTextBoard(writeTextBoard(lenient.board), "written.txt");
  EXPECT_NO_THROW(refuseLeniency(again));
  RunRequest a, b;
  a.board = lenient.board;
  b.board = again.board;
  a.duration = b.duration = 20;
  a.keys = b.keys = {TimedKey{1.0, 32, KeyDirection::Down}, TimedKey{1.5, 32, KeyDirection::Up}};
  const RunSummary sa = simulate<double>(a), sb = simulate<double>(b);
  EXPECT_GT(sa.total, 100u);
  EXPECT_EQ(sa.executed, sb.executed);
  ASSERT_EQ(sa.balls.size(), sb.balls.size());
  for (std::size_t i = 0; i < sa.balls.size(); ++i) {
    EXPECT_EQ(sa.balls[i].x, sb.balls[i].x);
    EXPECT_EQ(sa.balls[i].vy, sb.balls[i].vy);
  }
}

TEST(TextReaderLeniency, StrictRefusesEachLeniencyAtItsPlace) {
  const std::vector<std::string> e = strict("Square S 1 1\nConnect S S\nConnect S S\n");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0],
            "b.txt:3:1: error: this connection repeats the one on line 2; the repetition is ignored (refused: "
            "--strict reads a board only as written)");
  EXPECT_NO_THROW(refuseLeniency(read("Square S 1 1\nConnect S S\n")));
}

TEST(ForeignFormats, AreRefusedAsWhatTheyLookLike) {
  const auto first = [](const std::string& content) {
    return errorsOf([&] { readBoardString(content, "f"); }).front();
  };
  const std::string tail = ", not a Gizmoball board of the text or XML format";
  EXPECT_EQ(first("[[\"Ball\",19,16,0.8,0.8,0]]"), "f: error: this looks like a JSON file (it starts with '[')" + tail);
  EXPECT_EQ(first(std::string("\xAC\xED\0\x05sr\0", 8)),
            "f: error: this looks like a Java serialisation stream (binary, it starts with the bytes AC ED)" + tail);
  EXPECT_EQ(first("x=310 y=90 r=70 class=SquareGizmo\n"),
            "f: error: this looks like a file of key=value fields ('x=310' on its first line)" + tail);
  EXPECT_EQ(
      first("triangle 77 505 50 50\ncircle 217 140 50 50\n"),
      "f: error: this looks like a pixel-coordinate map ('triangle' followed by x, y, width and height in pixels, "
      "without a name)" +
          tail);
  EXPECT_EQ(first("Gravity 0.0 -25.0 0.0\nBall B0 5.5 5.5 10.0 0.0 0.0 0.0 1.0\n"),
            "f: error: this looks like a 3-D Gizmoball board ('Gravity' is a command of the .g3d format)" + tail);
  EXPECT_EQ(first("SquareBumper S0 1 3 1 1\n"),
            "f: error: this looks like a board of another Gizmoball dialect ('SquareBumper' with its own "
            "coordinates)" +
                tail);
  // Boards whose names are digits keep the shape of a pixel map and are boards all the same.
  EXPECT_EQ(readBoardString("Absorber 5 0 19 20 20\nBall 7 3 3 0 0\n", "f").board.gizmos.size(), 1u);
}

}  // namespace
}  // namespace gizmo::io
