// The text board reader: the spec example, every error with its position, every leniency with its
// warning, the malformed and lenient fixtures, and readBoardFile's file checks.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <string>

#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"
#include "io_test_util.hpp"
#include "support/scratch_dir.hpp"

namespace gizmo::io {
namespace {

using namespace test;

ReadResult readText(const std::string& s) { return readTextBoard(s, "b.txt"); }
std::vector<std::string> textErrors(const std::string& s) {
  return errorsOf([&] { readText(s); });
}
std::string firstTextError(const std::string& s) {
  const auto e = textErrors(s);
  return e.empty() ? std::string() : e.front();
}
std::vector<std::string> textWarnings(const std::string& s) { return formatted(readText(s).warnings); }
// As --strict reads: what would be a warning is an error.
ReadResult readStrict(const std::string& s) {
  ReadResult r = readText(s);
  refuseLeniency(r);
  return r;
}
std::vector<std::string> strictErrors(const std::string& s) {
  return errorsOf([&] { readStrict(s); });
}
// A board check's message as --strict reports the repair that leaves the later thing out.
std::string leftOut(const std::string& error, const std::string& what) {
  return error + "; the " + what + " is left out (refused: --strict reads a board only as written)";
}
std::string firstStrictError(const std::string& s) {
  const auto e = strictErrors(s);
  return e.empty() ? std::string() : e.front();
}

std::size_t countType(const BoardSpec& b, GizmoType t) {
  std::size_t n = 0;
  for (const auto& g : b.gizmos) n += g.type == t;
  return n;
}
const GizmoSpec* gizmo(const BoardSpec& b, const std::string& name) {
  for (const auto& g : b.gizmos)
    if (g.name == name) return &g;
  return nullptr;
}
bool hasConnection(const BoardSpec& b, const std::string& s, const std::string& t) {
  for (const auto& c : b.connections)
    if (c.source == s && c.target == t) return true;
  return false;
}
bool hasKey(const BoardSpec& b, int key, KeyDirection d, const std::string& t) {
  for (const auto& k : b.keyConnections)
    if (k.key == key && k.direction == d && k.target == t) return true;
  return false;
}
// The shortest text of a double, for building boards at exact values.
std::string num(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// ---------------------------------------------------------------------------------------------
// The specification's example board.

TEST(TextReader, SpecExampleLoadsWithTheRightContents) {
  const ReadResult r = readBoardFile((fixturesDir() / "boards" / "spec-example.txt").string());
  EXPECT_TRUE(r.warnings.empty());
  const BoardSpec& b = r.board;
  EXPECT_EQ(b.gizmos.size(), 35u);
  EXPECT_EQ(countType(b, GizmoType::Square), 15u);
  EXPECT_EQ(countType(b, GizmoType::Circle), 13u);
  EXPECT_EQ(countType(b, GizmoType::Triangle), 2u);
  EXPECT_EQ(countType(b, GizmoType::LeftFlipper), 2u);
  EXPECT_EQ(countType(b, GizmoType::RightFlipper), 2u);
  EXPECT_EQ(countType(b, GizmoType::Absorber), 1u);
  ASSERT_EQ(b.balls.size(), 1u);
  EXPECT_EQ(b.balls[0].name, "B");
  EXPECT_EQ(b.balls[0].x, 1.0);
  EXPECT_EQ(b.balls[0].y, 11.0);
  EXPECT_EQ(b.balls[0].vx, 0.0);
  EXPECT_EQ(b.balls[0].vy, 0.0);
  EXPECT_EQ(b.balls[0].where.line, 70);

  const GizmoSpec* t = gizmo(b, "T");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->orientation, 90);
  EXPECT_EQ(t->x, 19);
  EXPECT_EQ(t->y, 0);
  EXPECT_EQ(t->where.line, 2);  // the Rotate line is the last that changed it
  ASSERT_NE(gizmo(b, "T2"), nullptr);
  EXPECT_EQ(gizmo(b, "T2")->orientation, 0);
  EXPECT_EQ(gizmo(b, "S02")->where.line, 6);
  EXPECT_EQ(gizmo(b, "S02")->where.column, 1);

  const GizmoSpec* a = gizmo(b, "A");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->type, GizmoType::Absorber);
  EXPECT_EQ(a->x, 0);
  EXPECT_EQ(a->y, 19);
  EXPECT_EQ(a->width, 20);
  EXPECT_EQ(a->height, 1);
  EXPECT_EQ(a->orientation, 0);

  const GizmoSpec* lf = gizmo(b, "LF87");
  ASSERT_NE(lf, nullptr);
  EXPECT_EQ(lf->type, GizmoType::LeftFlipper);
  EXPECT_EQ(lf->width, 2);
  EXPECT_EQ(lf->height, 2);

