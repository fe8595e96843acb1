// Whole games: the event loop over long runs, where the events are not those of the first
// seconds (on the spec example the ball settles between two circle bumpers and most events are
// near-contact collisions). Each benchmark runs one game per iteration, once by default, so that
// `scripts/dev bench` stays short; the counters are those of bench_event_loop.cpp, so the study's
// event-loop chart shows these games beside the 10 s runs.
#include <benchmark/benchmark.h>

#include "bench_boards.hpp"
#include "bench_run.hpp"

namespace gizmo::bench {
namespace {

void runGame(benchmark::State& state, const std::optional<BoardSpec>& board, double boardSeconds) {
  runBoard(state, board, MotionModel::Ballistic, nullptr, boardSeconds);
}

void BM_SpecExample600sBallistic(benchmark::State& s) { runGame(s, specExample(), 600); }
void BM_SpecExample3600sBallistic(benchmark::State& s) { runGame(s, specExample(), 3600); }
void BM_Crowded60sBallistic(benchmark::State& s) { runGame(s, crowdedBoard(), 60); }
void BM_RealManyBalls60sBallistic(benchmark::State& s) { runGame(s, realBoard(kRealManyBalls), 60); }
// The pile of 55 balls at rest from about 55 s on (docs/physics.md, "Piles"): an hour of board time.
void BM_RealManyBalls3600sBallistic(benchmark::State& s) { runGame(s, realBoard(kRealManyBalls), 3600); }
void BM_RealFlipperCollision60sBallistic(benchmark::State& s) { runGame(s, realBoard(kRealFlipperCollision), 60); }
void BM_RealMultiball60sBallistic(benchmark::State& s) { runGame(s, realBoard(kRealMultiball), 60); }

BENCHMARK(BM_SpecExample600sBallistic)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_SpecExample3600sBallistic)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Crowded60sBallistic)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RealManyBalls60sBallistic)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RealManyBalls3600sBallistic)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RealFlipperCollision60sBallistic)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RealMultiball60sBallistic)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace gizmo::bench
