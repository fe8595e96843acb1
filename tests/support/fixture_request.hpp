#pragma once
// A run of a board from fixtures/, as the tests that run fixture boards describe it.
#include <string>

#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "support/paths.hpp"

namespace gizmo::test {

// `board` is a path below fixtures/, e.g. "boards/spec-example.txt".
inline RunRequest fixtureRequest(const std::string& board, MotionModel model, double seconds) {
  RunRequest r;
  r.board = io::readBoardFile(fixturePath(board)).board;
  r.model = model;
  r.duration = seconds;
  return r;
}

}  // namespace gizmo::test
