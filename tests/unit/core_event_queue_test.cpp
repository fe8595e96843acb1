// The event queue against a plain model of it: whatever is pushed, removed and popped, and in
// whatever order, each pop is the earliest live event by runsBefore. Times come from a handful
// of values so that ties on time, kind and first gizmo are common, as at a friction instant of
// a board of many balls. Beside a heap of 32 entries or more, friction ticks take the queue's
// lane, so a second mix is mostly ticks, of ids across several words of the lane's bit sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "gizmo/core/board/event_queue.hpp"
#include "gizmo/core/board_spec.hpp"

namespace gizmo {
namespace {

// A number below n from the test's seeded generator; the modulo, unlike the standard
// distributions, gives the same sequence with every standard library.
std::uint32_t below(std::mt19937_64& rng, std::uint32_t n) { return static_cast<std::uint32_t>(rng() % n); }

Event<double> someEvent(std::mt19937_64& rng) {
  Event<double> e;
  e.time = 0.25 * double(below(rng, 6));
  e.kind = static_cast<EventKind>(below(rng, kEventKindCount));
  e.a = static_cast<GizmoId>(below(rng, 12)) - 1;
  e.b = static_cast<GizmoId>(below(rng, 12)) - 1;
  e.feature = static_cast<std::int32_t>(below(rng, 3)) - 1;
  return e;
}

// Mostly friction ticks of gizmos 0 … 199 at four instants, one gizmo with a second tick
// now and then (which the lane cannot hold), and other kinds among them.
Event<double> mostlyTick(std::mt19937_64& rng) {
  Event<double> e;
  e.time = 0.01 * double(1 + below(rng, 4));
  e.kind = below(rng, 8) == 0 ? EventKind::Collision : EventKind::FrictionTick;
  e.a = static_cast<GizmoId>(below(rng, 200));
  e.b = e.kind == EventKind::Collision ? static_cast<GizmoId>(below(rng, 200)) : kNoGizmo;
  return e;
}

// An input names no gizmo: its b is the key's direction (EventKind::Input).
bool involves(const Event<double>& e, GizmoId g) { return e.kind != EventKind::Input && (e.a == g || e.b == g); }

using MakeEvent = Event<double> (*)(std::mt19937_64&);

void checkAgainstModel(std::uint64_t seed, int steps, MakeEvent makeEvent, std::uint32_t gizmos) {
  SCOPED_TRACE(::testing::Message() << "seed " << seed);
  std::mt19937_64 rng(seed);
  EventQueue<double> queue;
  std::vector<Event<double>> live;  // the model: every live event, with its sequence number
  for (int step = 0; step < steps; ++step) {
    const std::uint32_t op = below(rng, 10);
    if (op < 5 || live.empty()) {
      Event<double> e = makeEvent(rng);
      e.sequence = queue.push(e);
      live.push_back(e);
    } else if (op < 8) {
      const auto earliest = std::min_element(live.begin(), live.end(), runsBefore<double>);
      const Event<double> popped = queue.pop();
      ASSERT_EQ(popped.sequence, earliest->sequence) << "at step " << step;
      live.erase(earliest);
    } else {
      const GizmoId g = static_cast<GizmoId>(below(rng, gizmos));
      std::vector<std::uint64_t> removed;
      queue.removeInvolving(g, [&](const Event<double>& e) { removed.push_back(e.sequence); });
      std::vector<std::uint64_t> expected;
      for (const Event<double>& e : live)
        if (involves(e, g)) expected.push_back(e.sequence);
      ASSERT_EQ(removed, expected) << "at step " << step;  // in scheduling order
      std::erase_if(live, [&](const Event<double>& e) { return involves(e, g); });
    }
    ASSERT_EQ(queue.size(), live.size());
  }
  while (!live.empty()) {
    const auto earliest = std::min_element(live.begin(), live.end(), runsBefore<double>);
    ASSERT_EQ(queue.pop().sequence, earliest->sequence);
    live.erase(earliest);
  }
  EXPECT_TRUE(queue.empty());
}

TEST(EventQueue, PopsTheEarliestLiveEventThroughPushesRemovalsAndPops) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) checkAgainstModel(seed, 3000, someEvent, 11);
}

TEST(EventQueue, KeepsTieOrderWithFrictionTicksOfManyGizmosAtSeveralInstants) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) checkAgainstModel(seed, 5000, mostlyTick, 200);
}

// A key release is an input whose b is 1 (KeyDirection::Up), a press one whose b is 0: removing
// the events of gizmo 1 or 0 (recomputing the board's first gizmo, or the outer walls) must not
// take them (campaign seed 141421356, case 3610: a release scheduled for later in the tick was
// lost when the absorber, gizmo 1, recomputed).
TEST(EventQueue, InputsAreNotAnyGizmosEvents) {
  EventQueue<double> queue;
  for (const KeyDirection direction : {KeyDirection::Down, KeyDirection::Up}) {
    Event<double> input;
    input.time = 0.5;
    input.kind = EventKind::Input;
    input.b = static_cast<GizmoId>(direction);
    input.feature = 32;
    queue.push(input);
  }
  Event<double> hit;
  hit.time = 0.25;
  hit.kind = EventKind::Collision;
  hit.a = 1;
  hit.b = 0;
  queue.push(hit);
  int removed = 0;
  for (const GizmoId g : {0, 1}) queue.removeInvolving(g, [&](const Event<double>&) { ++removed; });
  EXPECT_EQ(removed, 1);
  ASSERT_EQ(queue.size(), 2u);
  EXPECT_EQ(queue.pop().kind, EventKind::Input);
  EXPECT_EQ(queue.pop().kind, EventKind::Input);
}

TEST(EventQueue, ManyEventsAtOneInstantComeOutInTieOrder) {
  // A hundred friction ticks at one instant, pushed in a scrambled order, leave by ball id.
  EventQueue<double> queue;
  std::mt19937_64 rng(7);
  std::vector<GizmoId> ids(100);
  for (GizmoId i = 0; i < 100; ++i) ids[std::size_t(i)] = i;
  for (std::size_t i = ids.size(); i > 1; --i) std::swap(ids[i - 1], ids[below(rng, std::uint32_t(i))]);
  for (GizmoId id : ids) {
    Event<double> e;
    e.time = 0.01;
    e.kind = EventKind::FrictionTick;
    e.a = id;
    queue.push(e);
  }
  for (GizmoId expected = 0; expected < 100; ++expected) EXPECT_EQ(queue.pop().a, expected);
}

}  // namespace
}  // namespace gizmo
