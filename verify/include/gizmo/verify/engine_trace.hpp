#pragma once
// Any engine's run of a board, read from a trace: JSON lines of its step times, each ball's
// position and velocity after each step, and the contacts it reported (docs/verification.md,
// "Any engine's run"). The run becomes the same RunRecord as Box2D's, so that `gizmo crosscheck
// BOARD --trace FILE` gives the same report (box2d_crosscheck.hpp's crosscheckRuns).
#include <istream>
#include <stdexcept>
#include <string>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/verify/box2d_crosscheck.hpp"

namespace gizmo::verify {

inline constexpr const char* kEngineTraceFormat = "gizmo-trace";
inline constexpr int kEngineTraceVersion = 1;

struct EngineTrace {
  std::string engine;  // the header's name of the engine
  EngineRun run;       // its samples, its contacts (when it reports them), its largest step
};

// What is wrong with a trace, and where: "FILE:LINE: error: WHAT" (line 0: the file as a whole,
// "FILE: error: WHAT").
class EngineTraceError : public std::runtime_error {
 public:
  EngineTraceError(const std::string& file, std::size_t line, const std::string& what)
      : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": error: " + what) {}
};

// Reads a trace of a run of `board` that must reach board time `end` (seconds); `file` names it
// in errors. Throws EngineTraceError at the first thing wrong.
EngineTrace readEngineTrace(std::istream& in, const std::string& file, const BoardSpec& board, double end);
// The same from a file (one that cannot be read is an error of the file as a whole).
EngineTrace readEngineTraceFile(const std::string& path, const BoardSpec& board, double end);

}  // namespace gizmo::verify
