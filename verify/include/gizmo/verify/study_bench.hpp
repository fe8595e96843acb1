#pragma once
// Google Benchmark's JSON output (`gizmo_bench --benchmark_format=json --benchmark_out=FILE`), as
// the study reads it for its Kernels section: each benchmark's time per iteration over its
// repetitions, its user counters, and what the files say about the machine.
#include <map>
#include <string>
#include <vector>

namespace gizmo::verify {

// A figure over a benchmark's repetitions: the mean, and the standard deviation when there were
// several (0 for one run).
struct BenchValue {
  double mean = 0;
  double stddev = 0;
};

struct BenchFigure {
  std::string name;  // Google Benchmark's run_name, e.g. "BM_EdgeTimeOfImpact<double>/ballistic:1"
  std::string file;  // the file it was read from
  int repetitions = 1;
  // Google Benchmark's own mean and stddev aggregates; otherwise computed here from the runs.
  bool fromAggregates = false;
  BenchValue realNs, cpuNs;  // per iteration
  std::map<std::string, BenchValue> counters;
};

// What one file says about the run: shown with the figures, since they mean little without it.
struct BenchSource {
  std::string file;
  std::string date, host;
  int cpus = 0;
  double mhz = 0;
  bool cpuScaling = false;
  std::vector<std::string> failed;  // "NAME: message" for each benchmark that reported an error
};

struct BenchResults {
  std::vector<BenchSource> sources;
  std::vector<BenchFigure> figures;  // file by file, each in its own order
  bool empty() const { return figures.empty(); }
  const BenchFigure* find(const std::string& name) const;
};

// Reads one file's text; `file` names it in messages. Throws StudyInputError (study_suite.hpp)
// naming the file and what is wrong: not JSON, no "benchmarks" array, an entry without a usable
// name, run type, time or time unit, or no benchmark at all.
BenchResults parseBenchJson(const std::string& text, const std::string& file);

// Every file, in order, into one set of figures; a benchmark found in two files is refused, since
// the study could not say which one to chart. Throws StudyInputError.
BenchResults readBenchFiles(const std::vector<std::string>& files);

}  // namespace gizmo::verify
