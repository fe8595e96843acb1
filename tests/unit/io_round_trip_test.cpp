// Writers: canonical output, exact numbers, and text→XML→text / XML→text→XML round trips of every
// fixture that loads and of generated boards.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"
#include "io_test_util.hpp"

namespace gizmo::io {
namespace {

using namespace test;

// Reads what was written: it must load cleanly (no warnings) and give the same board.
BoardSpec readBackText(const std::string& text, const BoardSpec& expected) {
  const ReadResult r = readTextBoard(text, "written.txt");
  EXPECT_TRUE(r.warnings.empty()) << format(r.warnings.front());
  expectSameBoard(expected, r.board);
  return r.board;
}
BoardSpec readBackXml(const std::string& xml, const BoardSpec& expected) {
  const ReadResult r = readXmlBoard(xml, "written.xml");
  EXPECT_TRUE(r.warnings.empty()) << format(r.warnings.front());
  expectSameBoard(expected, r.board);
  return r.board;
}

// text → XML → text and XML → text → XML, each written form stable once canonical.
void roundTrip(const BoardSpec& b) {
  {
    const std::string text1 = writeTextBoard(b);
    const BoardSpec b1 = readBackText(text1, b);
    const std::string xml = writeXmlBoard(b1);
    const BoardSpec b2 = readBackXml(xml, b);
    const std::string text2 = writeTextBoard(b2);
    readBackText(text2, b);
    EXPECT_EQ(text1, text2);
  }
  {
    const std::string xml1 = writeXmlBoard(b);
    const BoardSpec b1 = readBackXml(xml1, b);
    const std::string text = writeTextBoard(b1);
    const BoardSpec b2 = readBackText(text, b);
    const std::string xml2 = writeXmlBoard(b2);
    readBackXml(xml2, b);
    EXPECT_EQ(xml1, xml2);
  }
}

// A small board with every kind of statement.
BoardSpec sampleBoard() {
  BoardSpec b;
  b.gravity = 10;
  b.mu = 0.5;
  b.mu2 = 0.25;
  b.balls.push_back(BallSpec{"B", 1.5, 2.25, -3, 0.1, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::Triangle, "T", 1, 1, 180, 1, 1, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::Square, "S", 3, 3, 90, 1, 1, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::Absorber, "A", 0, 19, 0, 20, 1, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::LeftFlipper, "L", 10, 10, 270, 2, 2, {}});
  b.gizmos.push_back(GizmoSpec{GizmoType::Booster, "U", 5, 5, 90, 1, 1, {}});
  b.connections.push_back(ConnectSpec{"S", "L", {}});
  b.connections.push_back(ConnectSpec{"OuterWalls", "A", {}});
  b.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Up, "L", {}});
  return b;
}

TEST(BoardWriter, CanonicalText) {
  EXPECT_EQ(writeTextBoard(sampleBoard()),
            "Gravity 10\n"
            "Friction 0.5 0.25\n"
            "Triangle T 1 1\n"
            "Rotate T\n"
            "Rotate T\n"
            "Square S 3 3\n"
            "Rotate S\n"
            "Absorber A 0 19 20 20\n"
            "LeftFlipper L 10 10\n"
            "Rotate L\n"
            "Rotate L\n"
            "Rotate L\n"
            "Booster U 5 5\n"
            "Rotate U\n"
            "Ball B 1.5 2.25 -3 0.1\n"
            "Connect S L\n"
            "Connect OuterWalls A\n"
            "KeyConnect key 32 up L\n");
}