  EXPECT_EQ(b.connections.size(), 15u);
  EXPECT_EQ(b.keyConnections.size(), 9u);
  EXPECT_TRUE(hasConnection(b, "A", "A"));
  EXPECT_TRUE(hasConnection(b, "C1110", "LF87"));
  EXPECT_TRUE(hasConnection(b, "C1110", "RF137"));
  EXPECT_FALSE(hasConnection(b, "C99", "LF87"));
  EXPECT_TRUE(hasKey(b, 127, KeyDirection::Down, "A"));
  EXPECT_FALSE(hasKey(b, 127, KeyDirection::Up, "A"));
  EXPECT_TRUE(hasKey(b, 32, KeyDirection::Up, "RF112"));
  EXPECT_TRUE(hasKey(b, 81, KeyDirection::Down, "LF87"));
  EXPECT_EQ(b.gravity, 25.0);
  EXPECT_EQ(b.mu, 0.025);
  EXPECT_EQ(b.mu2, 0.025);
}

TEST(TextReader, MessySpecExampleIsTheSameBoard) {
  const BoardSpec clean = readBoardFile((fixturesDir() / "boards" / "spec-example.txt").string()).board;
  const ReadResult messy = readBoardFile((fixturesDir() / "boards" / "lenient" / "spec-example-messy.txt").string());
  expectSameBoard(clean, messy.board);
  EXPECT_FALSE(messy.warnings.empty());
}

// ---------------------------------------------------------------------------------------------
// Commands.

TEST(TextReader, EachGizmoGetsItsSize) {
  const BoardSpec b = readText(
                          "Square S 0 0\nCircle C 1 0\nTriangle T 2 0\nLeftFlipper L 3 0\n"
                          "RightFlipper R 5 0\nAbsorber A 0 10 7 13\n")
                          .board;
  ASSERT_EQ(b.gizmos.size(), 6u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(b.gizmos[i].width, 1);
    EXPECT_EQ(b.gizmos[i].height, 1);
  }
  EXPECT_EQ(b.gizmos[3].width, 2);
  EXPECT_EQ(b.gizmos[4].height, 2);
  EXPECT_EQ(b.gizmos[5].x, 0);
  EXPECT_EQ(b.gizmos[5].y, 10);
  EXPECT_EQ(b.gizmos[5].width, 7);
  EXPECT_EQ(b.gizmos[5].height, 3);
}

TEST(TextReader, RotateTurnsAQuarterClockwiseAndKeepsSquaresTurned) {
  const BoardSpec b = readText(
                          "Triangle T 1 1\nRotate T\nRotate T\nRotate T\nSquare S 3 3\nRotate S\n"
                          "LeftFlipper F 5 5\nRotate F\nRotate F\nRotate F\nRotate F\n")
                          .board;
  EXPECT_EQ(gizmo(b, "T")->orientation, 270);
  EXPECT_EQ(gizmo(b, "S")->orientation, 90);
  EXPECT_EQ(gizmo(b, "F")->orientation, 0);
}

TEST(TextReader, MoveAndDelete) {
  const BoardSpec b = readText(
                          "Square S 1 1\nBall B 5 5 1 2\nCircle C 7 7\nConnect S C\nConnect C S\n"
                          "KeyConnect key 32 down C\nKeyConnect key 32 down S\n"
                          "Move S 2 3\nMove B 6.5 7.25\nDelete C\n")
                          .board;
  ASSERT_EQ(b.gizmos.size(), 1u);
  EXPECT_EQ(b.gizmos[0].x, 2);
  EXPECT_EQ(b.gizmos[0].y, 3);
  EXPECT_EQ(b.gizmos[0].where.line, 8);
  ASSERT_EQ(b.balls.size(), 1u);
  EXPECT_EQ(b.balls[0].x, 6.5);
  EXPECT_EQ(b.balls[0].y, 7.25);
  EXPECT_EQ(b.balls[0].vx, 1.0);
  // Deleting C removed both connections that named it and its key connection.
  EXPECT_TRUE(b.connections.empty());
  ASSERT_EQ(b.keyConnections.size(), 1u);
  EXPECT_EQ(b.keyConnections[0].target, "S");
}

TEST(TextReader, ANameCanBeUsedAgainAfterDelete) {
  const BoardSpec b = readText("Square S 1 1\nConnect S S\nDelete S\nCircle S 4 4\n").board;
  ASSERT_EQ(b.gizmos.size(), 1u);
  EXPECT_EQ(b.gizmos[0].type, GizmoType::Circle);
  EXPECT_TRUE(b.connections.empty());  // the old S's connection went with it
}

TEST(TextReader, LastGravityAndFrictionWin) {
  const BoardSpec b = readText("Gravity 10\nFriction 0.5 0.25\nGravity -3.5\nFriction 0 0\n").board;
  EXPECT_EQ(b.gravity, -3.5);
  EXPECT_EQ(b.mu, 0.0);
  EXPECT_EQ(b.mu2, 0.0);
  const BoardSpec d = readText("").board;
  EXPECT_EQ(d.gravity, 25.0);
  EXPECT_EQ(d.mu, 0.025);
  EXPECT_EQ(d.mu2, 0.025);
}

TEST(TextReader, OuterWallsMayTrigger) {
  const BoardSpec b = readText("LeftFlipper F 2 4\nConnect OuterWalls F\n").board;
  ASSERT_EQ(b.connections.size(), 1u);
  EXPECT_EQ(b.connections[0].source, "OuterWalls");
}

// d-g-n/CS308-GizmoBall writes its booster as NAME X Y, names starting with a digit, and turns
// it with Rotate (its ballballcollisions.txt, lines 25-28): read as a booster without a warning.
TEST(TextReader, BoostersAsTheirProgramWritesThem) {
  const ReadResult r = readText(
      "Booster 16_15 16 15\r\nRotate 16_15\r\nRotate 16_15\r\nRotate 16_15\r\n"
      "Booster 1_3 1 3\r\n");
  ASSERT_EQ(countType(r.board, GizmoType::Booster), 2u);
  EXPECT_EQ(gizmo(r.board, "16_15")->orientation, 270);
  EXPECT_EQ(gizmo(r.board, "16_15")->x, 16);
  EXPECT_EQ(gizmo(r.board, "1_3")->orientation, 0);
  for (const std::string& w : formatted(r.warnings)) EXPECT_EQ(w.find("Booster"), std::string::npos) << w;
  EXPECT_EQ(firstStrictError("Booster U 1"),
            "b.txt:1:1: error: Booster takes 3 values (Booster NAME X Y) but the line has 2; "
            "it is another program's booster, left out, and so are the commands that "
            "name 'U' (refused: --strict reads a board only as written)");
}

// As lheckemann/gizmoball writes it (StandardLoader.java:188-201: Sink NAME X Y), read without a
// warning; written back as the same line, and as <sink> in XML.
TEST(TextReader, SinksAsTheirProgramWritesThem) {
  const ReadResult r = readTextBoard("Sink Sink0 4 7\nSquare S 1 1\nConnect Sink0 S\n", "b.txt");
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_EQ(r.board.gizmos.size(), 2u);
  EXPECT_EQ(r.board.gizmos[0].type, GizmoType::Sink);
  EXPECT_EQ(r.board.gizmos[0].x, 4);
  EXPECT_EQ(r.board.gizmos[0].y, 7);
  const std::string text = writeTextBoard(r.board);
  EXPECT_NE(text.find("Sink Sink0 4 7\n"), std::string::npos) << text;
  const std::string xml = writeXmlBoard(r.board);
  EXPECT_NE(xml.find("<sink name=\"Sink0\" x=\"4\" y=\"7\""), std::string::npos) << xml;
  const ReadResult back = readXmlBoard(xml, "b.xml");
  EXPECT_TRUE(back.warnings.empty());
  ASSERT_EQ(back.board.gizmos.size(), 2u);
  EXPECT_EQ(back.board.gizmos[0].type, GizmoType::Sink);
  EXPECT_EQ(back.board.connections.size(), 1u);
}

// As NiklavsM/Gizmoball writes it (GameLoader.java: Spinner NAME X Y, a 2×2 cross), read without a
// warning; written back as the same line, and as <spinner> in XML.
TEST(TextReader, SpinnersAsTheirProgramWritesThem) {
  const ReadResult r = readTextBoard("Spinner SP1 7 12\nSquare S 1 1\nConnect S SP1\n", "b.txt");
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_EQ(r.board.gizmos.size(), 2u);
  const GizmoSpec& s = r.board.gizmos[0];
  EXPECT_EQ(s.type, GizmoType::Spinner);
  EXPECT_EQ(s.x, 7);
  EXPECT_EQ(s.y, 12);
  EXPECT_EQ(s.width, 2);
  EXPECT_EQ(s.height, 2);
  const std::string text = writeTextBoard(r.board);
  EXPECT_NE(text.find("Spinner SP1 7 12\n"), std::string::npos) << text;
  const std::string xml = writeXmlBoard(r.board);
  EXPECT_NE(xml.find("<spinner name=\"SP1\" x=\"7\" y=\"12\"/>"), std::string::npos) << xml;
  const ReadResult back = readXmlBoard(xml, "b.xml");
  EXPECT_TRUE(back.warnings.empty());
  ASSERT_EQ(back.board.gizmos.size(), 2u);
  EXPECT_EQ(back.board.gizmos[0].type, GizmoType::Spinner);
  EXPECT_EQ(back.board.gizmos[0].width, 2);
  EXPECT_EQ(firstStrictError("Spinner SP1 19 3"),
            "b.txt:1:1: error: spinner 'SP1' covers x 19..21, y 3..5, not wholly on the board (0..20 in both); the "
            "spinner is left out (refused: --strict reads a board only as written)");
}

// d-g-n/CS308-GizmoBall's saver names each gizmo by its cell (spinnerboard.txt: `Spinner 7_12 7 12`),
// and its spinner is a bar that always turns, not NiklavsM's cross: left out, with a warning.
TEST(TextReader, DgnsSpinnerIsLeftOutByName) {
  const ReadResult r = readTextBoard("Spinner 7_12 7 12\nSpinner S 3 3\n", "b.txt");
  ASSERT_EQ(r.board.gizmos.size(), 1u);
  EXPECT_EQ(r.board.gizmos[0].name, "S");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].message.find("d-g-n"), std::string::npos) << r.warnings[0].message;
  EXPECT_EQ(r.warnings[0].line, 1);
}

