// Branch logs (replay.hpp: recordBranch; docs/replay-format.md, "Branch logs"):
//   - branching a log at event N and giving it the parent's own key input makes the parent's
//     decisions again from the branch log's start on, every value to the last bit, and ends as the
//     parent ended: on every golden board, in both motion models, at branch points inside a tick,
//     at an end of tick, with a key held, with a flipper mid-swing, with a spawned ball, at a
//     keyframe and between keyframes;
//   - a branch log replays identically, seeks, walks and compares with its parent on its own,
//     and so does a branch of a branch; a parent recorded at MPFR precision too;
//   - other key input parts from the parent only after the branch point's tick starts;
//   - a point beyond the log, a cut-off parent, a branch ending before its point, a diff against
//     a log that is not the parent: refused, with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gizmo/core/gizmos/spawner.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/io/key_script.hpp"
#include "gizmo/replay/checksum.hpp"
#include "gizmo/replay/log_file.hpp"
#include "gizmo/replay/replay.hpp"
#include "support/fixture_request.hpp"
#include "support/paths.hpp"

namespace {

using namespace gizmo;
using namespace gizmo::replay;
using Bytes = std::vector<std::uint8_t>;

std::vector<TimedKey> flipperKeys() {
  std::vector<TimedKey> keys;
  for (const io::KeyInput& k : io::readKeyScriptFile(test::fixturePath("keys/flippers.keys")))
    keys.push_back(TimedKey{k.time, k.key, k.direction});
  return keys;
}

// A sink that keeps a log's bytes, and says whether anything came at all.
struct MemoryLog {
  Bytes bytes;
  LogWriter writer{bytes};
};

// A parent run: a board of the golden list (fixtures/logs/golden.txt) in one model and scalar.
struct ParentCase {
  std::string board;  // in fixtures/
  MotionModel model = MotionModel::Ballistic;
  std::string precision;
  double seconds = 0;
  bool keys = false;
};
void PrintTo(const ParentCase& c, std::ostream* os) {
  *os << c.board << " " << motionModelName(c.model) << " " << c.precision << " " << c.seconds << "s"
      << (c.keys ? " keys" : "");
}

// Every board of the golden list in both models, in the scalar and for the time it is listed
// with (one case per board, model and scalar), and the spawner board with the flipper keys.
std::vector<ParentCase> parentCases() {
  std::ifstream in(test::fixturePath("logs/golden.txt"));
  std::vector<ParentCase> cases;
  std::set<std::string> seen;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string file, board, model, precision, keys, on;
    double seconds = 0;
    words >> file >> board >> model >> precision >> seconds >> keys >> on;
    if (!words || on != "host") continue;
    for (const MotionModel m : {MotionModel::Ballistic, MotionModel::Classic}) {
      const std::string id = board + " " + std::string(motionModelName(m)) + " " + precision;
      if (!seen.insert(id).second) continue;
      // The longer of a board's runs in one scalar (spec example: 25 s, which spans two chunks).
      cases.push_back(ParentCase{board, m, precision, seconds, keys == "keys"});
    }
  }
  for (ParentCase& c : cases) {
    std::ifstream again(test::fixturePath("logs/golden.txt"));
    while (std::getline(again, line)) {
      std::istringstream words(line);
      std::string file, board, model, precision;
      double seconds = 0;
      words >> file >> board >> model >> precision >> seconds;
      if (words && board == c.board && precision == c.precision) c.seconds = std::max(c.seconds, seconds);
    }
  }
  for (const MotionModel m : {MotionModel::Ballistic, MotionModel::Classic})
    cases.push_back(ParentCase{"boards/gizmos/spawner.txt", m, "double", 3, true});
#ifndef GIZMO_PORTABLE
  // A parent recorded at MPFR precision (a scalar whose exact encoding is longer than its
  // hardware floats'; the golden list has none): the branch keeps its scalar.
  cases.push_back(ParentCase{"boards/spec-example.txt", MotionModel::Ballistic, "mpfr:128", 2, true});
#endif
  return cases;
}

OpenedLog openBytes(const Bytes& bytes) { return openLog(ByteSource::memory(bytes)); }

Bytes recordParent(const ParentCase& c) {
  RunRequest request = test::fixtureRequest(c.board, c.model, c.seconds);
  if (c.keys) request.keys = flipperKeys();
  MemoryLog log;
  const RecordResult r = recordRun(request, *parsePrecision(c.precision), log.writer);
  EXPECT_TRUE(r.completed) << r.error;
  return log.bytes;
}

