// The kernel charts: one gnuplot script (verify/study_assets/kernels.gp) for all four, given the
// points as data and the categories and series as a tics file written here.
#include <algorithm>

#include "gizmo/verify/study_output.hpp"
#include "study_gnuplot.hpp"

namespace gizmo::verify {
namespace {

std::size_t indexOf(std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return std::size_t(it - names.begin());
  names.push_back(name);
  return names.size() - 1;
}

// A string inside gnuplot's double quotes: the names are the study's own, but a stray quote
// would end the string.
std::string quoted(std::string text) {
  std::replace(text.begin(), text.end(), '"', '\'');
  return "\"" + text + "\"";
}

// A string inside gnuplot's single quotes (on its -e line), where a quote is written twice.
std::string singleQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// The label beside a point: its ratio, when it is not the series the ratios are taken against.
std::string labelOf(const KernelPoint& p) {
  if (p.unit.rfind("x ", 0) == 0) return kernelRatioText(p.value.mean);
  if (p.ratio && p.series != p.ratioTo) return kernelRatioText(p.ratio->mean);
  return "";
}

void drawChart(KernelChart chart, const std::vector<KernelPoint>& points, const std::filesystem::path& dir) {
  const KernelChartText& text = kernelChartText(chart);
  std::vector<std::string> categories, series;
  std::string data;
  double top = text.line;
  for (const KernelPoint& p : points) {
    const std::size_t c = indexOf(categories, p.category), s = indexOf(series, p.series);
    data += std::to_string(c) + "," + std::to_string(s + 1) + "," + studyNumber(p.value.mean) + "," +
            studyNumber(p.value.stddev) + "," + studyCsvField(labelOf(p)) + "\n";
    top = std::max(top, p.value.mean + p.value.stddev);
  }
  std::string tics = "set xtics (";
  for (std::size_t c = 0; c < categories.size(); ++c)
    tics += (c ? ", " : "") + quoted(categories[c]) + " " + std::to_string(c);
  tics += ")\nset xrange [-0.5:" + studyNumber(double(categories.size()) - 0.5) +
          "]\nnseries = " + std::to_string(series.size()) + "\narray names[" + std::to_string(series.size()) + "] = [";
  for (std::size_t s = 0; s < series.size(); ++s) tics += (s ? ", " : "") + quoted(series[s]);
  tics += "]\n";
  // A linear axis starts at 0, so that a ratio's distance from the dashed line reads true.
  if (!text.logScale) tics += "set yrange [0:" + studyNumber(top * 1.15) + "]\n";
  const std::string stem = std::string("kernels-") + kernelChartName(chart);
  writeStudyFile((dir / (stem + ".csv")).string(), data);
  writeStudyFile((dir / (stem + "-tics.gp")).string(), tics);
  const std::size_t width = std::max<std::size_t>(640, 260 + 100 * categories.size());
  drawWithGnuplot(dir,
                  "datafile='" + stem + ".csv'; ticsfile='" + stem + "-tics.gp'; outfile='" + stem +
                      ".svg'; title=" + singleQuoted(text.title) + "; ylabel=" + singleQuoted(text.axis) +
                      "; logy=" + (text.logScale ? "1" : "0") + "; refline=" + studyNumber(text.line) +
                      "; reflabel=" + singleQuoted(text.lineLabel) + "; width=" + std::to_string(width),
                  "kernels.gp");
}

}  // namespace

void drawKernelCharts(const KernelFigures& kernels, const std::string& chartsDir) {
  const std::filesystem::path dir(chartsDir);
  writeStudyFile((dir / "kernels.gp").string(), studyAsset("kernels.gp"));
  for (KernelChart chart : kKernelCharts) {
    const std::vector<KernelPoint> points = kernels.of(chart);
    if (!points.empty()) drawChart(chart, points, dir);
  }
}

}  // namespace gizmo::verify
