#include "study_command.hpp"

#include <filesystem>
#include <iostream>

#include "board_input.hpp"
#include "gizmo/verify/study_bench.hpp"
#include "gizmo/verify/study_findings.hpp"
#include "gizmo/verify/study_kernels.hpp"
#include "gizmo/verify/study_output.hpp"
#include "gizmo/verify/study_suite.hpp"

namespace gizmo::cli {
namespace {

void progress(const std::string& scene, const std::string& method) {
  std::cerr << "gizmo study: " << scene << ": " << method << '\n';
}

// The output folder must be one we can write to before hours of runs are spent.
bool checkOutputFolder(const std::string& out) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    std::cerr << "gizmo study: --out " << out << " exists and is not a folder\n";
    return false;
  }
  fs::create_directories(out, ec);
  const fs::path probe = fs::path(out) / ".gizmo-study-write-check";
  try {
    verify::writeStudyFile(probe.string(), "");
  } catch (const verify::StudyOutputError&) {
    std::cerr << "gizmo study: --out " << out << ": cannot write into the folder\n";
    return false;
  }
  fs::remove(probe, ec);
  return true;
}

// One line per kernel chart: what it holds, so that a run in a terminal shows the Kernels part came out.
void printKernels(const verify::KernelFigures& kernels, std::size_t read) {
  std::cout << "kernels   " << read << " benchmarks read, " << kernels.points.size() << " points charted";
  if (!kernels.notCharted.empty()) std::cout << ", " << kernels.notCharted.size() << " benchmarks not charted";
  std::cout << '\n';
  for (verify::KernelChart chart : verify::kKernelCharts) {
    const std::vector<verify::KernelPoint> points = kernels.of(chart);
    if (!points.empty())
      std::cout << "kernels   " << verify::kernelChartName(chart) << ": " << points.size() << " points, charts/kernels-"
                << verify::kernelChartName(chart) << ".svg\n";
  }
}

}  // namespace

int studyCommand(const StudyOptions& o) {
  std::vector<verify::StudyScene> scenes;
  verify::BenchResults bench;
  const verify::StudyPlan plan = o.quick ? verify::StudyPlan::quickPlan() : verify::StudyPlan::full();
  try {
    verify::requireGnuplot();
    scenes = verify::loadSuite(o.scenes, o.quick);
    verify::checkStudy(scenes, plan);
    // Read before the runs: a bad file must not cost a study's time, nor leave half an output.
    bench = verify::readBenchFiles(o.bench);
  } catch (const verify::StudyInputError& e) {
    std::cerr << "gizmo study: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const verify::StudyOutputError& e) {
    std::cerr << "gizmo study: " << e.what() << '\n';
    return kExitBadInput;
  }
  if (!checkOutputFolder(o.out)) return kExitBadInput;
  try {
    verify::StudyReport report = verify::runStudy(scenes, plan, progress);
    report.bench = std::move(bench);
    verify::writeStudy(report, o.out);
    std::cout << "study     " << report.scenes.size() << " scenes, " << plan.methods().size() << " methods each"
              << (plan.quick ? " (quick)" : "") << "\n";
    std::cout << "written   " << o.out << "/index.html, results.csv, results.json, charts/"
              << (report.bench.empty() ? "" : ", kernels.csv, kernels.json") << "\n";
    if (!report.bench.empty()) printKernels(verify::kernelFigures(report.bench), report.bench.figures.size());
    for (const verify::SceneReport& s : report.scenes) {
      if (const auto c = verify::compareBallisticDoubleWithBox2d(s))
        std::cout << "box2d     " << s.scene.name << ": ballistic double " << c->oursCost << " s/s, error "
                  << c->oursError << " L; Box2D at equal error " << (c->speedupIsBound ? ">= " : "")
                  << c->speedupAtEqualError << "x the cost, at equal cost " << (c->accuracyGainIsBound ? ">= " : "")
                  << c->accuracyGainAtEqualCost << "x the error\n";
    }
  } catch (const verify::StudyInputError& e) {
    std::cerr << "gizmo study: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const verify::StudyOutputError& e) {
    std::cerr << "gizmo study: " << e.what() << '\n';
    return kExitCheckFailed;
  }
  return kExitOk;
}

}  // namespace gizmo::cli
