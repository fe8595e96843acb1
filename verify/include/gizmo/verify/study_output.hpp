#pragma once
// The study's output folder: the data as CSV and JSON, SVG charts drawn by gnuplot, and an HTML
// page that puts the charts, the tables and a short reading of them together.
#include <stdexcept>
#include <string>

#include "gizmo/verify/study.hpp"
#include "gizmo/verify/study_kernels.hpp"

namespace gizmo::verify {

class StudyOutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws StudyOutputError when gnuplot cannot be run: checked before the study starts, so that a
// missing gnuplot leaves no partial output.
void requireGnuplot();

std::string studyCsv(const StudyReport& report);   // one row per scene and method
std::string studyJson(const StudyReport& report);  // everything, with the findings

// DIR/charts: pareto-SCENE.svg per scene, stability.svg, and the data and gnuplot scripts that
// drew them (so that a chart can be drawn again by hand).
void drawStudyCharts(const StudyReport& report, const std::string& dir);

std::string studyPage(const StudyReport& report);  // DIR/index.html, charts linked from charts/

// With gizmo_bench's figures (StudyReport::bench): the kernel charts' points as CSV (one row per
// point), everything read as JSON (the files' context, every figure, the points), the charts
// (DIR/charts/kernels-CHART.svg, with their data and kernels.gp) and the page's Kernels part.
std::string kernelsCsv(const KernelFigures& kernels);
std::string kernelsJson(const BenchResults& bench, const KernelFigures& kernels);
void drawKernelCharts(const KernelFigures& kernels, const std::string& chartsDir);
std::string kernelsSection(const BenchResults& bench, const KernelFigures& kernels);  // empty without figures
std::string kernelRatioText(double ratio);  // "×1.55", "×2646": as the charts' labels and the tables give it

// The helpers the writers share: a whole file written or StudyOutputError, and a number as
// the tables and chart data give it (9 significant digits).
void writeStudyFile(const std::string& path, const std::string& text);
std::string studyNumber(double value);
std::string studyCsvField(const std::string& text);  // quoted when it holds a separator, a quote or a line break
std::string studyHtmlText(const std::string& text);  // &, <, > and " escaped

// All of the above: DIR/results.csv, DIR/results.json, DIR/charts/, DIR/index.html, and with
// gizmo_bench's figures DIR/kernels.csv and DIR/kernels.json.
void writeStudy(const StudyReport& report, const std::string& dir);

}  // namespace gizmo::verify
