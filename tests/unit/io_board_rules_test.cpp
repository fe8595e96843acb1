// The general rules by which both readers load what other Gizmoball programs save (docs/board-files.md
// §2, "What is read by a rule"): a command or element nobody here knows is left out by name, values
// after a command's own are ignored, a command short of values is left out with what it names, a
// key is read by its name in Java's, JavaFX's or the browsers' spelling, a ball written in pixels
// is converted, what lies off the board is left out, and overlaps are resolved even when other
// lines needed a rule. Each rule is a warning that --strict (refuseLeniency) refuses, and a board
// read by them and written back loads strictly. Every board here is written for its rule.
#include <gtest/gtest.h>

#include <string>

#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"
#include "io_test_util.hpp"

namespace gizmo::io {
namespace {

using test::errorsOf;
using test::formatted;

using test::read;
ReadResult readXml(const std::string& s) { return readXmlBoard(s, "b.xml"); }

// The one warning that contains `part`, or a test failure.
std::string warningWith(const ReadResult& r, const std::string& part) {
  std::string found;
  for (const std::string& w : formatted(r.warnings))
    if (w.find(part) != std::string::npos) {
      EXPECT_TRUE(found.empty()) << "two warnings contain " << part;
      found = w;
    }
  EXPECT_FALSE(found.empty()) << "no warning contains " << part;
  return found;
}

std::string firstStrictError(const ReadResult& r) {
  const std::vector<std::string> e = errorsOf([&] { refuseLeniency(r); });
  return e.empty() ? std::string() : e.front();
}

// What the rules made of a board is a board of the format: written back, it loads strictly.
void expectWrittenBackLoadsStrictly(const ReadResult& r) {
  const ReadResult again = read(writeTextBoard(r.board));
  EXPECT_TRUE(again.warnings.empty()) << formatted(again.warnings).front();
  EXPECT_EQ(again.board.gizmos.size(), r.board.gizmos.size());
  EXPECT_EQ(again.board.balls.size(), r.board.balls.size());
  EXPECT_EQ(again.board.connections.size(), r.board.connections.size());
  EXPECT_EQ(again.board.keyConnections.size(), r.board.keyConnections.size());
}

TEST(BoardRules, ACommandNobodyHereKnowsIsLeftOutByNameWithACount) {
  const ReadResult r = read(
      "Square S 1 1\nTeleporterConnect S T\nABSNOTCONNECTED\nABSNOTCONNECTED\nWidget W 3 3\n"
      "Connect W S\nConnect S S\n");
  ASSERT_EQ(r.board.gizmos.size(), 1u);
  ASSERT_EQ(r.board.connections.size(), 1u);  // Connect W S goes with W
  EXPECT_EQ(warningWith(r, "'TeleporterConnect'").substr(0, 30), "b.txt:2:1: warning: 'Teleporte");
  EXPECT_NE(warningWith(r, "'TeleporterConnect'").find("the line is left out"), std::string::npos);
  EXPECT_NE(warningWith(r, "'ABSNOTCONNECTED'").find("(and 1 more like this)"), std::string::npos);
  EXPECT_NE(warningWith(r, "'Widget' is not").find("the commands that name 'W'"), std::string::npos);
  EXPECT_EQ(warningWith(r, "names 'W'").substr(0, 11), "b.txt:6:1: ");
  EXPECT_EQ(firstStrictError(r).substr(0, 17), "b.txt:2:1: error:");
  expectWrittenBackLoadsStrictly(r);
}

TEST(BoardRules, AFileWithNoLineOfTheFormatIsNoBoard) {
  const std::vector<std::string> e = errorsOf([] { read("Hello there\nthis is a note\n"); });
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0],
            "b.txt:1:1: error: no line of this file is a command of the Gizmoball format (the first line's word "
            "is 'Hello'); it does not look like a Gizmoball board");
}

