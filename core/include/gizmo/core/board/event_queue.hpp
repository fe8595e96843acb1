#pragma once
// The seed's event queue: a binary heap that is kept between ticks, with removal of every event
// that involves a gizmo. Removal marks the event dead in O(1); dead events are dropped when they
// reach the top. Handles carry a serial number so a recycled slot is never mistaken for the
// event that once lived there.
//
// The heap holds each event's time and its first tie-breakers (kind, then a) beside its slot:
// sifting compares neighbouring heap entries without visiting the slots, which on a board with
// many events lie far apart in memory. Only events alike in all three are compared in full.
//
// Beside a large heap, friction ticks go to a lane of their own (instant_lane.hpp); a pop takes
// the earlier of the heap's top and the lane's front.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/board/instant_lane.hpp"

namespace gizmo {

template <class Real>
class EventQueue {
 public:
  // Adds an event; returns its sequence number.
  std::uint64_t push(Event<Real> e) {
    e.sequence = nextSequence_++;
    std::uint32_t slot;
    if (!freeSlots_.empty()) {
      slot = freeSlots_.back();
      freeSlots_.pop_back();
    } else {
      slot = static_cast<std::uint32_t>(events_.size());
      events_.emplace_back();
      states_.emplace_back();
    }
    const Event<Real>& stored = events_[slot] = std::move(e);
    SlotState& s = states_[slot];
    s.alive = true;
    ++s.serial;
    ++aliveCount_;
    // An input names no gizmo (its b is the key's direction, 0 or 1): tracked as one, it was
    // removed whenever the board recomputed gizmo 1, and a key release scheduled for later in
    // the tick was lost (campaign seed 141421356, case 3610: an absorber, gizmo 1, whose fired
    // ball left it just before the release).
    if (stored.kind != EventKind::Input) {
      track(stored.a, slot, s.serial);
      if (stored.b != stored.a) track(stored.b, slot, s.serial);
    }
    // A heap of a few events is cheaper than the lane's bookkeeping of instants, so ticks start
    // a lane only beside a large heap, and join one that has started.
    const bool laneWorthIt = !lane_.empty() || heap_.size() >= kLaneFrom;
    s.inLane = stored.kind == EventKind::FrictionTick && laneWorthIt && lane_.add(stored.time, stored.a, slot);
    if (!s.inLane) {
      heap_.push_back(HeapEntry{stored.time, orderKey(stored.kind, stored.a), slot});
      siftUp(heap_.size() - 1);
    }
    return stored.sequence;
  }

  bool empty() const { return aliveCount_ == 0; }
  std::size_t size() const { return aliveCount_; }

  // The earliest live event; the queue must not be empty.
  const Event<Real>& top() {
    dropDeadTop();
    return events_[laneFirst() ? lane_.front().slot : heap_.front().slot];
  }

  // pop, removeTop and siftUp are inlined by force: with the lane's branch in it, GCC 12 at -O3
  // calls all three out of line, and a one-ball board then ran 6% more instructions per event
  // (callgrind), though the heap it uses is unchanged.
  [[gnu::always_inline]] Event<Real> pop() {
    dropDeadTop();
    std::uint32_t slot;
    if (laneFirst()) {
      slot = lane_.front().slot;
      lane_.popFront();
    } else {
      slot = heap_.front().slot;
      removeTop();
    }
    Event<Real> e = std::move(events_[slot]);
    states_[slot].alive = false;
    --aliveCount_;
    freeSlots_.push_back(slot);
    return e;
  }

  // Removes every live event that involves gizmo g, calling onRemoved(event) for each, in the
  // order they were scheduled.
  template <class F>
  void removeInvolving(GizmoId g, F&& onRemoved) {
    if (g < 0 || static_cast<std::size_t>(g) >= byGizmo_.size()) return;
    std::vector<Handle>& list = byGizmo_[static_cast<std::size_t>(g)];
    for (const Handle& h : list) {
      if (!holds(h)) continue;
      SlotState& s = states_[h.slot];
      const Event<Real>& e = events_[h.slot];
      s.alive = false;
      --aliveCount_;
      if (s.inLane) {
        lane_.remove(e.time, e.a);
        freeSlots_.push_back(h.slot);
      } else {
        ++deadInHeap_;
      }
      onRemoved(e);
    }
    list.clear();
    // Dead events wait in the heap until they reach the top; when they outnumber the live ones,
    // sweep them out so the heap stays about as small as its share of the queue.
    if (deadInHeap_ > aliveCount_ - lane_.size() + 64) compact();
  }

