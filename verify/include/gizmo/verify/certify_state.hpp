#pragma once
// What the certifier takes from the double run, as plain doubles: the board's fixed layout
// (read once) and the state in force between two events (read after each executed event).
// These doubles are the certificate's exact input; nothing here is computed, only copied.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/core/geometry/features.hpp"
#include "gizmo/core/geometry/trajectory.hpp"

namespace gizmo::verify::detail {

enum class LayoutKind : std::uint8_t { Ball, FixedShape, Absorber, Flipper, Spinner };

struct LayoutGizmo {
  GizmoId id = kNoGizmo;
  LayoutKind kind = LayoutKind::FixedShape;
  std::string name;
  Shape<double> shape;           // fixed shapes and absorbers (a flipper's comes with each state)
  Box<double> bounds;            // everything the gizmo can ever touch (a flipper: its 2 × 2 box)
  std::array<double, 4> rect{};  // absorbers: x, y, width, height
  // Flippers: the pivot centre, the quarter turns of the rest and end positions, and the sense
  // of the forward swing (+1: θ grows), as flipperLayout gives them. Spinners: the centre.
  Vec2<double> pivot;
  int restQuarter = 0, endQuarter = 0, forwardSign = 1;
};

struct BoardLayout {
  MotionModel model = MotionModel::Ballistic;
  double ballRadius = 0.25;
  std::vector<LayoutGizmo> gizmos;  // by id
  std::vector<GizmoId> balls;
  // collider[ballIndex][gizmo]: the gizmo that handles the pair (formPair), or kNoGizmo when the
  // board never forms the pair.
  std::vector<std::vector<GizmoId>> collider;
  std::vector<std::int32_t> ballIndex;  // by gizmo id, −1 for non-balls
  // 1 L cells → the fixed gizmos (not the walls, not balls) whose bounds reach into them.
  static constexpr int kCells = 20;
  std::vector<std::vector<GizmoId>> cells;
};

struct BallSnapshot {
  GizmoId id = kNoGizmo;
  bool captured = false;
  // The anchored path p(t) = p + v (t − t0) + ½ a (t − t0)².
  double t0 = 0;
  Vec2<double> p, v, a;
  // Sliding contact: the surface and its segment (exact end points), and the features of that
  // gizmo the core does not look at while the ball slides (the segment and the circles capping it).
  GizmoId contactGizmo = kNoGizmo;
  Vec2<double> contactA, contactB;
  std::vector<std::int32_t> skippedFeatures;
};

struct FlipperSnapshot {
  GizmoId id = kNoGizmo;
  bool swinging = false;
  Shape<double> still;  // when not swinging: the capsule where it stands
  // When swinging: the axis points at the exact quarter turn `quarter` (the rest position, or
  // the end one when the swing starts back from there) turned by
  // forwardSign·6π·offset + turn·6π·(t − t0), the run's doubles t0 and offset (the progress
  // beyond that quarter) taken as exact; turn = forwardSign·direction, the sense it turns in.
  int quarter = 0;
  double offset = 0, t0 = 0;
  int turn = 0;
};

struct SpinnerSnapshot {
  GizmoId id = kNoGizmo;
  bool turning = false;
  Shape<double> still;  // when still: the cross where it stands
  // When turning: arm k points at the exact quarter turn quarter + k turned by
  // phase + kSpinnerTurnRate·(t − t0), the run's doubles phase and t0 taken as exact.
  int quarter = 0;
  double phase = 0, t0 = 0;
};

struct AbsorberSnapshot {
  GizmoId id = kNoGizmo;
  std::vector<GizmoId> firedInside;  // balls it fired that have not left yet (they leave, not collide)
};

struct BoardSnapshot {
  double now = 0;
  std::vector<BallSnapshot> balls;  // in the order of BoardLayout::balls
  std::vector<FlipperSnapshot> flippers;
  std::vector<SpinnerSnapshot> spinners;
  std::vector<AbsorberSnapshot> absorbers;
};

// The decision to check: the event the run executed, and the earliest event left in the queue
// whose time is fixed by the schedule rather than found as a root (end of tick, recalculation,
// friction tick, input, flipper stop).
struct DecisionInput {
  std::uint64_t eventIndex = 0;
  Event<double> executed;
  bool hasNextScheduled = false;
  Event<double> nextScheduled;
};

// An event as the tie order sees it (runsBefore: kind, then ids, then feature).
struct EventKey {
  EventKind kind = EventKind::EndOfTick;
  GizmoId a = kNoGizmo, b = kNoGizmo;
  std::int32_t feature = -1;
};
inline EventKey keyOf(const Event<double>& e) { return EventKey{e.kind, e.a, e.b, e.feature}; }
inline bool sameEvent(const EventKey& x, const EventKey& y) {
  return x.kind == y.kind && x.a == y.a && x.b == y.b && x.feature == y.feature;
}
// Whether x runs before y when both happen at the same instant.
inline bool tieOrderBefore(const EventKey& x, const EventKey& y) {
  if (x.kind != y.kind) return x.kind < y.kind;
  if (x.a != y.a) return x.a < y.a;
  if (x.b != y.b) return x.b < y.b;
  return x.feature < y.feature;
}

// An event that a rung could not separate from the executed one, kept for the exact step
// (certify_exact.hpp). Times are s = t − now, rounded outwards to doubles.
struct Overlap {
  EventKey key;
  bool scheduled = false;  // the next scheduled event (its time is exact: DecisionInput::nextScheduled)
  bool entry = false;      // a proven entry in [lo, hi]; otherwise it may lie anywhere in [lo, hi]
  bool polynomial = true;  // its gap is a polynomial (not a swinging flipper's or turning spinner's side or tip)
  double lo = 0, hi = 0;
};

// What one rung of the ladder concluded about a decision. Tie: proven exactly (the exact step).
enum class Verdict : std::uint8_t { Certified, Wrong, Undecided, Tie };
struct RungOutcome {
  Verdict verdict = Verdict::Undecided;
  EventKey other;  // Wrong: the event that should have come first; Undecided: the rival
  bool otherIsScheduled = false;
  double byLo = 0, byHi = 0;  // Wrong: it came first by at least byLo and at most byHi seconds
  double window = 0;          // Undecided: both may lie in one window this wide (seconds); inf if unknown
  std::string explanation;
  // Undecided: the executed event's own enclosure (s, outwards; a root event's entry, or the
  // scheduled time) and every event overlapping it.
  double ownLo = 0, ownHi = 0;
  bool ownPolynomial = true;
  std::vector<Overlap> overlaps;
  // Tie: the events that happen at exactly the executed event's time.
  std::vector<EventKey> tiedWith;
};

inline bool isRootKind(EventKind k) {
  return k == EventKind::Collision || k == EventKind::Leave || k == EventKind::ContactEnd;
}

}  // namespace gizmo::verify::detail
