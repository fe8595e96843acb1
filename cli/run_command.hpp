#pragma once
// `gizmo run`: simulate a board and print the final state and the count of each event kind.
#include <string>

namespace gizmo::cli {

struct RunOptions {
  std::string board;  // empty: the built-in spec example
  double time = 10.0;
  std::string model = "ballistic";
  std::string precision = "double";
  double maxTick = 0.05;
  std::string keys;
  bool json = false;
};

int runCommand(const RunOptions& options);

}  // namespace gizmo::cli
