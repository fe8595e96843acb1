#include <cstdio>

#include "gizmo/core/board/build_board.hpp"
#include "gizmo/io/board_file.hpp"

int main() {
  // A ball thrown to the right over a square; the text format of docs/board-files.md.
  const gizmo::io::ReadResult file = gizmo::io::readBoardString("Square S 10 15\nBall B 2.5 2.5 4 0\n", "inline.txt");
  const auto board = gizmo::buildBoard<double>(file.board, gizmo::PhysicsParams<double>{});
  board->tick(1.0);  // one second of board time
  const gizmo::Ball<double>& ball = *board->gizmo(board->ballIds().front()).asBall();
  const gizmo::Vec2<double> p = ball.positionAt(board->now());
  std::printf("ball %s at (%.6f, %.6f) after %g s\n", ball.name().c_str(), p.x, p.y, board->now());
  return p.x > 2.5 && p.y > 2.5 ? 0 : 1;  // it moved right and fell
}
