#pragma once
// The seed's event queue: a binary heap that is kept between ticks, with removal of every event
// that involves a gizmo. Removal marks the event dead in O(1); dead events are dropped when they
// reach the top. Handles carry a serial number so a recycled slot is never mistaken for the
// event that once lived there.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "gizmo/core/board/event.hpp"

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
      slot = static_cast<std::uint32_t>(slots_.size());
      slots_.emplace_back();
    }
    Slot& s = slots_[slot];
    s.event = std::move(e);
    s.alive = true;
    ++s.serial;
    ++aliveCount_;
    track(s.event.a, slot, s.serial);
    if (s.event.b != s.event.a) track(s.event.b, slot, s.serial);
    heap_.push_back(slot);
    siftUp(heap_.size() - 1);
    return s.event.sequence;
  }

  bool empty() const { return aliveCount_ == 0; }
  std::size_t size() const { return aliveCount_; }

  // The earliest live event; the queue must not be empty.
  const Event<Real>& top() {
    dropDeadTop();
    return slots_[heap_.front()].event;
  }

  Event<Real> pop() {
    dropDeadTop();
    const std::uint32_t slot = heap_.front();
    Event<Real> e = std::move(slots_[slot].event);
    slots_[slot].alive = false;
    --aliveCount_;
    removeTop();
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
      Slot& s = slots_[h.slot];
      if (s.serial != h.serial || !s.alive) continue;
      s.alive = false;
      --aliveCount_;
      ++deadInHeap_;
      onRemoved(s.event);
    }
    list.clear();
    // Dead events wait in the heap until they reach the top; when they outnumber the live ones,
    // sweep them out so the heap stays about as small as the queue.
    if (deadInHeap_ > aliveCount_ + 64) compact();
  }

  // Every live event, earliest first (for inspection and tests; O(n log n)).
  std::vector<Event<Real>> snapshot() const {
    std::vector<Event<Real>> out;
    for (const Slot& s : slots_)
      if (s.alive) out.push_back(s.event);
    std::sort(out.begin(), out.end(), [](const Event<Real>& x, const Event<Real>& y) { return runsBefore(x, y); });
    return out;
  }

  // Every live event in scheduling order, and the sequence number the next one will get: all
  // that decides what the queue does from here on (its heap layout does not).
  std::vector<Event<Real>> liveInSequenceOrder() const {
    std::vector<Event<Real>> out;
    for (const Slot& s : slots_)
      if (s.alive) out.push_back(s.event);
    std::sort(out.begin(), out.end(), [](const Event<Real>& x, const Event<Real>& y) { return x.sequence < y.sequence; });
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
    slots_.clear();
    heap_.clear();
    freeSlots_.clear();
    byGizmo_.clear();
    aliveCount_ = 0;
    deadInHeap_ = 0;
  }

 private:
  struct Slot {
    Event<Real> event;
    std::uint32_t serial = 0;
    bool alive = false;
  };
  struct Handle {
    std::uint32_t slot;
    std::uint32_t serial;
  };

  void track(GizmoId g, std::uint32_t slot, std::uint32_t serial) {
    if (g < 0) return;
    const std::size_t i = static_cast<std::size_t>(g);
    if (i >= byGizmo_.size()) byGizmo_.resize(i + 1);
    std::vector<Handle>& list = byGizmo_[i];
    // Keep the per-gizmo list short: drop handles of events that are gone.
    if (list.size() >= 16 && list.size() % 16 == 0) {
      std::erase_if(list, [&](const Handle& h) { return slots_[h.slot].serial != h.serial || !slots_[h.slot].alive; });
    }
    list.push_back(Handle{slot, serial});
  }

  bool before(std::uint32_t x, std::uint32_t y) const { return runsBefore(slots_[x].event, slots_[y].event); }

  void siftUp(std::size_t i) {
    while (i > 0) {
      const std::size_t parent = (i - 1) / 2;
      if (!before(heap_[i], heap_[parent])) break;
      std::swap(heap_[i], heap_[parent]);
      i = parent;
    }
  }
  void siftDown(std::size_t i) {
    const std::size_t n = heap_.size();
    for (;;) {
      std::size_t best = i;
      const std::size_t l = 2 * i + 1, r = l + 1;
      if (l < n && before(heap_[l], heap_[best])) best = l;
      if (r < n && before(heap_[r], heap_[best])) best = r;
      if (best == i) return;
      std::swap(heap_[i], heap_[best]);
      i = best;
    }
  }
  void removeTop() {
    heap_.front() = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) siftDown(0);
  }
  void dropDeadTop() {
    while (!slots_[heap_.front()].alive) {
      freeSlots_.push_back(heap_.front());
      removeTop();
      --deadInHeap_;
    }
  }
  void compact() {
    std::size_t kept = 0;
    for (std::uint32_t slot : heap_) {
      if (slots_[slot].alive) heap_[kept++] = slot;
      else freeSlots_.push_back(slot);
    }
    heap_.resize(kept);
    for (std::size_t i = kept / 2; i-- > 0;) siftDown(i);
    deadInHeap_ = 0;
  }

  std::vector<Slot> slots_;
  std::vector<std::uint32_t> heap_;
  std::vector<std::uint32_t> freeSlots_;
  std::vector<std::vector<Handle>> byGizmo_;
  std::size_t aliveCount_ = 0;
  std::size_t deadInHeap_ = 0;
  std::uint64_t nextSequence_ = 0;
};

}  // namespace gizmo
