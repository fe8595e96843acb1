// Box2D v3 in the cross-check (docs/verification.md, "Box2D v3"): the scene holds the one
// mapping's bodies as they are; only a spawner is refused (by name), as for Box2D 2.4; and, run
// under node and stepped by the driver that also steps Box2D 2.4, what v3 catches and misses on
// the thin-wall and head-on scenes, a flipper's strike, a turning spinner, an absorber's captures
// and fires, key-driven flippers and a flipper's coefficient of reflection. Those runs need node
// and the box2d3-wasm package (scripts/setup.sh installs them): without them each test says so
// and is skipped, except in CI (CI=true), where their absence is a failure.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "gizmo/io/key_script.hpp"
#include "gizmo/verify/box2d3_run.hpp"
#include "gizmo/verify/box2d_mapping.hpp"
#include "support/fixture_request.hpp"

namespace gizmo::verify {
namespace {

bool inCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

#define REQUIRE_BOX2D3()                                            \
  if (const std::optional<std::string> why = box2d3Unavailable()) { \
    if (inCi()) FAIL() << *why << " (CI must have it)";             \
    GTEST_SKIP() << *why;                                           \
  }

RunRequest board(const std::string& path, double seconds) {
  return test::fixtureRequest("boards/" + path, MotionModel::Ballistic, seconds);
}

// One step size of the v3 cross-check, as `gizmo crosscheck --engine box2d-v3` runs it.
StepComparison crosscheckV3(const RunRequest& request, double dt, Box2dOptions options = {}) {
  options.dt = dt;
  RunRequest longer = request;
  longer.duration += matchWindow(dt);
  EngineTrace trace = runBox2d3(longer, options);
  EXPECT_EQ(trace.engine, "Box2D v3 (box2d3-wasm 5.2.0)");
  trace.run.dt = dt;
  return crosscheckRuns(request, {trace.run}).steps.at(0);
}

TEST(Box2d3Scene, HoldsTheMappingsBodiesAsTheyAre) {
  const RunRequest r = board("trace/thin-wall.txt", 1);
  Box2dOptions o;
  o.dt = 1.0 / 120;
  o.bullet = false;
  const nlohmann::json scene = nlohmann::json::parse(box2d3Scene(r, o));
  EXPECT_EQ(scene.at("format"), "gizmo-box2d-scene");
  EXPECT_EQ(scene.at("dt").get<double>(), 1.0 / 120);
  EXPECT_FALSE(scene.at("bullets").get<bool>());
  EXPECT_TRUE(scene.at("continuous").get<bool>());
  ASSERT_EQ(scene.at("bodies").size(), 2u);
  const nlohmann::json& walls = scene.at("bodies").at(0);
  EXPECT_EQ(walls.at("name"), kOuterWallsName);
  EXPECT_EQ(walls.at("parts").size(), box2dOuterWalls().parts.size());
  const Box2dBody square = box2dBodyOf(r.board.gizmos.at(0));
  const nlohmann::json& s = scene.at("bodies").at(1);
  EXPECT_EQ(s.at("name"), "S");
  ASSERT_EQ(s.at("parts").size(), 1u);
  const nlohmann::json& points = s.at("parts").at(0).at("points");
  ASSERT_EQ(points.size(), square.parts.at(0).points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points.at(i).at(0).get<double>(), square.parts[0].points[i].x);
    EXPECT_EQ(points.at(i).at(1).get<double>(), square.parts[0].points[i].y);
  }
  EXPECT_EQ(s.at("parts").at(0).at("radius").get<double>(), kBox2dPolygonSkin);
  EXPECT_EQ(scene.at("balls").at(0).at("vx").get<double>(), 150.0);
}

// What the 2.4 bridge models, v3 models: flippers, spinners and absorbers are exported (kinematic
// bodies at their rest angle, a sensor) with their coefficients; a spawner is refused by name.
TEST(Box2d3Scene, OnlyASpawnerIsRefused) {
  for (const char* path :
       {"box2d/flipper-hit.txt", "box2d/spinner-turning.txt", "gizmos/absorber.txt", "spec-example.txt"})
    EXPECT_FALSE(box2d3CannotModel(board(path, 1).board)) << path;
  const std::optional<std::string> spawner = box2d3CannotModel(board("gizmos/spawner.txt", 1).board);
  ASSERT_TRUE(spawner);
  EXPECT_NE(spawner->find("spawner '"), std::string::npos) << *spawner;
  const RunRequest r = board("box2d/flipper-hit.txt", 1);
  const nlohmann::json scene = nlohmann::json::parse(box2d3Scene(r, Box2dOptions{}));
  const nlohmann::json& flipper = scene.at("bodies").at(2);  // the walls, S, then LF
  EXPECT_EQ(flipper.at("name"), "LF");
  EXPECT_TRUE(flipper.at("kinematic").get<bool>());
  EXPECT_EQ(flipper.at("restitution").get<double>(), 0.95);
  EXPECT_EQ(flipper.at("angle").get<double>(), box2dBodyOf(r.board.gizmos.at(1)).angle);
  const nlohmann::json absorber = nlohmann::json::parse(box2d3Scene(board("gizmos/absorber.txt", 1), Box2dOptions{}));
  EXPECT_TRUE(absorber.at("bodies").at(1).at("sensor").get<bool>());
}

// v3's continuous collision stops a 150 L/s ball at the square at 1/60 s (2.5 L a step); without
// it the ball passes through, at 1/60 and 1/120 s.
TEST(Box2d3Runs, ContinuousCollisionCatchesTheThinWall) {
  REQUIRE_BOX2D3();
  const RunRequest r = board("trace/thin-wall.txt", 0.1);  // one hit of ours: S at 0.051 s
  const StepComparison caught = crosscheckV3(r, 1.0 / 60);
  EXPECT_EQ(caught.matched, 1u);
  EXPECT_EQ(caught.missedByThem + caught.missedByUs, 0u);
  EXPECT_LE(caught.maxTimeError, 1.0 / 60);
  Box2dOptions off;
  off.continuous = false;
  for (double dt : {1.0 / 60, 1.0 / 120}) {
    const StepComparison tunnel = crosscheckV3(r, dt, off);
    EXPECT_EQ(tunnel.missedByThem, 1u) << dt;
    ASSERT_TRUE(tunnel.firstUnmatched) << dt;
    EXPECT_EQ(tunnel.firstUnmatched->side, "ours");
    EXPECT_EQ(tunnel.firstUnmatched->collision.other, "S");
  }
}

// Two balls at 100 L/s head on: v3's bullets have continuous collision with static bodies and
// with dynamic ones that are not bullets, so two bullet balls pass through each other at 1/60 s,
// where Box2D 2.4's bullets meet (Box2dScenes.FastBallsTunnelWithoutBullets).
TEST(Box2d3Runs, TwoBulletBallsPassThroughEachOther) {
  REQUIRE_BOX2D3();
  const RunRequest r = board("box2d/fast-balls-head-on.txt", 0.1);
  for (bool bullet : {true, false}) {
    Box2dOptions o;
    o.bullet = bullet;
    const StepComparison c = crosscheckV3(r, 1.0 / 60, o);
    ASSERT_TRUE(c.firstUnmatched) << bullet;
    EXPECT_EQ(c.firstUnmatched->side, "ours");
    EXPECT_EQ(c.firstUnmatched->collision.other, "B2");
    EXPECT_NEAR(c.firstUnmatched->collision.time, 0.0475, 1e-12);
    ASSERT_TRUE(c.parting);
    EXPECT_EQ(c.parting->agreesWith, "ours");
  }
}

// 200 L/s between the side walls: v3's speed limit (400 m/s) is not reached, so unlike Box2D
// 2.4 at 1/60 s (Box2dScenes.SpeedCapSlowsTheBallForGood) the energy stays; but each wall hit
// stops the ball at the wall for the rest of its step, so at 1/60 s the hits fall behind ours and
// stop matching, while at 1/480 s every one of the 10 matches.
TEST(Box2d3Runs, FastBallKeepsItsEnergyButFallsBehind) {
  REQUIRE_BOX2D3();
  const RunRequest r = board("box2d/speed-cap.txt", 1);
  const StepComparison coarse = crosscheckV3(r, 1.0 / 60);
  EXPECT_LT(coarse.maxEnergyDifference, 1e-5);
  EXPECT_GT(coarse.missedByThem, 0u);
  const StepComparison fine = crosscheckV3(r, 1.0 / 480);
  EXPECT_EQ(fine.matched, 10u);
  EXPECT_EQ(fine.missedByThem + fine.missedByUs, 0u);
}

// 5000 L/s through a field of bumpers: beyond v3's speed limit (400 m/s), so the run's steps are
// counted as capped in the report, as Box2D 2.4's are.
TEST(Box2d3Runs, StepsBeyondTheSpeedLimitAreCounted) {
  REQUIRE_BOX2D3();
  const StepComparison c =
      crosscheckV3(test::fixtureRequest("study/fast-ball-5000.txt", MotionModel::Ballistic, 0.1), 1.0 / 60);
  EXPECT_GT(c.speedCappedSteps, 0u);
  EXPECT_EQ(c.rotationCappedSteps, 0u);
}

// Bounces 0.01 L high (0.71 L/s): with the restitution threshold at 0, v3's soft contacts keep
// fewer than half of our 35 in 2 s, more at the finer step.
TEST(Box2d3Runs, SlowBouncesAreLost) {
  REQUIRE_BOX2D3();
  const RunRequest r = board("box2d/slow-bounce.txt", 2);
  const StepComparison coarse = crosscheckV3(r, 1.0 / 60), fine = crosscheckV3(r, 1.0 / 480);
  EXPECT_LT(2 * coarse.theirCollisions, 35u);
  EXPECT_LT(2 * fine.theirCollisions, 35u);
  EXPECT_GT(fine.theirCollisions, coarse.theirCollisions);
  EXPECT_GT(coarse.missedByThem, 0u);
}

// A stand-in for the node program in a folder of its own (GIZMO_BOX2D3_DIR), with the package's
// marker file: what it says, or that it ends early, is reported naming the program.
class FakeProgram {
 public:
  explicit FakeProgram(const std::string& script)
      : dir_(std::filesystem::temp_directory_path() / ("gizmo-fake-box2d3-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir_ / "node_modules" / "box2d3-wasm");
    std::ofstream(dir_ / "node_modules" / "box2d3-wasm" / "package.json") << "{}\n";
    std::ofstream(dir_ / "run_scene.mjs") << script;
    ::setenv("GIZMO_BOX2D3_DIR", dir_.c_str(), 1);
  }
  ~FakeProgram() {
    ::unsetenv("GIZMO_BOX2D3_DIR");
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }

 private:
  std::filesystem::path dir_;
};

std::string failureOf(const std::string& script) {
  const FakeProgram fake(script);
  try {
    runBox2d3(board("trace/thin-wall.txt", 0.1), Box2dOptions{});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no failure";
}

// The pipe's failures: a program that ends before its first reply (found when it stops reading
// or when its reply does not come, whichever is first), and one whose reply is not JSON.
TEST(Box2d3Runs, AProgramThatFailsIsReportedByName) {
  REQUIRE_BOX2D3();  // node itself
  const std::string ended = failureOf("process.exit(3);\n");
  EXPECT_EQ(ended.rfind("the Box2D v3 program (node run_scene.mjs) ", 0), 0u) << ended;
  EXPECT_NE(ended.find("(exit code 3)"), std::string::npos) << ended;
  const std::string garbled = failureOf("process.stdout.write('hello\\n');\n");
  EXPECT_NE(garbled.find("the Box2D v3 program's reply: not JSON"), std::string::npos) << garbled;
}

constexpr double kSteps[] = {1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480};

// Our run and v3's at one step size, their collisions matched as the cross-check matches them.
struct Matched {
  RunRecord ours, theirs;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
};

Matched matchedV3(const RunRequest& request, double dt, bool bullet) {
  Box2dOptions o;
  o.dt = dt;
  o.bullet = bullet;
  Matched m;
  std::uint64_t events = 0;
  m.ours = runOurs(request, events);
  m.theirs = runBox2d3(request, o).run.record;
  m.pairs = matchCollisions(m.ours.collisions, m.theirs.collisions, matchWindow(dt));
  return m;
}

// v3's hit matched with our n-th hit of `ball` on `other` (0 the first), or nothing when v3 missed
// it; a failure when we made no such hit.
std::optional<std::pair<CollisionRecord, CollisionRecord>> matchOf(const Matched& m, const std::string& ball,
                                                                   const std::string& other, int nth = 0) {
  for (std::size_t i = 0; i < m.ours.collisions.size(); ++i) {
    const CollisionRecord& c = m.ours.collisions[i];
    if (c.ball != ball || c.other != other || nth-- > 0) continue;
    for (const auto& [ours, theirs] : m.pairs)
      if (ours == i) return std::pair(c, m.theirs.collisions[theirs]);
    return std::nullopt;
  }
  ADD_FAILURE() << "our run has no such hit of " << ball << " on " << other;
  return std::nullopt;
}

// |t_v3 − t_ours| of that match.
std::optional<double> timeError(const Matched& m, const std::string& ball, const std::string& other, int nth = 0) {
  const auto match = matchOf(m, ball, other, nth);
  if (!match) return std::nullopt;
  return std::fabs(match->second.time - match->first.time);
}

// The time of v3's n-th hit of `ball` on `other` (0 the first), matched or not.
std::optional<double> theirHit(const Matched& m, const std::string& ball, const std::string& other, int nth = 0) {
  for (const CollisionRecord& c : m.theirs.collisions)
    if (c.ball == ball && c.other == other && nth-- == 0) return c.time;
  return std::nullopt;
}

std::string label(double dt, bool bullet) {
  return "dt 1/" + std::to_string(std::lround(1 / dt)) + (bullet ? ", bullets" : ", no bullets");
}

// Both runs' collisions, for a failure's message.
std::string collisions(const Matched& m) {
  std::string out;
  for (const auto* side : {&m.ours, &m.theirs}) {
    out += side == &m.ours ? "\nours:" : "\nv3:";
    for (const CollisionRecord& c : side->collisions)
      out += " " + c.ball + "-" + c.other + "@" + std::to_string(c.time) + "(" + std::to_string(c.position.x) + "," +
             std::to_string(c.position.y) + ")";
  }
  return out;
}

// flipper-hit: T's hit on S swings LF, whose bar meets B at rest. v3 places a hit at the fraction
// of the step's straight path where the ball stands after it, and a ball at rest has no path: the
// strike is placed at the start of its step, at most a step early; and the swing started at the
// time placed on T's hit, itself within its step. So the strike is matched within two steps, at
// every step size, with bullets on and off (bullets change nothing: both bodies B meets are not
// dynamic).
TEST(Box2d3Runs, FlipperStrikeIsMatchedWithinTwoSteps) {
  REQUIRE_BOX2D3();
  const RunRequest r = board("box2d/flipper-hit.txt", 0.5);
  for (double dt : kSteps)
    for (bool bullet : {true, false}) {
      const Matched m = matchedV3(r, dt, bullet);
      const std::optional<double> trigger = timeError(m, "T", "S"), strike = timeError(m, "B", "LF");
      ASSERT_TRUE(trigger) << label(dt, bullet);
      ASSERT_TRUE(strike) << label(dt, bullet);
      EXPECT_LE(*trigger, dt) << label(dt, bullet);
      EXPECT_LE(*strike, 2 * dt) << label(dt, bullet);
    }
}

// spinner-turning: B falls on the still cross and starts it; D meets the turning cross, later than
// it would meet the still one. Both hits are matched within a step at every step size, and
// D leaves it as ours does: the cross is where the core's schedule puts it at each step's end.
// 0.1 s after the hit D is 0.01 (1/480 s) to 0.30 L (1/60 s) from ours; off a cross left still, D
// meets about as early but leaves another way, 2.2 to 2.6 L from ours by then.
TEST(Box2d3Runs, TurningSpinnerHitsAreMatchedWithinAStep) {
  REQUIRE_BOX2D3();
  const RunRequest r = board("box2d/spinner-turning.txt", 1.5);
  for (double dt : kSteps)
    for (bool bullet : {true, false}) {
      const Matched m = matchedV3(r, dt, bullet);
      const std::optional<double> still = timeError(m, "B", "S"), turning = timeError(m, "D", "S");
      ASSERT_TRUE(still) << label(dt, bullet);
      ASSERT_TRUE(turning) << label(dt, bullet);
      EXPECT_LE(*still, dt) << label(dt, bullet);
      EXPECT_LE(*turning, dt) << label(dt, bullet);
      // D leaves the turning cross as ours does: 0.1 s on it is within a ball's width of ours.
      const double after = matchOf(m, "D", "S")->first.time + 0.1;
      const std::size_t d = 1;  // the board's second ball
      EXPECT_LT(length(interpolate(m.theirs.samples, after).positions.at(d) -
                       interpolate(m.ours.samples, after).positions.at(d)),
                2 * kBallRadius)
          << label(dt, bullet);
    }
}

// gizmos/absorber.txt: B falls onto the absorber, which captures it and, connected to itself,
// fires it straight up; it hits the top wall and falls back to be captured again. v3 (its sensor
// and the core's Absorber between steps) captures, fires and captures again at every step size,
// bullets or not. The first capture is matched within a step: v3 reports a sensor's overlap at the
// end of the step in which it began. The second carries the delays of the whole round (the fire
// at the first capture's time, the wall's stop holding the ball for the rest of its step, the
// second overlap seen at a step's end): matched from 1/120 s on (34 ms late at 1/120 s), 51 ms late
// at 1/60 s, just beyond that step's match window of 50 ms, so only its existence is asserted there.
TEST(Box2d3Runs, AbsorberCapturesAndFires) {
  REQUIRE_BOX2D3();
  const RunRequest r = board("gizmos/absorber.txt", 3);
  for (double dt : kSteps)
    for (bool bullet : {true, false}) {
      const Matched m = matchedV3(r, dt, bullet);
      const std::optional<double> capture = timeError(m, "B", "A"), roof = timeError(m, "B", kOuterWallsName);
      ASSERT_TRUE(capture) << label(dt, bullet) << collisions(m);
      ASSERT_TRUE(roof) << label(dt, bullet) << collisions(m);
      EXPECT_LE(*capture, dt) << label(dt, bullet);
      EXPECT_TRUE(theirHit(m, "B", "A", 1)) << label(dt, bullet) << collisions(m);
      if (dt < 1.0 / 60) {
        EXPECT_TRUE(timeError(m, "B", "A", 1)) << label(dt, bullet) << collisions(m);
      }
    }
}

// The same absorber fired by a key instead of its own capture: B is captured at 1.07 s and held at
// the absorber's hold position, out of v3's world, until the key at 1.5 s fires it at the top
// wall. While held, v3's ball stands where ours does (to float rounding of a coordinate below 20,
// 2 µL).
TEST(Box2d3Runs, AbsorberHoldsTheBallUntilItsKey) {
  REQUIRE_BOX2D3();
  RunRequest r = board("gizmos/absorber.txt", 2.5);
  r.board.connections.clear();
  KeyConnectSpec key;
  key.key = 32;
  key.target = "A";
  r.board.keyConnections = {key};
  r.keys = {TimedKey{1.5, 32, KeyDirection::Down}};
  for (double dt : kSteps)
    for (bool bullet : {true, false}) {
      const Matched m = matchedV3(r, dt, bullet);
      const auto capture = matchOf(m, "B", "A");
      ASSERT_TRUE(capture) << label(dt, bullet) << collisions(m);
      const Vec2<double> holdPosition = interpolate(m.ours.samples, 1.4).positions.at(0);  // ours, held
      std::size_t held = 0;
      for (const TrajectorySample& s : m.theirs.samples) {
        if (s.time < capture->second.time + dt || s.time > 1.5 - dt) continue;
        ++held;
        EXPECT_LT(length(s.positions.at(0) - holdPosition), 2e-6) << label(dt, bullet) << " at " << s.time;
      }
      EXPECT_GT(held, 0u) << label(dt, bullet);
      EXPECT_TRUE(timeError(m, "B", kOuterWallsName)) << label(dt, bullet) << collisions(m);
    }
}

// pinched-ball with fixtures/keys/flippers.keys: the space key swings F (0.10 s) and lets it go
// (0.15 s); our bar strikes B at 0.1427 s. v3 has no continuous collision between a kinematic body
// and a ball that is not fast, and its speculative margin (0.02 L) is far below the bar's travel
// in a step at 1/60 s (0.44 L where it meets B): the bar goes from 0.25 L clear of B at 0.133 s to
// 0.22 L into it at 0.15 s, where the key's release turns it back, and, moving away, it pushes
// nothing. At 1/60 and 1/120 s B falls on untouched (v3 makes no hit at all in 0.5 s); from 1/240 s
// the strike is matched within two steps (its time placed at a step's start, the key at its own).
TEST(Box2d3Runs, KeyTriggeredFlipperStrikesTheBallFromQuarterSteps) {
  REQUIRE_BOX2D3();
  RunRequest r = board("scenes/pinched-ball.txt", 0.5);
  for (const io::KeyInput& k : io::readKeyScriptFile(test::fixturePath("keys/flippers.keys")))
    r.keys.push_back(TimedKey{k.time, k.key, k.direction});
  for (double dt : kSteps) {
    const Matched m = matchedV3(r, dt, true);
    const std::optional<double> strike = timeError(m, "B", "F");
    if (dt > 1.0 / 240) {
      EXPECT_FALSE(strike) << label(dt, true) << collisions(m);
      EXPECT_TRUE(m.theirs.collisions.empty()) << label(dt, true) << collisions(m);
      continue;
    }
    ASSERT_TRUE(strike) << label(dt, true) << collisions(m);
    EXPECT_LE(*strike, 2 * dt) << label(dt, true);
  }
}

// How high B rises after its first bounce, as a fraction of its drop, in v3's run: from rest onto
// the top of the gizmo, apex read off the steps between our first and second hit.
double firstRebound(const RunRequest& request, double dt) {
  const Matched m = matchedV3(request, dt, true);
  if (m.ours.collisions.size() < 2) {
    ADD_FAILURE() << "our run has no second bounce";
    return 0;
  }
  const double contact = m.ours.collisions[0].position.y, start = request.board.balls.at(0).y;
  const double from = m.ours.collisions[0].time + 0.05, to = m.ours.collisions[1].time - 0.05;
  double apex = contact;
  for (const TrajectorySample& s : m.theirs.samples)
    if (s.time > from && s.time < to) apex = std::min(apex, s.positions.at(0).y);
  return (contact - apex) / (contact - start);
}

// zeno-flipper: B dropped from rest onto the level bar of a flipper at rest, against the same drop
// onto a square (coefficient 1) whose top face lies where the bar's does. v3's own rule takes the
// larger of two coefficients (a ball's is 1), which would bounce B off both alike; the restitution
// callback gives the flipper's 0.95, so B rises 0.95² as high off the bar as off the square. v3's
// soft contact loses some height on both (0.92 of the drop off the square at 1/60 s): the ratio
// removes it. v3 reflects the normal velocity it had at the start of the step of the impact,
// which falls short of the impact speed v by up to g·dt: each rebound's height is uncertain by a
// fraction 2·g·dt/v, and the ratio's by twice that. At 1/60 s that is 0.27, wider than the
// difference the test looks for (1 against 0.9025); at 1/240 and 1/480 s it is 0.07 and 0.03.
TEST(Box2d3Runs, FlipperBouncesWithItsOwnCoefficient) {
  REQUIRE_BOX2D3();
  RunRequest flipper = board("../study/zeno-flipper.txt", 0.9);
  flipper.board.balls.at(0).x = 10.5;
  RunRequest square = flipper;
  GizmoSpec s;
  s.type = GizmoType::Square;
  s.name = "S";
  s.x = 10;
  s.y = 15;
  square.board.gizmos = {s};
  const double g = flipper.board.gravity, drop = 0.75;  // from y = 14 to the bar's top less the radius
  const double v = std::sqrt(2 * g * drop);
  for (double dt : {1.0 / 240, 1.0 / 480}) {
    const double ratio = firstRebound(flipper, dt) / firstRebound(square, dt);
    EXPECT_NEAR(ratio, 0.95 * 0.95, 0.95 * 0.95 * 4 * g * dt / v) << label(dt, true);
  }
}

// A folder of its own for the trace files of one test, removed after it.
class TraceFolder {
 public:
  TraceFolder() : dir_(std::filesystem::temp_directory_path() / ("gizmo-v3-trace-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~TraceFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) out.push_back(entry.path().filename().string());
    return out;
  }

 private:
  std::filesystem::path dir_;
};

std::string describe(const CollisionRecord& c) {
  std::ostringstream out;
  out.precision(17);
  out << c.ball << "-" << c.other << "@" << c.time << "(" << c.position.x << "," << c.position.y << ")";
  return out.str();
}

// --trace-out: the program writes its run as a trace, and that trace read back is the run the
// driver recorded. Every collision is the same to the last bit, in the same order (the trace keeps
// each double as the shortest text that reads back as it): the hits, and the absorber's captures,
// which the program knows by the driver's hold that follows an entry; the trace's contacts after
// the run's end (the driver drops them) aside. The paths are the same too where no ball is
// captured (a capture shows in the trace one step later: the program writes v3's world after each
// step, the driver its own after its rules). So the two reports agree on every collision figure.
TEST(Box2d3Runs, TheProgramsTraceIsItsRun) {
  REQUIRE_BOX2D3();
  struct Scene {
    const char* path;
    double seconds;
    bool sameSamples;
  };
  const double dt = 1.0 / 120;
  for (const Scene& scene : {Scene{"box2d/spinner-turning.txt", 1.5, true}, Scene{"box2d/flipper-hit.txt", 1, true},
                             Scene{"gizmos/absorber.txt", 3, false}, Scene{"spec-example.txt", 4, false}}) {
    const RunRequest r = board(scene.path, scene.seconds);
    RunRequest longer = r;
    longer.duration += matchWindow(dt);
    Box2dOptions o;
    o.dt = dt;
    const TraceFolder folder;
    const std::string file = folder.file("v3.jsonl");
    EngineTrace run = runBox2d3(longer, o, file);
    run.run.dt = dt;
    EXPECT_EQ(folder.names(), std::vector<std::string>{"v3.jsonl"}) << scene.path << ": no temporary file is left";
    EngineTrace trace = readEngineTraceFile(file, r.board, r.duration);
    EXPECT_EQ(trace.engine, run.engine);
    EXPECT_TRUE(trace.run.withCollisions);
    std::erase_if(trace.run.record.collisions, [&](const CollisionRecord& c) { return c.time > longer.duration; });
    const std::vector<CollisionRecord>& ours = run.run.record.collisions;
    const std::vector<CollisionRecord>& read = trace.run.record.collisions;
    EXPECT_GE(ours.size(), 2u) << scene.path;
    ASSERT_EQ(read.size(), ours.size()) << scene.path;
    for (std::size_t i = 0; i < ours.size(); ++i)
      EXPECT_EQ(describe(read[i]), describe(ours[i])) << scene.path << ", collision " << i;
    const std::vector<TrajectorySample>& a = run.run.record.samples;
    const std::vector<TrajectorySample>& b = trace.run.record.samples;
    ASSERT_EQ(b.size(), a.size()) << scene.path;
    std::size_t differ = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      ASSERT_EQ(b[k].time, a[k].time) << scene.path << ", step " << k;
      differ += b[k].positions != a[k].positions || b[k].energy != a[k].energy;
    }
    if (scene.sameSamples) {
      EXPECT_EQ(differ, 0u) << scene.path;
    }
    const StepComparison direct = crosscheckRuns(r, {run.run}).steps.at(0);
    const StepComparison traced = crosscheckRuns(r, {trace.run}).steps.at(0);
    EXPECT_EQ(traced.theirCollisions, direct.theirCollisions) << scene.path;
    EXPECT_EQ(traced.matched, direct.matched) << scene.path;
    EXPECT_EQ(traced.missedByThem, direct.missedByThem) << scene.path;
    EXPECT_EQ(traced.missedByUs, direct.missedByUs) << scene.path;
    EXPECT_EQ(traced.maxTimeError, direct.maxTimeError) << scene.path;
    EXPECT_EQ(traced.meanTimeError, direct.meanTimeError) << scene.path;
    EXPECT_EQ(traced.maxPositionError, direct.maxPositionError) << scene.path;
    ASSERT_EQ(traced.firstUnmatched.has_value(), direct.firstUnmatched.has_value()) << scene.path;
    if (direct.firstUnmatched) {
      EXPECT_EQ(describe(traced.firstUnmatched->collision), describe(direct.firstUnmatched->collision)) << scene.path;
    }
  }
}

// A capture in the run's last step: the driver holds the ball after it, with no step to follow,
// so the hold goes with the end of the run and the trace still has the capture.
TEST(Box2d3Runs, ACaptureInTheLastStepIsInTheTrace) {
  REQUIRE_BOX2D3();
  Box2dOptions o;
  o.dt = 1.0 / 120;
  RunRequest r = board("gizmos/absorber.txt", 1.5);
  const auto captureIn = [](const std::vector<CollisionRecord>& list) {
    return std::find_if(list.begin(), list.end(), [](const CollisionRecord& c) { return c.other == "A"; }) !=
           list.end();
  };
  const std::vector<CollisionRecord> whole = runBox2d3(r, o).run.record.collisions;
  const auto capture =
      std::find_if(whole.begin(), whole.end(), [](const CollisionRecord& c) { return c.other == "A"; });
  ASSERT_NE(capture, whole.end());
  // The run ends with the step whose reply reports the capture: the one ending at or after its
  // time, or the one after it (a contact placed in the step before its own).
  std::size_t found = 0;
  for (double extra : {0.0, o.dt}) {
    r.duration = capture->time + extra;
    const TraceFolder folder;
    const std::vector<CollisionRecord> ours = runBox2d3(r, o, folder.file("v3.jsonl")).run.record.collisions;
    if (!captureIn(ours)) continue;
    ++found;
    EXPECT_TRUE(captureIn(readEngineTraceFile(folder.file("v3.jsonl"), r.board, r.duration).run.record.collisions))
        << "run to " << r.duration << " s";
  }
  EXPECT_GT(found, 0u);
}

// A trace the program cannot write stops the run with its reason, and leaves nothing.
TEST(Box2d3Runs, ATraceThatCannotBeWrittenStopsTheRun) {
  REQUIRE_BOX2D3();
  const TraceFolder folder;
  Box2dOptions o;
  o.dt = 1.0 / 60;
  try {
    runBox2d3(board("trace/thin-wall.txt", 0.1), o, folder.file("no-such-folder/v3.jsonl"));
    ADD_FAILURE() << "the run should fail";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the Box2D v3 program (node run_scene.mjs) "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(exit code 2)"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(folder.names().empty());
}

}  // namespace
}  // namespace gizmo::verify
