#pragma once
// What the study's chart writers share: the built-in gnuplot scripts, and gnuplot run on one of
// them in the charts folder (so that every name it sees is a plain file name).
#include <filesystem>
#include <string>

namespace gizmo::verify {

// The built-in copy of verify/study_assets/NAME; StudyOutputError when there is none.
std::string studyAsset(const std::string& name);

// Runs `gnuplot -e VARIABLES SCRIPT` in dir, its output appended to dir/gnuplot.log; throws
// StudyOutputError when it fails.
void drawWithGnuplot(const std::filesystem::path& dir, const std::string& variables, const std::string& script);

}  // namespace gizmo::verify
