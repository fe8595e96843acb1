// Certified decisions against the run they certify: the spec example, 60 s of board time, in
// each motion model. The requirement is that certifying costs at most 5× the run when nothing
// needs escalation; BM_CertifyRatio measures both in the same process, alternating, and reports
// certify time / run time as the counter "ratio" (certifying includes re-simulating the run).
#include <benchmark/benchmark.h>

#include <chrono>

#include "bench_boards.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/certify.hpp"

namespace gizmo::bench {
namespace {

constexpr double kBoardSeconds = 60.0;

RunRequest specExampleRun(MotionModel model) {
  RunRequest request;
  request.board = specExample();
  request.model = model;
  request.duration = kBoardSeconds;
  return request;
}

MotionModel modelOf(const benchmark::State& state) {
  return state.range(0) == 0 ? MotionModel::Classic : MotionModel::Ballistic;
}

void BM_SpecExampleRun60s(benchmark::State& state) {
  const RunRequest request = specExampleRun(modelOf(state));
  for (auto _ : state) benchmark::DoNotOptimize(simulate<double>(request).total);
}

void BM_SpecExampleCertify60s(benchmark::State& state) {
  const RunRequest request = specExampleRun(modelOf(state));
  std::uint64_t decisions = 0, certified = 0;
  for (auto _ : state) {
    const verify::CertifyReport r = verify::certifyRun(request);
    decisions = r.decisions;
    certified = r.certified();
  }
  state.counters["decisions"] = double(decisions);
  state.counters["certified"] = double(certified);
}

// Both in one loop, alternating, so that the ratio compares like with like.
void BM_CertifyRatio(benchmark::State& state) {
  const RunRequest request = specExampleRun(modelOf(state));
  using Clock = std::chrono::steady_clock;
  double runSeconds = 0, certifySeconds = 0;
  for (auto _ : state) {
    const Clock::time_point a = Clock::now();
    benchmark::DoNotOptimize(simulate<double>(request).total);
    const Clock::time_point b = Clock::now();
    benchmark::DoNotOptimize(verify::certifyRun(request).decisions);
    const Clock::time_point c = Clock::now();
    runSeconds += std::chrono::duration<double>(b - a).count();
    certifySeconds += std::chrono::duration<double>(c - b).count();
  }
  state.counters["ratio"] = certifySeconds / runSeconds;
}

BENCHMARK(BM_SpecExampleRun60s)->ArgName("ballistic")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpecExampleCertify60s)->ArgName("ballistic")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CertifyRatio)->ArgName("ballistic")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gizmo::bench
