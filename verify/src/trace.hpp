#pragma once
// A run's executed events as the ladder compares them, and the run of one scalar that records
// or compares them. Declared here, compiled once per scalar (trace_run_*.cpp), so that no
// translation unit instantiates the core for more than one scalar.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gizmo/core/math/precision.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/wide_value.hpp"

namespace gizmo::verify {

// One executed event that changes the board (a recalculation does not): its decision (kind, participants, feature) and its numbers, held wide.
struct TracePoint {
  EventKind kind = EventKind::EndOfTick;
  GizmoId a = kNoGizmo, b = kNoGizmo;
  std::int32_t feature = -1;
  WideValue time;
  std::uint8_t ballCount = 0;  // the balls the event changed
  std::array<GizmoId, 2> ball{kNoGizmo, kNoGizmo};
  std::array<WideValue, 2> x, y;  // their positions
  WideValue energy;               // the board's mechanical energy after the event
};
using Trace = std::vector<TracePoint>;

// How a run's decisions compare with a reference trace.
struct Agreement {
  std::uint64_t events = 0;  // leading events that agree
  double time = 0;           // where the first difference is (the end of the run if none)
  bool throughout = false;
  double maxTimeError = 0;
  double maxPositionError = 0;
  double energyDrift = 0;
  std::string difference;  // the two decisions at the first difference, in words
};

// The balls' positions and the board's energy at one fixed instant of board time, held wide.
struct TraceSample {
  double time = 0;
  std::vector<WideValue> x, y;  // every ball, in the board's order (captured balls at their hold)
  WideValue energy;
};

// What a traced run does besides recording or comparing its events.
struct TraceExtras {
  // Increasing instants at which to sample the balls. Each must be a tick boundary of the run
  // (a multiple of its maximum tick length): only there is the state between two events at
  // hand, so that the classic model's straight steps are sampled where they really are.
  std::vector<double> sampleAt;
  std::vector<TraceSample>* samples = nullptr;
  // The ladder stops a run at its first difference from the reference (nothing after it is
  // comparable); the study runs on to sample positions to the end.
  bool stopAtDifference = true;
};

struct TracedRun {
  std::uint64_t events = 0;
  std::uint64_t compared = 0;  // the events that change the board (all but recalculations)
  double endTime = 0;
  std::string stopped;  // why the run ended before its duration
  Agreement agreement;  // when compared with a reference
};

// Runs request at Real (for MPFR: at the thread's current precision). Appends every executed
// event to *record when record is given; compares with *reference when it is given, and then
// stops at the first difference.
// An exact run stops (`stopped` says so) once the board time's numerator and denominator
// together have more than exactDigits decimal digits: every event makes them longer, and the
// cost of each operation grows with them.
template <class Real>
TracedRun traceRun(const RunRequest& request, const Trace* reference, Trace* record, std::size_t exactDigits,
                   const TraceExtras& extras = {});

// Wall seconds of the same run without any observer, over at most maxEvents events: the cost of
// the scalar itself.
template <class Real>
double timeRun(const RunRequest& request, std::uint64_t maxEvents, std::uint64_t& events);

// traceRun and timeRun at a precision chosen at run time (ladder.cpp).
TracedRun traceAt(const PrecisionChoice& precision, const RunRequest& request, const Trace* reference, Trace* record,
                  std::size_t exactDigits, const TraceExtras& extras = {});
double timeAt(const PrecisionChoice& precision, const RunRequest& request, std::uint64_t maxEvents,
              std::uint64_t& events);

}  // namespace gizmo::verify
