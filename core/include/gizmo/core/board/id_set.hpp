#pragma once
// A set of gizmo ids below a fixed bound that lists its members in ascending order. The broad
// phase gathers candidates from several grid cells, with repeats, and must visit them in id
// order for the schedule to be deterministic; one bit per id gives that order and drops the
// repeats without sorting, which on a crowded board cost more than the bits and mispredicted
// its comparisons.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "gizmo/core/board/event.hpp"

namespace gizmo {

class IdSet {
 public:
  // Empties the set and makes room for the ids 0 … bound − 1.
  void reset(std::size_t bound) {
    words_.assign((bound + 63) / 64, 0);
    first_ = words_.size();
    end_ = 0;
  }

  void insert(GizmoId id) {
    const std::size_t w = static_cast<std::size_t>(id) / 64;
    words_[w] |= std::uint64_t(1) << (static_cast<std::size_t>(id) % 64);
    first_ = std::min(first_, w);
    end_ = std::max(end_, w + 1);
  }

  // Appends the members to `out` in ascending order and empties the set. Only the words between
  // the lowest and highest member are visited.
  void drainInto(std::vector<GizmoId>& out) {
    for (std::size_t w = first_; w < end_; ++w) {
      std::uint64_t bits = words_[w];
      words_[w] = 0;
      while (bits != 0) {
        out.push_back(static_cast<GizmoId>(w * 64 + std::size_t(std::countr_zero(bits))));
        bits &= bits - 1;
      }
    }
    first_ = words_.size();
    end_ = 0;
  }

 private:
  std::vector<std::uint64_t> words_;
  std::size_t first_ = 0;  // the members lie in words_[first_, end_)
  std::size_t end_ = 0;
};

}  // namespace gizmo