// As rgallagher27/308gizmoball writes it (FileParser.java:118-120: Portal NAME X Y EXITX EXITY, an
// entry cell and an exit cell), read without a warning; written back as the same line, and as
// <portal> with its exit in XML.
TEST(TextReader, PortalsAsTheirProgramWritesThem) {
  const ReadResult r = readTextBoard("Portal P1 1 9 17 1\n", "b.txt");
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_EQ(r.board.gizmos.size(), 1u);
  const GizmoSpec& p = r.board.gizmos[0];
  EXPECT_EQ(p.type, GizmoType::Portal);
  EXPECT_EQ(p.x, 1);
  EXPECT_EQ(p.y, 9);
  EXPECT_EQ(p.exitX, 17);
  EXPECT_EQ(p.exitY, 1);
  const std::string text = writeTextBoard(r.board);
  EXPECT_NE(text.find("Portal P1 1 9 17 1\n"), std::string::npos) << text;
  const std::string xml = writeXmlBoard(r.board);
  EXPECT_NE(xml.find("<portal name=\"P1\" x=\"1\" y=\"9\" exitX=\"17\" exitY=\"1\"/>"), std::string::npos) << xml;
  const ReadResult back = readXmlBoard(xml, "b.xml");
  EXPECT_TRUE(back.warnings.empty());
  ASSERT_EQ(back.board.gizmos.size(), 1u);
  EXPECT_EQ(back.board.gizmos[0].exitX, 17);
  EXPECT_EQ(back.board.gizmos[0].exitY, 1);
  EXPECT_EQ(firstStrictError("Portal P1 1 9 17"),
            "b.txt:1:1: error: Portal takes 5 values (Portal NAME X Y EXITX EXITY) but the line has 4; it is another "
            "program's portal, left out, and so are the commands that name 'P1' (refused: --strict reads a board only "
            "as written)");
  EXPECT_EQ(firstStrictError("Portal P1 1 9 20 3"),
            "b.txt:1:1: error: portal 'P1' has its exit at cell 20,3, which is not on the board (cells 0..19 in both); "
            "the portal is left out (refused: --strict reads a board only as written)");
  EXPECT_TRUE(readText("Portal P1 1 9 20 3").board.gizmos.empty());
}

