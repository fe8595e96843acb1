#pragma once
// The events of the seed's discrete-event queue, plus the model events that the two motion
// models add, and the fixed order in which simultaneous events run.
#include <cstdint>
#include <string_view>

namespace gizmo {

using GizmoId = std::int32_t;
inline constexpr GizmoId kNoGizmo = -1;

// The order of this enum is the tie order for events at the same instant (docs/physics.md §5):
// physical contacts first, then what the models add, input, and the bookkeeping events last.
enum class EventKind : std::uint8_t {
  Collision,     // seed: a collision between collider (a) and collidee (b) through feature
  Leave,         // a ball that an absorber fired leaves its rectangle (a = absorber, b = ball)
  ContactEnd,    // a ball sliding on a surface reaches the end of it (a = ball)
  FlipperStop,   // a swinging flipper reaches its end or rest angle (a = flipper)
  FrictionTick,  // ballistic model: friction applied at time k·h (a = ball)
  Input,         // a key press or release from the input script (feature = key, b = direction)
  Recalculate,   // seed: recalculate-collision-time (a = the ball whose pairs are recomputed)
  EndOfTick,     // seed: the end of the current tick
};
inline constexpr int kEventKindCount = 8;

inline std::string_view eventKindName(EventKind k) {
  switch (k) {
    case EventKind::Collision: return "collision";
    case EventKind::Leave: return "leave";
    case EventKind::ContactEnd: return "contact-end";
    case EventKind::FlipperStop: return "flipper-stop";
    case EventKind::FrictionTick: return "friction-tick";
    case EventKind::Input: return "input";
    case EventKind::Recalculate: return "recalculate";
    case EventKind::EndOfTick: return "end-of-tick";
  }
  return "?";
}

template <class Real>
struct Event {
  Real time{0};
  EventKind kind = EventKind::EndOfTick;
  GizmoId a = kNoGizmo;
  GizmoId b = kNoGizmo;
  std::int32_t feature = -1;
  std::uint64_t sequence = 0;  // order of scheduling: the last tie-breaker, still deterministic
};

// Earliest first; equal times by kind, then gizmo ids, then feature, then scheduling order.
// Nothing here depends on addresses or hashes.
template <class Real>
bool runsBefore(const Event<Real>& x, const Event<Real>& y) {
  if (x.time < y.time) return true;
  if (y.time < x.time) return false;
  if (x.kind != y.kind) return x.kind < y.kind;
  if (x.a != y.a) return x.a < y.a;
  if (x.b != y.b) return x.b < y.b;
  if (x.feature != y.feature) return x.feature < y.feature;
  return x.sequence < y.sequence;
}

}  // namespace gizmo
