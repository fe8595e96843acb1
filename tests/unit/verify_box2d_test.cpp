// The Box2D bridge: the mapping, our times of impact against b2TimeOfImpact (single contacts
// and a rapidcheck property over random sweeps of every feature kind), and whole runs of the
// named scenes in fixtures/boards/box2d/ where Box2D fails in known ways.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/verify/box2d_crosscheck.hpp"
#include "gizmo/verify/box2d_mapping.hpp"
#include "gizmo/verify/box2d_time_of_impact.hpp"
#include "support/paths.hpp"

namespace gizmo::verify {
namespace {

TEST(Box2dMapping, ConstantsAreTheLibrarys) {
  EXPECT_EQ(float(kBox2dLinearSlop), b2_linearSlop);
  EXPECT_EQ(float(kBox2dPolygonSkin), b2_polygonRadius);
  EXPECT_EQ(float(kBox2dMaxTranslation), b2_maxTranslation);
  EXPECT_EQ(float(kBox2dMaxRotation), b2_maxRotation);
  EXPECT_EQ(b2_version.major, 2);
  EXPECT_EQ(b2_version.minor, 4);
}

TEST(Box2dMapping, PolygonsAreInsetByTheSkinSoThatFacesCoincide) {
  GizmoSpec square;
  square.type = GizmoType::Square;
  square.name = "S";
  square.x = 3;
  square.y = 4;
  const Box2dBody body = box2dBodyOf(square);
  ASSERT_EQ(body.parts.size(), 1u);
  const Box2dPart& core = body.parts[0];
  ASSERT_EQ(core.points.size(), 4u);
  for (const Vec2<double>& p : core.points) {
    EXPECT_TRUE(p.x == 3.01 || p.x == 3.99) << p.x;
    EXPECT_TRUE(p.y == 4.01 || p.y == 4.99) << p.y;
  }
  EXPECT_EQ(core.radius, kBox2dPolygonSkin);
  // A triangle's 45° face moves in by the skin too: each core vertex lies `skin` inside both
  // edges that meet there.
  GizmoSpec triangle = square;
  triangle.type = GizmoType::Triangle;
  triangle.orientation = 90;
  const Box2dPart t = box2dBodyOf(triangle).parts.at(0);
  const Shape<double> ours = coreShape(t);
  ASSERT_EQ(ours.segments.size(), 3u);
  const Box2dBody walls = box2dOuterWalls();
  for (const Box2dPart& e : walls.parts)
    for (const Vec2<double>& p : e.points) EXPECT_TRUE(p.x == -0.01 || p.x == 20.01 || p.y == -0.01 || p.y == 20.01);
}

// A 2 × 2 gizmo of `type` whose box's low corner is (x, y).
GizmoSpec twoByTwo(GizmoType type, const char* name, int x, int y) {
  GizmoSpec g;
  g.type = type;
  g.name = name;
  g.x = x;
  g.y = y;
  g.width = g.height = 2;
  return g;
}

TEST(Box2dMapping, FlipperIsAKinematicCapsuleAboutItsPivot) {
  const Box2dBody body = box2dBodyOf(twoByTwo(GizmoType::RightFlipper, "RF", 11, 2));
  EXPECT_TRUE(body.kinematic);
  EXPECT_EQ(body.origin.x, 12.75);
  EXPECT_EQ(body.origin.y, 2.25);
  EXPECT_NEAR(body.angle, 1.5707963267948966, 1e-15);  // rest: pointing down
  ASSERT_EQ(body.parts.size(), 3u);
  EXPECT_EQ(body.parts[0].points.at(2).y, kFlipperRadius - kBox2dPolygonSkin);
  EXPECT_EQ(body.parts[2].centre.x, kFlipperLength);
}

TEST(Box2dMapping, SpinnerIsAKinematicCrossAboutItsCentre) {
  const Box2dBody body = box2dBodyOf(twoByTwo(GizmoType::Spinner, "S", 9, 9));
  EXPECT_TRUE(body.kinematic);
  EXPECT_EQ(body.origin.x, 10.0);
  EXPECT_EQ(body.origin.y, 10.0);
  EXPECT_EQ(body.angle, 0.0);  // still at load, its arms along the axes
  EXPECT_EQ(body.restitution, 0.9);
  ASSERT_EQ(body.parts.size(), 6u);  // two rectangles and the four tips
  EXPECT_EQ(body.parts[0].points.at(2).x, kSpinnerArmLength);
  EXPECT_EQ(body.parts[0].points.at(2).y, kSpinnerArmRadius - kBox2dPolygonSkin);
  EXPECT_EQ(body.parts[3].centre.y, kSpinnerArmLength);
  EXPECT_EQ(body.parts[3].radius, kSpinnerArmRadius);
}

// A ball head-on at a square's face at 10 L/s: we meet it when the centre is 0.25 from the
// face, Box2D 3 linear slops later (0.0015 s), within its tolerance.
TEST(Box2dTimeOfImpact, HeadOnFaceStopsThreeLinearSlopsPastContact) {
  StraightSweep s;
  s.kind = SweepKind::Edge;
  s.gizmo.type = GizmoType::Square;
  s.gizmo.name = "S";
  s.gizmo.x = 8;
  s.gizmo.y = 8;
  s.p = Vec2<double>(5, 8.5);
  s.v = Vec2<double>(10, 0);
  s.duration = 1;
  const SweepVerdict v = compareSweep(s);
  ASSERT_TRUE(v.ours && v.box2d) << v.box2dState;
  EXPECT_DOUBLE_EQ(*v.ours, 0.275);
  EXPECT_EQ(v.oursFeature, "edge");
  EXPECT_NEAR(*v.box2d - *v.ours, 3 * kBox2dLinearSlop / 10, kBox2dToiTolerance / 10);
  EXPECT_NEAR(v.depth, 3 * kBox2dLinearSlop, kBox2dToiTolerance);
  EXPECT_TRUE(v.explained) << v.why;
}

// The same for two balls meeting: the stop depth is shared, 3 linear slops between centres.
TEST(Box2dTimeOfImpact, BallsMeetThreeLinearSlopsDeep) {
  StraightSweep s;
  s.kind = SweepKind::Ball;
  s.p = Vec2<double>(2, 10);
  s.v = Vec2<double>(20, 0);
  s.otherP = Vec2<double>(12, 10);
  s.otherV = Vec2<double>(-20, 0);
  s.duration = 0.5;
  const SweepVerdict v = compareSweep(s);
  ASSERT_TRUE(v.ours && v.box2d);
  EXPECT_DOUBLE_EQ(*v.ours, 9.5 / 40);
  EXPECT_NEAR(v.depth, 3 * kBox2dLinearSlop, kBox2dToiTolerance);
  EXPECT_TRUE(v.explained) << v.why;
}

// A finding the survey found (seed 1): a whole quarter turn of a flipper in one call sweeps the
// bar through a ball at rest and out again; b2TimeOfImpact's separating axis is clear at the
// end and it reports no contact. Box2D never turns a body that far in one step, but the check
// must flag it.
TEST(Box2dTimeOfImpact, QuarterTurnInOneSweepIsAFinding) {
  StraightSweep s;
  s.kind = SweepKind::FlipperQuarterTurn;
  s.gizmo.type = GizmoType::LeftFlipper;
  s.gizmo.name = "LF";
  s.gizmo.x = 8;
  s.gizmo.y = 8;
  s.gizmo.orientation = 90;
  s.gizmo.width = s.gizmo.height = 2;
  s.p = Vec2<double>(0x1.1f14808569dbdp+3, 0x1.467f0aca68997p+3);
  s.v = Vec2<double>(-0x1.7fbc52fc53a83p+3, -0x1.513218295f1d6p+3);
  s.duration = 1.0 / 12;
  const SweepVerdict v = compareSweep(s);
  ASSERT_TRUE(v.ours);
  EXPECT_TRUE(v.latest) << "Box2D's own target is reached";
  EXPECT_FALSE(v.box2d) << v.box2dState;
  EXPECT_FALSE(v.explained);
  EXPECT_NE(describeSweep(s).find("0x1.1f14808569dbdp+3"), std::string::npos);  // exact inputs
}

// The property: over random straight sweeps of every feature kind, Box2D's answer always lies
// in the window its documented target and tolerance allow. The seed is fixed (RC_PARAMS=seed=N
// overrides it) and printed.
void checkKind(SweepKind kind) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  const char* env = std::getenv("RC_PARAMS");
  if (!env || !std::strstr(env, "seed")) params.seed = 20240601;
  params.maxSuccess = 1000;
  std::cout << "rapidcheck seed " << params.seed << " for " << sweepKindName(kind) << '\n';
  rc::detail::TestMetadata metadata;
  metadata.id = std::string("Box2dTimeOfImpact/") + std::string(sweepKindName(kind));
  const auto result = rc::detail::checkTestable(
      [kind] {
        std::array<double, kSweepRandoms> u;
        for (double& x : u) x = std::ldexp(double(*rc::gen::inRange<std::uint64_t>(0, std::uint64_t(1) << 53)), -53);
        const StraightSweep s = makeSweep(kind, u);
        const SweepVerdict v = compareSweep(s);
        if (!v.explained) RC_FAIL(v.why + "; " + describeSweep(s));
      },
      metadata, params);
  if (!result.template is<rc::detail::SuccessResult>()) {
    std::ostringstream out;
    rc::detail::printResultMessage(result, out);
    FAIL() << out.str();
  }
}

TEST(Box2dTimeOfImpact, PropertyEdge) { checkKind(SweepKind::Edge); }
TEST(Box2dTimeOfImpact, PropertyVertex) { checkKind(SweepKind::Vertex); }
TEST(Box2dTimeOfImpact, PropertyCircle) { checkKind(SweepKind::Circle); }
TEST(Box2dTimeOfImpact, PropertyBall) { checkKind(SweepKind::Ball); }
TEST(Box2dTimeOfImpact, PropertyFlipperAtRest) { checkKind(SweepKind::FlipperAtRest); }
TEST(Box2dTimeOfImpact, PropertyFlipperSwinging) { checkKind(SweepKind::FlipperSwinging); }

// Whatever a quarter turn does to Box2D, it is late or silent, never early: the window's lower
// end holds for every kind, whole swings included.
TEST(Box2dTimeOfImpact, SurveyNeverEarly) {
  const std::vector<SweepKindSurvey> survey = surveySweeps(7, 300);
  ASSERT_EQ(survey.size(), kSweepKinds.size());
  for (const SweepKindSurvey& k : survey) {
    for (const std::string& f : k.findings) EXPECT_EQ(f.find("before"), std::string::npos) << f;
    if (k.kind != SweepKind::FlipperQuarterTurn) {
      EXPECT_EQ(k.findingCount, 0) << sweepKindName(k.kind);
    }
    EXPECT_GT(k.box2dHits, 0);
  }
}

TEST(Box2dCrosscheck, MatchingPairsSameBallSameGizmoNearestTime) {
  const std::vector<CollisionRecord> ours{{1.0, "B", "S", {1, 1}}, {2.0, "B", "S", {1, 1}}, {3.0, "B", "C", {5, 5}}};
  const std::vector<CollisionRecord> box2d{
      {2.01, "B", "S", {1, 1}}, {1.02, "B", "S", {1, 1}}, {3.0, "B", "T", {5, 5}}, {1.03, "B", "S", {9, 9}}};
  const auto pairs = matchCollisions(ours, box2d, 0.05);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0], (std::pair<std::size_t, std::size_t>{0, 1}));
  EXPECT_EQ(pairs[1], (std::pair<std::size_t, std::size_t>{1, 0}));
}