Bytes branchOf(const OpenedLog& parent, std::uint64_t event, const std::vector<TimedKey>& keys) {
  BranchRequest request;
  request.at.events = event;
  request.keys = keys;
  MemoryLog log;
  const BranchResult r = recordBranch(parent, request, log.writer);
  EXPECT_TRUE(r.record.completed) << r.record.error;
  EXPECT_EQ(r.origin.event, event);
  return log.bytes;
}

std::vector<DecisionView> decisionsOf(const OpenedLog& log) {
  std::vector<DecisionView> out;
  DecisionStream stream(log);
  while (std::optional<DecisionView> d = stream.next()) out.push_back(std::move(*d));
  return out;
}

// Two decisions with every field alike, values compared by their exact text (every bit).
std::string differenceOf(const DecisionView& x, const DecisionView& y) {
  std::ostringstream why;
  auto field = [&](const char* name, const auto& a, const auto& b) {
    if (!(a == b) && why.str().empty()) why << name;
  };
  field("index", x.index, y.index);
  field("event index", x.eventIndex, y.eventIndex);
  field("type", x.type, y.type);
  field("time", x.time.text, y.time.text);
  field("event time", x.eventTime.text, y.eventTime.text);
  field("kind", x.kind, y.kind);
  field("a", x.a, y.a);
  field("b", x.b, y.b);
  field("feature", x.feature, y.feature);
  field("sequence", x.sequence, y.sequence);
  field("gizmo", x.gizmo, y.gizmo);
  field("other", x.other, y.other);
  field("key", x.key, y.key);
  field("direction", x.direction, y.direction);
  field("rule", x.rule, y.rule);
  field("balls", x.balls.size(), y.balls.size());
  for (std::size_t i = 0; i < std::min(x.balls.size(), y.balls.size()); ++i) {
    const BallView &p = x.balls[i], &q = y.balls[i];
    field("ball", p.ball, q.ball);
    for (const auto& [a, b] : {std::pair{p.x, q.x}, std::pair{p.y, q.y}, std::pair{p.vx, q.vx}, std::pair{p.vy, q.vy},
                               std::pair{p.vxBefore, q.vxBefore}, std::pair{p.vyBefore, q.vyBefore}})
      field("ball value", a.text, b.text);
  }
  return why.str();
}

std::string stateText(const StateView& s) {
  std::string out = s.time.text + " " + std::to_string(s.events);
  for (const BallView& b : s.balls)
    out += " " + b.name + " " + b.x.text + " " + b.y.text + " " + b.vx.text + " " + b.vy.text;
  for (const std::string& q : s.queue) out += "\n" + q;
  return out;
}

// The branch points to try in a parent, each with what it is; found from its decisions.
struct Point {
  std::uint64_t event;
  std::string what;
};
std::vector<Point> branchPoints(const OpenedLog& parent, const std::vector<DecisionView>& d) {
  std::vector<Point> points{{0, "the start"}};
  const std::uint64_t total = parent.reader.end()->events;
  std::optional<std::uint64_t> firstTickEnd, midTickEnd, midTick, keyHeld, pressed, midSwing, spawned;
  std::optional<std::uint64_t> downAt;
  for (const DecisionView& v : d) {
    const std::uint64_t after = v.eventIndex + 1;  // the events once an executed event has run
    if (v.type == DecisionType::Executed && v.kind == EventKind::EndOfTick) {
      if (!firstTickEnd) firstTickEnd = after;
      if (!midTickEnd && after >= total / 2) midTickEnd = after;
    }
    if (v.type == DecisionType::Executed && v.kind == EventKind::Collision && !midTick && after >= total / 3)
      midTick = after;
    if (v.type == DecisionType::Executed && v.kind == EventKind::Input) {
      if (v.b == 0 && !downAt) downAt = after;
      if (v.b == 1 && downAt && !keyHeld && after > *downAt + 1) keyHeld = (*downAt + after) / 2;
    }
    if (v.type == DecisionType::Action && !pressed && downAt) pressed = v.eventIndex;  // right after the press
    if (v.type == DecisionType::Executed && v.kind == EventKind::FlipperStop && pressed && !midSwing &&
        v.eventIndex > *pressed)
      midSwing = v.eventIndex;  // the last event before the flipper stops
    if (v.type == DecisionType::Rule && v.rule == SpawnerRule::Spawned && !spawned) spawned = v.eventIndex;
  }
  auto add = [&](const std::optional<std::uint64_t>& n, const std::string& what) {
    if (n) points.push_back({*n, what});
  };
  add(firstTickEnd, "the end of the first tick");
  add(midTickEnd, "an end of tick halfway");
  add(midTick, "inside a tick, after a collision");
  add(keyHeld, "with a key held");
  add(pressed, "right after a key press");
  add(midSwing, "with a flipper mid-swing");
  add(spawned, "right after a ball was spawned");
  const std::vector<ChunkEntry>& chunks = parent.reader.chunks();
  for (std::size_t i = 1; i < chunks.size(); ++i) {
    points.push_back({chunks[i].eventsDone, "at keyframe " + std::to_string(i)});
    points.push_back({(chunks[i - 1].eventsDone + chunks[i].eventsDone) / 2 + 1, "between keyframes"});
  }
  points.push_back({total > 0 ? total - 1 : 0, "one event before the end"});
  points.push_back({total, "the end"});
  return points;
}

