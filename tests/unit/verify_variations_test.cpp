// Variations of a user's run (verify/fuzz/variations.hpp) and campaigns of them: case 0 is the run
// given, departures are the same from the same seed and stay valid, shrinking goes back toward the
// run given, and a failure planted in a narrow window of key timing is found and shrunk to one press.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>
#include <vector>

#include <filesystem>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/verify/fuzz/campaign.hpp"
#include "gizmo/verify/fuzz/expectations.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"
#include "gizmo/verify/fuzz/seeded_random.hpp"
#include "gizmo/verify/fuzz/variations.hpp"
#include "support/board_builder.hpp"
#include "support/paths.hpp"

namespace gizmo::verify::fuzz {
namespace {

using test::ballAt;
using test::gizmoAt;

// A ball dropped beside a left flipper's sweep: it bounces on the floor for ever, below y = 5,
// unless the flipper swings up while the ball passes through its reach (a key press inside a
// window of about a tenth of a second), which throws it above y = 3.
RunRequest plantedWindow() {
  RunRequest r;
  r.board = test::emptyBoard(25, 0, 0);
  r.board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "LF", 9, 14));
  r.board.keyConnections.push_back({32, KeyDirection::Down, "LF", {}});
  r.board.keyConnections.push_back({32, KeyDirection::Up, "LF", {}});
  r.board.balls.push_back(ballAt("B", 10.9, 10));
  r.duration = 1.5;
  return r;
}

RunRequest specLike() {
  RunRequest r;
  r.board = test::emptyBoard(25, 0.025, 0.025);
  r.board.gizmos.push_back(gizmoAt(GizmoType::Square, "S", 5, 12));
  r.board.gizmos.push_back(gizmoAt(GizmoType::Circle, "C", 6, 12));
  r.board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "A", 0, 19, 0, 20, 1));
  r.board.keyConnections.push_back({65, KeyDirection::Down, "A", {}});
  r.board.balls.push_back(ballAt("B1", 5.5, 11.74, 3, -2));
  r.board.balls.push_back(ballAt("B2", 12, 4));
  r.board.balls.push_back(ballAt("B3", 10.5, 19.5));  // at rest in the absorber: captured, and must not be kicked
  r.board.balls.push_back(ballAt("B4", 15, 10));      // two balls 0.02 L apart: each may move, not into the other
  r.board.balls.push_back(ballAt("B5", 15.52, 10));
  r.keys = {{1.0, 65, KeyDirection::Down}, {2.0, 65, KeyDirection::Up}};
  r.duration = 5;
  return r;
}

TEST(Variations, CaseZeroIsTheRunGiven) {
  const VariationSource source(specLike(), VariationOptions{});
  EXPECT_EQ(describeRun(source.make(7, 0).run), describeRun(specLike()));
  EXPECT_TRUE(source.departure(7, 0).empty());
  EXPECT_EQ(describeDeparture(specLike(), source.departure(7, 0)), "none: the board as given");
}

TEST(Variations, AcaseIsMadeFromItsSeedAlone) {
  const VariationSource a(specLike(), VariationOptions{}), b(specLike(), VariationOptions{});
  int differentFromBase = 0;
  for (std::uint64_t k = 1; k < 50; ++k) {
    EXPECT_EQ(describeRun(a.make(11, k).run), describeRun(b.make(11, k).run)) << k;
    EXPECT_EQ(describeDeparture(a.base(), a.departure(11, k)), describeDeparture(b.base(), b.departure(11, k)));
    if (describeRun(a.make(11, k).run) != describeRun(specLike())) ++differentFromBase;
  }
  EXPECT_GE(differentFromBase, 45);  // nearly every case departs from the run given
  EXPECT_NE(describeRun(a.make(11, 1).run), describeRun(a.make(12, 1).run));
}

