#pragma once
// Where a run taken over at a moment of a log starts (docs/replay-format.md, "Branch logs"): the
// one piece of code behind `gizmo record --from` (recordBranch) and the game page's "play from
// here" and "rewind" (web/play_module.cpp), which records the branch live as it is played.
#include <cstdint>
#include <memory>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/replay/replay.hpp"

namespace gizmo::replay {

template <class Real>
struct BranchStart {
  // The branch's run: the parent's board, model and tick; its keys the parent's applied by the
  // branch point, then the request's from the point on; its duration the request's (or the
  // parent's).
  RunRequest run;
  // The parent's state at the last tick boundary at or before the point, restored onto a board
  // of `run` (its keys scheduled): the branch runs on from here, remaking the parent's decisions
  // up to the point and its own after it.
  std::unique_ptr<GameBoard<Real>> board;
  std::uint64_t ticksDone = 0;      // the ticks run by that boundary
  std::uint64_t decisionsDone = 0;  // the parent's decisions before it, as its log numbers them
  BranchOrigin origin;              // the parent's digest and the branch point's event index
  Exact time;                       // the branch point's board time
  std::size_t keysLeftOut = 0;      // keys of the request before the branch point
};

// Checks everything recordBranch checks and throws BranchError (or FormatError for a damaged
// parent) when the branch cannot be taken. The log's scalar must be Real.
template <class Real>
BranchStart<Real> startBranch(const OpenedLog& parent, const BranchRequest& request);

extern template BranchStart<double> startBranch<double>(const OpenedLog&, const BranchRequest&);

}  // namespace gizmo::replay
