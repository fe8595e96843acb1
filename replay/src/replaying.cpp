// Replaying a log: the run made again and checked against the log's chunk digests, or record by
// record, with the first decision where they part explained (replay.hpp: replayLog).
#include <algorithm>
#include <map>

#include "gizmo/replay/decision_digest.hpp"
#include "gizmo/replay/recorder.hpp"
#include "run_start.hpp"

namespace gizmo::replay {
namespace {

using namespace detail;

// Compares each chunk of the new run with the log's as it is made.
class ComparingSink final : public ChunkSink {
 public:
  struct Parted {};   // the run's chunk `chunks - 1` (kept in `ours`) differs from the log's
  struct LogEnds {};  // the log was cut off and everything it holds matched

  explicit ComparingSink(const LogReader& log) : log_(log) {}
  void header(std::span<const std::uint8_t>) override {}  // compared before the run (replayAs)
  void chunk(std::span<const std::uint8_t> payload, const ChunkEntry& entry) override {
    const std::size_t i = chunks++;
    if (i >= log_.chunks().size()) {
      if (!log_.end()) {
        eventsInLog = entry.eventsDone;  // the events of the chunks before this one
        throw LogEnds{};
      }
      ours.assign(payload.begin(), payload.end());
      throw Parted{};
    }
    const std::vector<std::uint8_t> theirs = log_.chunkPayload(i);
    if (!std::equal(payload.begin(), payload.end(), theirs.begin(), theirs.end())) {
      ours.assign(payload.begin(), payload.end());
      throw Parted{};
    }
  }
  void finish(const RunEnd& end) override { ended = end; }

  std::size_t chunks = 0;
  std::uint64_t eventsInLog = 0;  // when the log ends first
  std::vector<std::uint8_t> ours;
  std::optional<RunEnd> ended;

 private:
  const LogReader& log_;
};

// One side of a parting: a chunk's records read one at a time, with the byte range of the last,
// and the latest state of each ball they show.
template <class Real>
class ChunkSide {
 public:
  ChunkSide(std::span<const std::uint8_t> payload, const OpenedLog& log, const PhysicsParams<Real>& params)
      : payload_(payload),
        log_(log),
        opened_(openChunk<Real>(payload)),
        records_(payload, opened_, params, maxQueued(log)),
        events_(opened_.preamble.eventsDone),
        time_(opened_.keyframe ? opened_.keyframe->now : Real(0)) {}

  const OpenedChunk<Real>& opened() const { return opened_; }
  std::span<const std::uint8_t> preambleAndKeyframe() const { return payload_.first(opened_.recordsAt); }
  std::uint64_t events() const { return events_; }

  // The next record, or nullopt at the chunk's end.
  std::optional<Decision<Real>> next() {
    if (records_.atEnd()) return std::nullopt;
    from_ = records_.position();
    Decision<Real> d = records_.next();
    to_ = records_.position();
    return d;
  }
  std::span<const std::uint8_t> lastBytes() const { return payload_.subspan(from_, to_ - from_); }

  // Takes a decision both sides made into the state.
  void apply(const Decision<Real>& d) {
    time_ = d.time;
    if (d.type != DecisionType::Executed) return;
    ++events_;
    for (const BallChange<Real>& ch : d.outcome.balls()) balls_[ch.ball] = ballView(ch, log_.gizmoNames);
  }
  StateView state() const {
    StateView s;
    s.time = exact(time_);
    s.events = events_;
    for (const auto& [id, b] : balls_) s.balls.push_back(b);
    return s;
  }

