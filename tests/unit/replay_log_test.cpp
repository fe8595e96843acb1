// The replay log end to end, through its public API (replay.hpp, log_file.hpp):
//   - every fixture board records and replays identically, in both motion models, in double and
//     in long double;
//   - a log whose header no longer describes its decisions replays as different, and the report
//     names the first decision that differs;
//   - every corrupted byte is detected, and nothing crashes on one;
//   - a log cut off anywhere either does not open (its header frame is cut) or keeps exactly its
//     complete chunks, which replay and walk without error;
//   - files that are not logs say what is wrong with them;
//   - seeking by events or by time lands on the state a direct run limited there reaches;
//   - walking a log sees every executed event;
//   - the golden logs in fixtures/logs/ are reproduced by this build.
//
// Golden logs: run with GIZMO_UPDATE_GOLDEN=1 in the environment, e.g.
//   GIZMO_UPDATE_GOLDEN=1 ./replay_tests --gtest_filter='*ReplayGolden*'
// to rewrite fixtures/logs/ from this build instead of comparing with it. Do that only when the
// log format or the simulation changes on purpose, and say so in the commit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/key_script.hpp"
#include "gizmo/replay/checksum.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_file.hpp"
#include "gizmo/replay/log_format.hpp"
#include "gizmo/replay/log_header.hpp"
#include "gizmo/replay/replay.hpp"
#include "gizmo/replay/scalar_codec.hpp"
#include "support/fixture_request.hpp"
#include "support/paths.hpp"

namespace {

using namespace gizmo;
using namespace gizmo::replay;
using Bytes = std::vector<std::uint8_t>;

// --- fixtures and files -------------------------------------------------------------------------

std::string fixture(const std::string& relative) { return test::fixturePath(relative); }

// fixtures/keys/flippers.keys as run input (none if the file is missing).
std::vector<TimedKey> flipperKeys() {
  const std::string path = fixture("keys/flippers.keys");
  std::vector<TimedKey> keys;
  if (!std::filesystem::exists(path)) return keys;
  for (const io::KeyInput& k : io::readKeyScriptFile(path)) keys.push_back(TimedKey{k.time, k.key, k.direction});
  return keys;
}

RunRequest requestFor(const std::string& board, MotionModel model, double seconds, bool keys = true) {
  RunRequest r = test::fixtureRequest(board, model, seconds);
  if (keys) r.keys = flipperKeys();
  return r;
}

// A file in the test's temporary folder, unique to this process and this test (the release and
// the sanitizer builds may run at the same time).
std::string tempPath(const std::string& stem) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "." + info->name() + "." + stem;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  return ::testing::TempDir() + "gizmo-" + std::to_string(::getpid()) + "-" + name + ".gzlog";
}

Bytes readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

struct Recorded {
  RecordResult result;
  Bytes bytes;  // the log file as LogWriter wrote it
};

// Records the run into a temporary file with LogWriter and returns the file's bytes.
Recorded record(const RunRequest& request, const PrecisionChoice& precision, const std::string& stem,
                const std::vector<std::string>& boardWarnings = {}) {
  const std::string path = tempPath(stem);
  Recorded out;
  {
    LogWriter writer(path);
    out.result = recordRun(request, precision, writer, boardWarnings);
  }
  out.bytes = readBytes(path);
  std::remove(path.c_str());
  return out;
}

OpenedLog openBytes(Bytes bytes, bool verifyChecksums = true) {
  return openLog(ByteSource::memory(std::move(bytes)), verifyChecksums);
}

std::uint64_t readU64(const Bytes& b, std::size_t at) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < 8; ++i) v |= std::uint64_t(b.at(at + i)) << (8 * i);
  return v;
}
std::uint32_t readU32(const Bytes& b, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t(b.at(at + i)) << (8 * i);
  return v;
}
void putU64(Bytes& b, std::size_t at, std::uint64_t v) {
  for (std::size_t i = 0; i < 8; ++i) b.at(at + i) = static_cast<std::uint8_t>(v >> (8 * i));
}
void putU32(Bytes& b, std::size_t at, std::uint32_t v) {
  for (std::size_t i = 0; i < 4; ++i) b.at(at + i) = static_cast<std::uint8_t>(v >> (8 * i));
}

// Recomputes the checksum of the frame at `frameAt` over its payload as it now is, as the writer
// of an edited log would.
void resealFrame(Bytes& b, std::size_t frameAt) {
  const std::uint32_t length = readU32(b, frameAt + 1);
  const std::span<const std::uint8_t> payload(b.data() + frameAt + kFrameHeaderSize, length);
  putU64(b, frameAt + kFrameHeaderSize + length, checksum64(payload, (std::uint64_t(b.at(frameAt)) << 32) | length));
}

// The log with its header frame's payload replaced by h's encoding, which must have the same size,
// framed again with a correct checksum: every byte checks.
Bytes withHeader(const Bytes& log, const LogHeader& h) {
  const Bytes payload = encodeHeader(h);
  EXPECT_EQ(payload.size(), readU32(log, kFileHeaderSize + 1)) << "the edited header must keep its size";
  Bytes edited = log;
  std::copy(payload.begin(), payload.end(), edited.begin() + std::ptrdiff_t(kFileHeaderSize + kFrameHeaderSize));
  resealFrame(edited, kFileHeaderSize);
  return edited;
}

// The end of the header frame (where the first chunk starts) and the index frame's offset, read
// from the bytes as docs/replay-format.md lays them out.
std::uint64_t headerFrameEnd(const Bytes& b) {
  return kFileHeaderSize + kFrameHeaderSize + readU32(b, kFileHeaderSize + 1) + kFrameChecksumSize;
}
std::uint64_t indexOffset(const Bytes& b) { return readU64(b, b.size() - kTrailerSize); }

// The message of the FormatError f throws; anything else fails the test.
std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const FormatError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected a FormatError, got: " << e.what();
    return "(not a FormatError)";
  }
  return "(nothing thrown)";
}
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// --- describing what differs ------------------------------------------------------------------------

std::string describe(const std::optional<DecisionView>& d) {
  if (!d) return "(none: that side had ended)";
  std::ostringstream os;
  os << "decision " << d->index << " (after " << d->eventIndex << " events): " << decisionTypeName(d->type)
     << " t=" << d->time.text;
  switch (d->type) {
    case DecisionType::Scheduled:
    case DecisionType::Removed:
    case DecisionType::Executed:
      os << " " << eventKindName(d->kind) << " at " << d->eventTime.text << " a=" << d->a << " b=" << d->b
         << " feature=" << d->feature << " seq=" << d->sequence;
      for (const BallView& b : d->balls)
        os << " [" << b.name << " at (" << b.x.text << ", " << b.y.text << ") v (" << b.vxBefore.text << ", "
           << b.vyBefore.text << ") -> (" << b.vx.text << ", " << b.vy.text << ")]";
      break;
    case DecisionType::Trigger: os << " " << d->gizmo << " -> " << d->other; break;
    case DecisionType::Action: os << " gizmo " << d->gizmo; break;
    case DecisionType::Input: os << " key " << d->key << (d->direction == KeyDirection::Up ? " up" : " down"); break;
    case DecisionType::Rule: os << " rule " << int(d->rule) << " gizmo " << d->gizmo << " other " << d->other; break;
    case DecisionType::Tick:
    case DecisionType::Time: break;
  }
  return os.str();
}

