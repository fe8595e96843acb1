// The state of a log's run at an event or a time, from the nearest keyframe (replay.hpp: seekLog).
#include <stdexcept>

#include "log_views.hpp"

namespace gizmo::replay {
namespace {

using namespace detail;

template <class Real>
StateView stateOf(const GameBoard<Real>& board, const Real& at, const std::vector<std::string>& names) {
  StateView s;
  s.time = exact(at);
  s.events = board.executedTotal();
  for (GizmoId id : board.ballIds()) {
    const Ball<Real>& b = *board.gizmo(id).asBall();
    const Vec2<Real> p = b.positionAt(at), v = b.velocityAt(at);
    s.balls.push_back(BallView{id, gizmoName(names, id), exact(p.x), exact(p.y), exact(v.x), exact(v.y), {}, {}});
  }
  for (const Event<Real>& e : board.pendingEvents()) {
    std::string line = exactText(e.time) + " " + std::string(eventKindName(e.kind));
    if (e.a != kNoGizmo) line += " " + gizmoName(names, e.a);
    if (e.b != kNoGizmo && e.kind != EventKind::Input) line += " " + gizmoName(names, e.b);
    if (e.kind == EventKind::Collision) line += " feature " + std::to_string(e.feature);
    if (e.kind == EventKind::Input) line += (e.b ? " up " : " down ") + std::to_string(e.feature);
    s.queue.push_back(line);
  }
  return s;
}

// A board of the log's run at the start of chunk i, its keyframe restored and checked.
template <class Real>
std::unique_ptr<GameBoard<Real>> boardAtChunk(const OpenedLog& log, std::size_t i, std::uint64_t* ticksDone) {
  const std::vector<std::uint8_t> payload = log.reader.chunkPayload(i);
  const OpenedChunk<Real> opened = openChunk<Real>(payload);
  std::unique_ptr<GameBoard<Real>> board = prepareRun<Real>(log.request);
  if (opened.keyframe) {
    try {
      board->restoreState(*opened.keyframe);
    } catch (const StateError& e) {
      throw FormatError(std::string("chunk ") + std::to_string(i) + ": keyframe does not fit the board: " + e.what(),
                        log.reader.chunks()[i].offset);
    }
    if (stateHash(stateBytes(board->saveState())) != opened.keyframeHash)
      throw FormatError("chunk " + std::to_string(i) + ": the restored keyframe does not hash as recorded",
                        log.reader.chunks()[i].offset);
  }
  *ticksDone = opened.preamble.ticksDone;
  return board;
}

template <class Real>
StateView seekAs(const OpenedLog& log, const SeekTarget& target) {
  const std::vector<ChunkEntry>& chunks = log.reader.chunks();
  if (chunks.empty()) throw FormatError("the log holds no chunk", 0);
  std::size_t i = 0;
  while (i + 1 < chunks.size() &&
         (target.events ? chunks[i + 1].eventsDone <= *target.events : chunks[i + 1].time <= *target.time))
    ++i;
  std::uint64_t ticksDone = 0;
  std::unique_ptr<GameBoard<Real>> board = boardAtChunk<Real>(log, i, &ticksDone);
  if (target.time && fromDouble<Real>(*target.time) < board->now() && i > 0)
    board = boardAtChunk<Real>(log, --i, &ticksDone);
  typename GameBoard<Real>::RunLimit limit;
  if (target.events) limit.events = *target.events;
  if (target.time) limit.time = fromDouble<Real>(*target.time);
  board->setRunLimit(limit);
  continueRun(*board, log.request, std::int64_t(ticksDone));
  if (target.events && board->executedTotal() != *target.events)
    throw std::out_of_range("the run has " + std::to_string(board->executedTotal()) + " events, fewer than " +
                            std::to_string(*target.events));
  const Real at = target.time ? maxOf(fromDouble<Real>(*target.time), board->now()) : board->now();
  return stateOf(*board, at, log.gizmoNames);
}

}  // namespace

StateView seekLog(const OpenedLog& log, const SeekTarget& target) {
  return detail::withLogScalar(log, [&]<class Real>() { return seekAs<Real>(log, target); });
}

}  // namespace gizmo::replay