// A ball is never moved into a gizmo or another ball, nor a ball at rest in an absorber set moving
// there (the reader refuses each; a kicked captured ball once failed no-tunnelling and round-trip,
// and two balls of a real board, each moved where it fitted alone, overlapped).
TEST(Variations, KeysStayInOrderWithinTheRunAndBallsStillFit) {
  const RunRequest base = specLike();
  const std::size_t problems = checkBoardSpec(base.board).size();
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const Departure d = randomDeparture(base, seed, VariationOptions{});
    const RunRequest run = applyDeparture(base, d);
    EXPECT_TRUE(std::is_sorted(run.keys.begin(), run.keys.end(),
                               [](const TimedKey& x, const TimedKey& y) { return x.time < y.time; }));
    for (const TimedKey& k : run.keys) {
      EXPECT_GE(k.time, 0);
      EXPECT_LT(k.time, run.duration);
      EXPECT_EQ(k.key, 65);  // only the key the board connects
    }
    EXPECT_LE(checkBoardSpec(run.board).size(), problems) << describeDeparture(base, d);
    for (const BallDeparture& b : d.balls) EXPECT_LE(b.dx * b.dx + b.dy * b.dy, 0.25 * 0.25 * (1 + 1e-12));
  }
}

TEST(Variations, ASwitchedOffVariationNeverHappens) {
  VariationOptions none;
  none.keyPressesPer10s = none.position = none.speed = none.angle = none.kick = none.gravity = none.friction = 0;
  none.model = none.maxTick = false;
  for (std::uint64_t seed = 1; seed <= 100; ++seed)
    EXPECT_TRUE(randomDeparture(specLike(), seed, none).empty()) << seed;
  VariationOptions onlyKeys = none;
  onlyKeys.keyPressesPer10s = 4;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const Departure d = randomDeparture(specLike(), seed, onlyKeys);
    EXPECT_FALSE(d.added.empty());
    EXPECT_TRUE(d.balls.empty() && d.gravityFactor == 1 && d.muFactor == 1 && !d.otherModel && d.maxTickFactor == 1);
  }
}

// The scalar varies only when asked (long double differs between kinds of machine), and then
// in about one case in four; its run is checked in long double.
TEST(Variations, TheScalarVariesOnlyWhenAsked) {
  VariationOptions on;
  on.scalar = true;
  int longDouble = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    EXPECT_FALSE(randomDeparture(specLike(), seed, VariationOptions{}).otherScalar);
    const Departure d = randomDeparture(specLike(), seed, on);
    if (d.otherScalar) ++longDouble;
    EXPECT_EQ(scalarOf(Precision::Double, d), d.otherScalar ? Precision::LongDouble : Precision::Double);
    EXPECT_EQ(scalarOf(Precision::LongDouble, d), d.otherScalar ? Precision::Double : Precision::LongDouble);
  }
  EXPECT_GT(longDouble, 60);
  EXPECT_LT(longDouble, 140);
  const VariationSource source(specLike(), on);
  std::uint64_t k = 1;
  while (!source.departure(3, k).otherScalar) ++k;
  EXPECT_EQ(source.make(3, k).scalar, Precision::LongDouble);
  EXPECT_NE(describeDeparture(specLike(), source.departure(3, k)).find("in long double (double given)"),
            std::string::npos);
}

TEST(Variations, ShrinkingGoesBackToTheRunGivenWhenEverythingFails) {
  const RunRequest base = specLike();
  VariationOptions everything;
  everything.scalar = true;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Departure d = randomDeparture(base, seed, everything);
    const ShrunkDeparture s = shrinkDeparture(
        base, d, [](const RunRequest&, const Departure&) { return true; }, 10000, 1.0);
    Departure back = s.departure;
    ASSERT_TRUE(back.duration.has_value());  // cut as short as allowed, and no shorter
    EXPECT_GE(*back.duration, 1.0);
    EXPECT_LT(*back.duration, 1.0 / 0.9);
    back.duration.reset();
    EXPECT_TRUE(back.empty()) << describeDeparture(base, s.departure);
  }
}