class ReplayBranch : public ::testing::TestWithParam<ParentCase> {};

// The heart of branching: with the parent's own key input, a branch at any point is the parent's
// run from the branch log's start on, bit for bit, and stands alone as a log.
TEST_P(ReplayBranch, WithTheParentsKeysMakesTheParentsDecisions) {
  const ParentCase& c = GetParam();
  const Bytes parentBytes = recordParent(c);
  const OpenedLog parent = openBytes(parentBytes);
  const std::vector<DecisionView> theirs = decisionsOf(parent);
  const std::vector<Point> points = branchPoints(parent, theirs);
  ASSERT_GE(points.size(), 5u);
  if (c.keys) {
    const auto named = [&](const std::string& what) {
      return std::any_of(points.begin(), points.end(), [&](const Point& p) { return p.what == what; });
    };
    EXPECT_TRUE(named("with a key held"));
    if (c.board.find("spawner") != std::string::npos) {
      EXPECT_TRUE(named("right after a ball was spawned"));
    } else {
      EXPECT_TRUE(named("with a flipper mid-swing"));
    }
  }
  for (const Point& p : points) {
    SCOPED_TRACE("branch at event " + std::to_string(p.event) + ", " + p.what);
    const Bytes branchBytes = branchOf(parent, p.event, parent.request.keys);
    const OpenedLog branch = openBytes(branchBytes);
    ASSERT_TRUE(branch.header.parent);
    EXPECT_EQ(branch.header.parent->parentDigest, checksum64(parentBytes));
    EXPECT_EQ(branch.header.parent->event, p.event);
    EXPECT_EQ(branch.reader.formatVersion(), 5);

    // Decision for decision, from the branch's first one to the end.
    const std::vector<DecisionView> ours = decisionsOf(branch);
    ChunkPreamble start;
    readPreamble(branch.reader.chunkPayload(0), start);
    EXPECT_TRUE(start.hasKeyframe);
    const std::uint64_t first = start.decisionsDone;
    ASSERT_LE(first, theirs.size());
    ASSERT_EQ(ours.size(), theirs.size() - first);
    for (std::size_t i = 0; i < ours.size(); ++i) {
      const std::string why = differenceOf(ours[i], theirs[first + i]);
      ASSERT_TRUE(why.empty()) << "decision " << first + i << ": " << why;
    }
    // It starts at or before the branch point, at a tick boundary (after a tick record), or at
    // the board as built, before the first tick (after the events its building scheduled).
    EXPECT_LE(start.eventsDone, p.event);
    if (start.ticksDone == 0) {
      for (std::uint64_t i = 0; i < first; ++i) EXPECT_EQ(theirs[i].type, DecisionType::Scheduled) << "decision " << i;
    } else {
      ASSERT_GT(first, 0u);
      EXPECT_EQ(theirs[first - 1].type, DecisionType::Tick);
    }
    ASSERT_TRUE(branch.reader.end());
    EXPECT_EQ(branch.reader.end()->events, parent.reader.end()->events);
    EXPECT_EQ(branch.reader.end()->time, parent.reader.end()->time);
    EXPECT_EQ(branch.reader.end()->completed, parent.reader.end()->completed);

    // On its own: replays identically both ways, and seeks to the parent's state.
    const ReplayReport byDigests = replayLog(branch);
    EXPECT_TRUE(byDigests.identical) << byDigests.where;
    EXPECT_TRUE(byDigests.byDigests);
    const ReplayReport byRecords = replayLog(branch, ReplayMethod::Records);
    EXPECT_TRUE(byRecords.identical) << byRecords.where;
    EXPECT_EQ(stateText(seekLog(branch, SeekTarget{p.event, std::nullopt})),
              stateText(seekLog(parent, SeekTarget{p.event, std::nullopt})));

    const DiffReport diff = diffLogs(parent, branch, 3, false);
    EXPECT_FALSE(diff.parted) << diff.where;
    EXPECT_EQ(diff.firstDecision, first);
    EXPECT_EQ(diff.matched, ours.size());
  }
}

