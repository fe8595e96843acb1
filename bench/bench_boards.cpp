#include "bench_boards.hpp"

#include <filesystem>
#include <string>

#include "gizmo/io/board_file.hpp"

namespace gizmo::bench {

std::optional<BoardSpec> realBoard(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(GIZMO_REAL_BOARDS_DIR) / name;
  if (!std::filesystem::exists(path)) return std::nullopt;
  return io::readBoardFile(path.string()).board;
}

BoardSpec specExample() { return io::readBoardFile(GIZMO_FIXTURES_DIR "/boards/spec-example.txt").board; }

BoardSpec crowdedBoard() {
  BoardSpec s;
  const GizmoType kinds[] = {GizmoType::Square, GizmoType::Circle, GizmoType::Triangle};
  int n = 0, balls = 0;
  for (int y = 2; y < 18; ++y)
    for (int x = 0; x < 20; ++x) {
      if ((x + 2 * y) % 3 != 0) {
        GizmoSpec g;
        g.type = kinds[(x * 7 + y * 3) % 3];
        g.name = "G" + std::to_string(n++);
        g.x = x;
        g.y = y;
        g.orientation = 90 * ((x + y) % 4);
        s.gizmos.push_back(g);
      } else if (balls < 100) {
        // Deterministic, varied velocities: no random source.
        const double vx = double((x * 13 + y * 7) % 21) - 10, vy = double((x * 5 + y * 11) % 17) - 8;
        s.balls.push_back(BallSpec{"B" + std::to_string(balls++), x + 0.5, y + 0.5, vx, vy, {}});
      }
    }
  return s;
}

}  // namespace gizmo::bench