std::string describe(const ReplayReport& r) {
  std::ostringstream os;
  os << (r.identical ? "identical" : "DIFFERENT") << " after " << r.decisions << " decisions, " << r.events
     << " events";
  if (!r.where.empty()) os << "\n  where: " << r.where;
  if (!r.note.empty()) os << "\n  note: " << r.note;
  if (r.logDecision || r.runDecision)
    os << "\n  log: " << describe(r.logDecision) << "\n  run: " << describe(r.runDecision);
  return os.str();
}

// --- record, then replay: every fixture board ----------------------------------------------------------

struct BoardCase {
  std::string file;  // under fixtures/
  double seconds;
};

std::vector<BoardCase> fixtureBoards() {
  // The spec example runs long enough that its log spans several chunks in both models (the
  // classic model's logs are the smaller: it has no friction ticks).
  std::vector<BoardCase> out{{"boards/spec-example.txt", 150.0}, {"boards/spec-example.xml", 150.0}};
  for (const char* folder : {"boards/gizmos", "boards/scenes"}) {
    std::vector<std::string> names;
    std::error_code error;  // a missing folder leaves its boards out; the spec example still fails loudly
    for (const auto& entry : std::filesystem::directory_iterator(fixture(folder), error))
      if (entry.path().extension() == ".txt") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    for (const std::string& n : names) out.push_back({std::string(folder) + "/" + n, 20.0});
  }
  return out;
}

void PrintTo(const BoardCase& b, std::ostream* os) { *os << b.file << " for " << b.seconds << " s"; }

using RoundTripParam = std::tuple<BoardCase, MotionModel, Precision>;

class ReplayRoundTrip : public ::testing::TestWithParam<RoundTripParam> {};

TEST_P(ReplayRoundTrip, RecordThenReplayIsIdentical) {
  const auto& [board, model, precision] = GetParam();
  const RunRequest request = requestFor(board.file, model, board.seconds);
  const std::string path = tempPath("log");
  RecordResult result;
  {
    LogWriter writer(path);
    result = recordRun(request, PrecisionChoice{precision, 0}, writer);
  }
  EXPECT_TRUE(result.completed) << result.error;
  const OpenedLog log = openLog(path);
  std::remove(path.c_str());

  EXPECT_EQ(log.reader.truncation(), "");
  ASSERT_TRUE(log.reader.end().has_value());
  EXPECT_EQ(log.reader.end()->completed, result.completed);
  EXPECT_EQ(log.reader.end()->events, result.summary.total);
  EXPECT_EQ(log.precision.kind, precision);
  if (board.file.find("spec-example") != std::string::npos) {
    EXPECT_GT(log.reader.chunks().size(), 1u) << "the spec example should span several chunks";
  }

  // By digests (a fresh log needs nothing more), and record by record.
  for (const ReplayMethod method : {ReplayMethod::Digests, ReplayMethod::Records}) {
    const ReplayReport report = replayLog(log, method);
    EXPECT_TRUE(report.identical) << describe(report);
    EXPECT_EQ(report.byDigests, method == ReplayMethod::Digests);
    EXPECT_EQ(report.note, "");
    EXPECT_EQ(report.events, result.summary.total);
  }

  std::uint64_t executed = 0;
  DecisionStream stream(log);
  while (const std::optional<DecisionView> d = stream.next())
    if (d->type == DecisionType::Executed) ++executed;
  EXPECT_EQ(executed, result.summary.total);
}

std::string roundTripName(const ::testing::TestParamInfo<RoundTripParam>& info) {
  const auto& [board, model, precision] = info.param;
  std::string name = std::filesystem::path(board.file).filename().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  name += model == MotionModel::Ballistic ? "_ballistic" : "_classic";
  name += precision == Precision::Double ? "_double" : "_long_double";
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryFixtureBoard, ReplayRoundTrip,
                         ::testing::Combine(::testing::ValuesIn(fixtureBoards()),
                                            ::testing::Values(MotionModel::Ballistic, MotionModel::Classic),
                                            ::testing::Values(Precision::Double, Precision::LongDouble)),
                         roundTripName);

// --- the logs the remaining tests share ------------------------------------------------------------------

// The spec example for `seconds` with the flipper keys, ballistic, in double: recorded once per
// process.
const Recorded& specExample(double seconds) {
  static std::map<double, Recorded> logs;
  auto it = logs.find(seconds);
  if (it == logs.end())
    it = logs.emplace(seconds, record(requestFor("boards/spec-example.txt", MotionModel::Ballistic, seconds),
                                      PrecisionChoice{Precision::Double, 0}, "spec"))
             .first;
  return it->second;
}

// --- replay finds a difference ----------------------------------------------------------------------

// A log whose header was re-encoded with the first key pressed 0.01 s earlier, framed again with
// a correct checksum: every byte checks, but the decisions recorded no longer follow from the
// header. Replay must say so and point at the input's scheduling.
TEST(ReplayLog, ReplayFindsTheFirstDecisionThatDiffers) {
  const Recorded& rec = specExample(5.0);
  const OpenedLog original = openBytes(rec.bytes);
  ASSERT_FALSE(original.header.keys.empty()) << "needs fixtures/keys/flippers.keys";

  LogHeader h = decodeHeader(original.reader.headerPayload());
  const double recordedTime = h.keys[0].time;
  h.keys[0].time = recordedTime - 0.01;  // still inside the same tick for flippers.keys (0.10 → 0.09)
  const OpenedLog log = openBytes(withHeader(rec.bytes, h));  // a key's time is a fixed 8 bytes
  ASSERT_EQ(log.request.keys.size(), original.request.keys.size());
  EXPECT_EQ(log.request.keys[0].time, recordedTime - 0.01);
  const ReplayReport report = replayLog(log);
  SCOPED_TRACE(describe(report));
  EXPECT_FALSE(report.identical);
  EXPECT_FALSE(report.byDigests) << "a differing chunk is compared record by record";
  EXPECT_NE(report.where, "");
  EXPECT_TRUE(contains(report.where, "decision")) << report.where;
  ASSERT_TRUE(report.logDecision.has_value());
  ASSERT_TRUE(report.runDecision.has_value());
  EXPECT_NE(describe(report.logDecision), describe(report.runDecision));
  EXPECT_EQ(report.logDecision->index, report.runDecision->index);
  // The log scheduled the key at its recorded time, the run at the tampered one.
  EXPECT_EQ(report.logDecision->type, DecisionType::Scheduled);
  EXPECT_EQ(report.logDecision->kind, EventKind::Input);
  EXPECT_EQ(report.logDecision->eventTime.value, recordedTime);
  if (report.runDecision->type == DecisionType::Scheduled && report.runDecision->kind == EventKind::Input) {
    EXPECT_EQ(report.runDecision->eventTime.value, recordedTime - 0.01);
  }
  ASSERT_TRUE(report.logState.has_value());
  ASSERT_TRUE(report.runState.has_value());
  // Everything before the difference was compared and matched.
  EXPECT_EQ(report.decisions, report.logDecision->index);
}

