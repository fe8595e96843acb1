#pragma once
// The board's 1 L cells and which of them gizmos cover: for code that places gizmos one by one
// and must keep them apart (the fuzzer's generator, the tests' random boards). A gizmo covers
// every cell of its bounding box, so two gizmos overlap exactly when they share a cell.
#include <array>

#include "gizmo/core/board_spec.hpp"

namespace gizmo {

class CellOccupancy {
 public:
  // Whether every cell g covers is on the board and not yet taken.
  bool isFree(const GizmoSpec& g) const {
    if (g.x < 0 || g.y < 0 || g.width < 1 || g.height < 1 || g.x + g.width > kBoardSize || g.y + g.height > kBoardSize)
      return false;
    for (int y = g.y; y < g.y + g.height; ++y)
      for (int x = g.x; x < g.x + g.width; ++x)
        if (taken_[index(x, y)]) return false;
    return true;
  }

  // Takes g's cells when they are free; false, and nothing taken, when they are not.
  bool place(const GizmoSpec& g) {
    if (!isFree(g)) return false;
    for (int y = g.y; y < g.y + g.height; ++y)
      for (int x = g.x; x < g.x + g.width; ++x) taken_[index(x, y)] = true;
    return true;
  }

 private:
  static std::size_t index(int x, int y) { return std::size_t(y) * kBoardSize + std::size_t(x); }
  std::array<bool, kBoardSize * kBoardSize> taken_{};
};

}  // namespace gizmo
