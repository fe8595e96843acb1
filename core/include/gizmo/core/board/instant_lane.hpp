#pragma once
// Beside the event queue's heap, a lane for the friction ticks. Every moving ball has one, on
// the global grid k·h, so at any moment they fall on one or two instants; at each instant they
// run in ball id order (runsBefore: same time, same kind, then a). The lane keeps one bit set of
// gizmo ids per instant, which gives the earliest tick at once, where a heap of a hundred balls'
// ticks costs three or four levels of comparisons per pop. On a board of 100 balls with friction,
// 100,000 of 110,206 events in 10 s are these ticks. (With one ball the heap holds a few events
// and is cheaper: the queue starts a lane only beside a large heap.)
//
// The lane holds at most one event per gizmo id; the queue keeps any other in its heap, so the
// lane never has to order two events of one instant and id.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

#include "gizmo/core/board/event.hpp"

namespace gizmo {

template <class Real>
class InstantLane {
 public:
  bool empty() const { return order_.empty(); }
  std::size_t size() const { return size_; }

  // Takes the event in `slot`, at `time`, of gizmo `id`; false (and nothing held) when the lane
  // holds one for that id already, or the id or time cannot be ordered by it.
  bool add(const Real& time, GizmoId id, std::uint32_t slot) {
    if (id < 0 || !(time == time)) return false;
    const std::size_t i = static_cast<std::size_t>(id);
    if (i >= slotOf_.size()) grow(i + 1);
    if (slotOf_[i] != kNoSlot) return false;
    slotOf_[i] = slot;
    ++size_;
    instants_[instantAt(time)].insert(i);
    return true;
  }

  // Drops the event of gizmo `id`, which the lane holds at `time`.
  void remove(const Real& time, GizmoId id) {
    std::size_t k = 0;
    while (!(instants_[order_[k]].time == time)) ++k;
    drop(k, static_cast<std::size_t>(id));
  }

  // The earliest event. The lane must not be empty.
  struct Front {
    const Real& time;
    GizmoId id;
    std::uint32_t slot;
  };
  Front front() const {
    const Instant& first = instants_[order_.front()];
    const std::size_t i = first.lowest();
    return Front{first.time, static_cast<GizmoId>(i), slotOf_[i]};
  }

  void popFront() { drop(0, instants_[order_.front()].lowest()); }

  void clear() {
    for (std::uint32_t k : order_) {
      std::fill(instants_[k].words.begin(), instants_[k].words.end(), 0);
      unused_.push_back(k);
    }
    order_.clear();
    std::fill(slotOf_.begin(), slotOf_.end(), kNoSlot);
    size_ = 0;
  }

 private:
  static constexpr std::uint32_t kNoSlot = std::numeric_limits<std::uint32_t>::max();

  // The ids with an event at one instant. `low` is the first non-zero word: ids mostly leave an
  // instant in ascending order, so keeping it costs next to nothing and the lowest id is at hand.
  struct Instant {
    Real time;
    std::vector<std::uint64_t> words;
    std::size_t low = 0;
    std::size_t count = 0;

    void insert(std::size_t i) {
      words[i / 64] |= std::uint64_t(1) << (i % 64);
      low = std::min(low, i / 64);
      ++count;
    }
    void erase(std::size_t i) {
      words[i / 64] &= ~(std::uint64_t(1) << (i % 64));
      --count;
      while (low < words.size() && words[low] == 0) ++low;
    }
    std::size_t lowest() const { return low * 64 + std::size_t(std::countr_zero(words[low])); }
  };

  // The instant at `time`, put in time order if the lane has none there yet. Ticks are nearly
  // always scheduled for the latest instant, so the search runs from the back. Instants are
  // kept for reuse, words and all, so a new one allocates nothing.
  std::uint32_t instantAt(const Real& time) {
    std::size_t k = order_.size();
    while (k > 0 && !(instants_[order_[k - 1]].time < time)) {
      if (instants_[order_[k - 1]].time == time) return order_[k - 1];
      --k;
    }
    std::uint32_t fresh;
    if (unused_.empty()) {
      fresh = static_cast<std::uint32_t>(instants_.size());
      instants_.emplace_back().words.assign(slotOf_.size() / 64 + 1, 0);
    } else {
      fresh = unused_.back();
      unused_.pop_back();
    }
    Instant& in = instants_[fresh];
    in.time = time;
    in.low = in.words.size();
    in.count = 0;
    order_.insert(order_.begin() + std::ptrdiff_t(k), fresh);
    return fresh;
  }

  // Drops id i from the k-th instant in time order, and the instant when it empties.
  void drop(std::size_t k, std::size_t i) {
    slotOf_[i] = kNoSlot;
    --size_;
    Instant& in = instants_[order_[k]];
    in.erase(i);
    if (in.count == 0) {
      unused_.push_back(order_[k]);
      order_.erase(order_.begin() + std::ptrdiff_t(k));
    }
  }

  void grow(std::size_t bound) {
    slotOf_.resize(std::max(bound, 2 * slotOf_.size()), kNoSlot);
    for (Instant& in : instants_) in.words.resize(slotOf_.size() / 64 + 1, 0);
  }

  std::vector<Instant> instants_;     // in use (listed in order_) or not (in unused_)
  std::vector<std::uint32_t> order_;  // the instants in use, in ascending time; none empty
  std::vector<std::uint32_t> unused_;
  std::vector<std::uint32_t> slotOf_;  // by gizmo id: the slot of its event in the lane
  std::size_t size_ = 0;
};

}  // namespace gizmo