// A log whose header names another toolkit version (same length, framed again with a correct
// checksum) replays identically, by either method, with a note saying so.
// Format 3: the header keeps the warnings of the board it was recorded from (recordRun's last
// argument), the log replays identically with them, and they take their own bytes in the header.
TEST(ReplayLog, TheHeaderKeepsTheBoardsWarnings) {
  const RunRequest request = requestFor("boards/spec-example.txt", MotionModel::Ballistic, 1.0);
  const std::vector<std::string> warnings = {"b.txt:3:1: warning: 'Sink' (...) is left out",
                                             "b.txt:9:6: warning: this ball is named 'B_2'"};
  const std::string path = tempPath("warnings");
  {
    LogWriter writer(path);
    recordRun(request, PrecisionChoice{Precision::Double, 0}, writer, warnings);
  }
  const Bytes bytes = readBytes(path);
  std::remove(path.c_str());
  const OpenedLog log = openBytes(bytes);
  EXPECT_EQ(log.header.boardWarnings, warnings);
  EXPECT_TRUE(replayLog(log).identical);

  LogHeader h = decodeHeader(log.reader.headerPayload());
  h.boardWarnings.clear();
  EXPECT_EQ(decodeHeader(encodeHeader(h)).boardWarnings, std::vector<std::string>{});
  const Bytes payload = encodeHeader(h);
  EXPECT_LT(payload.size(), log.reader.headerPayload().size());
}

TEST(ReplayLog, AHeaderFromAnotherVersionIsNoted) {
  const Recorded& rec = specExample(5.0);
  const OpenedLog original = openBytes(rec.bytes);
  LogHeader h = decodeHeader(original.reader.headerPayload());
  ASSERT_FALSE(h.toolkit.empty());
  h.toolkit = std::string(h.toolkit.size(), '9');
  const OpenedLog log = openBytes(withHeader(rec.bytes, h));
  for (const ReplayMethod method : {ReplayMethod::Digests, ReplayMethod::Records}) {
    const ReplayReport report = replayLog(log, method);
    EXPECT_TRUE(report.identical) << describe(report);
    EXPECT_PRED2(contains, report.note, "written by another version (" + h.toolkit + ")");
  }
  EXPECT_EQ(replayLog(original).note, "");
}

// A log whose board this build reads otherwise than the build that wrote it (here a command
// spelled as no kind this build knows, as a build without a kind reads a board with one) is
// refused by name and line: read leniently, every gizmo id after the line left out would name
// another gizmo.
TEST(ReplayLog, ABoardThisBuildReadsOtherwiseIsRefused) {
  const Recorded& rec = specExample(5.0);
  const OpenedLog original = openBytes(rec.bytes);
  LogHeader h = decodeHeader(original.reader.headerPayload());
  const std::size_t at = h.board.find("Square ");
  ASSERT_NE(at, std::string::npos);
  h.board.replace(at, 6, "Sqware");  // the same length, so the frame keeps its size
  h.boardHash = checksum64(std::span(reinterpret_cast<const std::uint8_t*>(h.board.data()), h.board.size()));
  const std::string message = messageOf([&] { (void)replayLog(openBytes(withHeader(rec.bytes, h))); });
  EXPECT_TRUE(contains(message, "does not read the log's board as written") && contains(message, "'Sqware'") &&
              contains(message, "the log's board:"))
      << message;
}

// A log whose header names another binary format for its scalar (as a long-double log of another
// machine does): replaying it and comparing it with a log of this build's format are refused,
// naming both formats.
TEST(ReplayLog, ALogOfAnotherScalarFormatIsRefused) {
  const Recorded& rec = specExample(5.0);
  const OpenedLog original = openBytes(rec.bytes);
  LogHeader h = decodeHeader(original.reader.headerPayload());
  ASSERT_EQ(h.format, "binary64");
  h.format = "binary32";  // the same length, so the frame keeps its size
  const OpenedLog log = openBytes(withHeader(rec.bytes, h));
  const std::string replayed = messageOf([&] { (void)replayLog(log); });
  EXPECT_TRUE(contains(replayed, "binary32") && contains(replayed, "binary64") && contains(replayed, "formats differ"))
      << replayed;
  const std::string compared = messageOf([&] { (void)diffLogs(original, log, 0, false); });
  EXPECT_TRUE(contains(compared, "different formats (binary64, binary32)")) << compared;
}

TEST(ReplayLog, TheHeaderNamesTheScalarsFormat) {
  const RunRequest request = requestFor("boards/spec-example.txt", MotionModel::Ballistic, 0.2);
  for (const auto& [precision, format] : {std::pair{Precision::Float, "binary32"},
                                          {Precision::Double, "binary64"},
                                          {Precision::LongDouble, hardwareFormatOf<long double>()},
                                          {Precision::Float128, "binary128"}}) {
    const Recorded rec = record(request, PrecisionChoice{precision, 0}, "format");
    EXPECT_EQ(openBytes(rec.bytes).header.format, format) << precisionName(PrecisionChoice{precision, 0});
  }
  const Recorded mpfr = record(request, PrecisionChoice{Precision::Mpfr, 128}, "format");
  EXPECT_EQ(openBytes(mpfr.bytes).header.format, "mpfr:131");
}

// An index whose first chunk digest was changed, framed again with a correct checksum: the run
// matches every record, but not the digest. Replay must not call the log identical.
TEST(ReplayLog, ReplaySaysWhenTheIndexDigestsDoNotMatchTheRecords) {
  const Recorded& rec = specExample(5.0);
  const OpenedLog original = openBytes(rec.bytes);
  ASSERT_TRUE(original.reader.chunks().front().digest.has_value());
  Bytes tampered = rec.bytes;
  const std::size_t indexAt = static_cast<std::size_t>(readU64(tampered, tampered.size() - kTrailerSize));
  const std::size_t payloadAt = indexAt + kFrameHeaderSize;
  const std::size_t length = readU32(tampered, indexAt + 1);
  ByteReader r(std::span<const std::uint8_t>(tampered.data() + payloadAt, length));
  r.varint();  // chunks
  r.varint();  // the first chunk's offset, events and ticks
  r.varint();
  r.varint();
  r.u64();  // its time
  const std::size_t digestAt = payloadAt + r.position();
  putU64(tampered, digestAt, readU64(tampered, digestAt) ^ 1);
  resealFrame(tampered, indexAt);

  const OpenedLog log = openBytes(tampered);  // every checksum holds
  EXPECT_EQ(*log.reader.chunks().front().digest, *original.reader.chunks().front().digest ^ 1);
  const ReplayReport report = replayLog(log);
  EXPECT_FALSE(report.identical);
  EXPECT_FALSE(report.byDigests);
  EXPECT_PRED2(contains, report.where, "digests do not match");
  // Record by record, the log replays identically: its records are the run's.
  EXPECT_TRUE(replayLog(log, ReplayMethod::Records).identical);
}