TEST(BoardRules, ValuesAfterWhatPlacesAGizmoOrABallAreIgnored) {
  const ReadResult r = read("Circle C 3 3 0.5\nSquare S 5 5 # the corner\n");
  ASSERT_EQ(r.board.gizmos.size(), 2u);
  EXPECT_EQ(r.board.gizmos[0].x, 3);
  EXPECT_EQ(r.board.gizmos[0].y, 3);
  EXPECT_EQ(warningWith(r, "Circle NAME X Y").substr(0, 21), "b.txt:1:14: warning: ");
  EXPECT_NE(warningWith(r, "Square NAME X Y").find("comments on lines of their own"), std::string::npos);
  EXPECT_EQ(firstStrictError(r).substr(0, 18), "b.txt:1:14: error:");
  expectWrittenBackLoadsStrictly(r);
  // After any other command, more values say what this reader cannot know (`Gravity 24 3`).
  EXPECT_EQ(errorsOf([] { read("Gravity 24 3\n"); }).at(0),
            "b.txt:1:12: error: unexpected '3' after the end of the command: Gravity G takes 1 value");
}

TEST(BoardRules, AnAddedGizmoShortOfValuesIsLeftOutWithWhatItNames) {
  // Another program's portal, without our exit cell, and the commands that name it.
  const ReadResult r = read("Square S 1 1\nPortal P 3 3\nConnect S P\nRotate P\nBall B 10 10 0 0\n");
  EXPECT_EQ(r.board.gizmos.size(), 1u);
  EXPECT_TRUE(r.board.connections.empty());
  EXPECT_EQ(r.board.balls.size(), 1u);
  const std::string portal = warningWith(r, "Portal takes 5 values");
  EXPECT_EQ(portal.substr(0, 11), "b.txt:2:1: ");
  EXPECT_NE(portal.find("another program's portal, left out, and so are the commands that name 'P'"),
            std::string::npos);
  EXPECT_NE(warningWith(r, "names 'P'").find("(and 1 more like this)"), std::string::npos);
  expectWrittenBackLoadsStrictly(r);
  // A command of the format short of its values is malformed, as its programs' own error tests say.
  EXPECT_EQ(errorsOf([] { read("Square S 1 1\nConnect S\n"); }).at(0),
            "b.txt:2:1: error: Connect needs 2 values (Connect PRODUCER CONSUMER) but the line has 1");
  EXPECT_EQ(errorsOf([] { read("Ball B 1.0 11.0\n"); }).at(0),
            "b.txt:1:1: error: Ball needs 5 values (Ball NAME X Y VX VY) but the line has 3");
}

TEST(BoardRules, KeysAreReadByTheirNamesInEachSpelling) {
  const std::pair<const char*, int> named[] = {
      {"VK_SPACE", 32},  {"ArrowLeft", 37},    {"KeyA", 65},     {"DIGIT1", 49}, {"Digit7", 55},   {"BACK_SPACE", 8},
      {"ShiftLeft", 16}, {"ControlRight", 17}, {"NUMPAD7", 103}, {"F12", 123},   {"PageDown", 34}, {"vk_enter", 10},
      {"x", 88},
  };
  for (const auto& [name, code] : named) {
    const ReadResult r = read("Square S 1 1\nKeyConnect key " + std::string(name) + " down S\n");
    ASSERT_EQ(r.board.keyConnections.size(), 1u) << name;
    EXPECT_EQ(r.board.keyConnections[0].key, code) << name;
    EXPECT_NE(warningWith(r, "is read as the key code").find("'" + std::string(name) + "'"), std::string::npos);
  }
  // A word that names no key leaves its connection out; a malformed number is still an error.
  const ReadResult unknown = read("Square S 1 1\nKeyConnect key Frobnicate down S\nKeyConnect key 32 down S\n");
  ASSERT_EQ(unknown.board.keyConnections.size(), 1u);
  EXPECT_EQ(warningWith(unknown, "'Frobnicate'").substr(0, 12), "b.txt:2:16: ");
  EXPECT_EQ(errorsOf([] { read("Square S 1 1\nKeyConnect key 3x down S\n"); }).size(), 1u);
}

