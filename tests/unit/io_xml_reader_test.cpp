// The XML board reader: the spec example in XML, well-formedness, the schema, numbers, positions,
// leniency, and the XML fixtures.
#include <gtest/gtest.h>

#include <string>

#include "gizmo/io/board_file.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"
#include "io_test_util.hpp"

namespace gizmo::io {
namespace {

using namespace test;

ReadResult readXml(const std::string& s) { return readXmlBoard(s, "x.xml"); }
std::vector<std::string> xmlErrors(const std::string& s) {
  return errorsOf([&] { readXml(s); });
}
std::string firstXmlError(const std::string& s) {
  const auto e = xmlErrors(s);
  return e.empty() ? std::string() : e.front();
}
std::vector<std::string> xmlWarnings(const std::string& s) { return formatted(readXml(s).warnings); }

// A board around some gizmos and connections.
std::string board(const std::string& gizmos, const std::string& connections = "") {
  return "<board>\n  <gizmos>\n" + gizmos + "  </gizmos>\n  <connections>\n" + connections +
         "  </connections>\n</board>\n";
}

TEST(XmlReader, SpecExampleInXmlIsTheSpecExample) {
  const ReadResult xml = readBoardFile((fixturesDir() / "boards" / "spec-example.xml").string());
  const ReadResult text = readBoardFile((fixturesDir() / "boards" / "spec-example.txt").string());
  EXPECT_TRUE(xml.warnings.empty());  // comments, the declaration and xmlns/xsi attributes are not worth a warning
  expectSameBoard(text.board, xml.board);
  ASSERT_EQ(xml.board.balls.size(), 1u);
  EXPECT_EQ(xml.board.balls[0].where.line, 5);
  EXPECT_EQ(xml.board.balls[0].where.column, 3);
  ASSERT_FALSE(xml.board.gizmos.empty());
  EXPECT_EQ(xml.board.gizmos[0].name, "T");
  EXPECT_EQ(xml.board.gizmos[0].where.line, 7);
  EXPECT_EQ(xml.board.gizmos[0].where.column, 5);
}

TEST(XmlReader, ReadsEveryElement) {
  const ReadResult r = readXml(
      "<board gravity=\"10\" friction1=\"0.5\" friction2=\"0.25\">\n"
      "  <ball name=\"Ball\" x=\"2\" y=\"2\" xVelocity=\"-15.4\" yVelocity=\"-10.3\"/>\n"
      "  <ball name=\"Fast\" x=\"10\" y=\"10\" xVelocity=\"-100\" yVelocity=\"-25\"/>\n"
      "  <gizmos>\n"
      "    <squareBumper name=\"S\" x=\"0\" y=\"5\"/>\n"
      "    <circleBumper name=\"C\" x=\"4\" y=\"3\"/>\n"
      "    <triangleBumper name=\"T\" x=\"1\" y=\"8\" orientation=\"270\"/>\n"
      "    <leftFlipper name=\"L\" x=\"10\" y=\"15\" orientation=\"90\"/>\n"
      "    <rightFlipper name=\"R\" x=\"12\" y=\"15\" orientation=\"0\"/>\n"
      "    <absorber name=\"A\" x=\"0\" y=\"19\" width=\"20\" height=\"1\"/>\n"
      "  </gizmos>\n"
      "  <connections>\n"
      "    <connect sourceGizmo=\"S\" targetGizmo=\"L\"/>\n"
      "    <connect sourceGizmo=\"OuterWalls\" targetGizmo=\"R\"/>\n"
      "    <keyConnect key=\"32\" keyDirection=\"up\" targetGizmo=\"A\"/>\n"
      "  </connections>\n"
      "</board>\n");
  EXPECT_TRUE(r.warnings.empty());
  const BoardSpec& b = r.board;
  EXPECT_EQ(b.gravity, 10.0);
  EXPECT_EQ(b.mu, 0.5);
  EXPECT_EQ(b.mu2, 0.25);
  ASSERT_EQ(b.balls.size(), 2u);
  EXPECT_EQ(b.balls[0].vx, -15.4);
  EXPECT_EQ(b.balls[0].vy, -10.3);
  EXPECT_EQ(b.balls[1].vx, -100.0);
  ASSERT_EQ(b.gizmos.size(), 6u);
  EXPECT_EQ(b.gizmos[0].type, GizmoType::Square);
  EXPECT_EQ(b.gizmos[1].type, GizmoType::Circle);
  EXPECT_EQ(b.gizmos[2].type, GizmoType::Triangle);
  EXPECT_EQ(b.gizmos[2].orientation, 270);
  EXPECT_EQ(b.gizmos[3].type, GizmoType::LeftFlipper);
  EXPECT_EQ(b.gizmos[3].orientation, 90);
  EXPECT_EQ(b.gizmos[3].width, 2);
  EXPECT_EQ(b.gizmos[4].type, GizmoType::RightFlipper);
  EXPECT_EQ(b.gizmos[5].type, GizmoType::Absorber);
  EXPECT_EQ(b.gizmos[5].width, 20);
  EXPECT_EQ(b.gizmos[5].height, 1);
  ASSERT_EQ(b.connections.size(), 2u);
  EXPECT_EQ(b.connections[1].source, "OuterWalls");
  ASSERT_EQ(b.keyConnections.size(), 1u);
  EXPECT_EQ(b.keyConnections[0].key, 32);
  EXPECT_EQ(b.keyConnections[0].direction, KeyDirection::Up);
  EXPECT_EQ(b.keyConnections[0].where.line, 15);
}

TEST(XmlReader, DefaultsAndOptionalOrientation) {
  const BoardSpec b = readXml(board("    <triangleBumper name=\"T\" x=\"1\" y=\"1\"/>\n"
                                    "    <squareBumper name=\"S\" x=\"3\" y=\"3\" orientation=\"90\"/>\n"))
                          .board;
  EXPECT_EQ(b.gravity, 25.0);
  EXPECT_EQ(b.mu, 0.025);
  EXPECT_EQ(b.mu2, 0.025);
  EXPECT_EQ(b.gizmos[0].orientation, 0);
  EXPECT_EQ(b.gizmos[1].orientation, 90);  // a turned square is kept turned
}

TEST(XmlReader, NumbersMayHaveSurroundingWhiteSpace) {
  const ReadResult r = readXml(board("    <squareBumper name=\"S\" x=\" 3 \" y=\"&#9;4\"/>\n"));
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.board.gizmos[0].x, 3);
  EXPECT_EQ(r.board.gizmos[0].y, 4);
}

// ---------------------------------------------------------------------------------------------
// Well-formedness and structure.

TEST(XmlReaderErrors, NotWellFormedAtTheRightLineAndColumn) {
  // CR LF line ends count as one line end each.
  EXPECT_EQ(firstXmlError("<board>\r\n  <gizmos>\r\n  </gizmo>\r\n</board>\r\n"),
            "x.xml:3:5: error: the XML is not well-formed: Start-end tags mismatch");
  const std::string unquoted = firstXmlError("<board>\n<ball name=B/>\n</board>");
  EXPECT_EQ(unquoted.substr(0, 50), "x.xml:2:12: error: the XML is not well-formed: Err");
  const std::string unclosed = firstXmlError("<board>\n  <gizmos>\n");
  EXPECT_NE(unclosed.find("error: the XML is not well-formed: "), std::string::npos);
}

TEST(XmlReaderErrors, ExactlyOneRootNamedBoard) {
  EXPECT_EQ(
      xmlErrors("<board><gizmos/><connections/></board>\n  <board/>"),
      (std::vector<std::string>{
          "x.xml:2:3: error: a second root element <board>: a board file has exactly one root element, <board>"}));
  EXPECT_EQ(firstXmlError("<?xml version=\"1.0\"?>\n<Board/>"),
            "x.xml:2:1: error: the root element is <Board>; a board file's root element is <board>");
  EXPECT_EQ(firstXmlError(""), "x.xml: error: the file holds no XML element; a board file's root element is <board>");
  EXPECT_EQ(firstXmlError("<!-- nothing -->\n"),
            "x.xml: error: the file holds no XML element; a board file's root element is <board>");
  EXPECT_EQ(firstXmlError("junk <board><gizmos/><connections/></board>"),
            "x.xml:1:1: error: unexpected text outside the <board> element");
}

TEST(XmlReaderErrors, UnexpectedContent) {
  EXPECT_EQ(firstXmlError("<board>hello<gizmos/><connections/></board>"),
            "x.xml:1:8: error: unexpected text inside <board>");
  EXPECT_EQ(firstXmlError("<board><![CDATA[x]]><gizmos/><connections/></board>"),
            "x.xml:1:17: error: unexpected text inside <board>");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\" y=\"1\"><foo/></squareBumper>\n")),
            "x.xml:3:40: error: <squareBumper> cannot contain <foo>");
  EXPECT_EQ(firstXmlError(board("    some text\n")), "x.xml:3:5: error: unexpected text inside <gizmos>");
  // Another schema's elements are left out by name (io_board_rules_test.cpp).
  EXPECT_EQ(xmlWarnings(board("", "    <fire trigger=\"A\"/>\n")).at(0),
            "x.xml:5:5: warning: unknown element <fire> in <connections> (it holds <connect> and <keyConnect>); it is "
            "left out");
  EXPECT_EQ(xmlWarnings("<board><Gizmos/><connections/></board>").at(1),
            "x.xml:1:8: warning: unknown element <Gizmos> in <board> (it holds <ball>, <gizmos> and <connections> (did "
            "you mean <gizmos>?)); it is left out");
}