// --- corruption ----------------------------------------------------------------------------------------

enum class Detected { No, Opening, Reading, Replaying };

// Whether a damaged log is noticed, and where: opening it, reading every chunk through a
// DecisionStream to the end, and replaying it must not all succeed cleanly.
Detected detect(Bytes bytes) {
  Detected stage = Detected::Opening;
  try {
    const OpenedLog log = openBytes(std::move(bytes));
    if (!log.reader.truncation().empty()) return Detected::Opening;
    stage = Detected::Reading;
    // DecisionStream fetches each chunk, in order, with chunkPayload (which checks the frame and
    // its place in the index) before decoding it, so a chunk that fails here would make the
    // stream throw at the latest when it reaches that chunk. Checking them first is only faster.
    for (std::size_t i = 0; i < log.reader.chunks().size(); ++i) (void)log.reader.chunkPayload(i);
    DecisionStream stream(log);
    while (stream.next()) {}
    stage = Detected::Replaying;
    const ReplayReport report = replayLog(log);
    if (!report.identical || !report.note.empty()) return Detected::Replaying;
    return Detected::No;
  } catch (const std::exception&) {  // FormatError, or anything else that refuses the log
    return stage;
  }
}

// Damages one byte at a time in a copy of `clean` and expects each copy to be caught. Logs under
// about 40 kB: every byte. Larger ones: every byte of the framing (file header, header frame,
// each chunk's frame header, preamble, last payload word and checksum, the index and the
// trailer) and the chunk payloads at a stride with a seeded random start (each payload is guarded
// by a checksum that provably catches any change confined to one 8-byte word, checksum.hpp).
void expectEveryCorruptionDetected(const Bytes& clean, std::uint64_t seed) {
  const OpenedLog log = openBytes(clean);
  ASSERT_EQ(detect(clean), Detected::No) << "the undamaged log must pass";
  std::set<std::size_t> positions;
  auto addRange = [&](std::uint64_t from, std::uint64_t to) {
    for (std::uint64_t p = from; p < to && p < clean.size(); ++p) positions.insert(std::size_t(p));
  };
  const std::uint64_t firstChunk = headerFrameEnd(clean), index = indexOffset(clean);
  addRange(0, firstChunk);
  addRange(index, clean.size());
  const std::vector<ChunkEntry>& chunks = log.reader.chunks();
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const std::uint64_t end = i + 1 < chunks.size() ? chunks[i + 1].offset : index;
    addRange(chunks[i].offset, chunks[i].offset + kFrameHeaderSize + 16);
    addRange(end - kFrameChecksumSize - 8, end);
  }
  std::mt19937_64 rng(seed);
  const std::size_t stride = clean.size() < 40000 ? 1 : 23;
  for (std::size_t p = std::size_t(rng() % stride); p < clean.size(); p += stride) positions.insert(p);
  std::printf(
      "corrupting %zu of %zu byte positions of a log of %zu chunks (payload stride %zu, mt19937_64 seed %llu)\n",
      positions.size(), clean.size(), chunks.size(), stride, static_cast<unsigned long long>(seed));

  std::map<Detected, std::size_t> counts;
  std::vector<std::size_t> missed;
  for (std::size_t p : positions) {
    Bytes damaged = clean;
    damaged[p] ^= static_cast<std::uint8_t>(1 + rng() % 255);
    const Detected d = detect(std::move(damaged));
    ++counts[d];
    if (d == Detected::No) missed.push_back(p);
  }
  std::printf("detected on opening %zu, on reading %zu, on replaying %zu; missed %zu\n", counts[Detected::Opening],
              counts[Detected::Reading], counts[Detected::Replaying], counts[Detected::No]);
  std::string list;
  for (std::size_t i = 0; i < missed.size() && i < 20; ++i) list += " " + std::to_string(missed[i]);
  EXPECT_TRUE(missed.empty()) << missed.size() << " corruptions went unnoticed, at bytes" << list;
}

TEST(ReplayLog, EveryCorruptedByteIsDetected) {
  // 30 s of the spec example: three chunks, about 160 kB.
  const Recorded& rec = specExample(30.0);
  ASSERT_GT(openBytes(rec.bytes).reader.chunks().size(), 1u);
  expectEveryCorruptionDetected(rec.bytes, 0x5EED2024);
}

TEST(ReplayLog, EveryCorruptedByteOfASmallLogIsDetected) {
  // 5 s of the spec example in the classic model: one chunk, a few kB, every byte damaged.
  const Recorded rec = record(requestFor("boards/spec-example.txt", MotionModel::Classic, 5.0),
                              PrecisionChoice{Precision::Double, 0}, "small");
  ASSERT_LT(rec.bytes.size(), 40000u);
  expectEveryCorruptionDetected(rec.bytes, 0x5EED2025);
}

// With the checksums switched off, damaged chunks reach the decoder itself: it must reject or
// misread them, never crash (the sanitizer build runs this too). Whatever it decodes is allowed.
TEST(ReplayLog, DamagedRecordsNeverCrashTheDecoder) {
  const Recorded& rec = specExample(20.0);  // two chunks: the second has a keyframe
  const Bytes& clean = rec.bytes;
  const OpenedLog log = openBytes(clean);
  ASSERT_GT(log.reader.chunks().size(), 1u);
  const std::uint64_t index = indexOffset(clean);
  constexpr std::uint64_t kSeed = 77;
  std::mt19937_64 rng(kSeed);
  std::size_t rejected = 0, tried = 0, replayRejected = 0, replayedIdentical = 0;
  for (std::size_t i = 0; i < log.reader.chunks().size(); ++i) {
    const std::uint64_t from = log.reader.chunks()[i].offset + kFrameHeaderSize;
    const std::uint64_t to =
        (i + 1 < log.reader.chunks().size() ? log.reader.chunks()[i + 1].offset : index) - kFrameChecksumSize;
    // The first bytes (preamble, keyframe) densely, the records sparsely.
    std::vector<std::uint64_t> at;
    for (std::uint64_t p = from; p < from + 200 && p < to; p += 3) at.push_back(p);
    for (int k = 0; k < 40; ++k) at.push_back(from + rng() % (to - from));
    for (std::uint64_t p : at) {
      Bytes damaged = clean;
      damaged[p] ^= static_cast<std::uint8_t>(1 + rng() % 255);
      ++tried;
      try {
        const OpenedLog bad = openBytes(std::move(damaged), /*verifyChecksums=*/false);
        try {
          DecisionStream stream(bad, log.reader.chunks()[i].time);
          for (int n = 0; n < 100000 && stream.next(); ++n) {}
        } catch (const std::exception&) {
          ++rejected;
        }
        // Replaying record by record compares the chunks and explains the first that differs by
        // decoding it. (By digests, damage to records is the checksums' to catch: they are off here.)
        const ReplayReport report = replayLog(bad, ReplayMethod::Records);
        if (report.identical) ++replayedIdentical;
      } catch (const std::exception&) {
        ++replayRejected;
      }
    }
  }
  std::printf(
      "%zu damaged chunks read without checksums (mt19937_64 seed %llu): %zu rejected by the stream, %zu "
      "by replay, %zu replayed as identical\n",
      tried, static_cast<unsigned long long>(kSeed), rejected, replayRejected, replayedIdentical);
  // Even unchecked, a damaged chunk differs from the run's own: replay never calls it identical.
  EXPECT_EQ(replayedIdentical, 0u);
}