 private:
  std::span<const std::uint8_t> payload_;
  const OpenedLog& log_;
  OpenedChunk<Real> opened_;
  ChunkRecords<Real> records_;
  std::uint64_t events_;
  Real time_;
  std::size_t from_ = 0, to_ = 0;
  std::map<GizmoId, BallView> balls_;
};

// Reads the run's chunk and the log's side by side to the first record whose bytes differ.
template <class Real>
void explainParting(const OpenedLog& log, ComparingSink& sink, ReplayReport& report) {
  const PhysicsParams<Real> params = paramsOf<Real>(log);
  const std::size_t i = sink.chunks - 1;
  ChunkSide<Real> ours(sink.ours, log, params);
  const std::uint64_t firstIndex = ours.opened().preamble.decisionsDone;
  if (i >= log.reader.chunks().size()) {
    report.where = "the run goes on after the log's last chunk";
    if (const std::optional<Decision<Real>> d = ours.next())
      report.runDecision = viewOf(*d, firstIndex, ours.events(), log.gizmoNames);
    return;
  }
  const std::vector<std::uint8_t> theirBytes = log.reader.chunkPayload(i);
  ChunkSide<Real> theirs(theirBytes, log, params);
  const auto a = ours.preambleAndKeyframe(), b = theirs.preambleAndKeyframe();
  if (!std::equal(a.begin(), a.end(), b.begin(), b.end())) {
    report.where = "chunk " + std::to_string(i) + " starts from a different state (keyframe)";
    return;
  }
  std::uint64_t index = firstIndex;
  for (;; ++index) {
    const std::optional<Decision<Real>> x = theirs.next(), y = ours.next();
    const bool same = x && y && sameElements(theirs.lastBytes(), ours.lastBytes());
    if (!same) {
      if (x) report.logDecision = viewOf(*x, index, theirs.events(), log.gizmoNames);
      if (y) report.runDecision = viewOf(*y, index, ours.events(), log.gizmoNames);
      report.where = x && y ? "decision " + std::to_string(index) + " differs"
                     : x    ? "the run ends before the log"
                     : y    ? "the log ends before the run"
                            : "chunk " + std::to_string(i) + " differs after its last record";
      break;
    }
    theirs.apply(*x);
    ours.apply(*y);
  }
  report.logState = theirs.state();
  report.runState = ours.state();
  report.decisions = index;
  report.events = ours.events();
}

// Replaying by digests: the run made again with nothing encoded. Each chunk's reports are
// digested and checked against the index at the tick where the log's next chunk begins, and that
// chunk (read, so its checksum is checked) must start from the run's state there, byte for byte.
// Anything else that differs is for the record-by-record comparison to find and explain.
template <class Real>
class DigestChecker final : public BoardObserver<Real> {
 public:
  struct Differs {};

  DigestChecker(const LogReader& log, const GameBoard<Real>& board, std::uint64_t ticksDone)
      : log_(log), board_(board), ticks_(ticksDone) {
    readChunk(0);
  }

  void eventScheduled(const Event<Real>& e) override { digest_.scheduled(e); }
  void eventRemoved(const Event<Real>& e) override { digest_.removed(e); }
  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>& o) override { digest_.executed(e, o); }
  void triggerFired(const Real& t, GizmoId s, GizmoId g) override { digest_.trigger(t, s, g); }
  void actionPerformed(const Real& t, GizmoId g) override { digest_.action(t, g); }
  void inputApplied(const Real& t, int key, KeyDirection d) override { digest_.input(t, key, d); }
  void modelRuleApplied(const Real& t, ModelRule r, GizmoId g, GizmoId o) override { digest_.rule(t, r, g, o); }
  void tickBoundary(const Real& t) override {
    digest_.tick(t);
    ++ticks_;
    const std::vector<ChunkEntry>& chunks = log_.chunks();
    if (chunk_ + 1 < chunks.size() && ticks_ == chunks[chunk_ + 1].ticksDone) {
      closeChunk();
      readChunk(++chunk_);
      const std::vector<std::uint8_t> ours = stateBytes(board_.saveState());
      if (!sameElements(ours, start_.keyframe) || start_.preamble.eventsDone != board_.executedTotal()) throw Differs{};
    }
  }

  // After the run: it must have reached the log's last chunk, whose digest must match too.
  void finish() {
    if (chunk_ + 1 != log_.chunks().size()) throw Differs{};
    closeChunk();
  }

 private:
  void readChunk(std::size_t i) {
    payload_ = log_.chunkPayload(i);
    start_ = readChunkStart(payload_);
    digest_.reset();
  }
  void closeChunk() {
    if (log_.chunks()[chunk_].digest != digest_.value()) throw Differs{};
  }

