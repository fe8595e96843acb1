// The study's charts: gnuplot draws them from data files written here, with the scripts built
// into the program (verify/study_assets), run in DIR/charts so that every name it sees is a
// plain file name.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "gizmo/verify/study_findings.hpp"
#include "gizmo/verify/study_output.hpp"
#include "gizmo/verify/study_suite.hpp"
#include "study_gnuplot.hpp"

extern char** environ;

namespace gizmo::verify {
namespace {

void writeFile(const std::filesystem::path& path, const std::string& text) { writeStudyFile(path.string(), text); }

// Runs gnuplot with these arguments in folder `dir`, its output appended to dir/gnuplot.log.
int runGnuplot(const std::filesystem::path& dir, const std::vector<std::string>& args, bool quiet) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!dir.empty()) posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  const char* log = quiet ? "/dev/null" : "gnuplot.log";
  posix_spawn_file_actions_addopen(&actions, 1, log, O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, log, O_WRONLY | O_CREAT | O_APPEND, 0644);
  std::vector<char*> argv;
  std::string program = "gnuplot";
  argv.push_back(program.data());
  std::vector<std::string> copies = args;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

// An error of exactly 0 cannot stand on a log scale: it is drawn at this floor.
constexpr double kErrorFloor = 1e-40;

std::string paretoData(const SceneReport& s, const std::vector<ChartPoint>& points) {
  std::string text;
  for (const ChartPoint& p : points) {
    const MethodResult& r = s.results[p.result];
    text += std::string(familyName(r.method.family)) + "," + r.method.label() + "," + studyNumber(p.cost) + "," +
            studyNumber(std::max(p.error, kErrorFloor)) + "\n";
  }
  return text;
}

void drawPareto(const SceneReport& s, const std::filesystem::path& dir) {
  const std::vector<ChartPoint> points = chartPoints(s);
  const std::string stem = "pareto-" + s.scene.name;
  writeFile(dir / (stem + ".csv"), paretoData(s, points));
  writeFile(dir / (stem + "-front.csv"), paretoData(s, paretoFront(points)));
  drawWithGnuplot(dir,
                  "datafile='" + stem + ".csv'; frontfile='" + stem + "-front.csv'; outfile='" + stem +
                      ".svg'; scene='" + s.scene.name + "'",
                  "pareto.gp");
}

void drawStability(const StudyReport& report, const std::filesystem::path& dir) {
  const std::vector<StabilityRow> rows = stabilityMap(report);
  if (rows.empty()) return;
  const std::vector<StudyMethod> columns = stabilityColumns(report.plan);
  std::string data, tics = "set xtics (";
  for (std::size_t c = 0; c < columns.size(); ++c)
    tics += (c ? ", " : "") + std::string("\"") + columns[c].label() + "\" " + std::to_string(c);
  tics += ")\nset ytics (";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    tics += (r ? ", " : "") + std::string("\"") + rows[r].scene + "\" " + std::to_string(r);
    for (std::size_t c = 0; c < rows[r].cells.size(); ++c)
      data += std::to_string(c) + "," + std::to_string(r) + "," + std::to_string(rows[r].cells[c].status) + "\n";
  }
  // The first scene on top: the y axis runs from the last row down to the first.
  tics += ")\nset xrange [-0.5:" + studyNumber(double(columns.size()) - 0.5) + "]\nset yrange [" +
          studyNumber(double(rows.size()) - 0.5) + ":-0.5]\n";
  writeFile(dir / "stability.csv", data);
  writeFile(dir / "stability-tics.gp", tics);
  const std::string width = std::to_string(300 + 26 * columns.size()), height = std::to_string(260 + 26 * rows.size());
  drawWithGnuplot(dir,
                  "datafile='stability.csv'; ticsfile='stability-tics.gp'; outfile='stability.svg'; width=" + width +
                      "; height=" + height,
                  "stability.gp");
}

}  // namespace

std::string studyAsset(const std::string& name) {
  const char* text = builtInStudyFile("verify/study_assets/" + name);
  if (text == nullptr) throw StudyOutputError("the built-in asset " + name + " is missing");
  return text;
}

void drawWithGnuplot(const std::filesystem::path& dir, const std::string& variables, const std::string& script) {
  if (runGnuplot(dir, {"-e", variables, script}, false) != 0)
    throw StudyOutputError("gnuplot failed on " + script + " (" + variables + "): see " +
                           (dir / "gnuplot.log").string());
}

void requireGnuplot() {
  if (runGnuplot({}, {"--version"}, true) != 0)
    throw StudyOutputError(
        "gnuplot cannot be run: the study draws its charts with it (install gnuplot-nox, or run scripts/setup.sh)");
}

void drawStudyCharts(const StudyReport& report, const std::string& dirName) {
  const std::filesystem::path dir = std::filesystem::path(dirName) / "charts";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw StudyOutputError(dir.string() + ": cannot create the folder: " + ec.message());
  std::filesystem::remove(dir / "gnuplot.log", ec);
  for (const char* script : {"pareto.gp", "stability.gp"}) writeFile(dir / script, studyAsset(script));
  for (const SceneReport& s : report.scenes) drawPareto(s, dir);
  drawStability(report, dir);
  if (!report.bench.empty()) drawKernelCharts(kernelFigures(report.bench), dir.string());
}

}  // namespace gizmo::verify
