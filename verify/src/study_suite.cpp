// Reading the study's manifest and the boards and key scripts it names, from a folder or from the
// built-in copy of fixtures/study.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gizmo/io/board_file.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/key_script.hpp"
#include "gizmo/verify/study_suite.hpp"

namespace gizmo::verify {
namespace {

// Where the files come from: a folder on disk, or the built-in copy (keyed by the path relative
// to the project, as fixtures/study/... after normalizing "..").
class SuiteFiles {
 public:
  explicit SuiteFiles(std::string dir) : dir_(std::move(dir)) {}

  std::string display(const std::string& relative) const {
    return dir_.empty() ? builtInKey(relative) + " (built in)" : (std::filesystem::path(dir_) / relative).string();
  }

  std::string read(const std::string& relative) const {
    if (dir_.empty()) {
      const char* text = builtInStudyFile(builtInKey(relative));
      if (text == nullptr) throw StudyInputError(display(relative) + ": no such built-in file");
      return text;
    }
    const std::filesystem::path path = std::filesystem::path(dir_) / relative;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw StudyInputError(path.string() + ": cannot read the file");
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw StudyInputError(path.string() + ": cannot read the file");
    return text.str();
  }

 private:
  static std::string builtInKey(const std::string& relative) {
    return (std::filesystem::path("fixtures/study") / relative).lexically_normal().generic_string();
  }
  std::string dir_;
};

double number(const std::string& token, const std::string& where, const char* what) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(token, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != token.size() || !std::isfinite(value) || value < 0)
    throw StudyInputError(where + ": " + what + " '" + token + "' is not a number of seconds >= 0");
  return value;
}

StudyScene readScene(std::istringstream& words, const SuiteFiles& files, const std::string& where,
                     double& quickSeconds) {
  StudyScene scene;
  std::string seconds, quick, every, kind;
  if (!(words >> scene.name >> scene.board >> seconds >> quick >> every >> kind))
    throw StudyInputError(
        where + ": expected 'scene NAME BOARD SECONDS QUICK_SECONDS SAMPLE_EVERY main|stress [keys=FILE] NOTE'");
  if (scene.name.find_first_of(",\"<>&'") != std::string::npos)
    throw StudyInputError(where + ": scene name '" + scene.name + "' may not contain , \" < > & or '");
  scene.request.duration = number(seconds, where, "SECONDS");
  quickSeconds = number(quick, where, "QUICK_SECONDS");
  scene.sampleEvery = number(every, where, "SAMPLE_EVERY");
  if (scene.request.duration <= 0 || scene.request.duration > 1000)
    throw StudyInputError(where + ": SECONDS must be above 0 and at most 1000");
  if (quickSeconds > scene.request.duration) throw StudyInputError(where + ": QUICK_SECONDS is longer than SECONDS");
  if (scene.sampleEvery <= 0) throw StudyInputError(where + ": SAMPLE_EVERY must be above 0");
  if (kind != "main" && kind != "stress")
    throw StudyInputError(where + ": the kind must be main or stress, not '" + kind + "'");
  scene.stress = kind == "stress";
  std::string word;
  while (words >> word) {
    if (word.rfind("keys=", 0) == 0 && scene.note.empty()) {
      const std::string keys = word.substr(5);
      try {
        for (const io::KeyInput& k : io::readKeyScript(files.read(keys), files.display(keys)))
          scene.request.keys.push_back(TimedKey{k.time, k.key, k.direction});
      } catch (const io::InputError& e) {
        throw StudyInputError(e.what());
      }
      continue;
    }
    scene.note += (scene.note.empty() ? "" : " ") + word;
  }
  try {
    scene.request.board = io::readBoardString(files.read(scene.board), files.display(scene.board)).board;
  } catch (const io::InputError& e) {
    throw StudyInputError(e.what());
  }
  return scene;
}

}  // namespace

std::vector<StudyScene> loadSuite(const std::string& dir, bool quick) {
  const SuiteFiles files(dir);
  std::istringstream manifest(files.read(kSuiteManifest));
  std::vector<StudyScene> scenes;
  std::string line;
  for (int number = 1; std::getline(manifest, line); ++number) {
    const std::string where = files.display(kSuiteManifest) + ":" + std::to_string(number);
    std::istringstream words(line);
    std::string first;
    if (!(words >> first) || first[0] == '#') continue;
    if (first != "scene") throw StudyInputError(where + ": unknown line '" + first + "' (expected 'scene')");
    double quickSeconds = 0;
    StudyScene scene = readScene(words, files, where, quickSeconds);
    for (const StudyScene& s : scenes)
      if (s.name == scene.name) throw StudyInputError(where + ": scene '" + scene.name + "' is named twice");
    if (quick) {
      if (quickSeconds == 0) continue;
      scene.request.duration = quickSeconds;
    }
    scenes.push_back(std::move(scene));
  }
  if (scenes.empty())
    throw StudyInputError(files.display(kSuiteManifest) +
                          (quick ? ": no scene has a quick duration" : ": names no scene"));
  return scenes;
}

}  // namespace gizmo::verify