  const LogReader& log_;
  const GameBoard<Real>& board_;
  DecisionDigest<Real> digest_;
  std::vector<std::uint8_t> payload_;  // the current chunk's, which start_ points into
  ChunkStart start_;
  std::size_t chunk_ = 0;
  std::uint64_t ticks_ = 0;
};

// Whether the run's end differs from the log's, and how, in words; empty when it does not.
std::string endDifference(const OpenedLog& log, const RunEnd& run) {
  const std::optional<RunEnd>& end = log.reader.end();
  if (end && (end->completed != run.completed || end->events != run.events))
    return "the run ends differently: " + (run.completed ? std::string("completed") : run.message);
  return {};
}

// The notes an identical replay carries.
std::string notesOf(const OpenedLog& log, bool headerDiffers) {
  std::vector<std::string> notes;
  if (headerDiffers) notes.push_back("the header was written by another version (" + log.header.toolkit + ")");
  if (!log.reader.truncation().empty()) notes.push_back(log.reader.truncation());
  std::string note;
  for (const std::string& n : notes) note += (note.empty() ? "" : "; ") + n;
  return note;
}

// A replay by digests on a board prepared for the log's run, or nullopt when something differs.
template <class Real>
std::optional<ReplayReport> replayByDigests(const OpenedLog& log, std::unique_ptr<GameBoard<Real>> board,
                                            const RunStart& start, bool headerDiffers) {
  RunEnd run;
  try {
    DigestChecker<Real> checker(log.reader, *board, start.ticksDone);
    board->setObserver(&checker);
    run.completed = true;
    try {
      continueRun(*board, log.request, std::int64_t(start.ticksDone));
    } catch (const StallError& e) {
      run.completed = false;
      run.message = e.what();
    }
    checker.finish();
  } catch (const typename DigestChecker<Real>::Differs&) {
    return std::nullopt;
  }
  run.events = board->executedTotal();
  if (!endDifference(log, run).empty()) return std::nullopt;
  ReplayReport report;
  report.byDigests = true;
  report.events = run.events;
  report.note = notesOf(log, headerDiffers);
  return report;
}

// Whether the log's index gives every chunk's digest (a log cut off before its index has none;
// one whose index lists no chunk has nothing to check them against).
bool hasDigests(const OpenedLog& log) {
  const std::vector<ChunkEntry>& chunks = log.reader.chunks();
  return log.reader.end() && !chunks.empty() &&
         std::all_of(chunks.begin(), chunks.end(), [](const ChunkEntry& e) { return e.digest.has_value(); });
}

template <class Real>
ReplayReport replayAs(const OpenedLog& log, ReplayMethod method) {
  ReplayReport report;
  const RunStart start = runStartOf(log);
  std::unique_ptr<GameBoard<Real>> board = startBoard<Real>(log);
  if (paramBytes(board->params()) != log.header.params) {
    report.identical = false;
    report.where = "this build derives different simulation parameters from the log's board";
    return report;
  }
  // The header this build would write for the run (its toolkit version, its canonical board).
  const bool headerDiffers =
      !sameElements(headerBytes(log.request, log.precision, *board, log.header.boardWarnings, log.header.parent),
                    log.reader.headerPayload());
  const bool digestsTried = method == ReplayMethod::Digests && hasDigests(log);
  if (digestsTried) {
    if (std::optional<ReplayReport> r = replayByDigests<Real>(log, std::move(board), start, headerDiffers)) return *r;
    board = startBoard<Real>(log);
  }
  ComparingSink sink(log.reader);
  std::optional<Recorder<Real>> recorder;
  if (log.reader.isBranch())
    recorder.emplace(sink, *board, typename Recorder<Real>::Start{start.ticksDone, start.decisionsDone});
  else recorder.emplace(sink, *board);
  board->setObserver(&*recorder);
  bool completed = true;
  std::string error;
  try {
    try {
      continueRun(*board, log.request, std::int64_t(start.ticksDone));
    } catch (const StallError& e) {
      completed = false;
      error = e.what();
    }
    recorder->finish(completed, error);
  } catch (const ComparingSink::LogEnds&) {
    report.note = log.reader.truncation() + "; every decision it holds replays identically";
    report.events = sink.eventsInLog;
    return report;
  } catch (const ComparingSink::Parted&) {
    report.identical = false;
    explainParting<Real>(log, sink, report);
    return report;
  }
  if (sink.chunks != log.reader.chunks().size()) {
    report.identical = false;
    report.where = "the run made " + std::to_string(sink.chunks) + " chunks, the log has " +
                   std::to_string(log.reader.chunks().size());
    return report;
  }
  if (sink.ended) {
    if (std::string where = endDifference(log, *sink.ended); !where.empty()) {
      report.identical = false;
      report.where = std::move(where);
      return report;
    }
  }
  if (digestsTried) {
    // Every record matches, yet the digests said otherwise: the index does not fit its chunks.
    report.identical = false;
    report.where = "every record replays identically, but the index's chunk digests do not match them";
    return report;
  }
  report.note = notesOf(log, headerDiffers);
  report.events = board->executedTotal();
  return report;
}

}  // namespace

ReplayReport replayLog(const OpenedLog& log, ReplayMethod method) {
  return detail::withLogScalar(log, [&]<class Real>() { return replayAs<Real>(log, method); });
}

}  // namespace gizmo::replay