// --- truncation ----------------------------------------------------------------------------------------

// --- logs with valid checksums whose records are not what any run could write ------------------------

// A log made by hand: the header frame of `model` (a real log) and one chunk of `records` after a
// first-chunk preamble, with a correct index and trailer.
Bytes handMadeLog(const Bytes& model, const Bytes& records) {
  Bytes out(model.begin(), model.begin() + std::ptrdiff_t(headerFrameEnd(model)));
  auto frame = [&](FrameType type, const Bytes& payload) {
    const std::uint64_t at = out.size();
    out.push_back(static_cast<std::uint8_t>(type));
    out.resize(out.size() + 4);
    putU32(out, out.size() - 4, static_cast<std::uint32_t>(payload.size()));
    out.insert(out.end(), payload.begin(), payload.end());
    out.resize(out.size() + 8);
    putU64(out, out.size() - 8, checksum64(payload, (std::uint64_t(type) << 32) | payload.size()));
    return at;
  };
  std::vector<std::uint8_t> chunk;
  writePreamble(chunk, ChunkPreamble{});
  chunk.insert(chunk.end(), records.begin(), records.end());
  const std::uint64_t chunkAt = frame(FrameType::Chunk, chunk);
  ByteWriter index;
  index.varint(1);
  index.varint(chunkAt);
  index.varint(0);
  index.varint(0);
  index.u64(0);  // time
  index.u64(0);  // digest
  index.u8(1);
  index.varint(0);
  index.u64(0);
  index.varint(0);
  const auto ib = index.bytes();
  const std::uint64_t indexAt = frame(FrameType::Index, Bytes(ib.begin(), ib.end()));
  out.resize(out.size() + 8);
  putU64(out, out.size() - 8, indexAt);
  out.insert(out.end(), kTrailerMagic.begin(), kTrailerMagic.end());
  return out;
}

// Walks every decision; returns the FormatError's message, or "" when the log reads.
std::string walkError(const Bytes& log) {
  try {
    const OpenedLog opened = openBytes(log);
    DecisionStream stream(opened);
    while (stream.next()) {}
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

TEST(ReplayLog, ALogCannotMakeTheReaderHoldMoreEventsThanTheBoardCan) {
  // The crafted log of a 100000-bit MPFR run would hold a huge value for every event it schedules.
  const RunRequest request = requestFor("boards/spec-example.txt", MotionModel::Ballistic, 0.01);
  const Recorded mpfr = record(request, PrecisionChoice{Precision::Mpfr, 100000}, "mpfr-header");
  const Bytes endOfTickNow(100000, 0x07);  // "an end of tick is scheduled now", over and over
  EXPECT_PRED2(contains, walkError(handMadeLog(mpfr.bytes, endOfTickNow)),
               "more queued events than the board can hold");
}

TEST(ReplayLog, EveryRecordHasOneSpelling) {
  const Recorded& rec = specExample(5.0);
  // A recalculate event has only its ball: written in full, it is refused.
  EXPECT_PRED2(contains, walkError(handMadeLog(rec.bytes, Bytes{0x46, 0x02, 0x01, 0x01})), "short form holds");
  EXPECT_PRED2(contains, walkError(handMadeLog(rec.bytes, Bytes{0xA5, 0x02, 0x04})), "bad trigger record");
  EXPECT_PRED2(contains, walkError(handMadeLog(rec.bytes, Bytes{0xB7, 0x02})), "bad action record");
  // A removal whose long distance overflows.
  Bytes overflow{0x8F, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x01};
  overflow.insert(overflow.begin(), 15, 0x07);  // fifteen events scheduled first
  EXPECT_PRED2(contains, walkError(handMadeLog(rec.bytes, overflow)), "distance out of range");
  // The short forms themselves read.
  EXPECT_EQ(walkError(handMadeLog(rec.bytes, Bytes{0x06, 0x02, 0x07, 0x81, 0x80})), "");
}

TEST(ReplayLog, CutOffLogsKeepTheirCompleteChunks) {
  const Recorded& rec = specExample(30.0);
  const Bytes& full = rec.bytes;
  const OpenedLog whole = openBytes(full);
  const std::vector<ChunkEntry>& chunks = whole.reader.chunks();
  ASSERT_GT(chunks.size(), 1u);
  const std::uint64_t firstChunk = headerFrameEnd(full), index = indexOffset(full);
  ASSERT_EQ(chunks.front().offset, firstChunk);

  // Decisions before each chunk, and in all.
  std::vector<std::uint64_t> decisionsBefore;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    ChunkPreamble p;
    readPreamble(whole.reader.chunkPayload(i), p);
    decisionsBefore.push_back(p.decisionsDone);
  }
  std::uint64_t allDecisions = 0;
  {
    DecisionStream stream(whole);
    while (stream.next()) ++allDecisions;
  }
  decisionsBefore.push_back(allDecisions);

  std::set<std::uint64_t> cuts{0,
                               1,
                               7,
                               8,
                               9,
                               10,
                               11,
                               kFileHeaderSize,
                               kFileHeaderSize + 1,
                               kFileHeaderSize + 4,
                               kFileHeaderSize + kFrameHeaderSize,
                               firstChunk - kFrameChecksumSize,
                               firstChunk - 1};
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const std::uint64_t at = chunks[i].offset, end = i + 1 < chunks.size() ? chunks[i + 1].offset : index;
    for (std::uint64_t c : {at, at + 1, at + 4, at + kFrameHeaderSize, at + kFrameHeaderSize + 1, (at + end) / 2,
                            end - kFrameChecksumSize, end - 1})
      cuts.insert(c);
  }
  for (std::uint64_t c : {index, index + 1, index + kFrameHeaderSize, full.size() - kTrailerSize - 1,
                          full.size() - kTrailerSize, full.size() - kTrailerSize + 1, full.size() - 8, full.size() - 1})
    cuts.insert(c);

  for (std::uint64_t cut : cuts) {
    SCOPED_TRACE("log cut at byte " + std::to_string(cut) + " of " + std::to_string(full.size()));
    const Bytes bytes(full.begin(), full.begin() + std::ptrdiff_t(cut));
    if (cut < firstChunk) {
      const std::string message = messageOf([&] { (void)openBytes(bytes); });
      EXPECT_TRUE(contains(message, cut < kFileHeaderSize    ? "too short"
                                    : cut == kFileHeaderSize ? "ends before its header frame"
                                                             : "header frame is cut off"))
          << message;
      continue;
    }
    std::size_t complete = 0;
    while (complete < chunks.size() && (complete + 1 < chunks.size() ? chunks[complete + 1].offset : index) <= cut)
      ++complete;
    std::optional<OpenedLog> log;
    try {
      log.emplace(openBytes(bytes));
    } catch (const std::exception& e) {
      ADD_FAILURE() << "a cut log must open: " << e.what();
      continue;
    }
    EXPECT_NE(log->reader.truncation(), "");
    ASSERT_EQ(log->reader.chunks().size(), complete) << log->reader.truncation();
    for (std::size_t i = 0; i < complete; ++i) {
      EXPECT_EQ(log->reader.chunks()[i].offset, chunks[i].offset);
      EXPECT_EQ(log->reader.chunks()[i].eventsDone, chunks[i].eventsDone);
      EXPECT_EQ(log->reader.chunks()[i].ticksDone, chunks[i].ticksDone);
      EXPECT_EQ(log->reader.chunks()[i].time, chunks[i].time);
    }
    // Only a cut inside the trailer leaves the index (and with it the run's end) readable.
    EXPECT_EQ(log->reader.end().has_value(), cut >= full.size() - kTrailerSize);

    std::uint64_t walked = 0;
    try {
      DecisionStream stream(*log);
      while (stream.next()) ++walked;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "walking the complete chunks threw: " << e.what();
    }
    EXPECT_EQ(walked, decisionsBefore[complete]);

    const ReplayReport report = replayLog(*log);
    EXPECT_TRUE(report.identical) << describe(report);
    EXPECT_TRUE(contains(report.note, "cut off")) << "note: " << report.note;
    // The events the complete chunks hold (not those of the run's chunk beyond them).
    if (complete < chunks.size()) {
      EXPECT_EQ(report.events, chunks[complete].eventsDone);
    }
  }
}

