#include "gizmo/verify/fuzz/run_shrinker.hpp"

#include <algorithm>
#include <cmath>

#include "gizmo/core/board_spec_check.hpp"

namespace gizmo::verify::fuzz {
namespace {

// The run without the elements [from, to) of the list that `member` picks out.
template <class T>
RunRequest without(const RunRequest& run, std::vector<T> RunRequest::*list, std::size_t from, std::size_t to) {
  RunRequest r = run;
  auto& v = r.*list;
  v.erase(v.begin() + std::ptrdiff_t(from), v.begin() + std::ptrdiff_t(to));
  return r;
}

// Connections and key connections that name a gizmo that is gone would make the board invalid.
void dropDanglingConnections(BoardSpec& b) {
  auto exists = [&](const std::string& name) {
    return name == kOuterWallsName ||
           std::any_of(b.gizmos.begin(), b.gizmos.end(), [&](const GizmoSpec& g) { return g.name == name; });
  };
  std::erase_if(b.connections, [&](const ConnectSpec& c) { return !exists(c.source) || !exists(c.target); });
  std::erase_if(b.keyConnections, [&](const KeyConnectSpec& k) { return !exists(k.target); });
}

RunRequest withoutGizmos(const RunRequest& run, std::size_t from, std::size_t to) {
  RunRequest r = run;
  r.board.gizmos.erase(r.board.gizmos.begin() + std::ptrdiff_t(from), r.board.gizmos.begin() + std::ptrdiff_t(to));
  dropDanglingConnections(r.board);
  return r;
}

RunRequest withoutBalls(const RunRequest& run, std::size_t from, std::size_t to) {
  RunRequest r = run;
  r.board.balls.erase(r.board.balls.begin() + std::ptrdiff_t(from), r.board.balls.begin() + std::ptrdiff_t(to));
  return r;
}

// Removing all, the first half, the second half, then each one: a list of n shrinks to one
// element in about log n accepted steps when only one element matters.
template <class Remove>
void removals(std::size_t n, std::size_t keep, Remove remove, std::vector<RunRequest>& out) {
  if (n <= keep) return;
  if (keep == 0) out.push_back(remove(0, n));
  if (n >= 4 || (keep == 0 && n >= 2)) {
    out.push_back(remove(0, n / 2));
    out.push_back(remove(n / 2, n));
  }
  for (std::size_t i = 0; i < n; ++i) out.push_back(remove(i, i + 1));
}

}  // namespace

std::vector<RunRequest> shrinkCandidates(const RunRequest& run) {
  std::vector<RunRequest> out;
  const BoardSpec& b = run.board;
  removals(
      run.keys.size(), 0, [&](std::size_t f, std::size_t t) { return without(run, &RunRequest::keys, f, t); }, out);
  removals(
      b.gizmos.size(), 0, [&](std::size_t f, std::size_t t) { return withoutGizmos(run, f, t); }, out);
  removals(
      b.balls.size(), 1, [&](std::size_t f, std::size_t t) { return withoutBalls(run, f, t); }, out);
  removals(
      b.connections.size(), 0,
      [&](std::size_t f, std::size_t t) {
        RunRequest r = run;
        r.board.connections.erase(r.board.connections.begin() + std::ptrdiff_t(f),
                                  r.board.connections.begin() + std::ptrdiff_t(t));
        return r;
      },
      out);
  removals(
      b.keyConnections.size(), 0,
      [&](std::size_t f, std::size_t t) {
        RunRequest r = run;
        r.board.keyConnections.erase(r.board.keyConnections.begin() + std::ptrdiff_t(f),
                                     r.board.keyConnections.begin() + std::ptrdiff_t(t));
        return r;
      },
      out);
  if (run.duration > 0.01) {
    RunRequest r = run;
    r.duration = run.duration / 2;
    std::erase_if(r.keys, [&](const TimedKey& k) { return k.time > r.duration; });
    out.push_back(r);
  }
  if (b.gravity != 0) {
    RunRequest r = run;
    r.board.gravity = 0;
    out.push_back(r);
  }
  if (b.mu != 0 || b.mu2 != 0) {
    RunRequest r = run;
    r.board.mu = r.board.mu2 = 0;
    out.push_back(r);
  }
  // Simpler numbers for each ball: at rest, then its coordinates on a quarter-L grid.
  for (std::size_t i = 0; i < b.balls.size(); ++i) {
    const BallSpec& ball = b.balls[i];
    if (ball.vx != 0 || ball.vy != 0) {
      RunRequest r = run;
      r.board.balls[i].vx = r.board.balls[i].vy = 0;
      out.push_back(r);
    }
    const double qx = std::round(ball.x * 4) / 4, qy = std::round(ball.y * 4) / 4;
    if (qx != ball.x || qy != ball.y) {
      RunRequest r = run;
      r.board.balls[i].x = qx, r.board.balls[i].y = qy;
      out.push_back(r);
    }
  }
  std::erase_if(out, [](const RunRequest& r) { return !checkBoardSpec(r.board).empty(); });
  return out;
}

Minimised minimise(const RunRequest& failing, const std::function<bool(const RunRequest&)>& fails, std::size_t budget) {
  Minimised m{failing, 0, 0};
  for (bool progress = true; progress && m.tries < budget;) {
    progress = false;
    for (RunRequest& candidate : shrinkCandidates(m.run)) {
      if (m.tries >= budget) break;
      ++m.tries;
      if (fails(candidate)) {
        m.run = std::move(candidate);
        ++m.steps;
        progress = true;
        break;
      }
    }
  }
  return m;
}

}  // namespace gizmo::verify::fuzz