TEST(TextReader, EmptyAndBlankFilesGiveTheDefaultBoard) {
  EXPECT_TRUE(readText("").board.gizmos.empty());
  const ReadResult r = readText("\n   \n\t\n");
  EXPECT_TRUE(r.board.balls.empty());
  EXPECT_TRUE(r.warnings.empty());
}

// ---------------------------------------------------------------------------------------------
// Errors, each with its position.

TEST(TextReaderErrors, UnknownCommandsAreNamed) {
  // Words no Gizmoball program this reader knows gives a meaning: left out by name beside lines of
  // the format (io_board_rules_test.cpp); a file of nothing else is no board.
  for (const std::string cmd : {"Kircle", "NotAGizmo", "OuterWall", "model.Wall@5c0c0d45"}) {
    const std::string want =
        "b.txt:2:3: error: no line of this file is a command of the Gizmoball format (the first "
        "line's word is '" +
        cmd + "')";
    EXPECT_EQ(firstTextError("\n  " + cmd + " X 1 1\n").substr(0, want.size()), want);
    const std::string warning = "b.txt:2:3: warning: '" + cmd + "' is not a command of the Gizmoball format";
    EXPECT_EQ(textWarnings("Square S 1 1\n  " + cmd + " X 1 1\n").at(0).substr(0, warning.size()), warning);
  }
}

// The format's commands have their values; values after what places a gizmo or a ball are ignored
// (io_board_rules_test.cpp), and --strict refuses that at the first extra value.
TEST(TextReaderErrors, TokenCounts) {
  EXPECT_EQ(firstTextError("Absorber A 0 19 20"),
            "b.txt:1:1: error: Absorber needs 5 values (Absorber NAME X1 Y1 X2 Y2) but the line has 4");
  EXPECT_EQ(firstStrictError("Absorber A 0 19 20 20 1"),
            "b.txt:1:23: error: what follows Absorber NAME X1 Y1 X2 Y2 (1 more, from '1') is ignored; it is placed "
            "from its own values (refused: --strict reads a board only as written)");
  EXPECT_EQ(firstTextError("Rotate"), "b.txt:1:1: error: Rotate needs 1 value (Rotate NAME) but the line has 0");
  EXPECT_EQ(firstTextError("Gravity 1 2"),
            "b.txt:1:11: error: unexpected '2' after the end of the command: Gravity G takes 1 value");
  EXPECT_EQ(firstTextError("Friction 1"),
            "b.txt:1:1: error: Friction needs 2 values (Friction MU MU2) but the line has 1");
}

TEST(TextReaderErrors, NumbersAreCheckedWholly) {
  EXPECT_EQ(firstTextError("Ball B 1.5xyz 2 0 0"), "b.txt:1:8: error: the x coordinate must be a number, not '1.5xyz'");
  EXPECT_EQ(firstTextError("Ball B 5 5 0 NaN"), "b.txt:1:14: error: the y velocity must be a finite number, not 'NaN'");
  EXPECT_EQ(firstTextError("Ball B 5 -inf 0 0"),
            "b.txt:1:10: error: the y coordinate must be a finite number, not '-inf'");
  EXPECT_EQ(firstTextError("Gravity infinity"), "b.txt:1:9: error: gravity must be a finite number, not 'infinity'");
  EXPECT_EQ(firstTextError("Gravity 0x19"), "b.txt:1:9: error: gravity must be a decimal number, not '0x19'");
  EXPECT_EQ(firstTextError("Gravity 1e999"), "b.txt:1:9: error: gravity '1e999' is out of range");
  EXPECT_EQ(firstTextError("Gravity 1e"), "b.txt:1:9: error: gravity must be a number, not '1e'");
  EXPECT_EQ(firstTextError("Gravity ."), "b.txt:1:9: error: gravity must be a number, not '.'");
  EXPECT_EQ(firstTextError("Gravity 1,5"), "b.txt:1:9: error: gravity must be a number, not '1,5'");
  EXPECT_EQ(firstTextError("Square S x 2"), "b.txt:1:10: error: the x coordinate must be a number, not 'x'");
  EXPECT_EQ(firstTextError("Square S 3000000000 2"),
            "b.txt:1:10: error: the x coordinate '3000000000' is too large (the limit is 1000000000)");
  EXPECT_EQ(firstTextError("Move S 3.5 2"), "b.txt:1:6: error: there is no gizmo or ball named 'S'");
  EXPECT_EQ(firstTextError("Square S 1 1\nMove S 3.5 y"),
            "b.txt:2:12: error: the y coordinate must be a number, not 'y'");
}

TEST(TextReaderErrors, AcceptedNumberSpellings) {
  const BoardSpec b = readText("Ball B +5 .5e1 -0 5.\nGravity 2.5E1\n").board;
  EXPECT_EQ(b.balls[0].x, 5.0);
  EXPECT_EQ(b.balls[0].y, 5.0);
  EXPECT_EQ(b.balls[0].vx, 0.0);
  EXPECT_EQ(b.balls[0].vy, 5.0);
  EXPECT_EQ(b.gravity, 25.0);
}

