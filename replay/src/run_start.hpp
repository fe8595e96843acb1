#pragma once
// Where a log's run starts, for every use that runs it again (seeking.cpp, replaying.cpp,
// branching.cpp): the board at a chunk's keyframe, restored and checked, and the start of the
// whole run, which is the board as built for an ordinary log and its first chunk's keyframe for a
// branch log. Private to gizmo::replay.
#include <memory>
#include <stdexcept>
#include <string>

#include "log_views.hpp"

namespace gizmo::replay::detail {

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

// How far the log's run had got where its records begin: 0 for an ordinary log; for a branch
// log, its first chunk's preamble.
struct RunStart {
  std::uint64_t ticksDone = 0;
  std::uint64_t eventsDone = 0;
  std::uint64_t decisionsDone = 0;
};

inline RunStart runStartOf(const OpenedLog& log) {
  if (!log.reader.isBranch()) return {};
  if (log.reader.chunks().empty())
    throw FormatError("the branch log holds no complete chunk, so not the state it starts from", 0);
  ChunkPreamble p;
  readPreamble(log.reader.chunkPayload(0), p);
  return RunStart{p.ticksDone, p.eventsDone, p.decisionsDone};
}

// The board the log's run starts from: as built, its keys scheduled, or a branch log's first
// keyframe restored onto it.
template <class Real>
std::unique_ptr<GameBoard<Real>> startBoard(const OpenedLog& log) {
  if (!log.reader.isBranch()) return prepareRun<Real>(log.request);
  std::uint64_t ticksDone = 0;
  return boardAtChunk<Real>(log, 0, &ticksDone);
}

// Seeking (replay.hpp: seekLog), in two steps so that a caller can watch the run between them:
// the board at the keyframe of the last chunk before the target, then the run on to the target.
template <class Real>
struct SeekStart {
  std::unique_ptr<GameBoard<Real>> board;
  std::size_t chunk = 0;
  std::uint64_t ticksDone = 0;
};

template <class Real>
SeekStart<Real> seekStart(const OpenedLog& log, const SeekTarget& target) {
  const std::vector<ChunkEntry>& chunks = log.reader.chunks();
  if (chunks.empty()) throw FormatError("the log holds no chunk", 0);
  SeekStart<Real> s;
  while (s.chunk + 1 < chunks.size() &&
         (target.events ? chunks[s.chunk + 1].eventsDone <= *target.events : chunks[s.chunk + 1].time <= *target.time))
    ++s.chunk;
  s.board = boardAtChunk<Real>(log, s.chunk, &s.ticksDone);
  if (target.time && fromDouble<Real>(*target.time) < s.board->now() && s.chunk > 0)
    s.board = boardAtChunk<Real>(log, --s.chunk, &s.ticksDone);
  // A branch log holds nothing before its first keyframe.
  const bool before =
      target.events ? *target.events < chunks[0].eventsDone : fromDouble<Real>(*target.time) < s.board->now();
  if (log.reader.isBranch() && s.chunk == 0 && before)
    throw std::out_of_range("the branch log starts at event " + std::to_string(chunks[0].eventsDone) + ", time " +
                            std::to_string(toDouble(s.board->now())) + " s: it holds nothing before");
  return s;
}

template <class Real>
void runToTarget(SeekStart<Real>& s, const OpenedLog& log, const SeekTarget& target) {
  typename GameBoard<Real>::RunLimit limit;
  if (target.events) limit.events = *target.events;
  if (target.time) limit.time = fromDouble<Real>(*target.time);
  s.board->setRunLimit(limit);
  continueRun(*s.board, log.request, std::int64_t(s.ticksDone));
  if (target.events && s.board->executedTotal() != *target.events)
    throw std::out_of_range("the run has " + std::to_string(s.board->executedTotal()) + " events, fewer than " +
                            std::to_string(*target.events));
}

}  // namespace gizmo::replay::detail