RunRequest scene(const std::string& name, double seconds) {
  RunRequest r;
  r.board = io::readBoardFile(test::fixturePath("boards/box2d/" + name)).board;
  r.duration = seconds;
  return r;
}

StepComparison crosscheckAt(const RunRequest& request, double dt, Box2dOptions box2d = {}) {
  CrosscheckOptions o;
  o.request = request;
  o.steps = {dt};
  o.box2d = box2d;
  return crosscheck(o).steps.at(0);
}

// Bullets keep two fast balls from passing through each other; without them Box2D misses the hit.
TEST(Box2dScenes, FastBallsTunnelWithoutBullets) {
  const RunRequest r = scene("fast-balls-head-on.txt", 0.5);
  const StepComparison bullet = crosscheckAt(r, 1.0 / 60);
  EXPECT_EQ(bullet.missedByThem, 0u);
  EXPECT_EQ(bullet.missedByUs, 0u);
  EXPECT_EQ(bullet.matchedWithinToi, bullet.matched);
  Box2dOptions noBullet;
  noBullet.bullet = false;
  const StepComparison tunnel = crosscheckAt(r, 1.0 / 60, noBullet);
  ASSERT_TRUE(tunnel.firstUnmatched);
  EXPECT_EQ(tunnel.firstUnmatched->side, "ours");
  EXPECT_EQ(tunnel.firstUnmatched->collision.other, "B2");
  EXPECT_NEAR(tunnel.firstUnmatched->collision.time, 0.0475, 1e-12);
}