TEST(BoardWriter, CanonicalXml) {
  EXPECT_EQ(writeXmlBoard(sampleBoard()),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<board gravity=\"10\" friction1=\"0.5\" friction2=\"0.25\">\n"
            "  <ball name=\"B\" x=\"1.5\" y=\"2.25\" xVelocity=\"-3\" yVelocity=\"0.1\"/>\n"
            "  <gizmos>\n"
            "    <triangleBumper name=\"T\" x=\"1\" y=\"1\" orientation=\"180\"/>\n"
            "    <squareBumper name=\"S\" x=\"3\" y=\"3\" orientation=\"90\"/>\n"
            "    <absorber name=\"A\" x=\"0\" y=\"19\" width=\"20\" height=\"1\"/>\n"
            "    <leftFlipper name=\"L\" x=\"10\" y=\"10\" orientation=\"270\"/>\n"
            "    <booster name=\"U\" x=\"5\" y=\"5\" orientation=\"90\"/>\n"
            "  </gizmos>\n"
            "  <connections>\n"
            "    <connect sourceGizmo=\"S\" targetGizmo=\"L\"/>\n"
            "    <connect sourceGizmo=\"OuterWalls\" targetGizmo=\"A\"/>\n"
            "    <keyConnect key=\"32\" keyDirection=\"up\" targetGizmo=\"L\"/>\n"
            "  </connections>\n"
            "</board>\n");
}

TEST(BoardWriter, SampleBoardRoundTrips) {
  // The ball touches the bottom edge of the turned triangle exactly: a valid board.
  roundTrip(sampleBoard());
}

TEST(BoardWriter, NumbersAreTheShortestExactDecimal) {
  BoardSpec b;
  b.gravity = 0.1 + 0.2;
  b.mu = 1e-7;
  b.mu2 = 25;
  EXPECT_EQ(writeTextBoard(b), "Gravity 0.30000000000000004\nFriction 1e-07 25\n");
  b.gravity = -0.0;
  b.mu = 0.025;
  b.mu2 = 1.0 / 3;
  EXPECT_EQ(writeTextBoard(b), "Gravity -0\nFriction 0.025 0.3333333333333333\n");
}

TEST(BoardWriter, AwkwardDoublesSurviveExactly) {
  BoardSpec b;
  b.gravity = 1.0 / 3;
  b.mu = 0.1 + 0.2;
  b.mu2 = 1e-5 / 3;
  const double fractions[] = {1.0 / 3,
                              0.1,
                              0.2,
                              0.1 + 0.2,
                              std::nextafter(0.5, 1.0),
                              std::nextafter(0.5, 0.0),
                              2.0 / 7,
                              1e-9,
                              0.123456789012345678,
                              0.999};
  const double speeds[] = {-0.0, 5e-324,   1e-310, 1e5 / 3, -999999.9999999999, 2.2250738585072014e-308,
                           0.1,  -7.0 / 3, 1e6,    -1e6};
  for (int i = 0; i < 10; ++i)
    b.balls.push_back(
        BallSpec{"B" + std::to_string(i), 1 + 1.5 * i + fractions[i], 10 + fractions[i], speeds[i], speeds[9 - i], {}});
  roundTrip(b);
  const BoardSpec back = readTextBoard(writeTextBoard(b), "t").board;
  EXPECT_TRUE(std::signbit(back.balls[0].vx));  // −0 stays −0
  EXPECT_EQ(back.balls[1].vx, 5e-324);
}

TEST(BoardWriter, EveryLoadableFixtureRoundTrips) {
  std::vector<std::filesystem::path> files = {fixturesDir() / "boards" / "spec-example.txt",
                                              fixturesDir() / "boards" / "spec-example.xml"};
  for (const auto& f : boardFilesIn(fixturesDir() / "boards" / "lenient")) files.push_back(f);
  ASSERT_GE(files.size(), 7u);
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    roundTrip(readBoardFile(f.string()).board);
  }
}

