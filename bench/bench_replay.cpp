// The replay log's costs, each against the same run unrecorded in the same process: recording
// (to a sink that keeps nothing, and to a file), replaying (re-simulating and checking every
// chunk's digest, or comparing every record), seeking to the middle of a long log, and the log's
// size per executed event.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "bench_boards.hpp"
#include "gizmo/replay/replay.hpp"

namespace gizmo::bench {
namespace {

constexpr double kBoardSeconds = 60.0;

RunRequest request(const BoardSpec& board, double seconds = kBoardSeconds) {
  RunRequest r;
  r.board = board;
  r.model = MotionModel::Ballistic;
  r.duration = seconds;
  return r;
}

// Counts the bytes and drops them: the cost of making the log without the file system.
class CountingSink final : public replay::ChunkSink {
 public:
  void header(std::span<const std::uint8_t> p) override { bytes += p.size(); }
  void chunk(std::span<const std::uint8_t> p, const replay::ChunkEntry&) override { bytes += p.size(); }
  void finish(const replay::RunEnd&) override {}
  std::uint64_t bytes = 0;
};

// The process id keeps two benchmark runs on one machine (a CI run beside a developer's) apart.
std::string logPath(const char* name) {
  return (std::filesystem::temp_directory_path() /
          ("gizmo-bench-" + std::to_string(::getpid()) + "-" + name + ".gzlog"))
      .string();
}

void counters(benchmark::State& state, std::uint64_t events, std::uint64_t bytes) {
  state.counters["events/s"] = benchmark::Counter(double(events), benchmark::Counter::kIsRate);
  if (bytes) state.counters["bytes/event"] = double(bytes) / double(events);
}

void unrecorded(benchmark::State& state, const BoardSpec& board, double seconds = kBoardSeconds) {
  const RunRequest r = request(board, seconds);
  std::uint64_t events = 0;
  for (auto _ : state) events += simulate<double>(r).total;
  counters(state, events, 0);
}

void recordedInMemory(benchmark::State& state, const BoardSpec& board) {
  const RunRequest r = request(board);
  std::uint64_t events = 0, bytes = 0;
  for (auto _ : state) {
    CountingSink sink;
    events += replay::recordRun(r, PrecisionChoice{}, sink).summary.total;
    bytes += sink.bytes;
  }
  counters(state, events, bytes);
}

void recordedToFile(benchmark::State& state, const BoardSpec& board, const char* name, double seconds = kBoardSeconds) {
  const RunRequest r = request(board, seconds);
  const std::string path = logPath(name);
  std::uint64_t events = 0, bytes = 0;
  for (auto _ : state) {
    // A new file each time, as `gizmo record` usually makes: truncating the last one would add
    // the file system's cost of freeing it.
    state.PauseTiming();
    std::filesystem::remove(path);
    state.ResumeTiming();
    replay::LogWriter writer(path);
    events += replay::recordRun(r, PrecisionChoice{}, writer).summary.total;
    bytes += writer.bytesWritten();
  }
  counters(state, events, bytes);
  std::filesystem::remove(path);
}

void replayed(benchmark::State& state, const BoardSpec& board, const char* name,
              replay::ReplayMethod method = replay::ReplayMethod::Digests) {
  const std::string path = logPath(name);
  {
    replay::LogWriter writer(path);
    replay::recordRun(request(board), PrecisionChoice{}, writer);
  }
  std::uint64_t events = 0;
  for (auto _ : state) {
    const replay::ReplayReport report = replay::replayLog(replay::openLog(path), method);
    if (!report.identical) state.SkipWithError("the replay differs from the log");
    events += report.events;
  }
  counters(state, events, 0);
  std::filesystem::remove(path);
}

// The least any log of every decision can cost, for the recording goal's sake: the board builds
// its reports for an observer that either drops them (the seam alone) or copies each report's
// raw fields into a buffer made ready beforehand (no encoding, no checksum, no file).
class RawCopyObserver final : public BoardObserver<double> {
 public:
  explicit RawCopyObserver(std::size_t capacity) : buffer_(capacity) {}
  std::size_t bytes() const { return std::size_t(at_ - buffer_.data()); }
  bool overflowed() const { return overflowed_; }
  void rewind() { at_ = buffer_.data(); }

  void eventScheduled(const Event<double>& e) override { put(std::uint8_t(1), e.time, e.kind, e.a, e.b, e.feature); }
  void eventRemoved(const Event<double>& e) override { put(std::uint8_t(2), e.sequence); }
  void eventExecuted(const Event<double>& e, const EventOutcome<double>& o) override {
    put(std::uint8_t(3), e.sequence);
    for (const BallChange<double>& c : o.balls()) put(c.position, c.velocityBefore, c.velocityAfter);
  }
  void triggerFired(const double& t, GizmoId source, GizmoId target) override {
    put(std::uint8_t(4), t, source, target);
  }
  void actionPerformed(const double& t, GizmoId target) override { put(std::uint8_t(5), t, target); }
  void inputApplied(const double& t, int key, KeyDirection d) override { put(std::uint8_t(6), t, key, d); }
  void modelRuleApplied(const double& t, ModelRule r, GizmoId g, GizmoId other) override {
    put(std::uint8_t(7), t, r, g, other);
  }
  void tickBoundary(const double& t) override { put(std::uint8_t(8), t); }

