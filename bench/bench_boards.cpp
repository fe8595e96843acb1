#include "bench_boards.hpp"

#include <filesystem>
#include <string>

#include "gizmo/io/board_file.hpp"
#include "support/paths.hpp"

namespace gizmo::bench {

std::optional<BoardSpec> realBoard(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(test::realBoardsDir()) / name;
  if (!std::filesystem::exists(path)) return std::nullopt;
  return io::readBoardFile(path.string()).board;
}

BoardSpec specExample() { return io::readBoardFile(test::fixturePath("boards/spec-example.txt")).board; }

// The crowded board is a file, so that the play page's tests and benchmarks play the very board
// these benchmarks run (it was made by code here before: 100 balls at varied speeds among 214
// squares, circles and triangles).
BoardSpec crowdedBoard() { return io::readBoardFile(test::fixturePath("boards/play/crowded-100-balls.txt")).board; }

}  // namespace gizmo::bench
