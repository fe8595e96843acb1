#pragma once
// The study's scenes: a manifest (suite.txt) naming each scene's board, key script, durations,
// sampling interval and kind, read from a folder or from the copy of fixtures/study built into
// the program (so that `gizmo study` works from any directory).
#include <stdexcept>
#include <string>
#include <vector>

#include "gizmo/verify/study.hpp"

namespace gizmo::verify {

// A manifest, board or key script that cannot be used; the message names the file and line.
class StudyInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr const char* kSuiteManifest = "suite.txt";

// The scenes of the manifest DIR/suite.txt (board and key paths relative to DIR), or of the
// built-in suite when dir is empty. With quick, only the scenes that have a quick duration, each
// run for it. Throws StudyInputError.
std::vector<StudyScene> loadSuite(const std::string& dir, bool quick);

// The built-in copy of a study file by its path relative to the project (e.g.
// "fixtures/study/suite.txt", "verify/study_assets/pareto.gp"); nullptr when there is none. The
// suite, every file it names and the assets are built in at configure time
// (verify/study_assets/embed_study_files.cmake).
const char* builtInStudyFile(const std::string& path);

}  // namespace gizmo::verify
