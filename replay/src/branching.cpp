// A run taken over at a moment of a log (branch_start.hpp: startBranch, which the game page's play
// module shares), recorded as a branch log (replay.hpp: recordBranch).
//
// The board queues a tick's keys when the tick starts, so a run can only be resumed at a tick
// boundary. A branch therefore starts from the parent's state at the last tick boundary at or
// before the branch point, with the keys the parent had applied by the branch point followed by
// the branch's own: the branch makes the parent's decisions again up to the point, and its own
// after it.
#include <algorithm>

#include "gizmo/replay/branch_start.hpp"
#include "gizmo/replay/recorder.hpp"
#include "run_start.hpp"

namespace gizmo::replay {

using namespace detail;

namespace {

// Keeps the state of the parent's run at each tick boundary on the way to the branch point.
template <class Real>
class BoundaryWatch final : public BoardObserver<Real> {
 public:
  BoundaryWatch(const GameBoard<Real>& board, std::uint64_t ticksDone) : board_(board), ticks_(ticksDone) {}

  void tickBoundary(const Real&) override {
    ++ticks_;
    mark();
  }
  // Takes the board's state now as the latest boundary (the start of the watched run).
  void mark() {
    state = board_.saveState();
    ticksDone = ticks_;
  }

  std::optional<BoardState<Real>> state;  // at the latest tick boundary
  std::uint64_t ticksDone = 0;

