// A log made while its run goes on, as `gizmo play`'s page makes one (docs/play.md): the Recorder
// attached to a board whose inputs arrive as it runs, one tick at a time, and the log written at
// a tick boundary from the chunks kept so far (KeptChunks), the chunk in progress
// (Recorder::finishCopy) and a header made then (recordHeader). Each such log must be byte for
// byte the one recordRun writes of the same board and inputs to that moment, whether or not a
// chunk has just been closed there (saves every so many ticks, and at each of the three ticks
// after a chunk closes), and the run must go on undisturbed by the writing. The live log is
// written into memory (as the page writes it), the other into a file: the two targets of
// LogWriter give the same bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "gizmo/core/run/run.hpp"
#include "gizmo/replay/recorder.hpp"
#include "gizmo/replay/replay.hpp"
#include "support/fixture_request.hpp"
#include "support/scratch_dir.hpp"

namespace {

using namespace gizmo;
using namespace gizmo::replay;

std::vector<std::uint8_t> fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Keys pressed and released through the run, at times off the tick grid and on it.
std::vector<TimedKey> keysOver(double seconds) {
  std::vector<TimedKey> keys;
  for (double t = 0.213; t < seconds; t += 0.37) {
    keys.push_back(TimedKey{t, 32, KeyDirection::Down});
    keys.push_back(TimedKey{t + 0.15, 32, KeyDirection::Up});
  }
  for (double t = 0.5; t < seconds; t += 1.3) {  // on the grid of 0.01 s ticks, or next to it
    keys.push_back(TimedKey{t, 81, KeyDirection::Down});
    keys.push_back(TimedKey{t + 0.5, 81, KeyDirection::Up});
  }
  std::stable_sort(keys.begin(), keys.end(), [](const TimedKey& a, const TimedKey& b) { return a.time < b.time; });
  return keys;
}

void liveLogsMatchRecordedOnes(MotionModel model, double seconds, int saveEvery) {
  const test::ScratchDir dir;
  const std::string again = (dir / "again.gzlog").string();
  std::vector<std::uint8_t> live;
  const PrecisionChoice precision{Precision::Double, 0};

  RunRequest request = test::fixtureRequest("boards/spec-example.txt", model, 0);
  request.maxTick = 0.01;
  const std::vector<TimedKey> keys = keysOver(seconds);
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(request);
  KeptChunks kept;
  Recorder<double> recorder(kept, *board);
  board->setObserver(&recorder);

  RunRequest soFar = request;
  std::size_t nextKey = 0;
  int saves = 0, savesAfterAClose = 0;
  std::size_t chunksSeen = 0;
  std::int64_t closedAt = -10;
  const auto ticks = static_cast<std::int64_t>(seconds / request.maxTick);
  for (std::int64_t k = 1; k <= ticks; ++k) {
    const double end = double(k) * request.maxTick;
    for (; nextKey < keys.size() && keys[nextKey].time <= end; ++nextKey) {  // given just before their tick
      board->scheduleInput(keys[nextKey].time, keys[nextKey].key, keys[nextKey].direction);
      soFar.keys.push_back(keys[nextKey]);
    }
    board->tickSpan(0.0, k, end);
    if (kept.size() != chunksSeen) chunksSeen = kept.size(), closedAt = k;
    const bool afterAClose = k - closedAt < 3;
    if (k % saveEvery != 0 && k != ticks && !afterAClose) continue;
    soFar.duration = board->now();
    live.clear();
    {
      LogWriter writer(live);
      writer.header(recordHeader(soFar, *board));
      kept.sendTo(writer);
      recorder.finishCopy(writer);
    }
    {
      LogWriter writer(again);
      ASSERT_TRUE(recordRun(soFar, precision, writer).completed);
    }
    ASSERT_EQ(live, fileBytes(again)) << "the live log at t = " << soFar.duration << " (tick " << k << ")";
    ++saves;
    if (afterAClose) ++savesAfterAClose;
  }
  const ReplayReport report = replayLog(openLog(ByteSource::memory(live)));
  EXPECT_TRUE(report.identical) << report.where;
  EXPECT_GT(report.events, 1000u);
  EXPECT_GT(saves, 10);
  EXPECT_GE(savesAfterAClose, 3) << "no chunk closed while the run went on: no save just after one";
}

TEST(ReplayLiveRecording, ALogWrittenMidRunIsTheLogOfTheRunToThatMoment) {
  liveLogsMatchRecordedOnes(MotionModel::Ballistic, 40, 97);
}

TEST(ReplayLiveRecording, TheClassicModelToo) { liveLogsMatchRecordedOnes(MotionModel::Classic, 40, 151); }

}  // namespace