// The speed cap: at 1/60 s Box2D slows a 200 L/s ball to 120 L/s for good; at 1/120 s it fits.
TEST(Box2dScenes, SpeedCapSlowsTheBallForGood) {
  const RunRequest r = scene("speed-cap.txt", 1);
  const StepComparison capped = crosscheckAt(r, 1.0 / 60);
  EXPECT_GE(capped.speedCappedSteps, 1u);
  EXPECT_GT(capped.maxEnergyDifference, 0.5);  // ½·120² against ½·200²: 64 % of the energy gone
  const StepComparison free = crosscheckAt(r, 1.0 / 120);
  EXPECT_EQ(free.speedCappedSteps, 0u);
  EXPECT_EQ(free.missedByThem + free.missedByUs, 0u);
  EXPECT_LT(free.maxEnergyDifference, 1e-6);
}

// Slow bounces: with Box2D's default threshold of 1 m/s the 0.71 L/s bounce is lost at once;
// with the threshold at 0 Box2D keeps some bounces and loses the rest to its linear slop.
TEST(Box2dScenes, SlowBouncesAreLost) {
  const RunRequest r = scene("slow-bounce.txt", 1);
  Box2dOptions defaults;
  defaults.restitutionThreshold = 1;
  const StepComparison sticky = crosscheckAt(r, 1.0 / 240, defaults);
  const StepComparison zero = crosscheckAt(r, 1.0 / 240);
  EXPECT_LE(sticky.theirCollisions, 1u);
  EXPECT_GT(zero.theirCollisions, sticky.theirCollisions);
  EXPECT_GT(zero.missedByThem, 0u);
}

// Box2D's cross turns on the core's schedule: D meets the turning cross 0.87 s in, 0.024 s after it
// would have met the still one, and both hits on S are matched within a Box2D step or two.
TEST(Box2dScenes, TurningSpinnerHitIsMatched) {
  const RunRequest r = scene("spinner-turning.txt", 1.5);
  const StepComparison c = crosscheckAt(r, 1.0 / 480);
  EXPECT_EQ(c.matched, 2u);  // B on the still cross, D on the turning one
  EXPECT_EQ(c.missedByThem, 0u);
  EXPECT_EQ(c.missedByUs, 0u);
  EXPECT_LT(c.maxTimeError, 0.005);
}

// The flipper's strike is matched at a fine step: same ball, same flipper, within the window.
TEST(Box2dScenes, FlipperStrikeIsMatched) {
  const RunRequest r = scene("flipper-hit.txt", 0.5);
  const StepComparison c = crosscheckAt(r, 1.0 / 480);
  EXPECT_GE(c.matched, 2u);  // T on S, B on LF
  EXPECT_EQ(c.missedByUs, 0u);
}

}  // namespace
}  // namespace gizmo::verify