 private:
  const GameBoard<Real>& board_;
  std::uint64_t ticks_;
};

// How many of the log's decisions come before its state at a tick boundary, as the log numbers
// them: those up to the boundary's tick record, or, at the board as built before the first tick,
// those its building made (they come before the first tick's end is scheduled).
std::uint64_t decisionsBefore(const OpenedLog& log, std::size_t chunk, std::uint64_t ticksDone, std::uint64_t events) {
  const std::vector<std::uint8_t> payload = log.reader.chunkPayload(chunk);
  ChunkPreamble start;
  readPreamble(payload, start);
  if (start.hasKeyframe && ticksDone == start.ticksDone) return start.decisionsDone;
  DecisionStream stream(log, log.reader.chunks()[chunk].time);
  while (const std::optional<DecisionView> d = stream.next()) {
    if (ticksDone == 0 && d->type == DecisionType::Scheduled && d->kind == EventKind::EndOfTick) return d->index;
    if (ticksDone > 0 && d->type == DecisionType::Tick && d->eventIndex == events) return d->index + 1;
  }
  throw FormatError("the log's decisions do not reach the tick boundary before the branch point", 0);
}

// The keys in the order the board queues them: by time, equal times in the order given, and none
// after the run's end (prepareRun).
template <class Real>
std::vector<TimedKey> queueOrder(const RunRequest& request) {
  std::vector<TimedKey> keys;
  for (const TimedKey& k : request.keys)
    if (k.time <= request.duration) keys.push_back(k);
  std::stable_sort(keys.begin(), keys.end(), [](const TimedKey& x, const TimedKey& y) {
    return fromDouble<Real>(x.time) < fromDouble<Real>(y.time);
  });
  return keys;
}

template <class Real>
bool sameInput(const TimedKey& k, const Event<Real>& e) {
  return e.kind == EventKind::Input && sameEncoding(fromDouble<Real>(k.time), e.time) && e.feature == k.key &&
         e.b == GizmoId(k.direction == KeyDirection::Up ? 1 : 0);
}

// The parent's keys applied by the branch point: those queued so far, less those still waiting.
template <class Real>
std::vector<TimedKey> appliedKeys(const RunRequest& parent, const BoardState<Real>& at) {
  const std::vector<TimedKey> order = queueOrder<Real>(parent);
  std::vector<TimedKey> applied(order.begin(), order.begin() + std::ptrdiff_t(at.nextInput));
  for (const Event<Real>& e : at.events) {
    const auto waiting =
        std::find_if(applied.begin(), applied.end(), [&](const TimedKey& k) { return sameInput(k, e); });
    if (waiting != applied.end()) applied.erase(waiting);
  }
  return applied;
}

// The request's keys from the branch point on: none before its time, and at its very time none
// that the parent had applied there already (one for one).
template <class Real>
std::vector<TimedKey> keysFrom(const std::vector<TimedKey>& keys, const Real& time, std::vector<TimedKey> applied) {
  std::vector<TimedKey> kept;
  for (const TimedKey& k : keys) {
    const Real t = fromDouble<Real>(k.time);
    if (t < time) continue;
    if (sameEncoding(t, time)) {
      const auto same = std::find_if(applied.begin(), applied.end(), [&](const TimedKey& a) {
        return sameEncoding(fromDouble<Real>(a.time), t) && a.key == k.key && a.direction == k.direction;
      });
      if (same != applied.end()) {
        applied.erase(same);
        continue;
      }
    }
    kept.push_back(k);
  }
  return kept;
}

std::string eventText(std::uint64_t n) { return "event " + std::to_string(n); }

template <class Real>
BranchResult branchAs(const OpenedLog& parent, const BranchRequest& request, ChunkSink& sink) {
  const BranchStart<Real> start = startBranch<Real>(parent, request);
  BranchResult result;
  result.origin = start.origin;
  result.time = start.time;
  result.startEvents = start.board->executedTotal();
  result.keysLeftOut = start.keysLeftOut;

  GameBoard<Real>& board = *start.board;
  sink.branchHeader(headerBytes(start.run, parent.precision, board, parent.header.boardWarnings, result.origin));
  Recorder<Real> recorder(sink, board, typename Recorder<Real>::Start{start.ticksDone, start.decisionsDone});
  board.setObserver(&recorder);
  try {
    continueRun(board, start.run, std::int64_t(start.ticksDone));
  } catch (const StallError& e) {
    result.record.completed = false;
    result.record.error = e.what();
  }
  recorder.finish(result.record.completed, result.record.error);
  result.record.summary = summarize(board);
  return result;
}

}  // namespace

template <class Real>
BranchStart<Real> startBranch(const OpenedLog& parent, const BranchRequest& request) {
  if (scalarName<Real>() != parent.header.scalar)
    throw BranchError("the log was made with " + parent.header.scalar + ", a branch here computes " +
                      scalarName<Real>());
  const std::optional<RunEnd>& end = parent.reader.end();
  if (!end) throw BranchError(parent.reader.truncation() + ": a branch is taken from a whole log");
  if (request.at.events && *request.at.events > end->events)
    throw BranchError(eventText(*request.at.events) + " is beyond the log's end: its run has " +
                      std::to_string(end->events) + " events");
  if (request.at.time && !(*request.at.time >= 0 && *request.at.time <= end->time))
    throw BranchError("time " + std::to_string(*request.at.time) + " is beyond the log's run, which ends at " +
                      std::to_string(end->time) + " s");

  // The parent's run on to the branch point, from the keyframe before it.
  SeekStart<Real> seek;
  try {
    seek = seekStart<Real>(parent, request.at);
  } catch (const std::out_of_range& e) {
    throw BranchError(e.what());
  }
  BoundaryWatch<Real> watch(*seek.board, seek.ticksDone);
  seek.board->setObserver(&watch);
  seek.board->tickSpan(Real(0), 1, Real(0));  // builds a board fresh from its spec, as its run would first
  watch.mark();
  runToTarget(seek, parent, request.at);
  seek.board->setObserver(nullptr);
  const BoardState<Real> atPoint = seek.board->saveState();
  const Real time = request.at.time ? fromDouble<Real>(*request.at.time) : atPoint.now;

  // The branch's run: the parent's keys applied by the point, then the request's from it on.
  RunRequest branch = parent.request;
  const std::vector<TimedKey> applied = appliedKeys(parent.request, atPoint);
  const std::vector<TimedKey> later = keysFrom(request.keys, time, applied);
  branch.keys = applied;
  branch.keys.insert(branch.keys.end(), later.begin(), later.end());
  branch.duration = request.duration.value_or(parent.request.duration);
  if (fromDouble<Real>(branch.duration) < atPoint.now)
    throw BranchError("the branch would end at " + std::to_string(branch.duration) + " s, before its branch point at " +
                      std::to_string(toDouble(atPoint.now)) + " s");

  const BoardState<Real>& boundary = *watch.state;
  auto startingBoard = [&branch, &boundary] {
    std::unique_ptr<GameBoard<Real>> board = prepareRun<Real>(branch);
    board->restoreState(boundary);
    return board;
  };
  // The branch's keys at the point's very time run in the instant's order, which may put one
  // before a decision of the parent's up to the point: then the branch is not taken.
  {
    std::unique_ptr<GameBoard<Real>> check = startingBoard();
    check->setRunLimit({atPoint.executedTotal, std::nullopt});
    continueRun(*check, branch, std::int64_t(watch.ticksDone));
    const BoardState<Real> reached = check->saveState();
    const bool appliedWaits = std::any_of(reached.events.begin(), reached.events.end(), [&](const Event<Real>& e) {
      return std::any_of(applied.begin(), applied.end(), [&](const TimedKey& k) { return sameInput(k, e); });
    });
    if (reached.executed != atPoint.executed || !sameEncoding(reached.now, atPoint.now) || appliedWaits)
      throw BranchError("a key at the branch point's own time (" + exactText(time) +
                        ") would run before the parent's decisions up to the branch point; give it a later time");
  }

  const std::uint64_t decisionsDone = decisionsBefore(parent, seek.chunk, watch.ticksDone, watch.state->executedTotal);
  BranchStart<Real> start;
  start.origin = BranchOrigin{parent.reader.fileDigest(), atPoint.executedTotal};
  start.time = exact(atPoint.now);
  start.keysLeftOut = request.keys.size() - later.size();
  start.ticksDone = watch.ticksDone;
  start.decisionsDone = decisionsDone;
  start.board = startingBoard();
  start.run = std::move(branch);
  return start;
}

template BranchStart<double> startBranch<double>(const OpenedLog&, const BranchRequest&);

BranchResult recordBranch(const OpenedLog& parent, const BranchRequest& request, ChunkSink& sink) {
  return withLogScalar(parent, [&]<class Real>() { return branchAs<Real>(parent, request, sink); });
}

}  // namespace gizmo::replay
