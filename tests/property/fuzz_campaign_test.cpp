// The campaign machinery of `gizmo fuzz`: the same results whatever the threads and shards,
// merged shards equal to one run, results files that read back, and shrinking that ends small.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/replay/replay.hpp"
#include "gizmo/verify/fuzz/campaign.hpp"
#include "gizmo/verify/fuzz/run_generator.hpp"
#include "gizmo/verify/fuzz/run_shrinker.hpp"
#include "gizmo/verify/fuzz/seeded_random.hpp"
#include "support/scratch_dir.hpp"

namespace gizmo::verify::fuzz {
namespace {

CampaignOptions smallCampaign() {
  CampaignOptions o;
  for (const char* name : {"round-trip", "event-queue"}) o.properties.push_back(findProperty(name));
  o.count = 12;
  o.seed = 99;
  return o;
}

TEST(FuzzCampaign, SameResultOnAnyNumberOfThreads) {
  CampaignOptions one = smallCampaign(), three = smallCampaign();
  three.jobs = 3;
  const CampaignResult a = runCampaign(one), b = runCampaign(three);
  ASSERT_EQ(a.outcomes.size(), 24u);
  EXPECT_EQ(summaryLine(a), summaryLine(b));
  for (std::size_t i = 0; i < a.outcomes.size(); ++i) {
    EXPECT_EQ(a.outcomes[i].index, b.outcomes[i].index);
    EXPECT_EQ(a.outcomes[i].fingerprint, b.outcomes[i].fingerprint);
  }
}

TEST(FuzzCampaign, MergedShardsEqualOneRun) {
  const test::ScratchDir scratch;
  const std::filesystem::path dir = scratch / "campaign";  // written by writeCampaign
  CampaignResult whole = runCampaign(smallCampaign());
  std::vector<std::pair<std::string, CampaignResult>> parts;
  for (std::uint64_t k = 0; k < 3; ++k) {
    CampaignOptions o = smallCampaign();
    o.shard = k, o.shards = 3;
    CampaignResult part = runCampaign(o);
    for (const CaseOutcome& c : part.outcomes) EXPECT_EQ(c.index % 3, k) << "case in the wrong shard";
    const std::string out = (dir / ("shard" + std::to_string(k))).string();
    writeCampaign(part, out, "gizmo");
    parts.emplace_back(out, readCampaign(out));  // through the files, as --merge does
  }
  const CampaignResult merged = mergeCampaigns(parts);
  EXPECT_EQ(summaryLine(merged), summaryLine(whole));
  ASSERT_EQ(merged.outcomes.size(), whole.outcomes.size());
  for (std::size_t i = 0; i < merged.outcomes.size(); ++i) {
    EXPECT_EQ(merged.outcomes[i].index, whole.outcomes[i].index);
    EXPECT_EQ(merged.outcomes[i].property, whole.outcomes[i].property);
    EXPECT_EQ(merged.outcomes[i].fingerprint, whole.outcomes[i].fingerprint);
  }
  // A shard missing, or one given twice, is refused.
  EXPECT_THROW(mergeCampaigns({parts[0], parts[1]}), CampaignError);
  EXPECT_THROW(mergeCampaigns({parts[0], parts[1], parts[2], parts[1]}), CampaignError);
}

// What a killed or timed-out task leaves must not merge as if whole: a results file cut short at
// a line's end is refused, and a shard stopped early reads back as incomplete, with its counts.
TEST(FuzzCampaign, ResultsCutShortOrStoppedEarlyAreNotWhole) {
  const test::ScratchDir scratch;
  const std::filesystem::path dir = scratch / "campaign";  // written by writeCampaign
  CampaignOptions o = smallCampaign();
  o.shard = 1, o.shards = 2;
  CampaignResult whole = runCampaign(o);
  writeCampaign(whole, dir.string(), "gizmo");
  EXPECT_FALSE(std::filesystem::exists(dir / "results.txt.partial"));
  const CampaignResult back = readCampaign(dir.string());
  EXPECT_TRUE(back.complete);
  EXPECT_EQ(casesChecked(back), 6u);
  EXPECT_EQ(casesPlanned(back), 6u);

  std::string text;
  {
    std::ifstream in(dir / "results.txt");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::size_t lastLine = text.rfind('\n', text.size() - 2);
  {
    std::ofstream out(dir / "results.txt");
    out << text.substr(0, lastLine + 1);  // one check fewer, every line whole
  }
  EXPECT_THROW(readCampaign(dir.string()), CampaignError);

  o.stop = [] { return true; };
  CampaignResult stopped = runCampaign(o);
  EXPECT_FALSE(stopped.complete);
  writeCampaign(stopped, dir.string(), "gizmo");
  const CampaignResult early = readCampaign(dir.string());
  EXPECT_FALSE(early.complete);
  EXPECT_EQ(casesChecked(early), 0u);
  EXPECT_EQ(casesPlanned(early), 6u);
  EXPECT_NE(summaryLine(early).find("(stopped early)"), std::string::npos);
}

// A campaign of one case, 0 of seed 4, whose energy property failed (made up), shaped by `adjust`.
template <class Adjust>
CampaignResult oneMadeUpFailure(Adjust adjust) {
  CampaignResult r;
  r.seed = 4, r.count = 1, r.properties = "energy", r.shardsIncluded = {0};
  CaseOutcome c;
  c.index = 0, c.seed = caseSeed(4, 0), c.size = 0, c.property = "energy", c.holds = false;
  c.message = "made up for the test";
  c.minimal = caseRun(4, 0);
  adjust(c);
  r.outcomes.push_back(c);
  return r;
}

// A failure's folder: the shrunk board, its key script, its log, what failed, and the command
// that checks it again; and results.txt names the folder and reads back.
TEST(FuzzCampaign, WritesEachFailureWithItsCommand) {
  const test::ScratchDir scratch;
  const std::filesystem::path dir = scratch / "campaign";  // written by writeCampaign
  CampaignResult r = oneMadeUpFailure([](CaseOutcome& c) { c.minimal.keys = {TimedKey{0.1, 32, KeyDirection::Down}}; });
  writeCampaign(r, dir.string(), "gizmo");
  const std::filesystem::path folder = dir / "failures" / "energy-case0";
  EXPECT_EQ(r.outcomes[0].folder, "failures/energy-case0");
  for (const char* file : {"board.xml", "keys.txt", "run.gzlog", "failure.txt", "command.txt"})
    EXPECT_TRUE(std::filesystem::is_regular_file(folder / file)) << file;
  std::ifstream command(folder / "command.txt");
  std::string line;
  std::getline(command, line);
  EXPECT_EQ(line.rfind("gizmo fuzz --property energy --check " + (folder / "board.xml").string() + " --keys ", 0), 0u)
      << line;
  const CampaignResult back = readCampaign(dir.string());
  ASSERT_EQ(back.outcomes.size(), 1u);
  EXPECT_FALSE(back.outcomes[0].holds);
  EXPECT_EQ(back.outcomes[0].folder, "failures/energy-case0");
  EXPECT_EQ(summaryLine(back), summaryLine(r));
}

// A failure seen at a known time keeps a log of the run up to the end of that tick only: a late
// failure in a crowded run would otherwise write hundreds of megabytes.
TEST(FuzzCampaign, AFailuresLogEndsWithTheTickOfTheFailure) {
  const test::ScratchDir scratch;
  const std::filesystem::path dir = scratch / "campaign";  // written by writeCampaign
  CampaignResult r = oneMadeUpFailure([](CaseOutcome& c) {
    c.minimal.duration = 1;
    c.minimal.maxTick = 0.05;
    c.failedAt = 0.42;
  });
  writeCampaign(r, dir.string(), "gizmo");
  const std::filesystem::path folder = dir / "failures" / "energy-case0";
  const replay::OpenedLog log = replay::openLog((folder / "run.gzlog").string());
  EXPECT_EQ(log.request.duration, 0.45);
  std::ifstream in(folder / "failure.txt");
  const std::string failure((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(failure.find("run.gzlog holds the run up to t = 0.45"), std::string::npos) << failure;
  // The check it names is still the whole run's.
  std::ifstream command(folder / "command.txt");
  std::string line;
  std::getline(command, line);
  EXPECT_NE(line.find("--time 1"), std::string::npos) << line;
}

// A property that fails as soon as a board holds a circle bumper: the greedy minimiser must end
// with that circle and one ball, whatever else the case held.
TEST(FuzzShrinking, EndsWithAHandfulOfGizmos) {
  auto hasCircle = [](const RunRequest& r) {
    for (const GizmoSpec& g : r.board.gizmos)
      if (g.type == GizmoType::Circle) return true;
    return false;
  };
  int shrunk = 0;
  for (std::uint64_t seed = 0; seed < 40 && shrunk < 5; ++seed) {
    const RunRequest run = generateRun(seed, 100);
    if (!hasCircle(run) || run.board.gizmos.size() < 10) continue;
    const Minimised m = minimise(run, hasCircle, 1000);
    ++shrunk;
    EXPECT_EQ(m.run.board.gizmos.size(), 1u) << "seed " << seed;
    EXPECT_EQ(m.run.board.balls.size(), 1u) << "seed " << seed;
    EXPECT_TRUE(m.run.keys.empty()) << "seed " << seed;
    EXPECT_TRUE(m.run.board.connections.empty() && m.run.board.keyConnections.empty()) << "seed " << seed;
    EXPECT_TRUE(checkBoardSpec(m.run.board).empty()) << "seed " << seed;
  }
  EXPECT_EQ(shrunk, 5) << "too few generated boards with ten gizmos and a circle";
}

// Each near-degenerate placement occurs: a ball exactly one radius above a cell edge at rest, and
// two balls mirrored about a point with opposite velocities.
TEST(FuzzGenerator, PlacesNearDegenerateBalls) {
  int resting = 0, meeting = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const RunRequest run = generateRun(seed, 60);
    const std::vector<BallSpec>& balls = run.board.balls;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].vx == 0 && balls[i].vy == 0 && balls[i].y + kBallRadius == double(int(balls[i].y + kBallRadius)))
        ++resting;
      if (i + 1 < balls.size() && balls[i].vx == -balls[i + 1].vx && balls[i].vy == -balls[i + 1].vy &&
          (balls[i].vx != 0 || balls[i].vy != 0))
        ++meeting;
    }
  }
  EXPECT_GT(resting, 20);
  EXPECT_GT(meeting, 20);
}

// The generator's spawners have keys, and their boards' runs do grow: the fuzz properties meet
// spawned balls.
TEST(FuzzGenerator, SpawnersAddBalls) {
  int withSpawner = 0, grew = 0;
  for (std::uint64_t seed = 0; seed < 400 && grew < 5; ++seed) {
    const RunRequest run = generateRun(seed, 60);
    const auto spawner = std::find_if(run.board.gizmos.begin(), run.board.gizmos.end(),
                                      [](const GizmoSpec& g) { return g.type == GizmoType::Spawner; });
    if (spawner == run.board.gizmos.end()) continue;
    ++withSpawner;
    EXPECT_TRUE(std::any_of(run.board.keyConnections.begin(), run.board.keyConnections.end(),
                            [&](const KeyConnectSpec& k) { return k.target == spawner->name; }))
        << "seed " << seed;
    if (simulate<double>(run).balls.size() > run.board.balls.size()) ++grew;
  }
  EXPECT_GE(withSpawner, 5);
  EXPECT_EQ(grew, 5) << "too few generated runs in which a spawner adds a ball";
}

}  // namespace
}  // namespace gizmo::verify::fuzz