TEST(BoardRules, WhatLiesOffTheBoardIsLeftOut) {
  const ReadResult r = read("Square S 1 1\nBall B 16 -8 0 0\nCircle C 25 3\nConnect C S\nBall K 10 10 0 0\n");
  ASSERT_EQ(r.board.gizmos.size(), 1u);
  ASSERT_EQ(r.board.balls.size(), 1u);
  EXPECT_EQ(r.board.balls[0].name, "K");
  EXPECT_TRUE(r.board.connections.empty());
  EXPECT_EQ(warningWith(r, "ball 'B' at (16, -8)").substr(0, 11), "b.txt:2:1: ");
  EXPECT_NE(warningWith(r, "circle 'C'").find("the circle is left out"), std::string::npos);
  EXPECT_NE(warningWith(r, "this connection names 'C'"), "");
  EXPECT_EQ(firstStrictError(r).substr(0, 17), "b.txt:2:1: error:");
  expectWrittenBackLoadsStrictly(r);
}

TEST(BoardRules, ABallOffTheBoardInPixelsIsConverted) {
  // 25 px per L: (262.5, 62.5) is (10.5, 2.5); 20 px would give (13.125, 3.125), off the quarter grid.
  const ReadResult r = read("Square S 1 1\nBall B1 262.5 62.5 50 -25\nBall B2 5 5 1 0\n");
  ASSERT_EQ(r.board.balls.size(), 2u);
  EXPECT_EQ(r.board.balls[0].x, 10.5);
  EXPECT_EQ(r.board.balls[0].y, 2.5);
  EXPECT_EQ(r.board.balls[0].vx, 2);
  EXPECT_EQ(r.board.balls[0].vy, -1);
  EXPECT_EQ(r.board.balls[1].x, 5);  // on the board: read in L
  EXPECT_NE(warningWith(r, "in pixels").find("at 25 per L"), std::string::npos);
  // 20 px per L: (210, 150) is (10.5, 7.5); 30 would give (7, 5), on the grid too: the smaller wins.
  const ReadResult twenty = read("Ball B 210 150 0 0\n");
  EXPECT_EQ(twenty.board.balls[0].x, 10.5);
  EXPECT_EQ(twenty.board.balls[0].y, 7.5);
  // Converted into a gizmo, it is left out as any ball that starts inside one.
  const ReadResult inside = read("Square S 10 2\nBall B 262.5 62.5 0 0\n");
  EXPECT_TRUE(inside.board.balls.empty());
  EXPECT_NE(warningWith(inside, "overlaps").find("the ball is left out"), std::string::npos);
  // No size of L puts it on the board, or on the quarter grid (a ball a little past a wall): left out.
  EXPECT_TRUE(read("Ball B 2600 3 0 0\n").board.balls.empty());
  const ReadResult past = read("Ball B 20.1 5 0 0\n");
  EXPECT_TRUE(past.board.balls.empty());
  EXPECT_NE(warningWith(past, "ball 'B' at (20.1, 5)").find("is not on the board"), std::string::npos);
  expectWrittenBackLoadsStrictly(r);
}

// A file whose gizmos are placed in pixels: every corner a whole cell of 25 pixels, some gizmo far
// beyond the board. Every gizmo and ball is divided by 25 (20 leaves 250 at 12.5 cells).
TEST(BoardRules, AFileInPixelsIsConverted) {
  const ReadResult r = read(
      "Square S 250 250\nCircle C 100 0\nTriangle T 450 450\nLeftFlipper F 200 200\n"
      "Absorber A 100 400 400 410\nBall B 25 25 200 200\n");
  ASSERT_EQ(r.board.gizmos.size(), 5u);
  EXPECT_EQ(r.board.gizmos[0].x, 10);
  EXPECT_EQ(r.board.gizmos[0].y, 10);
  EXPECT_EQ(r.board.gizmos[2].x, 18);
  EXPECT_EQ(r.board.gizmos[3].x, 8);
  EXPECT_EQ(r.board.gizmos[3].width, 2);
  EXPECT_EQ(r.board.gizmos[4].x, 4);
  EXPECT_EQ(r.board.gizmos[4].y, 16);
  EXPECT_EQ(r.board.gizmos[4].width, 12);
  EXPECT_EQ(r.board.gizmos[4].height, 1);  // 10 pixels high: the one cell it reaches into
  ASSERT_EQ(r.board.balls.size(), 1u);
  EXPECT_EQ(r.board.balls[0].x, 1);
  EXPECT_EQ(r.board.balls[0].vx, 8);
  const std::string w = warningWith(r, "read as written in pixels at 25 per L");
  EXPECT_EQ(w.substr(0, 30), "b.txt:1:1: warning: square 'S'");
  expectWrittenBackLoadsStrictly(r);
  // Without that evidence, a gizmo beyond the board is only that: left out.
  const ReadResult lone = read("Square S 1 1\nSquare T 45 3\n");
  ASSERT_EQ(lone.board.gizmos.size(), 1u);
  EXPECT_EQ(lone.board.gizmos[0].name, "S");
  // Near the board, values are cells, whatever they divide by.
  const ReadResult near = read("Square S 0 0\nSquare T 20 0\n");
  ASSERT_EQ(near.board.gizmos.size(), 1u);
}