TEST(TextReaderErrors, Names) {
  EXPECT_EQ(firstTextError("Square OuterWalls 1 1"),
            "b.txt:1:8: error: the name OuterWalls is reserved for the outer walls");
  EXPECT_EQ(firstTextError("Ball OuterWalls 5 5 0 0"),
            "b.txt:1:6: error: the name OuterWalls is reserved for the outer walls");
  // Names are case-sensitive: these are two different gizmos.
  EXPECT_EQ(readText("Square s 1 1\nSquare S 3 3\n").board.gizmos.size(), 2u);
}

TEST(TextReaderErrors, OperationsOnUnknownNames) {
  EXPECT_EQ(firstTextError("Rotate X"), "b.txt:1:8: error: there is no gizmo named 'X'");
  EXPECT_EQ(firstTextError("Move X 1 1"), "b.txt:1:6: error: there is no gizmo or ball named 'X'");
  EXPECT_EQ(firstTextError("Delete X"), "b.txt:1:8: error: there is no gizmo or ball named 'X'");
  EXPECT_EQ(firstTextError("Rotate outerwalls"),
            "b.txt:1:8: error: there is no gizmo named 'outerwalls' (the outer walls are named OuterWalls)");
  // (Connect and KeyConnect to unknown names are read leniently: TextReaderLeniency.)
  // A name whose creation failed is not reported again; one that an unknown command would have
  // created is left out, with the commands that name it.
  EXPECT_EQ(textWarnings("Square S 1 1\nKircle X 1 1\nRotate X\nMove X 1 1\n").size(), 2u);
  EXPECT_EQ(textErrors("Square X x 1\nRotate X\n").size(), 1u);
}

TEST(TextReaderErrors, RotateOnlyWhatTurns) {
  EXPECT_EQ(firstTextError("Absorber A 0 19 20 20\nRotate A"), "b.txt:2:8: error: absorber 'A' cannot be rotated");
  EXPECT_EQ(firstTextError("Ball B 5 5 0 0\nRotate B"),
            "b.txt:2:8: error: ball 'B' cannot be rotated: only gizmos turn");
}

TEST(TextReaderErrors, KeyConnect) {
  EXPECT_EQ(firstTextError("Square S 1 1\nKeyConnect key 39 sideways S"),
            "b.txt:2:19: error: the key direction must be down or up, not 'sideways'");
  EXPECT_EQ(firstTextError("Square S 1 1\nKeyConnect key -1 up S"),
            "b.txt:2:16: error: key code -1 is outside 0..65535");
  EXPECT_EQ(firstTextError("Square S 1 1\nKeyConnect key 65536 up S"),
            "b.txt:2:16: error: key code 65536 is outside 0..65535");
  EXPECT_EQ(firstTextError("Square S 1 1\nKeyConnect key 3.5 up S"),
            "b.txt:2:16: error: the key code must be a whole number, not '3.5'");
  EXPECT_EQ(firstTextError("Square S 1 1\nKeyConnect code 3 up S"),
            "b.txt:2:12: error: expected the word 'key' after KeyConnect, not 'code'");
  EXPECT_EQ(firstTextError("Square S 1 1\nKeyConnect key 3 up OuterWalls"),
            "b.txt:2:21: error: the outer walls cannot be a connection target: they have no action");
  const BoardSpec b = readText("Square S 1 1\nKeyConnect key 0 up S\nKeyConnect key 65535 down S\n").board;
  EXPECT_EQ(b.keyConnections.size(), 2u);
}

TEST(TextReaderErrors, AbsorberCorners) {
  EXPECT_EQ(firstTextError("Absorber A 5 5 5 6"),
            "b.txt:1:16: error: the absorber's lower-right corner must lie right of its upper-left corner "
            "(X2 = 5 is not more than X1 = 5)");
  EXPECT_EQ(firstTextError("Absorber A 5 5 6 4"),
            "b.txt:1:18: error: the absorber's lower-right corner must lie below its upper-left corner "
            "(Y2 = 4 is not more than Y1 = 5)");
}

TEST(TextReaderErrors, GravityAndFrictionLimits) {
  EXPECT_EQ(firstTextError("Friction 0.025 -1"),
            "b.txt:1:16: error: friction mu2 is -1; friction constants cannot be negative");
  EXPECT_EQ(firstTextError("Gravity 2e6"),
            "b.txt:1:9: error: gravity 2000000 L/s^2 is beyond the limit of 1000000 L/s^2");
  EXPECT_EQ(firstTextError("Friction 5e6 0"),
            "b.txt:1:10: error: friction mu = 5000000 is beyond the limit of 1000000");
}

TEST(TextReaderErrors, BoardChecksMapToTheirLines) {
  EXPECT_EQ(firstStrictError("\n\nSquare S 20 3"),
            "b.txt:3:1: error: square 'S' covers x 20..21, y 3..4, not wholly on the board (0..20 in both); the square "
            "is left out (refused: --strict reads a board only as written)");
  EXPECT_EQ(firstStrictError("Square S -1 3"),
            "b.txt:1:1: error: square 'S' covers x -1..0, y 3..4, not wholly on the board (0..20 in both); the square "
            "is left out (refused: --strict reads a board only as written)");
  EXPECT_EQ(firstStrictError("Absorber A 0 19 21 20"),
            "b.txt:1:1: error: absorber 'A' covers x 0..21, y 19..20, not wholly on the board (0..20 in both); the "
            "absorber is left out (refused: --strict reads a board only as written)");
  EXPECT_EQ(firstStrictError("Absorber A 0 0 10 10\nLeftFlipper F 9 9"),
            leftOut("b.txt:2:1: error: left flipper 'F' overlaps absorber 'A' from line 1 (both occupy cell 9,9)",
                    "left flipper"));
  EXPECT_EQ(firstStrictError("Ball B 20.1 5 0 0"),
            "b.txt:1:1: error: ball 'B' at (20.1, 5) is not on the board, which spans 0..20 L in both directions; the "
            "ball is left out (refused: --strict reads a board only as written)");
  EXPECT_EQ(firstStrictError("Ball B 5 5 -1000001 0"),
            "b.txt:1:1: error: ball 'B' is too fast: its velocity (-1000001, 0) L/s exceeds 1000000 L/s in x or y");
  // Speeds of thousands of L/s are fine.
  EXPECT_NO_THROW(readStrict("Ball B 5 5 -5000 2500"));
}

