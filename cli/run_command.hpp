#pragma once
// `gizmo run`: simulate a board and print the final state and the count of each event kind.
#include "run_options.hpp"

namespace gizmo::cli {

int runCommand(const RunOptions& options);

// The run's summary as `gizmo run` prints it (also after `gizmo record`).
void printRunSummary(const std::string& board, const std::vector<std::string>& boardWarnings, const RunOptions& options,
                     const RunSummary& summary, double wall);

}  // namespace gizmo::cli
