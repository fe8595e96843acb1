// Loading boards: the specification's example, and crowded boards of 100 balls and ~400 gizmos,
// from text and from XML.
#include <benchmark/benchmark.h>

#include "bench_boards.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"

namespace gizmo::bench {
namespace {

// 400 one-cell gizmos filling rows 0–19 except the ball lanes, and 100 balls in those lanes.
BoardSpec fourHundredGizmos() {
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
void BM_LoadCrowdedText(benchmark::State& s) { loadText(s, fourHundredGizmos()); }
void BM_LoadCrowdedXml(benchmark::State& s) { loadXml(s, fourHundredGizmos()); }

BENCHMARK(BM_LoadSpecExampleText)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadCrowdedText)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadCrowdedXml)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gizmo::bench