TEST(TextReaderErrors, GizmoOverlapsAreDecidedByBoundingBoxes) {
  // Flippers fill only part of their 2×2 box, yet the boxes may not share area.
  EXPECT_EQ(
      firstStrictError("LeftFlipper L 0 0\nSquare S 1 1"),
      leftOut("b.txt:2:1: error: square 'S' overlaps left flipper 'L' from line 1 (both occupy cell 1,1)", "square"));
  // Touching edges and corners is fine.
  EXPECT_NO_THROW(readStrict("LeftFlipper L 0 0\nSquare S 2 2\nSquare T 2 0\nAbsorber A 0 2 2 4\n"));
  // Each gizmo is reported once, with the earliest gizmo it overlaps, at the first shared cell.
  EXPECT_EQ(textErrors("Absorber A 0 0 4 4\nSquare S 2 2\nAbsorber B 1 1 5 5\nGravity g\n").front(),
            "b.txt:2:1: error: square 'S' overlaps absorber 'A' from line 1 (both occupy cell 2,2)");
  EXPECT_EQ(textErrors("Absorber A 0 0 4 4\nSquare S 2 2\nAbsorber B 1 1 5 5\nGravity g\n")[1],
            "b.txt:3:1: error: absorber 'B' overlaps absorber 'A' from line 1 (both occupy cell 1,1)");
  EXPECT_EQ(strictErrors("Absorber A 0 0 4 4\nSquare S 2 2\nAbsorber B 1 1 5 5\n"),
            (std::vector<std::string>{
                "b.txt:2:1: error: square 'S' overlaps absorber 'A' from line 1 (both occupy cell 2,2); the square is "
                "left out (and 1 more like this) (refused: --strict reads a board only as written)"}));
}

TEST(TextReaderErrors, BallAgainstGizmoIsExact) {
  // Touching a square's edge is allowed; the next double towards it overlaps.
  EXPECT_NO_THROW(readStrict("Square S 5 5\nBall B 4.75 5.5 0 0"));
  EXPECT_EQ(firstStrictError("Square S 5 5\nBall B " + num(std::nextafter(4.75, 5.0)) + " 5.5 0 0"),
            leftOut("b.txt:2:1: error: ball 'B' at (4.750000000000001, 5.5) overlaps square 'S' from line 1", "ball"));
  // Near a corner: these doubles lie just outside the quarter circle about (5, 5)...
  EXPECT_NO_THROW(readStrict("Square S 5 5\nBall B 4.85 4.8 0 0"));
  // ...and the next doubles towards the corner lie just inside it.
  EXPECT_EQ(strictErrors("Square S 5 5\nBall B " + num(std::nextafter(4.85, 5.0)) + " " +
                         num(std::nextafter(4.8, 5.0)) + " 0 0")
                .size(),
            1u);
  // A circle bumper: radius 0.5 about the cell centre.
  EXPECT_NO_THROW(readStrict("Circle C 5 5\nBall B 6.25 5.5 0 0"));
  EXPECT_EQ(strictErrors("Circle C 5 5\nBall B " + num(std::nextafter(6.25, 0.0)) + " 5.5 0 0").size(), 1u);
  // The empty corner of a circle's cell is free.
  EXPECT_NO_THROW(readStrict("Circle C 5 5\nBall B 5.25 4.75 0 0"));
  // A ball wholly inside a square (no edge within reach) still overlaps it.
  // Of a ball and a gizmo, the ball is left out, whichever comes first.
  EXPECT_EQ(strictErrors("Ball B 10.5 10.5 0 0\nSquare S 10 10").front(),
            leftOut("b.txt:2:1: error: square 'S' overlaps ball 'B' from line 1 at (10.5, 10.5)", "ball"));
}

TEST(TextReaderErrors, BallAgainstTriangleAndFlipper) {
  // Triangle, orientation 0 at (1, 1): the north-west half of the cell. The south-east half is free.
  EXPECT_NO_THROW(readStrict("Triangle T 1 1\nBall B 1.75 1.75 0 0"));
  EXPECT_EQ(strictErrors("Triangle T 1 1\nBall B 1.3 1.3 0 0").size(), 1u);
  // Rotated twice (180): now the south-east half is taken.
  EXPECT_EQ(strictErrors("Triangle T 1 1\nRotate T\nRotate T\nBall B 1.75 1.75 0 0").size(), 1u);
  EXPECT_NO_THROW(readStrict("Triangle T 1 1\nRotate T\nRotate T\nBall B 1.25 1.25 0 0"));
  // Left flipper at (0, 0): a capsule of radius 0.25 about x = 0.25, y 0.25..1.75.
  EXPECT_NO_THROW(readStrict("LeftFlipper F 0 0\nBall B 0.75 1 0 0"));
  EXPECT_EQ(strictErrors("LeftFlipper F 0 0\nBall B " + num(std::nextafter(0.75, 0.0)) + " 1 0 0").size(), 1u);
  EXPECT_NO_THROW(readStrict("LeftFlipper F 0 0\nBall B 0.25 2.25 0 0"));  // touching the tip, just below the box
  EXPECT_EQ(strictErrors("LeftFlipper F 0 0\nBall B 0.25 " + num(std::nextafter(2.25, 0.0)) + " 0 0").size(), 1u);
  // The rest of the flipper's box is free.
  EXPECT_NO_THROW(readStrict("LeftFlipper F 0 0\nBall B 1.5 1.5 0 0"));
  // Right flipper at (0, 0): its pivot is at (1.75, 0.25).
  EXPECT_NO_THROW(readStrict("RightFlipper F 0 0\nBall B 0.5 1 0 0"));
  EXPECT_EQ(strictErrors("RightFlipper F 0 0\nBall B 1.6 1 0 0").size(), 1u);
}

