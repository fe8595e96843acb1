// Reading Google Benchmark's JSON for the study. Every entry is checked before anything is kept,
// so that a damaged file is refused whole (exit 2, nothing written) instead of charting half of it.
#include "gizmo/verify/study_bench.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "gizmo/verify/study_suite.hpp"

namespace gizmo::verify {
namespace {

using Json = nlohmann::json;

// One entry of "benchmarks" that the study can use.
struct Entry {
  std::string runName;
  double realNs = 0, cpuNs = 0;
  int repetitions = 0;
  std::map<std::string, double> counters;
};

// Per benchmark: its runs, and Google Benchmark's mean and stddev of them when it computed those.
struct Group {
  std::vector<Entry> runs;
  std::optional<Entry> mean, stddev;
};

// Members of an entry that are numbers but not counters.
const std::set<std::string> kNotCounters{"family_index", "per_family_instance_index",
                                         "repetitions",  "repetition_index",
                                         "threads",      "iterations",
                                         "real_time",    "cpu_time"};

class EntryReader {
 public:
  EntryReader(const std::string& file, std::size_t index)
      : file_(file), where_("benchmarks[" + std::to_string(index) + "]") {}

  [[noreturn]] void refuse(const std::string& what) const {
    throw StudyInputError(file_ + ": " + where_ + ": " + what);
  }

  std::string text(const Json& e, const char* key) const {
    const auto it = e.find(key);
    if (it == e.end()) refuse(std::string("has no \"") + key + "\"");
    if (!it->is_string()) refuse(std::string("\"") + key + "\" is not a string");
    return it->get<std::string>();
  }

  double time(const Json& e, const char* key, double nsPerUnit) const {
    const auto it = e.find(key);
    if (it == e.end()) refuse(std::string("has no \"") + key + "\"");
    if (!it->is_number()) refuse(std::string("\"") + key + "\" is not a number");
    const double v = it->get<double>();
    if (!std::isfinite(v) || v < 0) refuse(std::string("\"") + key + "\" is not a time");
    return v * nsPerUnit;
  }

  double nsPerUnit(const std::string& unit) const {
    if (unit == "ns") return 1;
    if (unit == "us") return 1e3;
    if (unit == "ms") return 1e6;
    if (unit == "s") return 1e9;
    refuse("unknown time_unit '" + unit + "' (ns, us, ms or s)");
  }

  // Names the benchmark in every later message, once its name is known.
  void named(const std::string& name) { where_ += " (" + name + ")"; }

 private:
  std::string file_;
  std::string where_;
};

BenchValue meanAndStddev(const std::vector<double>& values) {
  BenchValue v;
  if (values.empty()) return v;
  for (double x : values) v.mean += x;
  v.mean /= double(values.size());
  if (values.size() < 2) return v;
  // The sample standard deviation, as Google Benchmark's own stddev aggregate computes it.
  double squares = 0;
  for (double x : values) squares += (x - v.mean) * (x - v.mean);
  v.stddev = std::sqrt(squares / double(values.size() - 1));
  return v;
}

BenchFigure figureOf(const std::string& name, const Group& g, const std::string& file) {
  BenchFigure f;
  f.name = name;
  f.file = file;
  if (g.mean) {
    f.fromAggregates = true;
    f.repetitions = g.mean->repetitions > 0 ? g.mean->repetitions : int(g.runs.size());
    f.realNs = {g.mean->realNs, g.stddev ? g.stddev->realNs : 0};
    f.cpuNs = {g.mean->cpuNs, g.stddev ? g.stddev->cpuNs : 0};
    for (const auto& [key, value] : g.mean->counters) {
      double spread = 0;
      if (g.stddev) {
        const auto it = g.stddev->counters.find(key);
        if (it != g.stddev->counters.end()) spread = it->second;
      }
      f.counters[key] = {value, spread};
    }
    return f;
  }
  f.repetitions = int(g.runs.size());
  std::vector<double> real, cpu;
  for (const Entry& e : g.runs) real.push_back(e.realNs), cpu.push_back(e.cpuNs);
  f.realNs = meanAndStddev(real);
  f.cpuNs = meanAndStddev(cpu);
  for (const auto& counter : g.runs.front().counters) {
    std::vector<double> values;
    for (const Entry& e : g.runs)
      if (const auto it = e.counters.find(counter.first); it != e.counters.end()) values.push_back(it->second);
    f.counters[counter.first] = meanAndStddev(values);
  }
  return f;
}

BenchSource sourceOf(const Json& doc, const std::string& file) {
  BenchSource s;
  s.file = file;
  const auto context = doc.find("context");
  if (context == doc.end()) return s;
  if (!context->is_object()) throw StudyInputError(file + ": \"context\" is not an object");
  // The context is description only: what is missing or of another type is left blank.
  if (const auto it = context->find("date"); it != context->end() && it->is_string()) s.date = it->get<std::string>();
  if (const auto it = context->find("host_name"); it != context->end() && it->is_string())
    s.host = it->get<std::string>();
  if (const auto it = context->find("num_cpus"); it != context->end() && it->is_number_integer())
    s.cpus = it->get<int>();
  if (const auto it = context->find("mhz_per_cpu"); it != context->end() && it->is_number()) s.mhz = it->get<double>();
  if (const auto it = context->find("cpu_scaling_enabled"); it != context->end() && it->is_boolean())
    s.cpuScaling = it->get<bool>();
  return s;
}

// What nlohmann's parse error says after its "[json.exception.parse_error.101] " tag.
std::string parseProblem(const std::string& what) {
  const std::size_t tag = what.find("] ");
  return tag == std::string::npos ? what : what.substr(tag + 2);
}

}  // namespace

const BenchFigure* BenchResults::find(const std::string& name) const {
  for (const BenchFigure& f : figures)
    if (f.name == name) return &f;
  return nullptr;
}

BenchResults parseBenchJson(const std::string& text, const std::string& file) {
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw StudyInputError(file + ": not valid JSON: " + parseProblem(e.what()));
  }
  if (!doc.is_object())
    throw StudyInputError(file + ": not Google Benchmark's JSON: the top level is not an object with \"benchmarks\"");
  const auto list = doc.find("benchmarks");
  if (list == doc.end() || !list->is_array())
    throw StudyInputError(file + ": not Google Benchmark's JSON: it has no \"benchmarks\" array");

