#pragma once
// An event written by hand, for tests that hand events to a gizmo, a certifier or a log's encoder
// without a board's queue numbering them.
#include <cstdint>

#include "gizmo/core/board/event.hpp"

namespace gizmo::test {

inline Event<double> eventAt(double time, EventKind kind, GizmoId a = kNoGizmo, GizmoId b = kNoGizmo,
                             std::int32_t feature = -1, std::uint64_t sequence = 0) {
  Event<double> e;
  e.time = time;
  e.kind = kind;
  e.a = a;
  e.b = b;
  e.feature = feature;
  e.sequence = sequence;
  return e;
}

}  // namespace gizmo::test