TEST(XmlReaderErrors, Attributes) {
  EXPECT_EQ(xmlErrors("<board>\n  <ball name=\"B\"/>\n  <gizmos/>\n  <connections/>\n</board>"),
            (std::vector<std::string>{"x.xml:2:3: error: <ball> lacks the required attribute 'x'",
                                      "x.xml:2:3: error: <ball> lacks the required attribute 'y'",
                                      "x.xml:2:3: error: <ball> lacks the required attribute 'xVelocity'",
                                      "x.xml:2:3: error: <ball> lacks the required attribute 'yVelocity'"}));
  EXPECT_EQ(firstXmlError(board("    <absorber name=\"A\" x=\"0\" y=\"19\" width=\"20\"/>\n")),
            "x.xml:3:5: error: <absorber> lacks the required attribute 'height'");
  EXPECT_EQ(firstXmlError(board("", "    <keyConnect key=\"32\" targetGizmo=\"A\"/>\n")),
            "x.xml:5:5: error: <keyConnect> lacks the required attribute 'keyDirection'");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\"\n        y=\"1\" y=\"2\"/>\n")),
            "x.xml:4:15: error: the attribute 'y' is given twice");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"Ball(1,2)\" x=\"1\" y=\"1\"/>\n")),
            "x.xml:3:19: error: 'Ball(1,2)' is not a valid name: names use only letters, digits and _");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S&amp;\" x=\"1\" y=\"1\"/>\n")),
            "x.xml:3:19: error: 'S&' is not a valid name: names use only letters, digits and _");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"\" x=\"1\" y=\"1\"/>\n")),
            "x.xml:3:19: error: a name cannot be empty");
}

