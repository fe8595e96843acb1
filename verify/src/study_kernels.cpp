// The kernel charts' points, from the benchmark names bench/ uses. Ratios are taken between
// figures of the same file set, so that they compare runs made on the same machine at the same
// time: their absolute times mean little on a shared machine, their ratios much more.
#include "gizmo/verify/study_kernels.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <regex>
#include <set>

namespace gizmo::verify {
namespace {

// The precisions in ladder order; a template argument the ladder does not know goes after them.
const std::vector<std::string> kPrecisionOrder{"float", "double", "long-double", "float128",
                                               "bin50", "bin100", "mpfr:256"};

std::string precisionOfTemplateArgument(const std::string& argument) {
  if (argument == "long double") return "long-double";
  if (argument == "Float128") return "float128";
  return argument;
}

// "SwingingFlipper" -> "swinging flipper".
std::string words(const std::string& camel) {
  std::string out;
  for (char c : camel) {
    if (std::isupper(static_cast<unsigned char>(c)) && !out.empty()) out += ' ';
    out += char(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::size_t rankOf(const std::vector<std::string>& order, const std::string& item) {
  const auto it = std::find(order.begin(), order.end(), item);
  return it == order.end() ? order.size() : std::size_t(it - order.begin());
}

const char* modelName(const std::string& ballisticArgument) {
  return ballisticArgument == "1" ? "ballistic" : "classic";
}

class Builder {
 public:
  explicit Builder(const BenchResults& bench) : bench_(bench) {}

  KernelFigures build() {
    timeOfImpact();
    eventLoop();
    recording();
    certification();
    for (const BenchFigure& f : bench_.figures)
      if (!used_.count(f.name)) figures_.notCharted.push_back(f.name);
    return figures_;
  }

 private:
  // A counter's mean; 0 when the figure has none.
  static double counter(const BenchFigure& f, const std::string& name) {
    const auto it = f.counters.find(name);
    return it == f.counters.end() ? 0 : it->second.mean;
  }

  static KernelPoint point(KernelChart chart, const std::string& category, const std::string& series, BenchValue value,
                           const std::string& unit, std::vector<std::string> benchmarks, int repetitions) {
    KernelPoint p;
    p.chart = chart;
    p.category = category;
    p.series = series;
    p.value = value;
    p.unit = unit;
    p.benchmarks = std::move(benchmarks);
    p.repetitions = repetitions;
    return p;
  }

  const BenchFigure* use(const std::string& name) {
    const BenchFigure* f = bench_.find(name);
    if (f) used_.insert(name);
    return f;
  }

  // Ratios to the series `to` of each category, for the points of one chart from `first` on.
  void ratiosTo(std::size_t first, const std::string& to) {
    for (std::size_t i = first; i < figures_.points.size(); ++i) {
      KernelPoint& p = figures_.points[i];
      for (std::size_t j = first; j < figures_.points.size(); ++j) {
        const KernelPoint& base = figures_.points[j];
        if (base.category != p.category || base.series != to) continue;
        p.ratio = ratioOf(p.value, base.value);
        p.ratioTo = to;
      }
    }
  }

  void timeOfImpact() {
    static const std::regex name(R"(^BM_([A-Za-z]+)TimeOfImpact<([^>]+)>/ballistic:([01])$)");
    struct Found {
      std::size_t feature, model, precision;
      KernelPoint point;
    };
    std::vector<std::string> features;
    std::vector<Found> found;
    for (const BenchFigure& f : bench_.figures) {
      std::smatch m;
      if (!std::regex_match(f.name, m, name)) continue;
      const std::string feature = words(m[1]), precision = precisionOfTemplateArgument(m[2]);
      if (rankOf(features, feature) == features.size()) features.push_back(feature);
      use(f.name);
      found.push_back(Found{rankOf(features, feature), m[3] == "1" ? 1u : 0u, rankOf(kPrecisionOrder, precision),
                            point(KernelChart::TimeOfImpact, feature + ", " + modelName(m[3]), precision, f.realNs,
                                  "ns per call", {f.name}, f.repetitions)});
    }
    std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
      return std::tie(a.feature, a.model, a.precision) < std::tie(b.feature, b.model, b.precision);
    });
    const std::size_t first = figures_.points.size();
    for (const Found& x : found) figures_.points.push_back(x.point);
    ratiosTo(first, "double");
  }

  void eventLoop() {
    const std::size_t first = figures_.points.size();
    // The 10 s runs, then the whole games of bench/bench_games.cpp.
    for (const auto& [board, label] :
         {std::pair{"SpecExample", "spec example"}, std::pair{"Crowded", "crowded"},
          std::pair{"SpecExample600s", "spec example, 600 s"}, std::pair{"SpecExample3600s", "spec example, 3600 s"},
          std::pair{"Crowded60s", "crowded, 60 s"}, std::pair{"RealManyBalls60s", "many-balls, 60 s"},
          std::pair{"RealFlipperCollision60s", "flipper-coll, 60 s"}, std::pair{"RealMultiball60s", "multiball, 60 s"}})
      for (const auto& [variant, series] :
           {std::pair{"Ballistic", "ballistic"}, std::pair{"BallisticObserved", "ballistic, observed"},
            std::pair{"Classic", "classic"}}) {
        const BenchFigure* f = bench_.find(std::string("BM_") + board + variant);
        if (!f) continue;
        const double events = counter(*f, "events/run"), eventRate = counter(*f, "events/s");
        const double boardRate = counter(*f, "board_s/s");
        if (!(events > 0 && eventRate > 0 && boardRate > 0)) continue;
        use(f->name);
        // Both rates are divided by the same time at each repetition, so their ratio is exactly
        // the run's events per board second, whatever the spread: it gives the board seconds of
        // one run without the benchmark's own constant. Events and board seconds are the same at
        // every repetition; only the time spreads.
        const double boardSeconds = events * boardRate / eventRate;
        KernelPoint p = point(KernelChart::EventLoop, label, series,
                              {f->realNs.mean / boardSeconds / 1e6, f->realNs.stddev / boardSeconds / 1e6},
                              "wall ms per board s", {f->name}, f->repetitions);
        const double perEvent = f->realNs.mean / events;
        const ReadableUnit unit = readableUnit(perEvent);
        char text[96];
        std::snprintf(text, sizeof text, "%.3g %s per event, %.0f events in %.3g board s", perEvent / unit.ns,
                      unit.name, events, boardSeconds);
        p.detail = text;
        figures_.points.push_back(p);
      }
    ratiosTo(first, "ballistic");
  }

  // The point of a ratio between two figures, when both are there.
  void ratioPoint(KernelChart chart, const std::string& category, const std::string& series, const std::string& unit,
                  const std::string& numerator, const std::string& denominator) {
    const BenchFigure* a = bench_.find(numerator);
    const BenchFigure* b = bench_.find(denominator);
    if (!a || !b) return;
    const std::optional<BenchValue> r = ratioOf(a->realNs, b->realNs);
    if (!r) return;
    use(numerator);
    use(denominator);
    figures_.points.push_back(
        point(chart, category, series, *r, unit, {numerator, denominator}, std::min(a->repetitions, b->repetitions)));
  }

  void recording() {
    for (const auto& [board, label] : {std::pair{"Spec", "spec example"}, std::pair{"Crowded", "crowded"}})
      for (const auto& [variant, series] :
           {std::pair{"RecordedInMemory", "recorded in memory"}, std::pair{"RecordedToFile", "recorded to file"},
            std::pair{"Replayed", "replayed"}})
        ratioPoint(KernelChart::Recording, label, series, "x unrecorded", std::string("BM_") + board + variant,
                   std::string("BM_") + board + "Unrecorded");
  }

  void certification() {
    for (const char* model : {"0", "1"}) {
      const std::string arg = std::string("/ballistic:") + model;
      // Measured in one loop, alternating, by the benchmark itself: the steadiest of the two.
      if (const BenchFigure* f = bench_.find("BM_CertifyRatio" + arg)) {
        const auto ratio = f->counters.find("ratio");
        if (ratio != f->counters.end()) {
          use(f->name);
          figures_.points.push_back(point(KernelChart::Certification, modelName(model), "alternating in one loop",
                                          ratio->second, "x run", {f->name}, f->repetitions));
        }
      }
      ratioPoint(KernelChart::Certification, modelName(model), "separate benchmarks", "x run",
                 "BM_SpecExampleCertify60s" + arg, "BM_SpecExampleRun60s" + arg);
    }
  }

  const BenchResults& bench_;
  KernelFigures figures_;
  std::set<std::string> used_;
};

}  // namespace

const char* kernelChartName(KernelChart chart) {
  switch (chart) {
    case KernelChart::TimeOfImpact: return "time-of-impact";
    case KernelChart::EventLoop: return "event-loop";
    case KernelChart::Recording: return "recording";
    case KernelChart::Certification: return "certification";
  }
  return "?";
}

const KernelChartText& kernelChartText(KernelChart chart) {
  static const KernelChartText texts[] = {
      {"Time of impact", "ns per call (log scale)",
       "One time-of-impact call per feature kind and motion model, at each precision (bench/bench_kernels.cpp): "
       "ns per call, and its time over double's.",
       true, 0, ""},
      {"The event loop", "wall ms per board second (log scale)",
       "Whole runs per board and motion model, and the ballistic run with an observer that does nothing "
       "(bench/bench_event_loop.cpp): wall time per board second (the cost axis of the scenes' charts, in ms), its "
       "ratio to the unobserved ballistic run's, and below it the time per executed event.",
       true, 0, ""},
      {"Recording and replaying", "time over the unrecorded run's",
       "A ballistic run recorded to a sink that keeps nothing, recorded to a file, and replayed from its log "
       "(simulated again, every chunk compared), each over the same run unrecorded (bench/bench_replay.cpp).",
       false, 1, "the unrecorded run"},
      {"Certification", "certification time over the run's",
       "Certifying every decision of the spec example over running it, per motion model (bench/bench_certify.cpp): "
       "measured alternating in one loop (the benchmark's own ratio counter), and as two separate benchmarks.",
       false, 5, "at most 5x: the requirement"},
  };
  return texts[int(chart)];
}

std::vector<KernelPoint> KernelFigures::of(KernelChart chart) const {
  std::vector<KernelPoint> out;
  for (const KernelPoint& p : points)
    if (p.chart == chart) out.push_back(p);
  return out;
}

ReadableUnit readableUnit(double ns) {
  ReadableUnit unit{"ns", 1};
  for (const ReadableUnit& larger : {ReadableUnit{"µs", 1e3}, ReadableUnit{"ms", 1e6}, ReadableUnit{"s", 1e9}})
    if (ns >= larger.ns) unit = larger;
  return unit;
}

std::optional<BenchValue> ratioOf(const BenchValue& a, const BenchValue& b) {
  if (b.mean == 0) return std::nullopt;
  const double r = a.mean / b.mean;
  const double ra = a.mean != 0 ? a.stddev / a.mean : 0, rb = b.stddev / b.mean;
  return BenchValue{r, std::fabs(r) * std::sqrt(ra * ra + rb * rb)};
}

KernelFigures kernelFigures(const BenchResults& bench) { return Builder(bench).build(); }

}  // namespace gizmo::verify