// A branch of a branch: the same decisions again, compared with its own parent; its grandparent
// is not its parent.
TEST_P(ReplayBranch, BranchOfABranchMakesTheSameDecisions) {
  const ParentCase& c = GetParam();
  const Bytes parentBytes = recordParent(c);
  const OpenedLog parent = openBytes(parentBytes);
  const std::uint64_t total = parent.reader.end()->events;
  const Bytes firstBytes = branchOf(parent, total / 3, parent.request.keys);
  const OpenedLog first = openBytes(firstBytes);
  const Bytes secondBytes = branchOf(first, 2 * total / 3 + 1, first.request.keys);
  const OpenedLog second = openBytes(secondBytes);
  EXPECT_EQ(second.header.parent->parentDigest, checksum64(firstBytes));
  EXPECT_TRUE(replayLog(second).identical);
  const DiffReport againstFirst = diffLogs(first, second, 3, false);
  EXPECT_FALSE(againstFirst.parted) << againstFirst.where;
  const std::vector<DecisionView> theirs = decisionsOf(parent), ours = decisionsOf(second);
  ASSERT_FALSE(ours.empty());
  const std::uint64_t from = ours.front().index;
  ASSERT_EQ(ours.size(), theirs.size() - from);
  for (std::size_t i = 0; i < ours.size(); ++i)
    ASSERT_EQ(differenceOf(ours[i], theirs[from + i]), "") << "decision " << from + i;
  // The two branches of one parent compare from where the later starts.
  const Bytes siblingBytes = branchOf(parent, total / 2, parent.request.keys);
  const DiffReport siblings = diffLogs(first, openBytes(siblingBytes), 3, false);
  EXPECT_FALSE(siblings.parted) << siblings.where;
  EXPECT_THROW(diffLogs(parent, second, 3, false), BranchError);
}