  // Every live event, earliest first (for inspection and tests; O(n log n)).
  std::vector<Event<Real>> snapshot() const {
    std::vector<Event<Real>> out;
    for (std::size_t i = 0; i < events_.size(); ++i)
      if (states_[i].alive) out.push_back(events_[i]);
    std::sort(out.begin(), out.end(), [](const Event<Real>& x, const Event<Real>& y) { return runsBefore(x, y); });
    return out;
  }

  // Every live event in scheduling order, and the sequence number the next one will get: all
  // that decides what the queue does from here on (its heap layout does not).
  std::vector<Event<Real>> liveInSequenceOrder() const {
    std::vector<Event<Real>> out;
    for (std::size_t i = 0; i < events_.size(); ++i)
      if (states_[i].alive) out.push_back(events_[i]);
    std::sort(out.begin(), out.end(),
              [](const Event<Real>& x, const Event<Real>& y) { return x.sequence < y.sequence; });
    return out;
  }
  std::uint64_t nextSequence() const { return nextSequence_; }

  // Refills the queue with events saved by liveInSequenceOrder, keeping their sequence numbers.
  void restore(const std::vector<Event<Real>>& events, std::uint64_t nextSequence) {
    clear();
    for (const Event<Real>& e : events) {
      nextSequence_ = e.sequence;
      push(e);
    }
    nextSequence_ = nextSequence;
  }

  void clear() {
    events_.clear();
    states_.clear();
    heap_.clear();
    freeSlots_.clear();
    byGizmo_.clear();
    lane_.clear();
    aliveCount_ = 0;
    deadInHeap_ = 0;
  }

 private:
  // A slot's event, and apart from it whether it is alive: removal and the checks of handles
  // read only the small states, which stay in cache on a board with thousands of events.
  struct SlotState {
    std::uint32_t serial = 0;
    bool alive = false;
    bool inLane = false;  // queued in lane_ rather than heap_
  };
  struct Handle {
    std::uint32_t slot;
    std::uint32_t serial;
  };
  // Whether the handle's event is still queued: its slot alive and not recycled since.
  bool holds(const Handle& h) const {
    const SlotState& s = states_[h.slot];
    return s.serial == h.serial && s.alive;
  }

  void track(GizmoId g, std::uint32_t slot, std::uint32_t serial) {
    if (g < 0) return;
    const std::size_t i = static_cast<std::size_t>(g);
    if (i >= byGizmo_.size()) byGizmo_.resize(i + 1);
    std::vector<Handle>& list = byGizmo_[i];
    // Keep the per-gizmo list short: drop handles of events that are gone.
    if (list.size() >= 16 && list.size() % 16 == 0) {
      std::erase_if(list, [&](const Handle& h) { return !holds(h); });
    }
    list.push_back(Handle{slot, serial});
  }

  struct HeapEntry {
    Real time;
    std::uint64_t order;  // orderKey of the event
    std::uint32_t slot;
  };
  // The heap size from which friction ticks start a lane: a pop from it descends three levels.
  static constexpr std::size_t kLaneFrom = 32;

  // runsBefore's kind, then a, in one number (a >= -1).
  static std::uint64_t orderKey(EventKind kind, GizmoId a) { return std::uint64_t(kind) << 32 | std::uint32_t(a + 1); }
  // runsBefore, with the full comparison only for events alike in time, kind and a. The common
  // outcomes are computed without branches: which of two entries comes first is a coin toss
  // that a branch predictor loses half the time, at every level of every sift.
  bool before(const HeapEntry& x, const HeapEntry& y) const {
    return before(x.time, x.order, x.slot, y.time, y.order, y.slot);
  }
  bool before(const Real& xTime, std::uint64_t xOrder, std::uint32_t xSlot, const Real& yTime, std::uint64_t yOrder,
              std::uint32_t ySlot) const {
    const bool earlier = xTime < yTime, later = yTime < xTime;
    const bool tie = !(earlier | later);
    if (tie & (xOrder == yOrder)) [[unlikely]]
      return runsBefore(events_[xSlot], events_[ySlot]);
    return earlier | (tie & (xOrder < yOrder));
  }

  // Whether the earliest live event is the lane's front rather than the heap's top (whose dead
  // entries are dropped first).
  bool laneFirst() const {
    if (lane_.empty()) return false;
    if (heap_.empty()) return true;
    const typename InstantLane<Real>::Front lane = lane_.front();
    const HeapEntry& top = heap_.front();
    return before(lane.time, orderKey(EventKind::FrictionTick, lane.id), lane.slot, top.time, top.order, top.slot);
  }