 private:
  template <class... T>
  void put(const T&... values) {
    if (std::size_t(buffer_.data() + buffer_.size() - at_) < (sizeof values + ...)) {
      overflowed_ = true;
      return;
    }
    ((std::memcpy(at_, &values, sizeof values), at_ += sizeof values), ...);
  }
  std::vector<std::uint8_t> buffer_;
  std::uint8_t* at_ = buffer_.data();
  bool overflowed_ = false;
};

void observed(benchmark::State& state, const BoardSpec& board, bool copy) {
  const RunRequest r = request(board);
  std::uint64_t events = 0, bytes = 0;
  BoardObserver<double> silent;
  RawCopyObserver raw(16u << 20);  // a 60 s spec-example run makes under 1 MB
  for (auto _ : state) {
    raw.rewind();
    events += simulate<double>(r, copy ? &raw : &silent).total;
    bytes += raw.bytes();
  }
  if (raw.overflowed()) state.SkipWithError("the raw copy outgrew its buffer");
  counters(state, events, bytes);
}

void BM_SpecUnrecorded(benchmark::State& s) { unrecorded(s, specExample()); }
void BM_SpecObservedSilently(benchmark::State& s) { observed(s, specExample(), false); }
void BM_SpecRawCopied(benchmark::State& s) { observed(s, specExample(), true); }
void BM_SpecRecordedInMemory(benchmark::State& s) { recordedInMemory(s, specExample()); }
void BM_SpecRecordedToFile(benchmark::State& s) { recordedToFile(s, specExample(), "spec"); }
void BM_SpecReplayed(benchmark::State& s) { replayed(s, specExample(), "spec-replay"); }
void BM_SpecReplayedEveryRecord(benchmark::State& s) {
  replayed(s, specExample(), "spec-replay-records", replay::ReplayMethod::Records);
}
// A whole game: over 600 s the spec example's ball rattles in the V of two circle bumpers, and
// nearly every record is a collision with its ball's change (docs/performance.md, "Whole games").
void BM_Spec600sUnrecorded(benchmark::State& s) { unrecorded(s, specExample(), 600); }
void BM_Spec600sRecordedToFile(benchmark::State& s) { recordedToFile(s, specExample(), "spec-600s", 600); }
void BM_CrowdedUnrecorded(benchmark::State& s) { unrecorded(s, crowdedBoard()); }
void BM_CrowdedRecordedToFile(benchmark::State& s) { recordedToFile(s, crowdedBoard(), "crowded"); }
void BM_CrowdedReplayed(benchmark::State& s) { replayed(s, crowdedBoard(), "crowded-replay"); }

// A log of about a million events (the crowded board for 90 s of board time: its event rate is
// steady); each iteration opens it and reaches the state after its middle event.
void BM_SeekMiddleOfMillionEventLog(benchmark::State& state) {
  const std::string path = logPath("million");
  std::uint64_t total = 0;
  {
    replay::LogWriter writer(path);
    total = replay::recordRun(request(crowdedBoard(), 90), PrecisionChoice{}, writer).summary.total;
  }
  for (auto _ : state) {
    const replay::OpenedLog log = replay::openLog(path);
    const replay::StateView s = replay::seekLog(log, replay::SeekTarget{total / 2, std::nullopt});
    benchmark::DoNotOptimize(s.balls.size());
  }
  state.counters["log_events"] = double(total);
  state.counters["log_MB"] = double(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove(path);
}

// On a shared machine the fastest of many repetitions is the steadiest figure: compare the
// `_min` rows (e.g. --benchmark_repetitions=20 --benchmark_report_aggregates_only=true).
double fastest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
#define GIZMO_REPLAY_BENCHMARK(fn) BENCHMARK(fn)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest)

GIZMO_REPLAY_BENCHMARK(BM_SpecUnrecorded);
GIZMO_REPLAY_BENCHMARK(BM_SpecObservedSilently);
GIZMO_REPLAY_BENCHMARK(BM_SpecRawCopied);
GIZMO_REPLAY_BENCHMARK(BM_SpecRecordedInMemory);
GIZMO_REPLAY_BENCHMARK(BM_SpecRecordedToFile);
GIZMO_REPLAY_BENCHMARK(BM_SpecReplayed);
GIZMO_REPLAY_BENCHMARK(BM_SpecReplayedEveryRecord);
GIZMO_REPLAY_BENCHMARK(BM_Spec600sUnrecorded)->Iterations(1);
GIZMO_REPLAY_BENCHMARK(BM_Spec600sRecordedToFile)->Iterations(1);
GIZMO_REPLAY_BENCHMARK(BM_CrowdedUnrecorded);
GIZMO_REPLAY_BENCHMARK(BM_CrowdedRecordedToFile);
GIZMO_REPLAY_BENCHMARK(BM_CrowdedReplayed);
BENCHMARK(BM_SeekMiddleOfMillionEventLog)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gizmo::bench

namespace gizmo::bench {
namespace {
// The file alone: five 64 KiB chunks and the index, as a 60 s spec-example log has.
void BM_LogWriterAlone(benchmark::State& state) {
  const std::string path = logPath("writer");
  const std::vector<std::uint8_t> chunk(64 * 1024, 0x5A);
  for (auto _ : state) {
    state.PauseTiming();
    std::filesystem::remove(path);
    state.ResumeTiming();
    replay::LogWriter writer(path);
    writer.header(std::span<const std::uint8_t>(chunk.data(), 2000));
    for (int i = 0; i < 5; ++i) writer.chunk(chunk, replay::ChunkEntry{});
    writer.finish(replay::RunEnd{});
  }
  std::filesystem::remove(path);
}
GIZMO_REPLAY_BENCHMARK(BM_LogWriterAlone);
}  // namespace
}  // namespace gizmo::bench
