#pragma once
// A run as data (docs/architecture.md, seam 4): a board, a motion model, a scalar, timed key
// input, and how long to simulate. The same function serves the command line, the tests and the
// benchmarks.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gizmo/core/board/build_board.hpp"

namespace gizmo {

struct TimedKey {
  double time = 0;
  int key = 0;
  KeyDirection direction = KeyDirection::Down;
};

struct RunRequest {
  BoardSpec board;
  MotionModel model = MotionModel::Ballistic;
  double maxTick = 0.05;
  double duration = 10.0;
  std::vector<TimedKey> keys;
};

struct BallState {
  std::string name;
  double x = 0, y = 0, vx = 0, vy = 0;
  bool captured = false;
};

struct RunSummary {
  double time = 0;
  std::array<std::uint64_t, kEventKindCount> executed{};
  std::uint64_t total = 0;
  double energy = 0;
  std::vector<BallState> balls;
};

template <class Real>
PhysicsParams<Real> paramsFor(const RunRequest& request) {
  PhysicsParams<Real> p;
  p.model = request.model;
  p.maxTick = fromDouble<Real>(request.maxTick);
  return p;
}

template <class Real>
RunSummary summarize(const GameBoard<Real>& board) {
  RunSummary s;
  s.time = toDouble(board.now());
  s.executed = board.executedCounts();
  s.total = board.executedTotal();
  s.energy = toDouble(board.energy());
  for (GizmoId id : board.ballIds()) {
    const Ball<Real>& b = *board.gizmo(id).asBall();
    const Vec2<Real> p = b.positionAt(board.now()), v = b.velocityAt(board.now());
    s.balls.push_back(BallState{b.name(), toDouble(p.x), toDouble(p.y), toDouble(v.x), toDouble(v.y), b.captured()});
  }
  return s;
}

// The board of a run at time 0, its keys scheduled, not yet ticked.
template <class Real>
std::unique_ptr<GameBoard<Real>> prepareRun(const RunRequest& request) {
  std::unique_ptr<GameBoard<Real>> board = buildBoard<Real>(request.board, paramsFor<Real>(request));
  for (const TimedKey& k : request.keys)
    if (k.time <= request.duration) board->scheduleInput(fromDouble<Real>(k.time), k.key, k.direction);
  return board;
}

// A run is one span of ticks from 0 to its duration. A run resumed from a state saved at the
// end of tick k carries on with tick k + 1 (the replay log's keyframes).
template <class Real>
void continueRun(GameBoard<Real>& board, const RunRequest& request, std::int64_t ticksDone) {
  board.tickSpan(Real(0), ticksDone + 1, fromDouble<Real>(request.duration));
}

// The same run cut at the end of the tick that holds time t: every decision up to that tick's end
// is the one the whole run makes, since ticks are counted from the start (k times the maximum
// tick) and only the last one is cut short. Tick k holds the events at its end, k·maxTick (the
// end-of-tick event runs last of its instant), and the first tick holds those at 0. A t at or
// past the end leaves the run whole.
inline RunRequest runThroughTickAt(const RunRequest& request, double t) {
  RunRequest cut = request;
  if (!(request.maxTick > 0) || !(t < request.duration)) return cut;
  double k =
      t > 0 ? std::floor(t / request.maxTick) : 0;  // then the first k with k·maxTick ≥ t, as tickSpan computes it
  while (k * request.maxTick < t) k += 1;
  while (k > 1 && !((k - 1) * request.maxTick < t)) k -= 1;
  if (k < 1) k = 1;
  if (k * request.maxTick < request.duration) cut.duration = k * request.maxTick;
  return cut;
}

// Builds the board, schedules the keys, simulates request.duration seconds and summarizes.
// The observer, if any, sees it all.
template <class Real>
RunSummary simulate(const RunRequest& request, BoardObserver<Real>* observer = nullptr) {
  std::unique_ptr<GameBoard<Real>> board = prepareRun<Real>(request);
  board->setObserver(observer);
  continueRun(*board, request, 0);
  return summarize(*board);
}

}  // namespace gizmo
