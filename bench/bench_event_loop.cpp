// The event loop per board and model: events per second, board seconds per wall second, and
// the cost of an attached observer that does nothing.
#include <benchmark/benchmark.h>

#include "bench_boards.hpp"
#include "bench_run.hpp"

namespace gizmo::bench {
namespace {

constexpr double kBoardSeconds = 10.0;

void runBoard(benchmark::State& state, const BoardSpec& board, MotionModel model, BoardObserver<double>* observer) {
  bench::runBoard(state, board, model, observer, kBoardSeconds);
}

struct SilentObserver final : BoardObserver<double> {};

void BM_SpecExampleBallistic(benchmark::State& s) { runBoard(s, specExample(), MotionModel::Ballistic, nullptr); }
void BM_SpecExampleClassic(benchmark::State& s) { runBoard(s, specExample(), MotionModel::Classic, nullptr); }
void BM_SpecExampleBallisticObserved(benchmark::State& s) {
  SilentObserver o;
  runBoard(s, specExample(), MotionModel::Ballistic, &o);
}
void BM_CrowdedBallistic(benchmark::State& s) { runBoard(s, crowdedBoard(), MotionModel::Ballistic, nullptr); }
void BM_CrowdedClassic(benchmark::State& s) { runBoard(s, crowdedBoard(), MotionModel::Classic, nullptr); }

BENCHMARK(BM_SpecExampleBallistic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpecExampleBallisticObserved)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpecExampleClassic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CrowdedBallistic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CrowdedClassic)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gizmo::bench