  // A 4-ary heap: half the levels of a binary one, and a node's children share cache lines, so a
  // pop visits fewer distant entries. Both sifts carry the entry in hand and move others past it.
  static constexpr std::size_t kArity = 4;
  static_assert(kArity == 4, "earliestChild's tournament is written for four children");
  static std::size_t parentOf(std::size_t i) { return (i - 1) / kArity; }
  [[gnu::always_inline]] void siftUp(std::size_t i) {
    HeapEntry x = std::move(heap_[i]);
    while (i > 0) {
      const std::size_t parent = parentOf(i);
      if (!before(x, heap_[parent])) break;
      heap_[i] = std::move(heap_[parent]);
      i = parent;
    }
    heap_[i] = std::move(x);
  }
  // The earliest of the children that begin at `first`. Four are compared as a tournament whose
  // winners are picked by arithmetic, not branches: which child is earliest is as unpredictable
  // as the comparisons in before(), and a branch per child cost four mispredictions a pop on a
  // board of 100 balls (callgrind's branch simulation).
  std::size_t earliestChild(std::size_t first, std::size_t n) const {
    if (first + kArity <= n) [[likely]] {
      const std::size_t left = first + std::size_t(before(heap_[first + 1], heap_[first]));
      const std::size_t right = first + 2 + std::size_t(before(heap_[first + 3], heap_[first + 2]));
      return left + (right - left) * std::size_t(before(heap_[right], heap_[left]));
    }
    std::size_t child = first;
    for (std::size_t c = first + 1; c < n; ++c) child = before(heap_[c], heap_[child]) ? c : child;
    return child;
  }
  void siftDown(std::size_t i) {
    const std::size_t n = heap_.size();
    HeapEntry x = std::move(heap_[i]);
    for (;;) {
      const std::size_t first = kArity * i + 1;
      if (first >= n) break;
      const std::size_t child = earliestChild(first, n);
      if (!before(heap_[child], x)) break;
      heap_[i] = std::move(heap_[child]);
      i = child;
    }
    heap_[i] = std::move(x);
  }
  // Bottom-up: the hole at the root follows the earliest children down to a leaf, and only then
  // does the last entry fill it and sift up. The last entry is a leaf's, nearly always later
  // than everything on the path, so comparing it at every level on the way down (a plain
  // siftDown) costs a quarter more comparisons and an exit branch that mispredicts.
  [[gnu::always_inline]] void removeTop() {
    HeapEntry last = std::move(heap_.back());
    heap_.pop_back();
    const std::size_t n = heap_.size();
    if (n == 0) return;
    std::size_t hole = 0;
    for (std::size_t first = 1; first < n; first = kArity * hole + 1) {
      const std::size_t child = earliestChild(first, n);
      heap_[hole] = std::move(heap_[child]);
      hole = child;
    }
    heap_[hole] = std::move(last);
    siftUp(hole);
  }
  void dropDeadTop() {
    while (!heap_.empty() && !states_[heap_.front().slot].alive) dropTop();
  }
  // Out of line: a dead top is rare, and inlined into every pop it would push the pop itself
  // out of line.
  [[gnu::noinline]] void dropTop() {
    freeSlots_.push_back(heap_.front().slot);
    removeTop();
    --deadInHeap_;
  }
  void compact() {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < heap_.size(); ++i) {
      if (!states_[heap_[i].slot].alive) {
        freeSlots_.push_back(heap_[i].slot);
        continue;
      }
      if (i != kept) heap_[kept] = std::move(heap_[i]);
      ++kept;
    }
    heap_.erase(heap_.begin() + std::ptrdiff_t(kept), heap_.end());
    if (kept > 1)  // every entry with children, from the last one's parent up to the root
      for (std::size_t i = parentOf(kept - 1) + 1; i-- > 0;) siftDown(i);
    deadInHeap_ = 0;
  }

  std::vector<Event<Real>> events_;  // by slot
  std::vector<SlotState> states_;    // by slot
  std::vector<HeapEntry> heap_;
  std::vector<std::uint32_t> freeSlots_;
  std::vector<std::vector<Handle>> byGizmo_;
  InstantLane<Real> lane_;
  std::size_t aliveCount_ = 0;
  std::size_t deadInHeap_ = 0;
  std::uint64_t nextSequence_ = 0;
};

}  // namespace gizmo