  BenchResults results;
  results.sources.push_back(sourceOf(doc, file));
  BenchSource& source = results.sources.back();
  std::vector<std::string> order;
  std::map<std::string, Group> groups;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const Json& e = (*list)[i];
    EntryReader read(file, i);
    if (!e.is_object()) read.refuse("is not an object");
    const std::string name = read.text(e, "name");
    if (name.empty()) read.refuse("\"name\" is empty");
    read.named(name);
    if (const auto failed = e.find("error_occurred");
        failed != e.end() && failed->is_boolean() && failed->get<bool>()) {
      const auto message = e.find("error_message");
      source.failed.push_back(name + ": " +
                              (message != e.end() && message->is_string() ? message->get<std::string>() : "failed"));
      continue;
    }
    const std::string runType = read.text(e, "run_type");
    if (runType != "iteration" && runType != "aggregate")
      read.refuse("unknown run_type '" + runType + "' (iteration or aggregate)");
    Entry entry;
    entry.runName = e.contains("run_name") ? read.text(e, "run_name") : name;
    std::string aggregate;
    if (runType == "aggregate") {
      aggregate = read.text(e, "aggregate_name");
      // Medians, coefficients of variation, custom statistics and complexity fits: the study
      // charts means with their standard deviation.
      if (aggregate != "mean" && aggregate != "stddev") continue;
    }
    const double unit = read.nsPerUnit(read.text(e, "time_unit"));
    entry.realNs = read.time(e, "real_time", unit);
    entry.cpuNs = read.time(e, "cpu_time", unit);
    if (const auto it = e.find("repetitions"); it != e.end() && it->is_number_integer())
      entry.repetitions = it->get<int>();
    for (const auto& [key, value] : e.items())
      if (value.is_number() && !kNotCounters.count(key)) entry.counters[key] = value.get<double>();

    if (!groups.count(entry.runName)) order.push_back(entry.runName);
    Group& g = groups[entry.runName];
    if (aggregate == "mean") g.mean = entry;
    else if (aggregate == "stddev") g.stddev = entry;
    else g.runs.push_back(entry);
  }
  for (const std::string& name : order) {
    const Group& g = groups.at(name);
    if (g.mean || !g.runs.empty()) results.figures.push_back(figureOf(name, g, file));
  }
  if (results.figures.empty())
    throw StudyInputError(
        file + ": no benchmark with a figure in it" +
        (source.failed.empty() ? std::string() : " (every one reported an error: " + source.failed.front() + ")"));
  return results;
}

BenchResults readBenchFiles(const std::vector<std::string>& files) {
  BenchResults all;
  for (const std::string& file : files) {
    std::error_code ec;
    std::ifstream in(file, std::ios::binary);
    if (!std::filesystem::is_regular_file(file, ec) || !in) throw StudyInputError(file + ": cannot read the file");
    std::ostringstream text;
    text << in.rdbuf();
    BenchResults one = parseBenchJson(text.str(), file);
    for (const BenchFigure& f : one.figures)
      if (const BenchFigure* seen = all.find(f.name))
        throw StudyInputError(file + ": benchmark " + f.name + " is in " + seen->file +
                              " too: give each benchmark in one file only");
    all.sources.insert(all.sources.end(), one.sources.begin(), one.sources.end());
    all.figures.insert(all.figures.end(), one.figures.begin(), one.figures.end());
  }
  return all;
}

}  // namespace gizmo::verify