TEST(TextReaderErrors, BallsInAbsorbers) {
  // At rest and wholly inside: captured, allowed, even together.
  EXPECT_NO_THROW(readStrict("Absorber A 0 18 20 20\nBall B 10 19 0 0\nBall C 10 19 0 0\nBall D 0.25 18.25 0 0"));
  EXPECT_EQ(firstStrictError("Absorber A 0 18 20 20\nBall B 10 19 0 -1"),
            "b.txt:2:1: error: ball 'B' at (10, 19) with velocity (0, -1) lies in absorber 'A'; it is read as "
            "captured there, at rest at (10, 19) (refused: --strict reads a board only as written)");
  // Partly inside.
  EXPECT_EQ(firstStrictError("Absorber A 0 18 20 20\nBall B 10 17.9 0 0"),
            leftOut("b.txt:2:1: error: ball 'B' at (10, 17.9) overlaps absorber 'A' from line 1", "ball"));
  // Resting on top is touching.
  EXPECT_NO_THROW(readStrict("Absorber A 0 18 20 20\nBall B 10 17.75 0 0"));
}

TEST(TextReaderErrors, BallsAgainstBalls) {
  EXPECT_NO_THROW(readStrict("Ball A 5 5 0 0\nBall B 5.5 5 0 0"));  // touching
  EXPECT_EQ(firstStrictError("Ball A 5 5 0 0\nBall B " + num(std::nextafter(5.5, 0.0)) + " 5 0 0"),
            leftOut("b.txt:2:1: error: ball 'B' at (5.499999999999999, 5) overlaps ball 'A' from line 1 at (5, 5): "
                    "their centres are closer than 0.5 L",
                    "ball"));
  // Each ball is reported once, with the earliest ball it overlaps.
  EXPECT_EQ(textErrors("Ball A 5 5 0 0\nBall B 5.1 5 0 0\nBall C 5.2 5 0 0\nGravity g\n").size(), 3u);
}

TEST(TextReaderErrors, AllErrorsAreReportedInOrder) {
  // A file with errors is not repaired: its board checks are errors too.
  // (The unknown command of line 4 is left out with a warning, not an error.)
  const auto e = textErrors("Square S 1 1\nSquare S 1 1\nBall B 1.5 1.5 0 0\nKircle X\nGravity g\n");
  EXPECT_EQ(e, (std::vector<std::string>{
                   "b.txt:2:1: error: square 'S_2' overlaps square 'S' from line 1 (both occupy cell 1,1)",
                   "b.txt:3:1: error: ball 'B' at (1.5, 1.5) overlaps square 'S' from line 1",
                   "b.txt:3:1: error: ball 'B' at (1.5, 1.5) overlaps square 'S_2' from line 2",
                   "b.txt:5:9: error: gravity must be a number, not 'g'"}));
}

TEST(TextReaderErrors, ErrorsAreCappedAtFifty) {
  std::string text;
  for (int i = 0; i < 73; ++i) text += "Square S" + std::to_string(i) + " x 1\n";
  const auto e = textErrors(text);
  ASSERT_EQ(e.size(), 51u);
  EXPECT_EQ(e[0], "b.txt:1:11: error: the x coordinate must be a number, not 'x'");
  EXPECT_EQ(e[49], "b.txt:50:12: error: the x coordinate must be a number, not 'x'");
  EXPECT_EQ(e[50], "b.txt: error: and 23 more errors (only the first 50 are shown)");
}

