// Time of impact per feature and per precision: the kernel every prediction of the event loop
// runs. One contact each, set up so that it is found (the cheap rejections do not end the call):
// an edge (a quadratic in the ballistic model, linear in the classic one), a circle bumper (a
// quartic), two balls (a quartic of the relative path), and a swinging flipper (a smooth,
// non-polynomial gap searched by subdivision). The JSON output (--benchmark_format=json) is
// what the study can chart next to its runs.
#include <benchmark/benchmark.h>

#include "gizmo/core/geometry/flipper_time_of_impact.hpp"
#include "gizmo/core/geometry/time_of_impact.hpp"
#include "gizmo/core/math/scalar.hpp"

namespace gizmo::bench {
namespace {

template <class Real>
Real r(double v) {
  return fromDouble<Real>(v);
}

// A ball above the board's middle, falling and drifting right: gravity for the ballistic model.
template <class Real>
Trajectory<Real> fallingBall(bool ballistic) {
  return Trajectory<Real>{Vec2<Real>(r<Real>(9.7), r<Real>(7.3)), Vec2<Real>(r<Real>(1.25), r<Real>(3.5)),
                          Vec2<Real>(Real(0), ballistic ? r<Real>(25) : Real(0))};
}

template <class Real>
void BM_EdgeTimeOfImpact(benchmark::State& state) {
  const bool ballistic = state.range(0) != 0;
  const Trajectory<Real> ball = fallingBall<Real>(ballistic);
  // The top edge of a square at (10, 10): normal up (−y), from (10, 10) to (11, 10).
  const SegmentFeature<Real> top{Vec2<Real>(r<Real>(10), r<Real>(10)), Vec2<Real>(r<Real>(11), r<Real>(10)),
                                 Vec2<Real>(Real(0), r<Real>(-1)), Vec2<Real>(r<Real>(1), Real(0)), r<Real>(1)};
  const Real radius = r<Real>(0.25), limit = r<Real>(1);
  for (auto _ : state) {
    std::optional<Real> tau = segmentTimeOfImpact(ball, radius, top, limit);
    if (!tau) state.SkipWithError("the edge contact was not found");
    benchmark::DoNotOptimize(tau);
  }
}

template <class Real>
void BM_CircleTimeOfImpact(benchmark::State& state) {
  const bool ballistic = state.range(0) != 0;
  const Trajectory<Real> ball = fallingBall<Real>(ballistic);
  const CircleFeature<Real> bumper{Vec2<Real>(r<Real>(10.5), r<Real>(10.5)), r<Real>(0.5)};
  const Real radius = r<Real>(0.25), limit = r<Real>(1);
  for (auto _ : state) {
    std::optional<Real> tau = circleTimeOfImpact(ball, radius, bumper, limit);
    if (!tau) state.SkipWithError("the circle contact was not found");
    benchmark::DoNotOptimize(tau);
  }
}

template <class Real>
void BM_BallTimeOfImpact(benchmark::State& state) {
  const bool ballistic = state.range(0) != 0;
  const Trajectory<Real> a = fallingBall<Real>(ballistic);
  // A second ball under the same gravity, coming up from below and to the right.
  const Trajectory<Real> b{Vec2<Real>(r<Real>(11.5), r<Real>(10.5)), Vec2<Real>(r<Real>(-1), r<Real>(-2)), a.a};
  const Real radius = r<Real>(0.25), limit = r<Real>(1);
  for (auto _ : state) {
    std::optional<Real> tau = ballTimeOfImpact(a, b, radius, limit);
    if (!tau) state.SkipWithError("the ball contact was not found");
    benchmark::DoNotOptimize(tau);
  }
}

template <class Real>
void BM_SwingingFlipperTimeOfImpact(benchmark::State& state) {
  const bool ballistic = state.range(0) != 0;
  // A left flipper at (9, 12) swinging from pointing down to pointing east (ω = −6π) over a
  // ball at rest under its tip's sweep.
  SwingingAxis<Real> axis;
  axis.pivot = Vec2<Real>(r<Real>(9.25), r<Real>(12.25));
  axis.baseQuarter = 1;
  axis.omega = Real(-6) * piOf<Real>();
  axis.length = r<Real>(1.5);
  axis.radius = r<Real>(0.25);
  const Trajectory<Real> ball{Vec2<Real>(r<Real>(10.3), r<Real>(12.5)), Vec2<Real>(),
                              Vec2<Real>(Real(0), ballistic ? r<Real>(25) : Real(0))};
  const Real radius = r<Real>(0.25), limit = Real(1) / Real(12);
  for (auto _ : state) {
    auto contact = swingingCapsuleTimeOfImpact(ball, radius, axis, limit);
    if (!contact) state.SkipWithError("the flipper contact was not found");
    benchmark::DoNotOptimize(contact);
  }
}

// MPFR at 256 bits: the study's reference precision, set for the thread before the run.
template <void (*Kernel)(benchmark::State&)>
void AtMpfr256(benchmark::State& state) {
  setMpfrBits(256);
  Kernel(state);
}

#define GIZMO_KERNEL_PRECISIONS(kernel)                                          \
  BENCHMARK_TEMPLATE(kernel, float)->ArgName("ballistic")->Arg(0)->Arg(1);       \
  BENCHMARK_TEMPLATE(kernel, double)->ArgName("ballistic")->Arg(0)->Arg(1);      \
  BENCHMARK_TEMPLATE(kernel, long double)->ArgName("ballistic")->Arg(0)->Arg(1); \
  BENCHMARK_TEMPLATE(kernel, Float128)->ArgName("ballistic")->Arg(0)->Arg(1);    \
  BENCHMARK(AtMpfr256<kernel<MpfrReal>>)->Name(#kernel "<mpfr:256>")->ArgName("ballistic")->Arg(0)->Arg(1);

GIZMO_KERNEL_PRECISIONS(BM_EdgeTimeOfImpact)
GIZMO_KERNEL_PRECISIONS(BM_CircleTimeOfImpact)
GIZMO_KERNEL_PRECISIONS(BM_BallTimeOfImpact)
GIZMO_KERNEL_PRECISIONS(BM_SwingingFlipperTimeOfImpact)

}  // namespace
}  // namespace gizmo::bench
