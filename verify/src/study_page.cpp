// The study's HTML page: the template built in from verify/study_assets/report.html, filled with
// the plan, a reading of the numbers (computed from them, never written by hand), the charts and
// a table per scene.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "gizmo/verify/study_findings.hpp"
#include "gizmo/verify/study_output.hpp"
#include "gizmo/verify/study_suite.hpp"

namespace gizmo::verify {
namespace {

std::string escape(const std::string& text) { return studyHtmlText(text); }

std::string g(double v, const char* format = "%.3g") {
  char text[48];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string cost(const Spread& s) { return g(s.median) + " [" + g(s.min) + "–" + g(s.max) + "]"; }

void replace(std::string& text, const std::string& key, const std::string& value) {
  const std::string placeholder = "{{" + key + "}}";
  for (std::size_t at = text.find(placeholder); at != std::string::npos; at = text.find(placeholder, at + value.size()))
    text.replace(at, placeholder.size(), value);
}

const MethodResult* find(const SceneReport& s, MethodFamily family, Precision precision) {
  for (const MethodResult& r : s.results)
    if (r.method.family == family && r.method.precision.kind == precision) return &r;
  return nullptr;
}

std::string planText(const StudyReport& report) {
  const StudyPlan& p = report.plan;
  std::string precisions, ticks, steps;
  for (const PrecisionChoice& c : p.precisions) precisions += (precisions.empty() ? "" : ", ") + precisionName(c);
  for (double h : p.classicTicks) ticks += (ticks.empty() ? "" : ", ") + g(h, "%g");
  for (const StudyMethod& m : p.methods())
    if (m.family == MethodFamily::Box2d)
      steps += (steps.empty() ? "" : ", ") + m.label().substr(m.label().find('=') + 1);
  return std::string(p.quick ? "Quick study" : "Full study") + ": " + std::to_string(report.scenes.size()) +
         " scenes; the ballistic model and the classic model at maximum ticks " + ticks + " s, each at " + precisions +
         "; Box2D " + report.box2dVersion + " and Box2D v3 (box2d3-wasm, under node) at steps " + steps +
         " s with and without bullets; each run timed " + std::to_string(p.repeats) +
         " times. Reference: the ballistic model at mpfr:256.";
}

// The front of one scene, most accurate first.
std::string frontText(const SceneReport& s) {
  const std::vector<ChartPoint> front = paretoFront(chartPoints(s));
  std::string text;
  for (auto it = front.rbegin(); it != front.rend(); ++it)
    text += std::string(text.empty() ? "" : "; ") + escape(s.results[it->result].method.label()) + " (" + g(it->error) +
            " L at " + g(it->cost) + " s/s)";
  return text;
}

std::string readingText(const StudyReport& report) {
  std::string html = "<h3>The Pareto front</h3>\n<ul>\n";
  for (const SceneReport& s : report.scenes)
    html += "<li><b>" + escape(s.scene.name) + "</b>: " + frontText(s) + "</li>\n";
  html +=
      "</ul>\n<h3>Our ballistic double run against Box2D</h3>\n<p class=\"note\">Speed-up at equal error: Box2D's "
      "cheapest run as accurate as ours, over our cost (≥: no step size tried was as accurate; the dearest is "
      "shown). Accuracy gain at equal cost: Box2D's smallest error at our cost or less, over ours (≥: every Box2D "
      "run costs more; the cheapest is shown). The goals: 10× and 100×.</p>\n<table><tr><th class=\"text\">scene"
      "</th><th>our cost s/s</th><th>our error L</th><th>speed-up at equal error</th><th>accuracy gain at equal "
      "cost</th></tr>\n";
  int fastEnough = 0, accurateEnough = 0, compared = 0;
  for (const SceneReport& s : report.scenes) {
    const auto c = compareBallisticDoubleWithBox2d(s);
    if (!c) continue;
    ++compared;
    fastEnough += c->speedupAtEqualError >= 10;
    accurateEnough += c->accuracyGainAtEqualCost >= 100;
    html += "<tr><td class=\"text\">" + escape(c->scene) + "</td><td>" + g(c->oursCost) + "</td><td>" +
            g(c->oursError) + "</td><td>" + (c->speedupIsBound ? "≥ " : "") + g(c->speedupAtEqualError) + "×</td><td>" +
            (c->accuracyGainIsBound ? "≥ " : "") + g(c->accuracyGainAtEqualCost) + "×</td></tr>\n";
  }
  html += "</table>\n<p>At least 10× faster at equal error on " + std::to_string(fastEnough) + " of " +
          std::to_string(compared) + " scenes; at least 100× more accurate at equal cost on " +
          std::to_string(accurateEnough) + " of " + std::to_string(compared) + ".</p>\n";

  html += "<h3>Where double stops being trustworthy</h3>\n<ul>\n";
  for (const SceneReport& s : report.scenes) {
    const MethodResult* d = find(s, MethodFamily::Ballistic, Precision::Double);
    if (d == nullptr) continue;
    std::string line = "<li><b>" + escape(s.scene.name) + "</b>: ";
    if (d->horizonDifference.empty()) line += "double makes every decision of the mpfr:256 run";
    else
      line += "double's decisions part from mpfr:256 after " + std::to_string(d->horizonEvents.value_or(0)) +
              " events, at " + g(d->horizonTime.value_or(0), "%.6g") + " s (" + escape(d->horizonDifference) + ")";
    line += d->divergedAt
                ? "; a ball is more than " + g(kFailDistance) + " L off from " + g(*d->divergedAt, "%g") + " s"
                : "; its largest position error is " + g(d->positionError) + " L";
    html += line + "</li>\n";
  }
  html += "</ul>\n";
  return html;
}

std::string stabilityTable(const StudyReport& report) {
  std::string html = "<table><tr><th class=\"text\">stress scene</th>";
  const MethodFamily families[] = {MethodFamily::Ballistic,     MethodFamily::Classic, MethodFamily::Box2d,
                                   MethodFamily::Box2dNoBullet, MethodFamily::Box2dV3, MethodFamily::Box2dV3NoBullet};
  for (MethodFamily f : families)
    html +=
        std::string("<th class=\"text\">") + familyName(f) + (f == MethodFamily::Classic ? " (double)" : "") + "</th>";
  html += "<th class=\"text\">what the coarsest failing method gets wrong</th></tr>\n";
  for (const SceneReport& s : report.scenes) {
    if (!s.scene.stress) continue;
    html += "<tr><td class=\"text\">" + escape(s.scene.name) + "</td>";
    for (MethodFamily f : families) html += "<td class=\"text\">" + escape(failsFrom(s, f)) + "</td>";
    std::string wrong;
    for (const MethodResult& r : s.results) {
      if (!r.failed() || r.reference) continue;
      wrong = escape(r.method.label()) + ": " +
              escape(!r.stopped.empty()      ? r.stopped
                     : !r.firstWrong.empty() ? r.firstWrong
                                             : "a ball " + g(r.positionError) + " L off");
      break;
    }
    html += "<td class=\"text\">" + (wrong.empty() ? std::string("—") : wrong) + "</td></tr>\n";
  }
  return html + "</table>\n";
}

std::string sceneSection(const SceneReport& s) {
  const std::vector<ChartPoint> front = paretoFront(chartPoints(s));
  auto onFront = [&](std::size_t i) {
    for (const ChartPoint& p : front)
      if (p.result == i) return true;
    return false;
  };
  std::string html = "<h3 id=\"" + escape(s.scene.name) + "\">" + escape(s.scene.name) + "</h3>\n<p class=\"note\">" +
                     escape(s.scene.note) + " — " + escape(s.scene.board) + ", " + g(s.scene.request.duration, "%g") +
                     " s, positions every " + g(s.scene.sampleEvery, "%g") + " s" +
                     (s.scene.stress ? ", stress scene" : "") + ".</p>\n<p><img src=\"charts/pareto-" +
                     escape(s.scene.name) + ".svg\" alt=\"error against cost\"></p>\n";
  html +=
      "<table><tr><th class=\"text\">method</th><th>cost s/s [min–max]</th><th>s/event</th><th>position error L"
      "</th><th>median</th><th>event time error s</th><th>matched</th><th>first wrong s</th><th>energy drift</th>"
      "<th>horizon events</th><th>horizon s</th><th>convergence L</th><th class=\"text\">first wrong decision / "
      "why stopped</th></tr>\n";
  for (std::size_t i = 0; i < s.results.size(); ++i) {
    const MethodResult& r = s.results[i];
    const std::string cls = !r.stopped.empty() ? "stopped" : r.failed() ? "failed" : onFront(i) ? "front" : "";
    html += "<tr class=\"" + cls + "\"><td class=\"text\">" + escape(r.method.label()) +
            (r.reference ? " (reference)" : "") + "</td><td>" + cost(r.secondsPerBoardSecond) + "</td><td>" +
            g(r.secondsPerEvent.median) + "</td><td>" + g(r.positionError) + "</td><td>" + g(r.positionErrorMedian) +
            "</td><td>" + g(r.eventTimeError) + "</td><td>" + std::to_string(r.matched) + "/" +
            std::to_string(r.referenceCollisions) + "</td><td>" +
            (r.firstWrongTime ? g(*r.firstWrongTime, "%.6g") : "") + "</td><td>" + g(r.energyDrift) + "</td><td>" +
            (r.horizonEvents ? std::to_string(*r.horizonEvents) : "") + "</td><td>" +
            (r.horizonTime ? g(*r.horizonTime, "%.6g") : "") + "</td><td>" +
            (r.convergenceError ? g(*r.convergenceError) : "") + "</td><td class=\"text\">" +
            escape(!r.stopped.empty() ? r.stopped : r.firstWrong) + "</td></tr>\n";
  }
  return html + "</table>\n";
}

}  // namespace

std::string studyHtmlText(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void writeStudyFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw StudyOutputError(path + ": cannot write the file");
}

std::string studyNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

std::string studyPage(const StudyReport& report) {
  const char* page = builtInStudyFile("verify/study_assets/report.html");
  if (page == nullptr) throw StudyOutputError("the built-in asset report.html is missing");
  std::string html = page;
  std::string scenes;
  for (const SceneReport& s : report.scenes) scenes += sceneSection(s);
  replace(html, "TITLE", "gizmo: speed against accuracy");
  replace(html, "PLAN", escape(planText(report)));
  replace(html, "FAIL_DISTANCE", g(kFailDistance, "%g"));
  replace(html, "READING", readingText(report));
  replace(html, "STABILITY", stabilityTable(report));
  replace(html, "KERNELS", report.bench.empty() ? "" : kernelsSection(report.bench, kernelFigures(report.bench)));
  replace(html, "SCENES", scenes);
  return html;
}

void writeStudy(const StudyReport& report, const std::string& dirName) {
  const std::filesystem::path dir(dirName);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw StudyOutputError(dir.string() + ": cannot create the folder: " + ec.message());
  writeStudyFile((dir / "results.csv").string(), studyCsv(report));
  writeStudyFile((dir / "results.json").string(), studyJson(report));
  if (!report.bench.empty()) {
    const KernelFigures kernels = kernelFigures(report.bench);
    writeStudyFile((dir / "kernels.csv").string(), kernelsCsv(kernels));
    writeStudyFile((dir / "kernels.json").string(), kernelsJson(report.bench, kernels));
  }
  drawStudyCharts(report, dirName);
  writeStudyFile((dir / "index.html").string(), studyPage(report));
}

}  // namespace gizmo::verify
