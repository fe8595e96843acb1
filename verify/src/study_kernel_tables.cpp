// The kernel figures as the study writes them: kernels.csv (one row per charted point),
// kernels.json (what was read, and the points) and the page's Kernels part (per chart: the
// chart, and a table of categories against series).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gizmo/verify/study_output.hpp"

namespace gizmo::verify {
namespace {

using Json = nlohmann::ordered_json;

Json valueJson(const BenchValue& v) { return {{"mean", v.mean}, {"stddev", v.stddev}}; }

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

std::string g(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

std::string withSpread(const BenchValue& v) { return v.stddev > 0 ? g(v.mean) + " ± " + g(v.stddev) : g(v.mean); }

// A time in nanoseconds in the unit that keeps it readable: 19.8 ± 0.56 µs rather than 1.98e+04 ns.
std::string timeWithSpread(const BenchValue& ns) {
  const ReadableUnit unit = readableUnit(ns.mean);
  return withSpread(BenchValue{ns.mean / unit.ns, ns.stddev / unit.ns}) + " " + unit.name;
}

// Nanoseconds per one of the unit's, for the units that are times; 0 for the others.
double nsPer(const std::string& unit) {
  if (unit.rfind("ns ", 0) == 0) return 1;
  if (unit.rfind("wall ms ", 0) == 0) return 1e6;
  return 0;
}

// A table cell: the value with its spread, and its ratio when it has one.
std::string cell(const KernelPoint& p) {
  if (p.unit.rfind("x ", 0) == 0) return "×" + withSpread(p.value);
  const double ns = nsPer(p.unit);
  std::string text = ns > 0 ? timeWithSpread(BenchValue{p.value.mean * ns, p.value.stddev * ns}) : withSpread(p.value);
  if (p.ratio && p.series != p.ratioTo) text += " (" + kernelRatioText(p.ratio->mean) + ")";
  return text;
}

std::string cellHtml(const KernelPoint& p) {
  const std::string text = studyHtmlText(cell(p));
  return p.detail.empty() ? text : text + "<br><span class=\"note\">" + studyHtmlText(p.detail) + "</span>";
}

std::string sourceText(const BenchSource& s) {
  std::string text = s.file;
  std::vector<std::string> about;
  if (!s.date.empty()) about.push_back(s.date);
  if (!s.host.empty()) about.push_back("host " + s.host);
  if (s.cpus > 0)
    about.push_back(std::to_string(s.cpus) + " CPUs" +
                    (s.mhz > 0 ? " at " + std::to_string(std::lround(s.mhz)) + " MHz" : ""));
  if (s.cpuScaling) about.push_back("CPU frequency scaling on");
  return about.empty() ? text : text + " (" + joined(about, ", ") + ")";
}

std::string chartSection(KernelChart chart, const std::vector<KernelPoint>& points) {
  const KernelChartText& text = kernelChartText(chart);
  std::vector<std::string> categories, series;
  for (const KernelPoint& p : points) {
    if (std::find(categories.begin(), categories.end(), p.category) == categories.end())
      categories.push_back(p.category);
    if (std::find(series.begin(), series.end(), p.series) == series.end()) series.push_back(p.series);
  }
  const std::string name = kernelChartName(chart);
  const std::string title = studyHtmlText(text.title);
  std::string html = "<h3 id=\"kernels-" + name + "\">" + title + "</h3>\n<p class=\"note\">" +
                     studyHtmlText(text.what) + "</p>\n<p><img src=\"charts/kernels-" + name + ".svg\" alt=\"" + title +
                     "\"></p>\n<table><tr><th class=\"text\"></th>";
  for (const std::string& s : series) html += "<th>" + studyHtmlText(s) + "</th>";
  html += "</tr>\n";
  for (const std::string& c : categories) {
    html += "<tr><td class=\"text\">" + studyHtmlText(c) + "</td>";
    for (const std::string& s : series) {
      const auto p = std::find_if(points.begin(), points.end(),
                                  [&](const KernelPoint& x) { return x.category == c && x.series == s; });
      html += "<td>" + (p == points.end() ? std::string() : cellHtml(*p)) + "</td>";
    }
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

}  // namespace

std::string kernelRatioText(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, ratio >= 1000 ? "×%.0f" : "×%.3g", ratio);
  return text;
}

std::string kernelsCsv(const KernelFigures& kernels) {
  std::ostringstream out;
  out << "chart,category,series,value,stddev,unit,ratio,ratio_stddev,ratio_to,repetitions,benchmarks,detail\n";
  for (const KernelPoint& p : kernels.points) {
    out << kernelChartName(p.chart) << ',' << studyCsvField(p.category) << ',' << studyCsvField(p.series) << ','
        << studyNumber(p.value.mean) << ',' << studyNumber(p.value.stddev) << ',' << studyCsvField(p.unit) << ','
        << (p.ratio ? studyNumber(p.ratio->mean) : "") << ',' << (p.ratio ? studyNumber(p.ratio->stddev) : "") << ','
        << studyCsvField(p.ratioTo) << ',' << p.repetitions << ',' << studyCsvField(joined(p.benchmarks, " / ")) << ','
        << studyCsvField(p.detail) << '\n';
  }
  return out.str();
}

std::string kernelsJson(const BenchResults& bench, const KernelFigures& kernels) {
  Json sources = Json::array(), figures = Json::array(), charts = Json::object();
  for (const BenchSource& s : bench.sources)
    sources.push_back({{"file", s.file},
                       {"date", s.date},
                       {"host_name", s.host},
                       {"num_cpus", s.cpus},
                       {"mhz_per_cpu", s.mhz},
                       {"cpu_scaling_enabled", s.cpuScaling},
                       {"failed", s.failed}});
  for (const BenchFigure& f : bench.figures) {
    Json counters = Json::object();
    for (const auto& [name, value] : f.counters) counters[name] = valueJson(value);
    figures.push_back({{"name", f.name},
                       {"file", f.file},
                       {"repetitions", f.repetitions},
                       {"from_aggregates", f.fromAggregates},
                       {"real_ns", valueJson(f.realNs)},
                       {"cpu_ns", valueJson(f.cpuNs)},
                       {"counters", counters}});
  }
  for (KernelChart chart : kKernelCharts) {
    Json points = Json::array();
    for (const KernelPoint& p : kernels.of(chart))
      points.push_back({{"category", p.category},
                        {"series", p.series},
                        {"value", valueJson(p.value)},
                        {"unit", p.unit},
                        {"ratio", p.ratio ? valueJson(*p.ratio) : Json(nullptr)},
                        {"ratio_to", p.ratioTo},
                        {"repetitions", p.repetitions},
                        {"benchmarks", p.benchmarks},
                        {"detail", p.detail}});
    charts[kernelChartName(chart)] = points;
  }
  const Json out{{"sources", sources}, {"figures", figures}, {"charts", charts}, {"not_charted", kernels.notCharted}};
  return out.dump(2) + "\n";
}

std::string kernelsSection(const BenchResults& bench, const KernelFigures& kernels) {
  if (bench.empty()) return "";
  std::vector<std::string> files, failed;
  int fewest = 0, most = 0;
  for (const BenchSource& s : bench.sources) {
    files.push_back(sourceText(s));
    failed.insert(failed.end(), s.failed.begin(), s.failed.end());
  }
  for (const KernelPoint& p : kernels.points) {
    fewest = fewest == 0 ? p.repetitions : std::min(fewest, p.repetitions);
    most = std::max(most, p.repetitions);
  }
  std::string html =
      "<h2 id=\"kernels\">Kernels</h2>\n<p class=\"note\">Google Benchmark's figures from gizmo_bench (bench/): " +
      studyHtmlText(joined(files, "; ")) + ". Each is the mean over its repetitions (" +
      (fewest == most ? std::to_string(most) : std::to_string(fewest) + " to " + std::to_string(most)) +
      ") ± one standard deviation, Google Benchmark's own aggregates where it made them; a single run has "
      "no spread. A ratio is of two means, with both spreads carried into it. Absolute times depend on the "
      "machine and its load; ratios measured in one run much less.</p>\n";
  for (KernelChart chart : kKernelCharts) {
    const std::vector<KernelPoint> points = kernels.of(chart);
    if (!points.empty()) html += chartSection(chart, points);
  }
  if (kernels.points.empty()) html += "<p>None of the benchmarks read is one the study charts.</p>\n";
  if (!kernels.notCharted.empty())
    html += "<p class=\"note\">Read but not charted: " + studyHtmlText(joined(kernels.notCharted, ", ")) + ".</p>\n";
  if (!failed.empty())
    html += "<p class=\"note\">Reported an error, left out: " + studyHtmlText(joined(failed, "; ")) + ".</p>\n";
  return html;
}

}  // namespace gizmo::verify
