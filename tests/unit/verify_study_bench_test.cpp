// The study's Kernels part (docs/verification.md, "Kernels"): Google Benchmark's JSON read as
// gizmo_bench writes it, the charts' points and ratios made from it, and bad files refused with
// what is wrong. The files are written here, with figures chosen so that every expected value
// can be worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "gizmo/verify/study_bench.hpp"
#include "gizmo/verify/study_kernels.hpp"
#include "gizmo/verify/study_output.hpp"
#include "gizmo/verify/study_suite.hpp"
#include "support/scratch_dir.hpp"

namespace gizmo::verify {
namespace {

// One entry of "benchmarks"; `more` is added inside the object (counters, aggregate fields).
std::string entry(const std::string& name, const std::string& runType, double realTime, const std::string& unit,
                  const std::string& more = "") {
  return "{\"name\": \"" + name + "\", \"run_name\": \"" + name + "\", \"run_type\": \"" + runType +
         "\", \"repetitions\": 1, \"threads\": 1, \"iterations\": 100, \"real_time\": " + std::to_string(realTime) +
         ", \"cpu_time\": " + std::to_string(realTime) + ", \"time_unit\": \"" + unit + "\"" +
         (more.empty() ? "" : ", " + more) + "}";
}

// An aggregate entry as Google Benchmark names it: NAME_KIND, with run_name NAME.
std::string aggregate(const std::string& name, const std::string& kind, double realTime, const std::string& unit,
                      const std::string& more = "") {
  return "{\"name\": \"" + name + "_" + kind + "\", \"run_name\": \"" + name +
         "\", \"run_type\": \"aggregate\", \"repetitions\": 3, \"threads\": 1, \"aggregate_name\": \"" + kind +
         "\", \"iterations\": 3, \"real_time\": " + std::to_string(realTime) +
         ", \"cpu_time\": " + std::to_string(realTime) + ", \"time_unit\": \"" + unit + "\"" +
         (more.empty() ? "" : ", " + more) + "}";
}

std::string benchJson(const std::vector<std::string>& entries) {
  std::string text =
      "{\n\"context\": {\"date\": \"2026-01-05T10:00:00+00:00\", \"host_name\": \"h\", \"num_cpus\": 2},\n"
      "\"benchmarks\": [\n";
  for (std::size_t i = 0; i < entries.size(); ++i) text += (i ? ",\n" : "") + entries[i];
  return text + "\n]\n}\n";
}

const KernelPoint& pointOf(const KernelFigures& k, KernelChart chart, const std::string& category,
                           const std::string& series) {
  for (const KernelPoint& p : k.points)
    if (p.chart == chart && p.category == category && p.series == series) return p;
  throw std::runtime_error("no point " + category + " / " + series);
}

// The message of the StudyInputError that parsing `text` throws, or "accepted".
std::string refusal(const std::string& text) {
  try {
    parseBenchJson(text, "k.json");
  } catch (const StudyInputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(StudyBench, AggregatesAreTakenAsGoogleBenchmarkComputedThem) {
  // --benchmark_report_aggregates_only: no single runs, only the aggregates; the median and the
  // coefficient of variation are not the study's figures.
  const std::string name = "BM_EdgeTimeOfImpact<double>/ballistic:1";
  const BenchResults r = parseBenchJson(benchJson({aggregate(name, "mean", 0.25, "us", "\"calls/s\": 4e6"),
                                                   aggregate(name, "median", 0.2, "us", "\"calls/s\": 5e6"),
                                                   aggregate(name, "stddev", 0.05, "us", "\"calls/s\": 1e6"),
                                                   aggregate(name, "cv", 0.2, "us", "\"calls/s\": 0.25")}),
                                        "k.json");
  ASSERT_EQ(r.figures.size(), 1u);
  const BenchFigure& f = r.figures[0];
  EXPECT_EQ(f.name, name);
  EXPECT_EQ(f.file, "k.json");
  EXPECT_TRUE(f.fromAggregates);
  EXPECT_EQ(f.repetitions, 3);
  EXPECT_DOUBLE_EQ(f.realNs.mean, 250);
  EXPECT_DOUBLE_EQ(f.realNs.stddev, 50);
  ASSERT_TRUE(f.counters.count("calls/s"));
  EXPECT_DOUBLE_EQ(f.counters.at("calls/s").mean, 4e6);
  EXPECT_DOUBLE_EQ(f.counters.at("calls/s").stddev, 1e6);
  // The context is kept for the page.
  ASSERT_EQ(r.sources.size(), 1u);
  EXPECT_EQ(r.sources[0].host, "h");
  EXPECT_EQ(r.sources[0].cpus, 2);
}

TEST(StudyBench, WithoutAggregatesTheRunsGiveMeanAndSampleStddev) {
  const std::string name = "BM_SpecExampleClassic";
  const BenchResults r =
      parseBenchJson(benchJson({entry(name, "iteration", 1, "ms", "\"events/run\": 380"),
                                entry(name, "iteration", 3, "ms", "\"events/run\": 380"),
                                entry("BM_Once", "iteration", 2, "s"), entry("BM_Tiny", "iteration", 7, "ns")}),
                     "k.json");
  ASSERT_EQ(r.figures.size(), 3u);
  const BenchFigure* f = r.find(name);
  ASSERT_NE(f, nullptr);
  EXPECT_FALSE(f->fromAggregates);
  EXPECT_EQ(f->repetitions, 2);
  EXPECT_DOUBLE_EQ(f->realNs.mean, 2e6);
  EXPECT_DOUBLE_EQ(f->realNs.stddev, std::sqrt(2.0) * 1e6);  // sqrt(((1-2)^2 + (3-2)^2) / (2-1)) ms
  EXPECT_DOUBLE_EQ(f->counters.at("events/run").mean, 380);
  EXPECT_EQ(f->counters.at("events/run").stddev, 0);
  // One run: no spread. Every time unit in nanoseconds.
  EXPECT_EQ(r.find("BM_Once")->repetitions, 1);
  EXPECT_DOUBLE_EQ(r.find("BM_Once")->realNs.mean, 2e9);
  EXPECT_EQ(r.find("BM_Once")->realNs.stddev, 0);
  EXPECT_DOUBLE_EQ(r.find("BM_Tiny")->realNs.mean, 7);
  // Not counters: the bookkeeping fields.
  EXPECT_FALSE(f->counters.count("iterations"));
  EXPECT_FALSE(f->counters.count("repetitions"));
}

TEST(StudyBench, ABenchmarkThatReportedAnErrorIsListedNotCharted) {
  const BenchResults r = parseBenchJson(benchJson({entry("BM_Good", "iteration", 5, "ns"),
                                                   "{\"name\": \"BM_Bad\", \"run_type\": \"iteration\", "
                                                   "\"error_occurred\": true, \"error_message\": \"no contact\"}"}),
                                        "k.json");
  ASSERT_EQ(r.figures.size(), 1u);
  EXPECT_EQ(r.figures[0].name, "BM_Good");
  ASSERT_EQ(r.sources[0].failed.size(), 1u);
  EXPECT_EQ(r.sources[0].failed[0], "BM_Bad: no contact");
}

TEST(StudyBench, BadFilesAreRefusedWithTheFileAndWhatIsWrong) {
  EXPECT_NE(refusal("{\n\"benchmarks\": [\n{\"name\": }\n]}").find("k.json: not valid JSON: parse error at line 3"),
            std::string::npos)
      << refusal("{\n\"benchmarks\": [\n{\"name\": }\n]}");
  EXPECT_NE(refusal("").find("k.json: not valid JSON"), std::string::npos);
  EXPECT_NE(refusal("[1, 2]").find("k.json: not Google Benchmark's JSON"), std::string::npos);
  EXPECT_NE(refusal("{\"context\": {}}").find("no \"benchmarks\" array"), std::string::npos);
  EXPECT_NE(refusal("{\"benchmarks\": {}}").find("no \"benchmarks\" array"), std::string::npos);
  EXPECT_NE(refusal(benchJson({})).find("k.json: no benchmark with a figure in it"), std::string::npos);
  EXPECT_NE(refusal(benchJson({"3"})).find("k.json: benchmarks[0]: is not an object"), std::string::npos);
  EXPECT_NE(refusal(benchJson({"{\"run_type\": \"iteration\"}"})).find("benchmarks[0]: has no \"name\""),
            std::string::npos);
  const std::string good = entry("BM_A", "iteration", 5, "ns");
  EXPECT_NE(refusal(benchJson({good, entry("BM_B", "iteration", 5, "minutes")}))
                .find("k.json: benchmarks[1] (BM_B): unknown time_unit 'minutes'"),
            std::string::npos);
  EXPECT_NE(refusal(benchJson({entry("BM_B", "sometimes", 5, "ns")})).find("(BM_B): unknown run_type 'sometimes'"),
            std::string::npos);
  EXPECT_NE(
      refusal(benchJson({"{\"name\": \"BM_C\", \"run_type\": \"iteration\", \"cpu_time\": 1, \"time_unit\": \"ns\"}"}))
          .find("(BM_C): has no \"real_time\""),
      std::string::npos);
  EXPECT_NE(
      refusal(benchJson({"{\"name\": \"BM_C\", \"run_type\": \"iteration\", \"real_time\": \"fast\", \"cpu_time\": 1, "
                         "\"time_unit\": \"ns\"}"}))
          .find("(BM_C): \"real_time\" is not a number"),
      std::string::npos);
  EXPECT_NE(refusal(benchJson({entry("BM_D", "iteration", -5, "ns")})).find("(BM_D): \"real_time\" is not a time"),
            std::string::npos);
  EXPECT_NE(refusal(benchJson({"{\"name\": \"BM_E\", \"run_type\": \"aggregate\", \"real_time\": 1}"}))
                .find("(BM_E): has no \"aggregate_name\""),
            std::string::npos);
  // Google Benchmark writes a NaN counter as a bare NaN, which is not JSON.
  EXPECT_NE(refusal(benchJson({entry("BM_F", "iteration", 5, "ns", "\"ratio\": NaN")})).find("not valid JSON"),
            std::string::npos);
  EXPECT_EQ(refusal(benchJson({good})), "accepted");
}

TEST(StudyBench, FilesAreReadInOrderAndABenchmarkIsInOneFileOnly) {
  const test::ScratchDir dir;
  const std::string a = (dir / "a.json").string(), b = (dir / "b.json").string(), c = (dir / "c.json").string();
  std::ofstream(a) << benchJson({entry("BM_A", "iteration", 1, "ns")});
  std::ofstream(b) << benchJson({entry("BM_B", "iteration", 2, "ns")});
  std::ofstream(c) << benchJson({entry("BM_A", "iteration", 3, "ns")});
  const BenchResults r = readBenchFiles({a, b});
  ASSERT_EQ(r.figures.size(), 2u);
  EXPECT_EQ(r.figures[1].name, "BM_B");
  EXPECT_EQ(r.figures[1].file, b);
  EXPECT_EQ(r.sources.size(), 2u);
  try {
    readBenchFiles({a, c});
    ADD_FAILURE() << "BM_A in two files was accepted";
  } catch (const StudyInputError& e) {
    EXPECT_NE(std::string(e.what()).find(c + ": benchmark BM_A is in " + a + " too"), std::string::npos) << e.what();
  }
  try {
    readBenchFiles({a, (dir / "missing.json").string()});
    ADD_FAILURE() << "a missing file was accepted";
  } catch (const StudyInputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.json: cannot read the file"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(readBenchFiles({}).empty());
}

TEST(StudyKernels, TimeOfImpactIsPerFeatureModelAndPrecisionWithItsRatioToDouble) {
  // Listed out of ladder order on purpose: the chart's series follow the ladder.
  const BenchResults r = parseBenchJson(
      benchJson({aggregate("BM_EdgeTimeOfImpact<mpfr:256>/ballistic:1", "mean", 25, "us"),
                 aggregate("BM_EdgeTimeOfImpact<mpfr:256>/ballistic:1", "stddev", 0.5, "us"),
                 aggregate("BM_EdgeTimeOfImpact<double>/ballistic:1", "mean", 100, "ns"),
                 aggregate("BM_EdgeTimeOfImpact<double>/ballistic:1", "stddev", 2, "ns"),
                 entry("BM_EdgeTimeOfImpact<long double>/ballistic:1", "iteration", 150, "ns"),
                 entry("BM_EdgeTimeOfImpact<float>/ballistic:1", "iteration", 80, "ns"),
                 entry("BM_SwingingFlipperTimeOfImpact<Float128>/ballistic:0", "iteration", 9000, "ns")}),
      "k.json");
  const KernelFigures k = kernelFigures(r);
  const std::vector<KernelPoint> toi = k.of(KernelChart::TimeOfImpact);
  ASSERT_EQ(toi.size(), 5u);
  std::vector<std::string> series;
  for (const KernelPoint& p : toi)
    if (p.category == "edge, ballistic") series.push_back(p.series);
  EXPECT_EQ(series, (std::vector<std::string>{"float", "double", "long-double", "mpfr:256"}));

  const KernelPoint& mpfr = pointOf(k, KernelChart::TimeOfImpact, "edge, ballistic", "mpfr:256");
  EXPECT_EQ(mpfr.unit, "ns per call");
  EXPECT_DOUBLE_EQ(mpfr.value.mean, 25000);
  EXPECT_DOUBLE_EQ(mpfr.value.stddev, 500);
  ASSERT_TRUE(mpfr.ratio.has_value());
  EXPECT_EQ(mpfr.ratioTo, "double");
  EXPECT_DOUBLE_EQ(mpfr.ratio->mean, 250);
  // Both relative spreads are 2 %: the ratio's is 2 % times sqrt 2.
  EXPECT_NEAR(mpfr.ratio->stddev, 250 * 0.02 * std::sqrt(2.0), 1e-9);
  EXPECT_DOUBLE_EQ(pointOf(k, KernelChart::TimeOfImpact, "edge, ballistic", "float").ratio->mean, 0.8);
  EXPECT_DOUBLE_EQ(pointOf(k, KernelChart::TimeOfImpact, "edge, ballistic", "double").ratio->mean, 1);
  // No double run of the flipper in the classic model: no ratio.
  const KernelPoint& flipper = pointOf(k, KernelChart::TimeOfImpact, "swinging flipper, classic", "float128");
  EXPECT_FALSE(flipper.ratio.has_value());
  EXPECT_TRUE(k.notCharted.empty());
}

TEST(StudyKernels, EventLoopRecordingAndCertificationAreReadAsRatios) {
  // 500 events a run at 5e5 events and 1e4 board seconds per second of the benchmark's clock:
  // 10 board seconds a run.
  const std::string specRates = "\"events/run\": 500, \"events/s\": 5e5, \"board_s/s\": 1e4";
  const BenchResults r = parseBenchJson(
      benchJson({entry("BM_SpecExampleBallistic", "iteration", 1, "ms", specRates),
                 entry("BM_SpecExampleBallisticObserved", "iteration", 1.1, "ms", specRates),
                 entry("BM_CrowdedClassic", "iteration", 30, "ms",
                       "\"events/run\": 10000, \"events/s\": 2e5, \"board_s/s\": 200"),
                 entry("BM_CrowdedBallistic", "iteration", 20, "ms", "\"events/run\": 90000"),
                 entry("BM_SpecExample600sBallistic", "iteration", 600, "ms",
                       "\"events/run\": 300000, \"events/s\": 5e5, \"board_s/s\": 1000"),
                 entry("BM_SpecUnrecorded", "iteration", 2, "ms"), entry("BM_SpecRecordedToFile", "iteration", 3, "ms"),
                 entry("BM_SpecReplayed", "iteration", 5, "ms"),
                 entry("BM_CrowdedRecordedToFile", "iteration", 9, "ms"),
                 aggregate("BM_CertifyRatio/ballistic:0", "mean", 10, "ms", "\"ratio\": 2.5"),
                 aggregate("BM_CertifyRatio/ballistic:0", "stddev", 1, "ms", "\"ratio\": 0.1"),
                 entry("BM_SpecExampleRun60s/ballistic:1", "iteration", 4, "ms"),
                 entry("BM_SpecExampleCertify60s/ballistic:1", "iteration", 12, "ms"),
                 entry("BM_LoadCrowdedXml", "iteration", 12, "us")}),
      "k.json");
  const KernelFigures k = kernelFigures(r);

  const KernelPoint& ballistic = pointOf(k, KernelChart::EventLoop, "spec example", "ballistic");
  EXPECT_EQ(ballistic.unit, "wall ms per board s");
  EXPECT_DOUBLE_EQ(ballistic.value.mean, 0.1);  // 1 ms for 10 board seconds
  EXPECT_EQ(ballistic.detail, "2 µs per event, 500 events in 10 board s");
  const KernelPoint& observed = pointOf(k, KernelChart::EventLoop, "spec example", "ballistic, observed");
  ASSERT_TRUE(observed.ratio.has_value());
  EXPECT_EQ(observed.ratioTo, "ballistic");
  EXPECT_NEAR(observed.ratio->mean, 1.1, 1e-12);
  EXPECT_DOUBLE_EQ(pointOf(k, KernelChart::EventLoop, "crowded", "classic").value.mean, 3);  // 30 ms for 10 board s
  // A whole game (bench/bench_games.cpp) beside the 10 s runs: 600 ms for 600 board seconds.
  const KernelPoint& game = pointOf(k, KernelChart::EventLoop, "spec example, 600 s", "ballistic");
  EXPECT_DOUBLE_EQ(game.value.mean, 1);
  EXPECT_EQ(game.detail, "2 µs per event, 300000 events in 600 board s");
  // Without its rates a run's board seconds are unknown: read, not charted.
  EXPECT_EQ(k.of(KernelChart::EventLoop).size(), 4u);

  const KernelPoint& file = pointOf(k, KernelChart::Recording, "spec example", "recorded to file");
  EXPECT_EQ(file.unit, "x unrecorded");
  EXPECT_DOUBLE_EQ(file.value.mean, 1.5);
  EXPECT_EQ(file.benchmarks, (std::vector<std::string>{"BM_SpecRecordedToFile", "BM_SpecUnrecorded"}));
  EXPECT_DOUBLE_EQ(pointOf(k, KernelChart::Recording, "spec example", "replayed").value.mean, 2.5);
  // The crowded board has no unrecorded run here: nothing to take its ratio to.
  EXPECT_EQ(k.of(KernelChart::Recording).size(), 2u);

  const KernelPoint& loop = pointOf(k, KernelChart::Certification, "classic", "alternating in one loop");
  EXPECT_DOUBLE_EQ(loop.value.mean, 2.5);  // the benchmark's own counter, not a time
  EXPECT_DOUBLE_EQ(loop.value.stddev, 0.1);
  EXPECT_DOUBLE_EQ(pointOf(k, KernelChart::Certification, "ballistic", "separate benchmarks").value.mean, 3);

  EXPECT_EQ(k.notCharted,
            (std::vector<std::string>{"BM_CrowdedBallistic", "BM_CrowdedRecordedToFile", "BM_LoadCrowdedXml"}));
}

TEST(StudyKernels, TheTablesCarryThePointsAndThePageHasKernelsOnlyWithFigures) {
  const BenchResults r =
      parseBenchJson(benchJson({entry("BM_BallTimeOfImpact<double>/ballistic:0", "iteration", 200, "ns"),
                                entry("BM_BallTimeOfImpact<float>/ballistic:0", "iteration", 150, "ns"),
                                entry("BM_BallTimeOfImpact<mpfr:256>/ballistic:0", "iteration", 25, "us")}),
                     "k.json");
  const KernelFigures k = kernelFigures(r);
  const std::string csv = kernelsCsv(k);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "chart,category,series,value,stddev,unit,ratio,ratio_stddev,ratio_to,repetitions,benchmarks,detail");
  EXPECT_NE(csv.find("\ntime-of-impact,\"ball, classic\",float,150,0,ns per call,0.75,0,double,1,"
                     "BM_BallTimeOfImpact<float>/ballistic:0,\n"),
            std::string::npos)
      << csv;
  const std::string json = kernelsJson(r, k);
  EXPECT_NE(json.find("\"time-of-impact\": ["), std::string::npos);
  EXPECT_NE(json.find("\"name\": \"BM_BallTimeOfImpact<double>/ballistic:0\""), std::string::npos);

  StudyReport report;
  EXPECT_EQ(studyPage(report).find("Kernels"), std::string::npos);
  report.bench = r;
  const std::string page = studyPage(report);
  EXPECT_NE(page.find("<h2 id=\"kernels\">Kernels</h2>"), std::string::npos);
  EXPECT_NE(page.find("charts/kernels-time-of-impact.svg"), std::string::npos);
  EXPECT_NE(page.find("150 ns (×0.75)"), std::string::npos);
  EXPECT_NE(page.find("25 µs (×125)"), std::string::npos);                  // times in a readable unit
  EXPECT_EQ(page.find("charts/kernels-recording.svg"), std::string::npos);  // no recording figures
}

}  // namespace
}  // namespace gizmo::verify