TEST(XmlReaderErrors, Numbers) {
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\" y=\"nan\"/>\n")),
            "x.xml:3:34: error: y must be a finite number, not 'nan'");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"\" y=\"1\"/>\n")), "x.xml:3:28: error: x is empty");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"2.5\" y=\"1\"/>\n")),
            "x.xml:3:28: error: x must be a whole number, not '2.5'");
  // CR LF line ends, and a value spread over lines, do not shift positions.
  EXPECT_EQ(firstXmlError("<board>\r\n  <gizmos>\r\n    <squareBumper name=\"S\"\r\n      x=\"2.5\" y=\"1\"/>\r\n"
                          "  </gizmos>\r\n  <connections/>\r\n</board>\r\n"),
            "x.xml:4:7: error: x must be a whole number, not '2.5'");
  EXPECT_EQ(firstXmlError(board("    <triangleBumper name=\"T\" x=\"1\" y=\"1\" orientation=\"45\"/>\n")),
            "x.xml:3:5: error: triangle 'T' has orientation 45; it must be 0, 90, 180 or 270");
  EXPECT_EQ(firstXmlError(board("    <absorber name=\"A\" x=\"0\" y=\"19\" width=\"0\" height=\"1\"/>\n")),
            "x.xml:3:5: error: absorber 'A' is 0 x 1 L; its width and height must each be at least 1");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\" y=\"1\"/>\n",
                                "    <keyConnect key=\"0x20\" keyDirection=\"down\" targetGizmo=\"S\"/>\n")),
            "x.xml:6:17: error: key must be a decimal number, not '0x20'");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\" y=\"1\"/>\n",
                                "    <keyConnect key=\"65536\" keyDirection=\"down\" targetGizmo=\"S\"/>\n")),
            "x.xml:6:17: error: key code 65536 is outside 0..65535");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\" y=\"1\"/>\n",
                                "    <keyConnect key=\"32\" keyDirection=\"pressed\" targetGizmo=\"S\"/>\n")),
            "x.xml:6:26: error: keyDirection must be down or up, not 'pressed'");
  EXPECT_EQ(firstXmlError("<board gravity=\"abc\"><gizmos/><connections/></board>"),
            "x.xml:1:8: error: gravity must be a number, not 'abc'");
  EXPECT_EQ(firstXmlError("<board friction1=\"0\" friction2=\"-0.5\"><gizmos/><connections/></board>"),
            "x.xml:1:22: error: friction mu2 (friction2) is -0.5; friction constants cannot be negative");
}

