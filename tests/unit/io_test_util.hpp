#pragma once
// Helpers shared by the io tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/text_reader.hpp"
#include "support/paths.hpp"

namespace gizmo::io::test {

// A board that a test writes, read as the file b.txt would be: messages name b.txt.
inline ReadResult read(const std::string& text) { return readTextBoard(text, "b.txt"); }

inline std::filesystem::path fixturesDir() { return std::filesystem::path(gizmo::test::fixturesDir()); }

inline std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot open " << p;
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void writeFile(const std::filesystem::path& p, const std::string& content) {
  std::ofstream out(p, std::ios::binary);
  out << content;
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

inline std::vector<std::string> formatted(const std::vector<Diagnostic>& ds) {
  std::vector<std::string> out;
  for (const Diagnostic& d : ds) out.push_back(format(d));
  return out;
}

// The formatted diagnostics of the InputError that f throws; a test failure when it throws none.
inline std::vector<std::string> errorsOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_FALSE(e.diagnostics().empty());
    for (const Diagnostic& d : e.diagnostics()) EXPECT_TRUE(d.error);
    return formatted(e.diagnostics());
  }
  ADD_FAILURE() << "no InputError was thrown";
  return {};
}

// Every field but the source positions.
inline void expectSameBoard(const BoardSpec& a, const BoardSpec& b) {
  EXPECT_EQ(a.gravity, b.gravity);
  EXPECT_EQ(a.mu, b.mu);
  EXPECT_EQ(a.mu2, b.mu2);
  ASSERT_EQ(a.balls.size(), b.balls.size());
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    SCOPED_TRACE("ball " + a.balls[i].name);
    EXPECT_EQ(a.balls[i].name, b.balls[i].name);
    EXPECT_EQ(a.balls[i].x, b.balls[i].x);
    EXPECT_EQ(a.balls[i].y, b.balls[i].y);
    EXPECT_EQ(a.balls[i].vx, b.balls[i].vx);
    EXPECT_EQ(a.balls[i].vy, b.balls[i].vy);
  }
  ASSERT_EQ(a.gizmos.size(), b.gizmos.size());
  for (std::size_t i = 0; i < a.gizmos.size(); ++i) {
    SCOPED_TRACE("gizmo " + a.gizmos[i].name);
    EXPECT_EQ(a.gizmos[i].type, b.gizmos[i].type);
    EXPECT_EQ(a.gizmos[i].name, b.gizmos[i].name);
    EXPECT_EQ(a.gizmos[i].x, b.gizmos[i].x);
    EXPECT_EQ(a.gizmos[i].y, b.gizmos[i].y);
    EXPECT_EQ(a.gizmos[i].orientation, b.gizmos[i].orientation);
    EXPECT_EQ(a.gizmos[i].width, b.gizmos[i].width);
    EXPECT_EQ(a.gizmos[i].height, b.gizmos[i].height);
  }
  ASSERT_EQ(a.connections.size(), b.connections.size());
  for (std::size_t i = 0; i < a.connections.size(); ++i) {
    EXPECT_EQ(a.connections[i].source, b.connections[i].source);
    EXPECT_EQ(a.connections[i].target, b.connections[i].target);
  }
  ASSERT_EQ(a.keyConnections.size(), b.keyConnections.size());
  for (std::size_t i = 0; i < a.keyConnections.size(); ++i) {
    EXPECT_EQ(a.keyConnections[i].key, b.keyConnections[i].key);
    EXPECT_EQ(a.keyConnections[i].direction, b.keyConnections[i].direction);
    EXPECT_EQ(a.keyConnections[i].target, b.keyConnections[i].target);
  }
}

// The board files of a fixtures folder (every file but the .expected ones), sorted.
inline std::vector<std::filesystem::path> boardFilesIn(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() != ".expected") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

inline std::filesystem::path expectedFor(const std::filesystem::path& board) {
  return board.parent_path() / (board.stem().string() + ".expected");
}

// A fixture board (text or XML) against its .expected file: the warnings it loads with, or the
// errors that refuse it. A file whose first expected line is a warning must load.
inline void checkAgainstExpected(const std::filesystem::path& board) {
  SCOPED_TRACE(board.filename().string());
  const std::vector<std::string> expected = lines(readFile(expectedFor(board)));
  ASSERT_FALSE(expected.empty());
  std::vector<std::string> got;
  bool loaded = false;
  try {
    got = formatted(readBoardString(readFile(board), board.filename().string()).warnings);
    loaded = true;
  } catch (const InputError& e) {
    got = formatted(e.diagnostics());
  }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(loaded, expected.front().find(": warning: ") != std::string::npos);
}

}  // namespace gizmo::io::test
