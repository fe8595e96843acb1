#include "study_command.hpp"

#include <filesystem>
#include <iostream>

#include "board_input.hpp"
#include "gizmo/verify/study_findings.hpp"
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

}  // namespace

int studyCommand(const StudyOptions& o) {
  std::vector<verify::StudyScene> scenes;
  const verify::StudyPlan plan = o.quick ? verify::StudyPlan::quickPlan() : verify::StudyPlan::full();
  try {
    verify::requireGnuplot();
    scenes = verify::loadSuite(o.scenes, o.quick);
    verify::checkStudy(scenes, plan);
  } catch (const verify::StudyInputError& e) {
    std::cerr << "gizmo study: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const verify::StudyOutputError& e) {
    std::cerr << "gizmo study: " << e.what() << '\n';
    return kExitBadInput;
  }
  if (!checkOutputFolder(o.out)) return kExitBadInput;
  try {
    const verify::StudyReport report = verify::runStudy(scenes, plan, progress);
    verify::writeStudy(report, o.out);
    std::cout << "study     " << report.scenes.size() << " scenes, " << plan.methods().size() << " methods each"
              << (plan.quick ? " (quick)" : "") << "\n";
    std::cout << "written   " << o.out << "/index.html, results.csv, results.json, charts/\n";
    for (const verify::SceneReport& s : report.scenes) {
      if (const auto c = verify::compareBallisticDoubleWithBox2d(s))
        std::cout << "box2d     " << s.scene.name << ": ballistic double " << c->oursCost << " s/s, error " << c->oursError
                  << " L; Box2D at equal error " << (c->speedupIsBound ? ">= " : "") << c->speedupAtEqualError
                  << "x the cost, at equal cost " << (c->accuracyGainIsBound ? ">= " : "") << c->accuracyGainAtEqualCost
                  << "x the error\n";
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