// --- files that are not logs ---------------------------------------------------------------------------

TEST(ReplayLog, BadFilesSayWhatIsWrong) {
  const Bytes& good = specExample(5.0).bytes;
  auto openedMessage = [](Bytes b) { return messageOf([&] { (void)openBytes(std::move(b)); }); };

  {
    const std::string path = tempPath("empty");
    writeBytes(path, {});
    const std::string message = messageOf([&] { (void)openLog(path); });
    std::remove(path.c_str());
    EXPECT_TRUE(contains(message, "too short")) << message;
    EXPECT_TRUE(contains(message, path)) << "the message names the file: " << message;
  }
  {
    Bytes b = good;
    b[0] = 'X';
    const std::string message = openedMessage(b);
    EXPECT_TRUE(contains(message, "bad magic")) << message;
  }
  {
    Bytes b = good;
    b[8] = 6;  // u16 format version, little-endian
    b[9] = 0;
    const std::string message = openedMessage(b);
    EXPECT_TRUE(contains(message, "version 6 is newer than this build reads (5)")) << message;
  }
  {
    Bytes b = good;
    b[8] = 5;  // a branch log's version on an ordinary log: its header names no parent
    const std::string message = openedMessage(b);
    EXPECT_TRUE(contains(message, "does not name its parent")) << message;
  }
  {
    Bytes b = good;
    b[8] = 0;  // version 256: the high byte counts
    b[9] = 1;
    const std::string message = openedMessage(b);
    EXPECT_TRUE(contains(message, "version 256 is newer")) << message;
  }
  // Before chunk digests; before the board's warnings; before the scalar's binary format.
  for (const std::uint8_t old : {1, 2, 3}) {
    Bytes b = good;
    b[8] = old;
    const std::string message = openedMessage(b);
    EXPECT_TRUE(contains(
        message, "version " + std::to_string(old) + " is older than this build reads (4); record the run again"))
        << message;
  }
  {
    Bytes b = good;
    putU32(b, kFileHeaderSize + 1, 0xFFFFFFF0u);  // the header frame's length
    const std::string message = openedMessage(b);
    EXPECT_TRUE(contains(message, "absurd frame length")) << message;
  }
  {
    // A chunk's length, in a log without its index (so that the frames are walked)...
    const OpenedLog log = openBytes(good);
    const std::uint64_t chunk = log.reader.chunks().front().offset;
    Bytes b(good.begin(), good.begin() + std::ptrdiff_t(indexOffset(good)));
    putU32(b, chunk + 1, 0xFFFFFFF0u);
    EXPECT_TRUE(contains(openedMessage(b), "absurd frame length")) << openedMessage(b);
    // ...and in a complete log, where the chunk is only read when asked for.
    Bytes c = good;
    putU32(c, chunk + 1, 0xFFFFFFF0u);
    const OpenedLog opened = openBytes(c);
    const std::string message = messageOf([&] { (void)opened.reader.chunkPayload(0); });
    EXPECT_TRUE(contains(message, "absurd frame length")) << message;
    const std::string streamed = messageOf([&] {
      DecisionStream stream(opened);
      while (stream.next()) {}
    });
    EXPECT_TRUE(contains(streamed, "absurd frame length")) << streamed;
  }
}

// --- seeking --------------------------------------------------------------------------------------------

struct Moment {
  std::string time;
  std::uint64_t events = 0;
  std::vector<std::string> balls;  // name, position and velocity in exact text
  bool operator==(const Moment&) const = default;
};

std::ostream& operator<<(std::ostream& os, const Moment& m) {
  os << "t=" << m.time << " after " << m.events << " events";
  for (const std::string& b : m.balls) os << "\n    " << b;
  return os;
}

Moment momentOf(const StateView& s) {
  Moment m{s.time.text, s.events, {}};
  for (const BallView& b : s.balls)
    m.balls.push_back(b.name + " at (" + b.x.text + ", " + b.y.text + ") v (" + b.vx.text + ", " + b.vy.text + ")");
  return m;
}

// The same run, not recorded, limited directly on the board; positions taken when it stopped
// (an event limit) or at the time asked for (a time limit).
Moment directMoment(const RunRequest& request, const PrecisionChoice& precision, const SeekTarget& target) {
  return withRecordablePrecision(precision, [&]<class Real>() {
    std::unique_ptr<GameBoard<Real>> board = prepareRun<Real>(request);
    typename GameBoard<Real>::RunLimit limit;
    if (target.events) limit.events = *target.events;
    if (target.time) limit.time = fromDouble<Real>(*target.time);
    board->setRunLimit(limit);
    continueRun(*board, request, 0);
    const Real at = target.time ? fromDouble<Real>(*target.time) : board->now();
    Moment m{exactText(at), board->executedTotal(), {}};
    for (GizmoId id : board->ballIds()) {
      const Ball<Real>& b = *board->gizmo(id).asBall();
      const Vec2<Real> p = b.positionAt(at), v = b.velocityAt(at);
      m.balls.push_back(b.name() + " at (" + exactText(p.x) + ", " + exactText(p.y) + ") v (" + exactText(v.x) + ", " +
                        exactText(v.y) + ")");
    }
    return m;
  });
}