TEST(TextReaderErrors, WhatIsIncludesEveryDiagnostic) {
  try {
    readText("Rotate a\nRotate b\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "b.txt:1:8: error: there is no gizmo named 'a'\nb.txt:2:8: error: there is no gizmo named 'b'");
  }
}

TEST(TextReaderErrors, AbsurdInputs) {
  const std::string longLine = "Square S 1 1" + std::string(70000, ' ') + "\nRotate S";
  EXPECT_EQ(
      textErrors(longLine),
      (std::vector<std::string>{"b.txt:1:1: error: the line is longer than 65536 bytes; no board line is that long",
                                "b.txt:2:8: error: there is no gizmo named 'S'"}));
  const std::string huge((std::size_t{16} << 20) + 1, '\n');
  EXPECT_EQ(textErrors(huge),
            (std::vector<std::string>{"b.txt: error: the file is larger than 16 MiB, the limit for board files"}));
  EXPECT_EQ(firstTextError(std::string("Square S 1 1\nBall B\0 5 5 0 0", 21)),
            "b.txt:2:7: error: unexpected control character (byte 0x00)");
  EXPECT_EQ(firstTextError("Square S 1 1\rSquare T 2 2\n"),
            "b.txt:1:13: error: unexpected control character (byte 0x0D)");
  std::string tooMany;
  for (int i = 0; i < 10001; ++i) tooMany += "Ball B" + std::to_string(i) + " 5 5 0 0\n";
  EXPECT_EQ(textErrors(tooMany),
            (std::vector<std::string>{"b.txt:10001:1: error: the board has 10001 balls; at most 10000 are allowed"}));
}

// ---------------------------------------------------------------------------------------------
// Leniency: read, with one warning per kind at its first place.

TEST(TextReaderLenient, KeywordCase) {
  const ReadResult r = readText("leftflipper F 1 1\nKEYCONNECT KEY 32 Down F\nconnect F F\n");
  EXPECT_EQ(r.board.keyConnections.size(), 1u);
  EXPECT_EQ(r.board.keyConnections[0].direction, KeyDirection::Down);
  EXPECT_EQ(r.board.connections.size(), 1u);
  EXPECT_EQ(
      formatted(r.warnings),
      (std::vector<std::string>{"b.txt:1:1: warning: 'leftflipper' is written 'LeftFlipper' in the standard format; "
                                "keywords are read without regard to case (and 4 more like this)"}));
}

TEST(TextReaderLenient, IntegralDecimals) {
  const ReadResult r = readText("Square S 3.0 4\nKeyConnect key 76.0 down S\nSquare T 1e1 0\n");
  EXPECT_EQ(r.board.gizmos[0].x, 3);
  EXPECT_EQ(r.board.keyConnections[0].key, 76);
  EXPECT_EQ(r.board.gizmos[1].x, 10);
  EXPECT_EQ(formatted(r.warnings),
            (std::vector<std::string>{"b.txt:1:10: warning: '3.0' is read as the whole number 3 "
                                      "(the standard format writes whole numbers here) (and 2 more like this)"}));
}

TEST(TextReaderLenient, CommentsCrlfAndWhiteSpace) {
  EXPECT_EQ(textWarnings("# a board\r\n\t Square   S\t1 1  \r\n"),
            (std::vector<std::string>{
                "b.txt:1:1: warning: '#' comment lines are not part of the standard format; ignored",
                "b.txt:1:10: warning: Windows line ending (CR LF) read as a plain line end (and 1 more like this)"}));
  EXPECT_TRUE(textWarnings("Square S 1 1\n\n   \n\t\n").empty());
}

TEST(TextReaderLenient, RepeatedConnectionsAreDropped) {
  const ReadResult r = readText(
      "Square S 1 1\nConnect S S\nConnect OuterWalls S\nConnect S S\n"
      "KeyConnect key 1 up S\nKeyConnect key 1 up S\nKeyConnect key 1 down S\n");
  EXPECT_EQ(r.board.connections.size(), 2u);
  EXPECT_EQ(r.board.keyConnections.size(), 2u);
  EXPECT_EQ(
      formatted(r.warnings),
      (std::vector<std::string>{"b.txt:4:1: warning: this connection repeats the one on line 2; the repetition is "
                                "ignored (and 1 more like this)"}));
}

TEST(TextReaderLenient, ByteOrderMarkDoesNotShiftColumns) {
  EXPECT_EQ(firstTextError("\xEF\xBB\xBFSquare S x 1"),
            "b.txt:1:10: error: the x coordinate must be a number, not 'x'");
}

// ---------------------------------------------------------------------------------------------
// Fixtures.

TEST(TextFixtures, MalformedFilesGiveTheirExpectedErrors) {
  int n = 0;
  for (const auto& f : boardFilesIn(fixturesDir() / "boards" / "malformed"))
    if (f.extension() == ".txt") {
      checkAgainstExpected(f);
      ++n;
    }
  EXPECT_GE(n, 20);
}

TEST(TextFixtures, LenientFilesLoadWithTheirExpectedWarnings) {
  int n = 0;
  for (const auto& f : boardFilesIn(fixturesDir() / "boards" / "lenient"))
    if (f.extension() == ".txt") {
      checkAgainstExpected(f);
      ++n;
    }
  EXPECT_GE(n, 22);
}

// ---------------------------------------------------------------------------------------------
// readBoardFile and readBoardString.

TEST(BoardFile, FileProblems) {
  const gizmo::test::ScratchDir dir;
  const std::string missing = (dir.path() / "missing.txt").string();
  EXPECT_EQ(errorsOf([&] { readBoardFile(missing); }),
            (std::vector<std::string>{missing + ": error: cannot read the file: it does not exist"}));
  EXPECT_EQ(errorsOf([&] { readBoardFile(dir.path().string()); }),
            (std::vector<std::string>{dir.path().string() + ": error: cannot read the file: it is a directory"}));
  const std::string binary = (dir.path() / "binary.txt").string();
  writeFile(binary, std::string("Square S 1 1\nSq\0are", 19));
  EXPECT_EQ(errorsOf([&] { readBoardFile(binary); }),
            (std::vector<std::string>{binary + ":2:3: error: the file contains a NUL byte: it is not a text file"}));
  const std::string big = (dir.path() / "big.txt").string();
  writeFile(big, std::string((std::size_t{16} << 20) + 1, ' '));
  EXPECT_EQ(errorsOf([&] { readBoardFile(big); }),
            (std::vector<std::string>{big + ": error: the file is larger than 16 MiB, the limit for board files"}));
  const std::string good = (dir.path() / "good.txt").string();
  writeFile(good, "Square S 1 1\n");
  EXPECT_EQ(readBoardFile(good).board.gizmos.size(), 1u);
}

TEST(BoardFile, FormatIsChosenByTheFirstCharacter) {
  EXPECT_EQ(readBoardString("\n  \t<board><gizmos/><connections/></board>", "x").board.gizmos.size(), 0u);
  EXPECT_EQ(readBoardString("\xEF\xBB\xBF<board gravity='3'><gizmos/><connections/></board>", "x").board.gravity, 3.0);
  EXPECT_EQ(readBoardString("Gravity 3", "x").board.gravity, 3.0);
  // Not XML: the text reader reports it.
  EXPECT_EQ(errorsOf([] { readBoardString("board <x/>", "x"); }).front().substr(0, 29),
            "x:1:1: error: no line of this");
}

}  // namespace
}  // namespace gizmo::io
