#pragma once
// `gizmo study`: the speed/accuracy study over a suite of scenes (docs/verification.md, "The
// speed/accuracy study"), written to a folder as CSV, JSON, SVG charts and an HTML page.
#include <string>
#include <vector>

namespace gizmo::cli {

struct StudyOptions {
  std::string scenes;  // a folder holding suite.txt; empty: the built-in suite
  std::string out = "study-results";
  bool quick = false;
  std::vector<std::string> bench;  // gizmo_bench JSON files (--bench, repeatable): the Kernels part
};
int studyCommand(const StudyOptions& options);

}  // namespace gizmo::cli