SeekTarget atEvents(std::uint64_t n) {
  SeekTarget t;
  t.events = n;
  return t;
}
SeekTarget atTime(double time) {
  SeekTarget t;
  t.time = time;
  return t;
}

struct SeekCase {
  MotionModel model;
  Precision precision;
  double seconds;
  const char* board = "boards/spec-example.txt";
};
void PrintTo(const SeekCase& c, std::ostream* os) {
  *os << c.board << " " << (c.model == MotionModel::Ballistic ? "ballistic " : "classic ")
      << precisionName({c.precision, 0}) << " " << c.seconds << " s";
}

class ReplaySeek : public ::testing::TestWithParam<SeekCase> {
 protected:
  void SetUp() override {
    const SeekCase& c = GetParam();
    request_ = requestFor(c.board, c.model, c.seconds);
    precision_ = PrecisionChoice{c.precision, 0};
    recorded_ = record(request_, precision_, "seek");
    log_.emplace(openBytes(recorded_.bytes));
    ASSERT_GT(log_->reader.chunks().size(), 1u) << "seeking should start from keyframes";
  }
  RunRequest request_;
  PrecisionChoice precision_;
  Recorded recorded_;
  std::optional<OpenedLog> log_;
};

TEST_P(ReplaySeek, ByEventsMatchesADirectRun) {
  const std::uint64_t total = recorded_.result.summary.total;
  std::set<std::uint64_t> targets{0, 1, total / 2, total - 1, total};
  for (const ChunkEntry& c : log_->reader.chunks())  // at, and either side of, each keyframe
    for (std::uint64_t n : {c.eventsDone - 1, c.eventsDone, c.eventsDone + 1})
      if (n <= total) targets.insert(n);
  for (std::uint64_t n : targets) {
    SCOPED_TRACE("events = " + std::to_string(n));
    const Moment seeked = momentOf(seekLog(*log_, atEvents(n)));
    EXPECT_EQ(seeked, directMoment(request_, precision_, atEvents(n)));
    EXPECT_EQ(seeked.events, n);
  }
}

TEST_P(ReplaySeek, ByTimeMatchesADirectRun) {
  const double end = request_.duration;
  std::set<double> targets{0.0, 0.025, 1.0, 7.3, end / 2, end - 0.01, end};
  for (const ChunkEntry& c : log_->reader.chunks())  // at, and either side of, each keyframe
    for (double t : {c.time - 1e-9, c.time, c.time + 1e-9})
      if (t >= 0 && t <= end) targets.insert(t);
  for (double t : targets) {
    SCOPED_TRACE("time = " + exactText(t));
    EXPECT_EQ(momentOf(seekLog(*log_, atTime(t))), directMoment(request_, precision_, atTime(t)));
  }
}

TEST_P(ReplaySeek, PastTheLastEventThrows) {
  const std::uint64_t total = recorded_.result.summary.total;
  EXPECT_NO_THROW((void)seekLog(*log_, atEvents(total)));
  try {
    (void)seekLog(*log_, atEvents(total + 1));
    ADD_FAILURE() << "seeking past the last event did not throw";
  } catch (const std::exception& e) {
    EXPECT_TRUE(contains(e.what(), std::to_string(total))) << "the message gives the run's events: " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(SpecExample, ReplaySeek,
                         ::testing::Values(SeekCase{MotionModel::Ballistic, Precision::Double, 60.0},
                                           SeekCase{MotionModel::Classic, Precision::LongDouble, 150.0},
                                           // boosts are decisions that seeking must reproduce
                                           SeekCase{MotionModel::Ballistic, Precision::Double, 60.0,
                                                    "boards/gizmos/booster.txt"}),
                         [](const ::testing::TestParamInfo<SeekCase>& info) {
                           // Boards other than the spec example add their name: "booster" → "Booster".
                           std::string board = std::filesystem::path(info.param.board).stem().string();
                           if (board == "spec-example") board.clear();
                           std::erase_if(board, [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); });
                           if (!board.empty()) board[0] = char(std::toupper(static_cast<unsigned char>(board[0])));
                           return board +
                                  std::string(info.param.model == MotionModel::Ballistic ? "Ballistic" : "Classic") +
                                  (info.param.precision == Precision::Double ? "Double" : "LongDouble");
                         });

// --- walking ---------------------------------------------------------------------------------------------

TEST(ReplayLog, DecisionStreamSeesEveryExecutedEvent) {
  for (MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    SCOPED_TRACE(model == MotionModel::Ballistic ? "ballistic" : "classic");
    const Recorded rec =
        record(requestFor("boards/spec-example.txt", model, 150.0), PrecisionChoice{Precision::Double, 0}, "walk");
    const OpenedLog log = openBytes(rec.bytes);
    ASSERT_GT(log.reader.chunks().size(), 1u);
    DecisionStream stream(log);
    std::uint64_t decisions = 0, executed = 0;
    double lastTime = 0;
    while (const std::optional<DecisionView> d = stream.next()) {
      ASSERT_EQ(d->index, decisions);
      ASSERT_EQ(d->eventIndex, executed);
      ASSERT_LE(lastTime, d->time.value) << "time goes back at " << describe(d);
      lastTime = d->time.value;
      ++decisions;
      if (d->type != DecisionType::Executed) continue;
      ++executed;
      EXPECT_EQ(d->eventTime.text, d->time.text) << "an event runs at its own time: " << describe(d);
    }
    EXPECT_EQ(executed, rec.result.summary.total);
    EXPECT_EQ(lastTime, rec.result.summary.time);

    // Starting later: from the keyframe at or before the time asked for.
    const ChunkEntry& last = log.reader.chunks().back();
    ChunkPreamble p;
    readPreamble(log.reader.chunkPayload(log.reader.chunks().size() - 1), p);
    DecisionStream late(log, last.time + 0.01);
    std::uint64_t lateExecuted = 0, lateDecisions = 0;
    while (const std::optional<DecisionView> d = late.next()) {
      if (lateDecisions++ == 0) {
        EXPECT_EQ(d->index, p.decisionsDone);
        EXPECT_EQ(d->eventIndex, last.eventsDone);
      }
      if (d->type == DecisionType::Executed) ++lateExecuted;
    }
    EXPECT_EQ(lateDecisions, decisions - p.decisionsDone);
    EXPECT_EQ(lateExecuted, rec.result.summary.total - last.eventsDone);
  }
}

// --- golden logs -------------------------------------------------------------------------------------------

// One line of fixtures/logs/golden.txt, which scripts/dev cross-check reads too.
struct GoldenCase {
  std::string file;   // in fixtures/logs/
  std::string board;  // in fixtures/
  MotionModel model = MotionModel::Ballistic;
  PrecisionChoice precision;
  double seconds = 0;
  bool keys = false;       // fixtures/keys/flippers.keys
  std::string recordedOn;  // "host", or the cross target whose scalar format it holds
};
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.file; }