TEST(BoardWriter, SpecExampleWrittenAsTextIsItsOwnCanonicalForm) {
  const BoardSpec b = readBoardFile((fixturesDir() / "boards" / "spec-example.txt").string()).board;
  const std::string text = writeTextBoard(b);
  // Canonical text: settings first, then gizmos (T turned once), balls, connections, key connections.
  const std::string head = "Gravity 25\nFriction 0.025 0.025\nTriangle T 19 0\nRotate T\nTriangle T2 1 1\n";
  EXPECT_EQ(text.substr(0, head.size()), head);
  EXPECT_NE(text.find("\nAbsorber A 0 19 20 20\nBall B 1 11 0 0\nConnect C43 LF87\n"), std::string::npos);
  const std::string tail = "Connect A A\nKeyConnect key 32 down LF92\n";
  EXPECT_NE(text.find(tail), std::string::npos);
  const std::string last = "KeyConnect key 127 down A\n";
  EXPECT_EQ(text.substr(text.size() - last.size()), last);
}

// ---------------------------------------------------------------------------------------------
// A generated board: 400 triangles fill every cell, and 100 balls sit in the free corners of 100
// of them, each touching two neighbouring triangles exactly.

BoardSpec generatedBoard() {
  BoardSpec b;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x)
      b.gizmos.push_back(
          GizmoSpec{GizmoType::Triangle, "T" + std::to_string(x) + "_" + std::to_string(y), x, y, 0, 1, 1, {}});
  for (int i = 0; i < 100; ++i) {
    const int cell = (i * 97) % 400;  // 97 and 400 are coprime: 100 distinct cells
    const int x = cell % 20, y = cell / 20;
    b.balls.push_back(BallSpec{"B" + std::to_string(i), x + 0.75, y + 0.75, i * 0.5 - 25, 3, {}});
  }
  for (int i = 0; i < 400; i += 3)
    b.connections.push_back(ConnectSpec{b.gizmos[i].name, b.gizmos[(i + 1) % 400].name, {}});
  for (int k = 0; k < 10; ++k)
    b.keyConnections.push_back(
        KeyConnectSpec{65 + k, k % 2 ? KeyDirection::Up : KeyDirection::Down, b.gizmos[k].name, {}});
  return b;
}

TEST(GeneratedBoard, HundredBallsAndFourHundredGizmosLoad) {
  const BoardSpec b = generatedBoard();
  // The cells really are distinct.
  for (std::size_t i = 0; i < b.balls.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      ASSERT_FALSE(b.balls[i].x == b.balls[j].x && b.balls[i].y == b.balls[j].y) << i << " " << j;
  const ReadResult text = readTextBoard(writeTextBoard(b), "generated.txt");
  EXPECT_EQ(text.board.balls.size(), 100u);
  EXPECT_EQ(text.board.gizmos.size(), 400u);
  const ReadResult xml = readXmlBoard(writeXmlBoard(b), "generated.xml");
  EXPECT_EQ(xml.board.balls.size(), 100u);
  EXPECT_EQ(xml.board.gizmos.size(), 400u);
  roundTrip(b);
}

TEST(GeneratedBoard, OneUlpCloserIsAnOverlap) {
  BoardSpec b = generatedBoard();
  // Ball 0 sits in cell (0, 0), touching T1_0 (the cell to its right) and T0_1 (below). The text
  // has Gravity and Friction on lines 1 and 2, the triangles row by row from line 3, then the balls.
  ASSERT_EQ(b.balls[0].x, 0.75);
  ASSERT_EQ(b.balls[0].y, 0.75);
  b.balls[0].x = std::nextafter(0.75, 1.0);
  // The reader leaves the ball out with a warning (a board check's message); --strict refuses it.
  const ReadResult r = readTextBoard(writeTextBoard(b), "g.txt");
  EXPECT_EQ(r.board.balls.size(), b.balls.size() - 1);
  const auto e = errorsOf([&] { refuseLeniency(r); });
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0],
            "g.txt:403:1: error: ball 'B0' at (0.7500000000000001, 0.75) overlaps triangle 'T1_0' from line 4; "
            "the ball is left out (refused: --strict reads a board only as written)");
}

}  // namespace
}  // namespace gizmo::io
