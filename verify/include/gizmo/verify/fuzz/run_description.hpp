#pragma once
// Runs as text with exact values, for failure messages and the files a failing case leaves:
// numbers print as shortest round-trip decimals with their hex float, because rapidcheck prints
// doubles with 6 digits and a counterexample must be reproducible bit for bit.
#include <optional>
#include <string>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/math/scalar.hpp"
#include "gizmo/core/run/run.hpp"

namespace gizmo::verify::fuzz {

// "0.1 (0x1.999999999999ap-4)": the shortest decimal that reads back to x, and x exactly.
std::string exact(double x);

// "collision t=… a=3 b=7 feature=1 #42"
std::string describeEvent(EventKind kind, double time, GizmoId a, GizmoId b, std::int32_t feature,
                          std::uint64_t sequence);
template <class Real>
std::string describeEvent(const Event<Real>& e) {
  return describeEvent(e.kind, toDouble(e.time), e.a, e.b, e.feature, e.sequence);
}

// The key script format that io::readKeyScript reads ("TIME down|up KEY" per line), times as
// shortest round-trip decimals so that it reads back to the same doubles.
std::string writeKeyScript(const std::vector<TimedKey>& keys);

// Everything a run is: model, maximum tick, duration, the key script and the board (XML, which
// the board writer prints with round-trip decimals), with exact values.
std::string describeRun(const RunRequest& run);

// The first difference between two boards, SourcePos aside, comparing numbers bit for bit;
// nullopt when they are the same board.
std::optional<std::string> boardDifference(const BoardSpec& a, const BoardSpec& b);

}  // namespace gizmo::verify::fuzz