std::vector<GoldenCase> goldenCases() {
  std::ifstream in(fixture("logs/golden.txt"));
  std::vector<GoldenCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    GoldenCase g;
    std::string model, precision, keys;
    words >> g.file >> g.board >> model >> precision >> g.seconds >> keys >> g.recordedOn;
    const std::optional<PrecisionChoice> p = parsePrecision(precision);
    if (!words || !p || (model != "ballistic" && model != "classic") || (keys != "keys" && keys != "-"))
      throw std::runtime_error("fixtures/logs/golden.txt: cannot read the line '" + line + "'");
    g.model = model == "ballistic" ? MotionModel::Ballistic : MotionModel::Classic;
    g.precision = *p;
    g.keys = keys == "keys";
    cases.push_back(g);
  }
  if (cases.empty()) throw std::runtime_error("fixtures/logs/golden.txt lists no log");
  return cases;
}

// The board reader's warnings about a fixture board as `gizmo record fixtures/BOARD` gives them,
// run from the tree's root: scripts/dev cross-check records the golden runs that way on every
// target and compares the bytes, and the header keeps the warnings.
std::vector<std::string> goldenBoardWarnings(const std::string& board) {
  std::ifstream in(fixture(board), std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> out;
  for (const io::Diagnostic& d : io::readBoardString(text, "fixtures/" + board).warnings) out.push_back(io::format(d));
  return out;
}

bool updatingGolden() {
  const char* v = std::getenv("GIZMO_UPDATE_GOLDEN");
  return v && std::string(v) == "1";
}

class ReplayGolden : public ::testing::TestWithParam<GoldenCase> {};

// This build records each golden run again; its chunks and the header's run description (not
// the toolkit version that wrote the header) must match the committed file exactly. With
// GIZMO_UPDATE_GOLDEN=1 the committed file is rewritten instead.
TEST_P(ReplayGolden, ThisBuildRecordsTheCommittedLog) {
  const GoldenCase& g = GetParam();
  const std::string path = fixture("logs/" + g.file);
  // A log recorded on another machine (long double as binary128, on aarch64) is checked by
  // scripts/dev cross-check on the targets that compute its format; where the format differs
  // from this build's, replaying it must be refused.
  if (g.recordedOn != "host") {
    const OpenedLog committed = openLog(path);
    const std::string here =
        withRecordablePrecision(committed.precision, []<class Real>() { return scalarFormat<Real>(); });
    if (committed.header.format != here)
      EXPECT_THROW(replayLog(committed), FormatError) << "a log of another format must not replay here";
    else EXPECT_TRUE(replayLog(committed).identical);
    GTEST_SKIP() << g.file << " was recorded on " << g.recordedOn << " (" << committed.header.format
                 << "); scripts/dev cross-check compares its bytes there";
  }
  const RunRequest request = requestFor(g.board, g.model, g.seconds, g.keys);
  const Recorded fresh = record(request, g.precision, "golden", goldenBoardWarnings(g.board));
  ASSERT_TRUE(fresh.result.completed) << fresh.result.error;
  if (updatingGolden()) {
    std::filesystem::create_directories(fixture("logs"));
    writeBytes(path, fresh.bytes);
    const ReplayReport check = replayLog(openLog(path));
    EXPECT_TRUE(check.identical) << describe(check);
    std::printf("GIZMO_UPDATE_GOLDEN=1: rewrote %s (%zu bytes)\n", path.c_str(), fresh.bytes.size());
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing; GIZMO_UPDATE_GOLDEN=1 writes it";
  const OpenedLog committed = openLog(path);
  const OpenedLog ours = openBytes(fresh.bytes);
  // The codecs only build where each scalar has the layout the log stores (scalar_codec.hpp), so
  // the scalar names must agree.
  ASSERT_EQ(committed.header.scalar, ours.header.scalar);

  const LogHeader &a = committed.header, &b = ours.header;
  EXPECT_EQ(a.precision, b.precision);
  EXPECT_EQ(a.model, b.model);
  EXPECT_EQ(a.maxTick, b.maxTick);
  EXPECT_EQ(a.duration, b.duration);
  EXPECT_EQ(a.board, b.board);
  EXPECT_EQ(a.boardHash, b.boardHash);
  EXPECT_EQ(a.boardWarnings, b.boardWarnings) << "the board reader's warnings, as gizmo record gives them";
  EXPECT_EQ(a.params, b.params) << "this build derives other simulation parameters from the board";
  ASSERT_EQ(a.keys.size(), b.keys.size());
  for (std::size_t i = 0; i < a.keys.size(); ++i) {
    EXPECT_EQ(a.keys[i].time, b.keys[i].time) << "key " << i;
    EXPECT_EQ(a.keys[i].key, b.keys[i].key) << "key " << i;
    EXPECT_EQ(a.keys[i].direction, b.keys[i].direction) << "key " << i;
  }

  std::optional<std::size_t> firstDifferent;
  const std::size_t n = std::max(committed.reader.chunks().size(), ours.reader.chunks().size());
  for (std::size_t i = 0; i < n && !firstDifferent; ++i)
    if (i >= committed.reader.chunks().size() || i >= ours.reader.chunks().size() ||
        committed.reader.chunkPayload(i) != ours.reader.chunkPayload(i))
      firstDifferent = i;
  ASSERT_TRUE(committed.reader.end().has_value());
  ASSERT_TRUE(ours.reader.end().has_value());
  const bool endsAlike = committed.reader.end()->completed == ours.reader.end()->completed &&
                         committed.reader.end()->events == ours.reader.end()->events &&
                         committed.reader.end()->time == ours.reader.end()->time &&
                         committed.reader.end()->message == ours.reader.end()->message;
  if (firstDifferent || !endsAlike) {
    // Say which decision parts them: replay the committed log with this build.
    const ReplayReport report = replayLog(committed);
    ADD_FAILURE() << "this build no longer records " << g.file << " ("
                  << (firstDifferent ? "chunk " + std::to_string(*firstDifferent) + " differs"
                                     : "the run ends differently")
                  << ").\nReplaying the committed log: " << describe(report)
                  << "\nIf the change is deliberate, rerun with GIZMO_UPDATE_GOLDEN=1 (fixtures/logs/README.md).";
  }
}

INSTANTIATE_TEST_SUITE_P(FixturesLogs, ReplayGolden, ::testing::ValuesIn(goldenCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.'));
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
