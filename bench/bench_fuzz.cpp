// `gizmo fuzz BOARD` on the spec example (docs/fuzzing.md, "Fuzzing your own board"): variations
// of it over 10 s of board time, checked against all six properties on two threads, as
// `gizmo fuzz spec-example.txt --time 10 --jobs 2` checks them. The counter is variations per
// second of wall time (the goal: at least 200 on this two-core machine).
#include <benchmark/benchmark.h>

#include "bench_boards.hpp"
#include "gizmo/verify/fuzz/campaign.hpp"
#include "gizmo/verify/fuzz/properties.hpp"

namespace gizmo::bench {
namespace {

void BM_FuzzSpecExampleVariations(benchmark::State& state) {
  RunRequest base;
  base.board = specExample();
  base.duration = 10;
  const verify::fuzz::VariationSource source(base, verify::fuzz::VariationOptions{});
  verify::fuzz::CampaignOptions c;
  for (const verify::fuzz::Property& p : verify::fuzz::allProperties()) c.properties.push_back(&p);
  c.source = &source;
  c.count = std::uint64_t(state.range(0));
  c.jobs = unsigned(state.range(1));
  std::uint64_t seed = 1, failures = 0;
  for (auto _ : state) {
    c.seed = seed++;  // other variations each round: the rate is over many, not the same few again
    failures += verify::fuzz::failureCount(verify::fuzz::runCampaign(c));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * state.range(0));
  state.counters["failures"] = double(failures);
}
BENCHMARK(BM_FuzzSpecExampleVariations)->Args({200, 2})->Args({200, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gizmo::bench
