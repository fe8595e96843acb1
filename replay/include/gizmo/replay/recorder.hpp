#pragma once
// The observer that turns a run into chunks (docs/architecture.md, seam 2): every report of
// the board becomes a record and enters the chunk's digest; at the first tick boundary after a
// chunk is full, the board's state is saved as the next chunk's keyframe.
#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/replay/chunk.hpp"
#include "gizmo/replay/decision_digest.hpp"

namespace gizmo::replay {

// The chunks of a recording kept in memory, for a log written later from them, when the run's
// inputs and end are known (a game played live, `gizmo play`): its header first (recordHeader in
// replay.hpp), then sendTo, then the Recorder's finishCopy.
class KeptChunks final : public ChunkSink {
 public:
  void header(std::span<const std::uint8_t>) override {}
  void chunk(std::span<const std::uint8_t> payload, const ChunkEntry& entry) override {
    chunks_.push_back(Kept{{payload.begin(), payload.end()}, entry});
  }
  void finish(const RunEnd&) override {}
  void sendTo(ChunkSink& sink) const {
    for (const Kept& c : chunks_) sink.chunk(c.bytes, c.entry);
  }
  std::size_t size() const { return chunks_.size(); }

 private:
  struct Kept {
    std::vector<std::uint8_t> bytes;
    ChunkEntry entry;
  };
  std::vector<Kept> chunks_;
};

template <class Real>
class Recorder final : public BoardObserver<Real> {
 public:
  Recorder(ChunkSink& sink, const GameBoard<Real>& board)
      : sink_(sink), board_(board), encoder_(chunk_, board.params()) {
    begin(std::nullopt);
  }
  // A recording that starts from the board's state now, at a tick boundary (a branch log, or a
  // log's run recorded again from one of its keyframes): its first chunk has that state as its
  // keyframe, and counts ticks and decisions on from those done before it.
  struct Start {
    std::uint64_t ticksDone = 0;
    std::uint64_t decisionsDone = 0;
  };
  Recorder(ChunkSink& sink, const GameBoard<Real>& board, const Start& start)
      : sink_(sink),
        board_(board),
        encoder_(chunk_, board.params()),
        decisionsBefore_(start.decisionsDone),
        ticks_(start.ticksDone) {
    begin(board.saveState());
  }

  void eventScheduled(const Event<Real>& e) override {
    if (next_) beginNext();
    digest_.scheduled(e);
    encoder_.scheduled(e);
  }
  void eventRemoved(const Event<Real>& e) override {
    if (next_) beginNext();
    digest_.removed(e);
    encoder_.removed(e);
  }
  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>& o) override {
    if (next_) beginNext();
    digest_.executed(e, o);
    encoder_.executed(e, o);
  }
  void triggerFired(const Real& t, GizmoId s, GizmoId g) override {
    if (next_) beginNext();
    digest_.trigger(t, s, g);
    encoder_.trigger(t, s, g);
  }
  void actionPerformed(const Real& t, GizmoId g) override {
    if (next_) beginNext();
    digest_.action(t, g);
    encoder_.action(t, g);
  }
  void inputApplied(const Real& t, int key, KeyDirection d) override {
    if (next_) beginNext();
    digest_.input(t, key, d);
    encoder_.input(t, key, d);
  }
  void modelRuleApplied(const Real& t, ModelRule r, GizmoId g, GizmoId o) override {
    if (next_) beginNext();
    digest_.rule(t, r, g, o);
    encoder_.rule(t, r, g, o);
  }
  void tickBoundary(const Real& t) override {
    if (next_) beginNext();
    digest_.tick(t);
    encoder_.tick(t);
    ++ticks_;
    if (chunk_.size() >= limit_) {
      close();
      // The next chunk starts from the state now; it is begun once a record follows.
      next_ = board_.saveState();
    }
  }

  // Closes the last chunk and the log.
  void finish(bool completed, const std::string& message = {}) {
    if (!next_) close();
    sink_.finish(RunEnd{completed, board_.executedTotal(), toDouble(board_.now()), message});
  }

  // For a run that goes on after its log so far is written (a game played live, `gizmo play`):
  // sends `other` the chunk in progress and the end that finish() would send now, changing
  // nothing here. Only at a tick boundary, where the encoder holds nothing back (tick() writes
  // what it held before the tick's record), so the chunk's bytes are the ones close() would send.
  void finishCopy(ChunkSink& other) const {
    if (!next_) {
      ChunkEntry entry = entry_;
      entry.digest = digest_.value();
      other.chunk(chunk_.bytes(), entry);
    }
    other.finish(RunEnd{true, board_.executedTotal(), toDouble(board_.now()), {}});
  }

 private:
  void beginNext() { begin(std::exchange(next_, std::nullopt)); }

  void begin(std::optional<BoardState<Real>> state) {
    chunk_.clear();
    ChunkPreamble p;
    p.ticksDone = ticks_;
    p.eventsDone = state ? state->executedTotal : 0;
    p.decisionsDone = decisionsBefore_ + encoder_.records();
    p.time = state ? toDouble(state->now) : 0.0;
    p.hasKeyframe = state.has_value();
    preamble_.clear();
    writePreamble(preamble_, p);
    chunk_.bytes(preamble_.data(), preamble_.size());
    std::size_t keyframeBytes = 0;
    if (state) {
      const std::vector<std::uint8_t> bytes = stateBytes(*state);
      chunk_.varint(bytes.size());
      chunk_.bytes(bytes.data(), bytes.size());
      chunk_.u64(stateHash(bytes));
      keyframeBytes = bytes.size();
      encoder_.reset(state->now, state->nextSequence);
    } else {
      encoder_.reset(Real(0), 0);
    }
    limit_ = std::max(kChunkTargetBytes, 8 * keyframeBytes);
    entry_ = entryOf(p, 0);
    digest_.reset();
  }

  void close() {
    encoder_.flush();
    entry_.digest = digest_.value();
    sink_.chunk(chunk_.bytes(), entry_);
  }

  ChunkSink& sink_;
  const GameBoard<Real>& board_;
  ByteWriter chunk_;
  RecordEncoder<Real> encoder_;
  DecisionDigest<Real> digest_;  // of the chunk's reports, for the index
  std::vector<std::uint8_t> preamble_;
  ChunkEntry entry_;
  std::size_t limit_ = kChunkTargetBytes;
  std::uint64_t decisionsBefore_ = 0;
  std::uint64_t ticks_ = 0;
  std::optional<BoardState<Real>> next_;  // the keyframe of the chunk to begin
};

}  // namespace gizmo::replay