TEST(BoardRules, OverlapsAreResolvedBesideOtherRules) {
  // Before, the circle's radius was an error, and with any error no placement was repaired.
  const ReadResult r = read("Square S14 5 5\nRightFlipper RF1 4 4\nCircle C 3 3 0.5\n");
  ASSERT_EQ(r.board.gizmos.size(), 2u);
  EXPECT_EQ(r.board.gizmos[1].name, "C");
  EXPECT_NE(warningWith(r, "'RF1' overlaps square 'S14'").find("the right flipper is left out"), std::string::npos);
  expectWrittenBackLoadsStrictly(r);
}

TEST(BoardRules, TheXmlReaderFollowsTheSameRules) {
  const ReadResult r = readXml(
      "<board>\n"
      "  <ball name=\"B\" x=\"262.5\" y=\"62.5\" xVelocity=\"0\" yVelocity=\"0\"/>\n"
      "  <ball name=\"K\" x=\"5.25\" y=\"5.5\" xVelocity=\"0\" yVelocity=\"0\"/>\n"
      "  <score value=\"3\"/>\n"
      "  <gizmos>\n"
      "    <squareBumper name=\"S\" x=\"5\" y=\"5\"/>\n"
      "    <gate name=\"T\" x=\"8\" y=\"8\"/>\n"
      "    <circleBumper name=\"C\" x=\"30\" y=\"3\"/>\n"
      "  </gizmos>\n"
      "  <connections>\n"
      "    <connect sourceGizmo=\"S\" targetGizmo=\"T\"/>\n"
      "    <mouseConnect button=\"left\"/>\n"
      "  </connections>\n"
      "</board>\n");
  ASSERT_EQ(r.board.gizmos.size(), 1u);
  ASSERT_EQ(r.board.balls.size(), 1u);
  EXPECT_EQ(r.board.balls[0].name, "B");
  EXPECT_EQ(r.board.balls[0].x, 10.5);
  EXPECT_TRUE(r.board.connections.empty());
  EXPECT_EQ(warningWith(r, "<score>").substr(0, 11), "b.xml:4:3: ");
  EXPECT_NE(warningWith(r, "<gate>").find("connections that name 'T'"), std::string::npos);
  EXPECT_NE(warningWith(r, "<mouseConnect>").find("left out"), std::string::npos);
  // The ball inside the square goes, though the file places it first.
  EXPECT_NE(warningWith(r, "ball 'K'").find("the ball is left out"), std::string::npos);
  EXPECT_NE(warningWith(r, "circle 'C'").find("left out"), std::string::npos);
  EXPECT_FALSE(firstStrictError(r).empty());
  expectWrittenBackLoadsStrictly(r);
  const std::vector<std::string> none = errorsOf([] { readXml("<board><note text=\"hi\"/></board>"); });
  ASSERT_EQ(none.size(), 1u);
  EXPECT_NE(none[0].find("does not look like a Gizmoball board"), std::string::npos);
}

}  // namespace
}  // namespace gizmo::io
