// Loading boards: the specification's example, 300 gizmos with 100 balls, and 400 gizmos (every
// cell), from text and from XML.
#include <benchmark/benchmark.h>

#include "bench_boards.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"

namespace gizmo::bench {
namespace {

// 300 one-cell gizmos, and 100 balls in every fourth column.
BoardSpec gizmosAndHundredBalls() {
  BoardSpec s;
  int n = 0, b = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      if (x % 4 == 3 && b < 100) {
        s.balls.push_back(BallSpec{"B" + std::to_string(b++), x + 0.5, y + 0.5, 1.0, -2.0, {}});
        continue;
      }
      GizmoSpec g;
      g.type = (x + y) % 2 ? GizmoType::Square : GizmoType::Circle;
      g.name = "G" + std::to_string(n++);
      g.x = x;
      g.y = y;
      s.gizmos.push_back(g);
    }
  return s;
}

// Every one of the 400 cells holds a gizmo.
BoardSpec fullGrid() {
  BoardSpec s;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      GizmoSpec g;
      g.type = (x + y) % 3 == 0 ? GizmoType::Triangle : (x + y) % 3 == 1 ? GizmoType::Square : GizmoType::Circle;
      g.name = "G" + std::to_string(y * 20 + x);
      g.x = x;
      g.y = y;
      g.orientation = 90 * ((x * 3 + y) % 4);
      s.gizmos.push_back(g);
    }
  return s;
}

void loadText(benchmark::State& state, const BoardSpec& board) {
  const std::string text = io::writeTextBoard(board);
  for (auto _ : state) benchmark::DoNotOptimize(io::readBoardString(text, "board.txt"));
  state.counters["gizmos"] = double(board.gizmos.size());
  state.counters["balls"] = double(board.balls.size());
}
void loadXml(benchmark::State& state, const BoardSpec& board) {
  const std::string xml = io::writeXmlBoard(board);
  for (auto _ : state) benchmark::DoNotOptimize(io::readBoardString(xml, "board.xml"));
  state.counters["gizmos"] = double(board.gizmos.size());
  state.counters["balls"] = double(board.balls.size());
}

void BM_LoadSpecExampleText(benchmark::State& s) { loadText(s, specExample()); }
void BM_LoadCrowdedText(benchmark::State& s) { loadText(s, gizmosAndHundredBalls()); }
void BM_LoadCrowdedXml(benchmark::State& s) { loadXml(s, gizmosAndHundredBalls()); }
void BM_LoadFullGridText(benchmark::State& s) { loadText(s, fullGrid()); }
void BM_LoadFullGridXml(benchmark::State& s) { loadXml(s, fullGrid()); }

BENCHMARK(BM_LoadSpecExampleText)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadCrowdedText)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadCrowdedXml)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadFullGridText)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadFullGridXml)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gizmo::bench