std::vector<ParentCase> allParents() { return parentCases(); }
INSTANTIATE_TEST_SUITE_P(GoldenBoards, ReplayBranch, ::testing::ValuesIn(allParents()),
                         [](const ::testing::TestParamInfo<ParentCase>& info) {
                           std::string name = info.param.board + "_" + std::string(motionModelName(info.param.model)) +
                                              "_" + info.param.precision;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

// The spec example with the flipper keys, ballistic, 5 s: the parent of the tests below.
Bytes specParent() {
  return recordParent(ParentCase{"boards/spec-example.txt", MotionModel::Ballistic, "double", 5, true});
}

// Other key input: the branch goes its own way, and the logs part no earlier than the start of
// the branch point's tick, where its keys are queued; with no key of the parent's in that tick
// after the point, no earlier than the point itself.
TEST(ReplayBranchKeys, OtherKeysPartAfterTheBranchPoint) {
  const Bytes parentBytes = specParent();
  const OpenedLog parent = openBytes(parentBytes);
  const std::vector<DecisionView> theirs = decisionsOf(parent);
  // The parent presses the space bar at 1.0 s; branch at 0.77 s (no key of the parent's in that
  // tick) with none, and at 0.5 s with an extra press at 0.6 s.
  for (const auto& [at, keys] :
       {std::pair{0.77, std::vector<TimedKey>{}},
        std::pair{0.5, std::vector<TimedKey>{{0.6, 32, KeyDirection::Down}, {0.65, 32, KeyDirection::Up}}}}) {
    SCOPED_TRACE("branch at " + std::to_string(at) + " s");
    BranchRequest request;
    request.at.time = at;
    request.keys = keys;
    MemoryLog log;
    const BranchResult r = recordBranch(parent, request, log.writer);
    const OpenedLog branch = openBytes(log.bytes);
    EXPECT_TRUE(replayLog(branch).identical);
    const DiffReport diff = diffLogs(parent, branch, 3, false);
    ASSERT_TRUE(diff.parted);
    ASSERT_TRUE(diff.first && diff.second);
    // The decision at which event N is done: the logs agree at least that far.
    std::uint64_t pointDecision = 0;
    for (const DecisionView& d : theirs)
      if (d.type == DecisionType::Executed && d.eventIndex + 1 == r.origin.event) pointDecision = d.index;
    EXPECT_GT(diff.firstDecision + diff.matched, pointDecision);
    EXPECT_GE(diff.second->time.value, at);
  }
}

// A branch at a time takes the parent's events up to that time; keys before it are left out.
TEST(ReplayBranchKeys, AtATimeTakesEveryEventUpToIt) {
  const OpenedLog parent = openBytes(specParent());
  BranchRequest request;
  request.at.time = 1.1;
  request.keys = parent.request.keys;
  MemoryLog log;
  const BranchResult r = recordBranch(parent, request, log.writer);
  EXPECT_EQ(r.origin.event, seekLog(parent, SeekTarget{std::nullopt, 1.1}).events);
  EXPECT_LE(r.time.value, 1.1);
  EXPECT_EQ(r.keysLeftOut, 5u);  // 0.10, 0.15, 0.50, 0.52 and 1.00: before 1.1 s
  const DiffReport diff = diffLogs(parent, openBytes(log.bytes), 3, false);
  EXPECT_FALSE(diff.parted) << diff.where;
}

// --- refusals ------------------------------------------------------------------------------------

TEST(ReplayBranchRefusals, SayWhatIsWrongAndWriteNothing) {
  const Bytes parentBytes = specParent();
  const OpenedLog parent = openBytes(parentBytes);
  const std::uint64_t total = parent.reader.end()->events;
  auto refusal = [&](const OpenedLog& log, const BranchRequest& request) {
    MemoryLog out;
    std::string message;
    try {
      recordBranch(log, request, out.writer);
    } catch (const BranchError& e) {
      message = e.what();
    }
    EXPECT_TRUE(out.bytes.empty()) << "nothing is written";
    return message;
  };
  BranchRequest beyond;
  beyond.at.events = total + 1;
  EXPECT_NE(refusal(parent, beyond).find("beyond the log's end"), std::string::npos);
  BranchRequest late;
  late.at.time = 5.5;
  EXPECT_NE(refusal(parent, late).find("beyond the log's run"), std::string::npos);
  BranchRequest shortRun;
  shortRun.at.events = total / 2;
  shortRun.duration = 0.1;
  EXPECT_NE(refusal(parent, shortRun).find("before its branch point"), std::string::npos);

  // A cut-off parent: every decision it holds is there, but not its end.
  Bytes cut(parentBytes.begin(), parentBytes.end() - 40);
  BranchRequest some;
  some.at.events = 10;
  EXPECT_NE(refusal(openBytes(cut), some).find("cut off"), std::string::npos);

  // A branch holds nothing before its start.
  const OpenedLog branch = openBytes(branchOf(parent, total / 2, parent.request.keys));
  BranchRequest before;
  before.at.events = 3;
  EXPECT_NE(refusal(branch, before).find("starts at event"), std::string::npos);
  EXPECT_THROW(seekLog(branch, SeekTarget{3, std::nullopt}), std::out_of_range);
}

TEST(ReplayBranchRefusals, DiffAgainstALogThatIsNotTheParent) {
  const OpenedLog parent = openBytes(specParent());
  const OpenedLog branch = openBytes(branchOf(parent, 50, parent.request.keys));
  const OpenedLog other =
      openBytes(recordParent(ParentCase{"boards/spec-example.txt", MotionModel::Ballistic, "double", 4, true}));
  try {
    diffLogs(other, branch, 3, false);
    ADD_FAILURE() << "a branch compared with a log it was not taken from";
  } catch (const BranchError& e) {
    EXPECT_NE(std::string(e.what()).find("not of the first"), std::string::npos) << e.what();
  }
  EXPECT_THROW(diffLogs(branch, other, 3, false), BranchError);
}

// Ordinary logs are written as before: version 4, no keyframe in the first chunk.
TEST(ReplayBranchFormat, OrdinaryLogsKeepVersion4) {
  const Bytes bytes = specParent();
  ASSERT_GE(bytes.size(), 12u);
  EXPECT_EQ(bytes[8], 4);
  EXPECT_EQ(bytes[9], 0);
  const OpenedLog log = openBytes(bytes);
  EXPECT_FALSE(log.header.parent);
  EXPECT_FALSE(log.reader.isBranch());
}

}  // namespace
