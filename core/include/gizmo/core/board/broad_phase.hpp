#pragma once
// The broad phase: which gizmos and balls may be near a box. The board is cut into 1 L cells;
// each fixed gizmo is listed in the cells its bounds cover, each free ball in the cells its swept
// box covers (where it can be until its predictions run out), and a ball whose box spans more
// than kWideCells cells in a list of wide balls that every query looks at instead. A query visits
// a superset of what overlaps the box, with repeats: the caller checks the boxes and takes the
// candidates in id order, so where anything is listed never changes what is predicted, or in
// which order (docs/physics.md, "Broad phase").
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/trajectory.hpp"
#include "gizmo/core/math/scalar.hpp"

namespace gizmo {

namespace detail {
// Widening of a ball's swept box, in L: far above rounding, far below any gap that matters.
inline constexpr double kBroadPhaseMargin = 1e-6;
// Above this many cells a ball's box is wide: a ball crossing four cells each way in one
// prediction horizon. A fast ball's box can span the whole board (5000 L/s over a 0.05 s tick):
// listed in each of its cells, it would cost every other ball's query a look per cell.
inline constexpr int kWideCells = 16;
// How far a fast ball's path may reach over its prediction horizon, in L (GameBoard::sweepSpan).
inline constexpr double kSweepReach = 4.0;
// The grid cell holding coordinate v, clamped to the board. Compared before converting, so
// that truncation is the floor (v >= 0), and no value (huge, NaN) converts out of range:
// std::floor costs a library call on a target without SSE4.1, and this runs for every box.
inline int cellOf(double v) {
  if (!(v >= 0)) return 0;
  if (v >= double(kBoardSize - 1)) return kBoardSize - 1;
  return static_cast<int>(v);
}
}  // namespace detail

template <class Real>
class BroadPhase {
 public:
  struct CellRange {
    int x0, x1, y0, y1;  // inclusive; empty when x1 < x0
    bool operator==(const CellRange&) const = default;
  };
  static CellRange cellsOf(const Box<Real>& b) {
    return CellRange{detail::cellOf(toDouble(b.lo.x)), detail::cellOf(toDouble(b.hi.x)),
                     detail::cellOf(toDouble(b.lo.y)), detail::cellOf(toDouble(b.hi.y))};
  }

  // Forgets everything listed; the board has `gizmos` gizmos (ids 0 to gizmos − 1).
  void reset(std::size_t gizmos) {
    for (auto& cell : fixed_) cell.clear();
    for (auto& cell : balls_) cell.clear();
    wideBalls_.clear();
    ballCells_.assign(gizmos, kNowhere);
  }
  // One more gizmo, a ball spawned as the board ran: listed nowhere yet.
  void grow() { ballCells_.push_back(kNowhere); }

  void addFixed(GizmoId g, const Box<Real>& bounds) {
    forEachCell(
        cellsOf(bounds), [&](std::vector<GizmoId>& cell) { cell.push_back(g); }, fixed_);
  }

  // Moves a ball's entries to the cells `box` covers, or to the wide balls (to none when not
  // inGrid: a captured ball meets nothing).
  void placeBall(GizmoId id, const Box<Real>& box, bool inGrid) {
    CellRange& old = ballCells_[static_cast<std::size_t>(id)];
    const CellRange now = inGrid ? cellsOf(box) : kNowhere;
    // Most moves stay within the same cells (the order within a cell or among the wide balls
    // does not matter: the candidates taken from them are sorted by id).
    if (now == old) return;
    if (isWide(old)) std::erase(wideBalls_, id);
    else
      forEachCell(
          old, [&](std::vector<GizmoId>& cell) { std::erase(cell, id); }, balls_);
    old = now;
    if (isWide(old)) wideBalls_.push_back(id);
    else
      forEachCell(
          old, [&](std::vector<GizmoId>& cell) { cell.push_back(id); }, balls_);
  }

  // Every fixed gizmo listed in a cell the box covers (the walls are in none: they meet a box
  // that reaches an edge of the board).
  template <class Visit>
  void forEachFixedNear(const Box<Real>& box, Visit visit) const {
    visitCells(cellsOf(box), fixed_, visit);
  }
  // Every free ball listed in a cell the box covers, and every wide ball: a superset of the
  // balls whose boxes overlap it (boxes that overlap share a cell, since cellsOf is monotone).
  template <class Visit>
  void forEachBallNear(const Box<Real>& box, Visit visit) const {
    visitCells(cellsOf(box), balls_, visit);
    for (GizmoId id : wideBalls_) visit(id);
  }

 private:
  using Grid = std::array<std::vector<GizmoId>, kBoardSize * kBoardSize>;
  static constexpr CellRange kNowhere{0, -1, 0, -1};

  static bool isWide(const CellRange& c) { return (c.x1 - c.x0 + 1) * (c.y1 - c.y0 + 1) > detail::kWideCells; }
  template <class Change>
  static void forEachCell(const CellRange& c, Change change, Grid& grid) {
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x) change(grid[std::size_t(y * kBoardSize + x)]);
  }
  template <class Visit>
  static void visitCells(const CellRange& c, const Grid& grid, Visit& visit) {
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x)
        for (GizmoId id : grid[std::size_t(y * kBoardSize + x)]) visit(id);
  }

  Grid fixed_;  // 1 L cells → fixed gizmos that reach into them
  Grid balls_;  // 1 L cells → free balls whose boxes reach in
  std::vector<GizmoId> wideBalls_;
  std::vector<CellRange> ballCells_;  // per gizmo: the cells its box covers (in balls_, or wide)
};

}  // namespace gizmo
