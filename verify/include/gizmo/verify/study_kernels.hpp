#pragma once
// What the study makes of gizmo_bench's figures (study_bench.hpp): the points of its four kernel
// charts — time of impact per feature kind, model and precision; the event loop per board and
// model; recording and replaying over the unrecorded run; certifying over the run — each with its
// spread over the repetitions and the ratio it is read by. Benchmarks are known by the names
// bench/ gives them; the others are listed as read but not charted.
#include <optional>
#include <string>
#include <vector>

#include "gizmo/verify/study_bench.hpp"

namespace gizmo::verify {

enum class KernelChart { TimeOfImpact, EventLoop, Recording, Certification };
inline constexpr KernelChart kKernelCharts[] = {KernelChart::TimeOfImpact, KernelChart::EventLoop,
                                                KernelChart::Recording, KernelChart::Certification};
const char* kernelChartName(KernelChart chart);  // "time-of-impact", "event-loop", ...

// How a chart is titled and read, for the chart itself and the page.
struct KernelChartText {
  const char* title;
  const char* axis;  // the y axis
  const char* what;  // what was measured and how to read it, in a sentence or two
  bool logScale;     // times that span orders of magnitude
  double line;       // a dashed line at this value (0: none), named by lineLabel
  const char* lineLabel;
};
const KernelChartText& kernelChartText(KernelChart chart);

struct KernelPoint {
  KernelChart chart = KernelChart::TimeOfImpact;
  std::string category;  // along the chart: "edge, ballistic", "spec example", "classic"
  std::string series;    // one colour: "double", "ballistic, observed", "recorded to file"
  BenchValue value;      // in `unit`
  std::string unit;      // "ns per call", "wall ms per board s", "x unrecorded", "x run"
  // Against the series `ratioTo` of the same category (time of impact: double; event loop: the
  // unobserved ballistic run), when that exists. Recording and certification points are ratios
  // already and have none.
  std::optional<BenchValue> ratio;
  std::string ratioTo;
  std::vector<std::string> benchmarks;  // the figures it comes from; a ratio's numerator first
  int repetitions = 1;                  // the fewest of theirs
  std::string detail;                   // a second figure for the tables, e.g. the cost per event
};

struct KernelFigures {
  std::vector<KernelPoint> points;      // chart by chart; categories and series in a fixed order
  std::vector<std::string> notCharted;  // figures read that no chart uses
  std::vector<KernelPoint> of(KernelChart chart) const;
};

KernelFigures kernelFigures(const BenchResults& bench);

// The unit that keeps a time of `ns` nanoseconds readable (ns, µs, ms or s), and its size in ns.
struct ReadableUnit {
  const char* name;
  double ns;
};
ReadableUnit readableUnit(double ns);

// a / b, with both spreads carried into the ratio (first order, independent errors); nothing
// when b is 0.
std::optional<BenchValue> ratioOf(const BenchValue& a, const BenchValue& b);

}  // namespace gizmo::verify
