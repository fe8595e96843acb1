#pragma once
// One benchmark iteration = one run of a board: events per second, board seconds per wall
// second and events per run, the counters the study's event-loop chart reads.
#include <benchmark/benchmark.h>

#include <optional>

#include "gizmo/core/run/run.hpp"

namespace gizmo::bench {

inline void runBoard(benchmark::State& state, const std::optional<BoardSpec>& board, MotionModel model,
                     BoardObserver<double>* observer, double boardSeconds) {
  if (!board) {
    state.SkipWithError("board not found beside the repository (../shared/boards/real)");
    return;
  }
  RunRequest request;
  request.board = *board;
  request.model = model;
  request.duration = boardSeconds;
  std::uint64_t events = 0;
  for (auto _ : state) {
    const RunSummary s = simulate<double>(request, observer);
    events += s.total;
    benchmark::DoNotOptimize(s.energy);
  }
  state.counters["events/s"] = benchmark::Counter(double(events), benchmark::Counter::kIsRate);
  state.counters["board_s/s"] =
      benchmark::Counter(boardSeconds * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["events/run"] = double(events) / double(state.iterations());
}

}  // namespace gizmo::bench