TEST(Variations, TheDepartureIsSaidInWords) {
  const RunRequest base = specLike();
  Departure d;
  d.added.push_back({65, 1.25, 1.4, 1, 0});
  d.removed.push_back(1);
  d.balls.push_back({0, 0, 0, 1.008, 0, 0, 0});
  d.gravityFactor = 1.1;
  d.otherModel = true;
  EXPECT_EQ(describeDeparture(base, d),
            "key 65 down at 1.25 s, up at 1.4 s; key 65 up at 2 s left out; B1 launched 0.8 % faster; gravity 27.5 "
            "L/s² (25 on "
            "the board); the classic model (ballistic given)");
}

// The planted failure: only some presses reach it; the campaign finds it within 100 cases and
// shrinks it to a single press of key 32 (and a shorter run), nothing else.
TEST(Variations, APlantedWindowOfKeyTimingIsFoundAndShrunkToOnePress) {
  const std::vector<Expectation> expect = parseExpectations("avoids 0 0 20 3\n", "window.expect");
  const Property expectations = expectationsProperty(expect);
  EXPECT_TRUE(expectations.check(plantedWindow(), Precision::Double).holds);  // the run given, no key pressed

  VariationOptions options;
  const VariationSource source(plantedWindow(), options);
  CampaignOptions c;
  c.properties = {&expectations};
  c.source = &source;
  c.count = 100;
  c.seed = 1;
  const CampaignResult r = runCampaign(c);
  ASSERT_GE(failureCount(r), 1u);
  const std::regex onePress(
      "key 32 down at [0-9.]+ s(, up at [0-9.]+ s| and held)(; the run cut to [0-9.]+ s \\(1\\.5 s given\\))?");
  for (const CaseOutcome& o : r.outcomes) {
    if (o.holds) continue;
    EXPECT_TRUE(std::regex_match(o.departure, onePress)) << "case " << o.index << ": " << o.departure;
    EXPECT_NE(o.message.find("ball B entered the rectangle (0, 0) to (20, 3)"), std::string::npos) << o.message;
    EXPECT_FALSE(expectations.check(o.minimal, o.scalar).holds);  // the minimal run still fails
  }
  // With the keys left alone, no variation of launch, gravity or model reaches it.
  VariationOptions noKeys;
  noKeys.keyPressesPer10s = 0;
  const VariationSource still(plantedWindow(), noKeys);
  c.source = &still;
  EXPECT_EQ(failureCount(runCampaign(c)), 0u);
}

// Every fixture board that is a board (not the malformed ones, nor the foreign formats that are
// refused), read as `gizmo run` reads it, and four cases of its variations over 3 s: the board as
// given and three variations, every property holds.
TEST(Variations, EveryFixtureBoardHoldsEveryPropertyOverVariations) {
  namespace fs = std::filesystem;
  std::vector<const Property*> all;
  for (const Property& p : allProperties()) all.push_back(&p);
  int boards = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(test::fixturePath("boards"))) {
    const std::string path = e.path().string();
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || (ext != ".txt" && ext != ".xml") || path.find("malformed") != std::string::npos ||
        path.find("foreign") != std::string::npos)
      continue;
    RunRequest base;
    base.board = io::readBoardFile(path).board;
    base.duration = 3;
    const VariationSource source(base, VariationOptions{});
    CampaignOptions c;
    c.properties = all;
    c.source = &source;
    c.count = 4;
    c.seed = 41;
    c.shrinkBudget = 0;  // a failure is reported as found, not shrunk
    const CampaignResult r = runCampaign(c);
    for (const CaseOutcome& o : r.outcomes)
      EXPECT_TRUE(o.holds) << path << " case " << o.index << " " << o.property << ": " << o.message;
    ++boards;
  }
  EXPECT_GE(boards, 70);
}

}  // namespace
}  // namespace gizmo::verify::fuzz