TEST(XmlReaderErrors, BoardChecks) {
  EXPECT_EQ(firstXmlError("<board>\n  <ball name=\"X\" x=\"5\" y=\"5\" xVelocity=\"0\" yVelocity=\"0\"/>\n  <gizmos>\n"
                          "    <squareBumper name=\"X\" x=\"1\" y=\"1\"/>\n  </gizmos>\n  <connections/>\n</board>"),
            "x.xml:4:5: error: square 'X' has the same name as the ball on line 2; names must be unique");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"OuterWalls\" x=\"1\" y=\"1\"/>\n")),
            "x.xml:3:5: error: the name 'OuterWalls' is reserved for the outer walls; a square cannot use it");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\" y=\"1\"/>\n",
                                "    <connect sourceGizmo=\"S\" targetGizmo=\"OuterWalls\"/>\n")),
            "x.xml:6:5: error: connection target cannot be the outer walls: they have no action");
  EXPECT_EQ(firstXmlError(board("    <squareBumper name=\"S\" x=\"1\" y=\"1\"/>\n",
                                "    <connect sourceGizmo=\"Gone\" targetGizmo=\"S\"/>\n")),
            "x.xml:6:5: error: connection source 'Gone' is not a gizmo on this board");
  // Off the board: left out (io_board_rules_test.cpp).
  EXPECT_EQ(xmlWarnings(board("    <rightFlipper name=\"F\" x=\"19\" y=\"5\" orientation=\"0\"/>\n")).at(0),
            "x.xml:3:5: warning: right flipper 'F' covers x 19..21, y 5..7, not wholly on the board (0..20 in both); "
            "the right flipper is left out");
}

// ---------------------------------------------------------------------------------------------
// Leniency.

TEST(XmlReaderLenient, Warnings) {
  EXPECT_EQ(xmlWarnings(
                "<board xmlns=\"urn:x\" xmlns:xsi=\"urn:y\" xsi:schemaLocation=\"z\"><gizmos/><connections/></board>"),
            std::vector<std::string>{});
  EXPECT_EQ(xmlWarnings("<board>\n<connections/>\n<gizmos/>\n</board>"),
            (std::vector<std::string>{
                "x.xml:3:1: warning: <gizmos> after <connections>: the schema puts the gizmos first (read anyway)"}));
  EXPECT_EQ(xmlWarnings("<board>\n<gizmos/>\n<gizmos/>\n<connections/>\n</board>"),
            (std::vector<std::string>{
                "x.xml:3:1: warning: a second <gizmos> element: the schema has one (its gizmos are read too)"}));
  EXPECT_EQ(xmlWarnings(board("    <triangleBumper name=\"T\" x=\"1\" y=\"1\" orientation=\"90.0\"/>\n")),
            (std::vector<std::string>{
                "x.xml:3:42: warning: '90.0' is read as the whole number 90 (the schema has whole numbers here)"}));
  const ReadResult split = readXml(
      "<board>\n<gizmos><squareBumper name=\"A\" x=\"1\" y=\"1\"/></gizmos>\n"
      "<connections/>\n<gizmos><squareBumper name=\"B\" x=\"3\" y=\"3\"/></gizmos>\n</board>");
  EXPECT_EQ(split.board.gizmos.size(), 2u);
}

TEST(XmlReaderLenient, ByteOrderMarkDoesNotShiftColumns) {
  EXPECT_EQ(firstXmlError("\xEF\xBB\xBF<board gravity=\"g\"><gizmos/><connections/></board>"),
            "x.xml:1:8: error: gravity must be a number, not 'g'");
}

// ---------------------------------------------------------------------------------------------
// Fixtures.

TEST(XmlFixtures, MalformedFilesGiveTheirExpectedErrors) {
  int n = 0;
  for (const auto& f : boardFilesIn(fixturesDir() / "boards" / "malformed"))
    if (f.extension() == ".xml") {
      checkAgainstExpected(f);
      ++n;
    }
  EXPECT_GE(n, 11);
}

TEST(XmlFixtures, LenientFilesLoadWithTheirExpectedWarnings) {
  int n = 0;
  for (const auto& f : boardFilesIn(fixturesDir() / "boards" / "lenient"))
    if (f.extension() == ".xml") {
      EXPECT_NO_THROW(readBoardString(readFile(f), f.filename().string()));
      checkAgainstExpected(f);
      ++n;
    }
  EXPECT_GE(n, 6);
}

}  // namespace
}  // namespace gizmo::io
