// Geometry of every gizmo kind in every orientation, and the time of impact against each
// kind of feature, checked against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gizmo/core/geometry/flipper_time_of_impact.hpp"
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/geometry/time_of_impact.hpp"
#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using test::gizmoAt;

bool hasVertex(const Shape<double>& s, double x, double y) {
  for (const auto& c : s.circles)
    if (c.radius == 0 && c.centre.x == x && c.centre.y == y) return true;
  return false;
}

TEST(Shapes, SquareHasFourOutwardEdgesAndFourCorners) {
  const Shape<double> s = restShape<double>(gizmoAt(GizmoType::Square, "S", 3, 4));
  ASSERT_EQ(s.segments.size(), 4u);
  ASSERT_EQ(s.circles.size(), 4u);
  for (const auto& seg : s.segments) {
    // The centre of the square lies behind every edge.
    const Vec2<double> centre(3.5, 4.5);
    EXPECT_LT(dot(centre - seg.a, seg.normal), 0.0);
    EXPECT_EQ(seg.length, 1.0);
  }
  EXPECT_TRUE(hasVertex(s, 3, 4) && hasVertex(s, 4, 4) && hasVertex(s, 4, 5) && hasVertex(s, 3, 5));
}

// docs/physics.md §2: orientation 0 has its right angle at NW, 90 at NE, 180 at SE, 270 at SW.
TEST(Shapes, TriangleRightAngleTurnsClockwise) {
  const struct {
    int orientation;
    double cornerX, cornerY;
  } cases[] = {{0, 0, 0}, {90, 1, 0}, {180, 1, 1}, {270, 0, 1}};
  for (const auto& c : cases) {
    const Shape<double> s = restShape<double>(gizmoAt(GizmoType::Triangle, "T", 10, 10, c.orientation));
    ASSERT_EQ(s.segments.size(), 3u);
    ASSERT_EQ(s.circles.size(), 3u);
    // The right-angle corner: the vertex whose two edges are axis-aligned and meet at 90°.
    EXPECT_TRUE(hasVertex(s, 10 + c.cornerX, 10 + c.cornerY)) << c.orientation;
    // The opposite corner of the cell is not a vertex.
    EXPECT_FALSE(hasVertex(s, 10 + 1 - c.cornerX, 10 + 1 - c.cornerY)) << c.orientation;
    int diagonal = 0;
    const Vec2<double> centroidish(10.5, 10.5);
    for (const auto& seg : s.segments) {
      if (seg.normal.x != 0 && seg.normal.y != 0) {
        ++diagonal;
        EXPECT_NEAR(seg.length, std::sqrt(2.0), 1e-15);
        // The hypotenuse faces away from the right angle.
        const Vec2<double> corner(10 + c.cornerX, 10 + c.cornerY);
        EXPECT_LT(dot(corner - seg.a, seg.normal), 0.0);
      }
    }
    EXPECT_EQ(diagonal, 1) << c.orientation;
  }
}

TEST(Shapes, CircleBumperIsOneCircle) {
  const Shape<double> s = restShape<double>(gizmoAt(GizmoType::Circle, "C", 4, 3));
  ASSERT_EQ(s.circles.size(), 1u);
  EXPECT_TRUE(s.segments.empty());
  EXPECT_EQ(s.circles[0].centre, Vec2<double>(4.5, 3.5));
  EXPECT_EQ(s.circles[0].radius, 0.5);
}

TEST(Shapes, AbsorberSpansItsRectangle) {
  const Shape<double> s = restShape<double>(gizmoAt(GizmoType::Absorber, "A", 0, 19, 0, 20, 1));
  EXPECT_TRUE(hasVertex(s, 0, 19) && hasVertex(s, 20, 19) && hasVertex(s, 20, 20) && hasVertex(s, 0, 20));
}

// docs/physics.md §2: pivots and angles of both flippers in all four orientations.
TEST(Shapes, FlipperLayoutsInAllOrientations) {
  const struct {
    GizmoType type;
    int orientation;
    double px, py;
    int rest, end, sign;
  } cases[] = {
      {GizmoType::LeftFlipper, 0, 0.25, 0.25, 1, 0, -1},   {GizmoType::LeftFlipper, 90, 1.75, 0.25, 2, 1, -1},
      {GizmoType::LeftFlipper, 180, 1.75, 1.75, 3, 2, -1}, {GizmoType::LeftFlipper, 270, 0.25, 1.75, 4, 3, -1},
      {GizmoType::RightFlipper, 0, 1.75, 0.25, 1, 2, 1},   {GizmoType::RightFlipper, 90, 1.75, 1.75, 2, 3, 1},
      {GizmoType::RightFlipper, 180, 0.25, 1.75, 3, 4, 1}, {GizmoType::RightFlipper, 270, 0.25, 0.25, 4, 5, 1},
  };
  for (const auto& c : cases) {
    const FlipperLayout f = flipperLayout(c.type, c.orientation);
    EXPECT_EQ(f.pivot, Vec2<double>(c.px, c.py)) << c.orientation;
    EXPECT_EQ(f.restQuarter, c.rest);
    EXPECT_EQ(f.endQuarter, c.end);
    EXPECT_EQ(f.forwardSign, c.sign);
    // At rest and at the end the capsule stays inside its 2×2 box.
    for (int q : {f.restQuarter, f.endQuarter}) {
      const Vec2<double> tip = f.pivot + kFlipperLength * quarterDirection<double>(q);
      for (const Vec2<double>& p : {f.pivot, tip}) {
        EXPECT_GE(p.x - kFlipperRadius, 0.0);
        EXPECT_LE(p.x + kFlipperRadius, 2.0);
        EXPECT_GE(p.y - kFlipperRadius, 0.0);
        EXPECT_LE(p.y + kFlipperRadius, 2.0);
      }
    }
  }
}

TEST(Shapes, OuterWallNormalsPointIntoTheBoard) {
  const Shape<double> s = outerWallsShape<double>();
  ASSERT_EQ(s.segments.size(), 4u);
  EXPECT_TRUE(s.circles.empty());
  for (const auto& seg : s.segments) EXPECT_GT(dot(Vec2<double>(10, 10) - seg.a, seg.normal), 0.0);
}

// --- times of impact --------------------------------------------------------------------------

// pathMayComeWithin says no only where no point of the path comes that near: for random paths
// (fast and slow, with and without gravity) and centres, checked at 257 points along each path.
// And it says no where the disc of the ball's travel cannot: a ball at 5000 L/s passing 5 L from
// a flipper's pivot travels 250 L in a tick.
TEST(Trajectories, APathRuledOutNeverComesNear) {
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> coordinate(0, 20), speed(-5000, 5000), accel(-1000, 1000), span(0, 0.05);
  int ruledOut = 0;
  for (int k = 0; k < 20000; ++k) {
    const double scale = k % 2 ? 1.0 : 1e-3;  // half of them slow
    const Trajectory<double> t{{coordinate(rng), coordinate(rng)},
                               {scale * speed(rng), scale * speed(rng)},
                               {k % 3 ? 0.0 : accel(rng), k % 3 ? 0.0 : accel(rng)}};
    const Vec2<double> c(coordinate(rng), coordinate(rng));
    const double T = span(rng), radius = 1.5;
    if (pathMayComeWithin(t, T, c, radius)) continue;
    ++ruledOut;
    for (int i = 0; i <= 256; ++i)
      ASSERT_GT(length(t.positionAt(T * i / 256) - c), radius) << "path " << k << " at " << i << "/256";
  }
  EXPECT_GT(ruledOut, 5000);
  const Trajectory<double> fast{{1, 10}, {5000, 0}, {0, 25}};
  EXPECT_FALSE(pathMayComeWithin(fast, 0.05, Vec2<double>(10, 5), 1.5));
  EXPECT_TRUE(pathMayComeWithin(fast, 0.05, Vec2<double>(10, 9), 1.5));
  EXPECT_TRUE(pathMayComeWithin(fast, 0.0005, Vec2<double>(2.5, 9), 1.5));  // within reach near the start
  EXPECT_FALSE(pathMayComeWithin(fast, 0.0005, Vec2<double>(10, 9), 1.5));  // not yet there
}

TEST(TimeOfImpact, SegmentHeadOnStraightLine) {
  // Walking left to right along y = 20, the free side is above: normal (d.y, −d.x) = (0, −1).
  const SegmentFeature<double> floor = makeSegment(Vec2<double>(0, 20), Vec2<double>(20, 20));
  ASSERT_EQ(floor.normal, Vec2<double>(0, -1));
  const Trajectory<double> t{{10, 10}, {0, 5}, {0, 0}};
  const auto tau = segmentTimeOfImpact(t, 0.25, floor, 10.0);
  ASSERT_TRUE(tau);
  EXPECT_DOUBLE_EQ(*tau, (19.75 - 10) / 5);
}

TEST(TimeOfImpact, SegmentUnderGravityIsTheQuadraticRoot) {
  const SegmentFeature<double> floor = makeSegment(Vec2<double>(0, 20), Vec2<double>(20, 20));
  const Trajectory<double> t{{1, 11}, {0, 0}, {0, 25}};
  const auto tau = segmentTimeOfImpact(t, 0.25, floor, 10.0);
  ASSERT_TRUE(tau);
  EXPECT_NEAR(*tau, std::sqrt(2 * 8.75 / 25), 1e-15);
}

TEST(TimeOfImpact, SegmentMissesBeyondItsEndsAndFromBehind) {
  const SegmentFeature<double> top = makeSegment(Vec2<double>(5, 5), Vec2<double>(6, 5));  // normal (0,−1)
  // Passing beside the segment: the contact point would lie off it.
  EXPECT_FALSE(segmentTimeOfImpact(Trajectory<double>{{7, 2}, {0, 5}, {0, 0}}, 0.25, top, 10.0));
  // Coming from behind (below): the other side's edges handle that.
  EXPECT_FALSE(segmentTimeOfImpact(Trajectory<double>{{5.5, 8}, {0, -5}, {0, 0}}, 0.25, top, 10.0));
  // Receding while touching: no collision (docs/physics.md §5).
  EXPECT_FALSE(segmentTimeOfImpact(Trajectory<double>{{5.5, 4.75}, {0, -1}, {0, 0}}, 0.25, top, 10.0));
  // Touching and approaching: now.
  const auto now = segmentTimeOfImpact(Trajectory<double>{{5.5, 4.75}, {0, 1}, {0, 0}}, 0.25, top, 10.0);
  ASSERT_TRUE(now);
  EXPECT_EQ(*now, 0.0);
}

// A ball thrown up beside a bumper starts behind the line of the bumper's top edge, and gravity
// brings it down onto that edge from above: the gap rises through zero beside the bumper (not an
// entry), then falls to zero over the edge. Found by the no-tunnelling property (campaign seed
// 20261201, case 359): the edge was never looked at from behind its line, so the ball sank into
// a flipper's top side until the next recalculation found it there.
TEST(TimeOfImpact, AnArcFromBehindAnEdgesLineLandsOnTheEdge) {
  const SegmentFeature<double> top = makeSegment(Vec2<double>(5, 5), Vec2<double>(6, 5));  // normal (0,−1)
  const Trajectory<double> arc{{7, 6}, {-2, -10}, {0, 25}};
  ASSERT_LT(dot(arc.p - top.a, top.normal), 0.0);
  const auto tau = segmentTimeOfImpact(arc, 0.25, top, 1.0);
  ASSERT_TRUE(tau);
  // 4.75 = 6 − 10τ + 12.5τ², the later root; the contact point is then over the edge.
  EXPECT_NEAR(*tau, (10 + std::sqrt(37.5)) / 25, 1e-14);
  const double x = arc.positionAt(*tau).x;
  EXPECT_TRUE(5 <= x && x <= 6);
  // The same arc cut short before it comes down, and a path that falls away behind the line
  // (never over it), meet nothing; neither is a contact now, though the gap is negative.
  EXPECT_FALSE(segmentTimeOfImpact(arc, 0.25, top, 0.6));
  EXPECT_FALSE(segmentTimeOfImpact(Trajectory<double>{{5.5, 8}, {0, 1}, {0, 25}}, 0.25, top, 1.0));
  EXPECT_FALSE(segmentTimeOfImpact(Trajectory<double>{{5.5, 5.5}, {0, -1}, {0, 25}}, 0.25, top, 1.0));
}

// A ball that comes down to an edge's line a hair beyond its end (where the end's vertex passes
// it as a graze) and then moves over the edge, on its line or a rounding below it and closing,
// is hit as it comes over the end: the gap's own entry lay beyond the end, and over the edge the
// gap only falls (campaign seed 667430151, case 701: a ball sank into a square's top).
TEST(TimeOfImpact, ABallComingOverAnEdgesEndOntoItsLineIsHitThere) {
  const SegmentFeature<double> top = makeSegment(Vec2<double>(5, 5), Vec2<double>(6, 5));  // normal (0,−1)
  auto path = [](double below, double vy) { return Trajectory<double>{{6.001, 4.75 + below}, {-1, vy}, {0, 0}}; };
  const auto tau = segmentTimeOfImpact(path(1e-13, 1e-9), 0.25, top, 1.0);
  ASSERT_TRUE(tau);
  EXPECT_NEAR(*tau, 1e-3, 1e-15);
  // Deeper than a graze of the vertex lets it be: the vertex's business, not the edge's.
  EXPECT_FALSE(segmentTimeOfImpact(path(1e-6, 1e-9), 0.25, top, 1.0));
  // On the line and moving along it (a ball sliding on a collinear neighbour): it meets the edge
  // when its contact ends, not here; and one opening away from the line meets nothing.
  EXPECT_FALSE(segmentTimeOfImpact(path(0, 0), 0.25, top, 1.0));
  EXPECT_FALSE(segmentTimeOfImpact(path(0, -1e-9), 0.25, top, 1.0));
}

// A free ball that comes over an edge's end along its line with a normal speed at rounding's
// level, either way, is pressed into the line by gravity and dips below it at once: it is hit as
// it comes over the end. A ball sliding on a collinear neighbour has no acceleration across the
// line (its surface takes gravity's part), and meets the edge when its contact ends, as before
// (campaign seed 27182818, case 174: a ball sent back along a flipper's top by the wall at its
// pivot end, 8·10⁻¹⁷ L beyond the side's end at 3.5·10⁻¹⁵ L/s across, sank into the side).
TEST(TimeOfImpact, ABallPressedOntoAnEdgesLineAsItComesOverTheEndIsHitThere) {
  const SegmentFeature<double> top = makeSegment(Vec2<double>(0.25, 18), Vec2<double>(1.75, 18));  // normal (0,−1)
  auto path = [](double vy, double ay) {
    return Trajectory<double>{{0.24999999999999992, 17.75}, {55.134951070500868, vy}, {0, ay}};
  };
  for (const double vy : {3.4694469519536142e-15, 0.0, -3.4694469519536142e-15}) {
    const auto tau = segmentTimeOfImpact(path(vy, 1000), 0.25, top, 0.05);
    ASSERT_TRUE(tau) << "vy " << vy;
    EXPECT_LT(*tau, 1e-16) << "vy " << vy;
  }
  // No acceleration across the line (sliding on a neighbour, or the classic model): not here.
  EXPECT_FALSE(segmentTimeOfImpact(path(3.4694469519536142e-15, 0), 0.25, top, 0.05));
  // Pulled away from the line: nothing to meet.
  EXPECT_FALSE(segmentTimeOfImpact(path(-3.4694469519536142e-15, -1000), 0.25, top, 0.05));
}

// Two balls 1e-8 L into each other (deeper than a graze leaves them) whose closing is a rounding
// (d·v = −1.8e-15, an ulp of 10, against |d||v| = 0.5) are not hit now: the response, computing
// the closing with its own roundings, may find them opening and change nothing, and the same hit
// would be predicted at that instant for ever (campaign seed 137035999, case 2822). Closing for
// real, they are hit now, however slowly (case 1906).
TEST(TimeOfImpact, APairDeeperThanAGrazeIsHitNowOnlyWhenItClosesBeyondRounding) {
  const Trajectory<double> still{{10, 10}, {0, 0}, {0, 0}};
  auto other = [](double vx) { return Trajectory<double>{{10.49999999, 10 + 2e-15}, {vx, -1}, {0, 0}}; };
  const auto rounding = ballTimeOfImpact(other(0), still, 0.25, 0.01);
  EXPECT_FALSE(rounding && *rounding == 0.0);
  EXPECT_EQ(ballTimeOfImpact(other(-1e-6), still, 0.25, 0.01), std::optional<double>(0.0));
}

// docs/physics.md, sliding ends: a ball closer to a segment's end than the position resolution
// (4ε(|x| + |y|), 8.7e-15 L here) and moving out over it has left the segment: it cannot get any
// nearer by moving, and hitting the edge again would begin a contact that ends at once, for ever.
TEST(TimeOfImpact, ABallWithinThePositionResolutionOfAnEdgesEndLeavesOverIt) {
  const SegmentFeature<double> top = makeSegment(Vec2<double>(5.1, 5), Vec2<double>(6, 5));  // normal (0,−1)
  auto onTop = [](double x, double vx) { return Trajectory<double>{{x, 4.75}, {vx, 0}, {0, 25}}; };
  ASSERT_LT(4e-15, positionResolution(Vec2<double>(5.1, 4.75)));
  EXPECT_FALSE(segmentTimeOfImpact(onTop(5.1 + 4e-15, -0.15), 0.25, top, 1.0));
  // Moving onto the segment from there, or moving out from farther than the resolution: a
  // contact now, as for any ball pressed onto an edge.
  EXPECT_EQ(segmentTimeOfImpact(onTop(5.1 + 4e-15, 0.15), 0.25, top, 1.0), std::optional<double>(0.0));
  EXPECT_EQ(segmentTimeOfImpact(onTop(5.1 + 1e-12, -0.15), 0.25, top, 1.0), std::optional<double>(0.0));
  EXPECT_TRUE(leavingOverEnd(top, 4e-15, -0.15, 0.0, positionResolution(Vec2<double>(5.1, 4.75))));
  EXPECT_FALSE(leavingOverEnd(top, 1e-12, -0.15, 0.0, positionResolution(Vec2<double>(5.1, 4.75))));
  EXPECT_TRUE(leavingOverEnd(top, top.length - 4e-15, 0.15, 0.0, positionResolution(Vec2<double>(6, 4.75))));
}

TEST(TimeOfImpact, BallAtRestOnAFloorThatGravityPressesIsInContactNow) {
  const SegmentFeature<double> floor = makeSegment(Vec2<double>(0, 20), Vec2<double>(20, 20));
  const auto tau = segmentTimeOfImpact(Trajectory<double>{{3, 19.75}, {0, 0}, {0, 25}}, 0.25, floor, 1.0);
  ASSERT_TRUE(tau);
  EXPECT_EQ(*tau, 0.0);
}

TEST(TimeOfImpact, VertexHitAtFortyFiveDegrees) {
  // Aimed along the diagonal at the corner (5,5): contact when the centre is 0.25 from it.
  const CircleFeature<double> corner{{5, 5}, 0};
  const Trajectory<double> t{{2, 2}, {1, 1}, {0, 0}};
  const auto tau = circleTimeOfImpact(t, 0.25, corner, 10.0);
  ASSERT_TRUE(tau);
  EXPECT_NEAR(*tau, 3 - 0.25 / std::sqrt(2.0), 1e-14);
}

// docs/physics.md, grazes: passing a corner 1e-14 L inside the tangent is no collision (the
// closing speed is about 3e-7 of the speed, rounding-level for a double root), 1e-6 L inside
// it is (3e-3 of the speed); a ball falling onto the corner's top, curving into it, always is.
TEST(TimeOfImpact, ARoundingLevelDipIntoACornerIsAGraze) {
  const CircleFeature<double> corner{{12, 11}, 0};
  auto passing = [](double depth) { return Trajectory<double>{{3, 10.75 + depth}, {47, 0}, {0, 0}}; };
  EXPECT_FALSE(circleTimeOfImpact(passing(1e-14), 0.25, corner, 1.0));
  const auto hit = circleTimeOfImpact(passing(1e-6), 0.25, corner, 1.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(*hit, 9.0 / 47, 1e-4);
  // On the corner's top, moving along the tangent, slower than gravity would let it fly off
  // (|v|² < g·0.25): it curves into the corner, a contact now, not a graze.
  const Trajectory<double> rolling{{12, 10.75}, {1, 0}, {0, 25}};
  EXPECT_FALSE(grazesAt(rolling, corner.centre, 0.0));
  const auto now = circleTimeOfImpact(rolling, 0.25, corner, 1.0);
  ASSERT_TRUE(now);
  EXPECT_EQ(*now, 0.0);
  EXPECT_TRUE(grazesAt(passing(1e-14), corner.centre, 9.0 / 47));
}

TEST(TimeOfImpact, CircleUnderGravityMatchesAQuarticRootFoundIndependently) {
  // A ball dropped beside a circle bumper's top: solve |p(t) − c| = 0.75 by bisection on a
  // fine grid here, independently of the library's root finder.
  const CircleFeature<double> c{{4.5, 3.5}, 0.5};
  const Trajectory<double> t{{4.9, 0.5}, {0.3, 0}, {0, 25}};
  auto gap = [&](double tau) { return length(t.positionAt(tau) - c.centre) - 0.75; };
  double lo = 0, hi = 0;
  for (double x = 0; x < 1; x += 1e-4)
    if (gap(x) > 0 && gap(x + 1e-4) <= 0) {
      lo = x;
      hi = x + 1e-4;
      break;
    }
  ASSERT_GT(hi, 0.0);
  for (int i = 0; i < 200; ++i) {
    const double m = (lo + hi) / 2;
    (gap(m) > 0 ? lo : hi) = m;
  }
  const auto tau = circleTimeOfImpact(t, 0.25, c, 1.0);
  ASSERT_TRUE(tau);
  EXPECT_NEAR(*tau, lo, 1e-12);
}

TEST(TimeOfImpact, TwoBallsHeadOn) {
  const Trajectory<double> a{{5, 10}, {2, 0}, {0, 25}}, b{{15, 10}, {-2, 0}, {0, 25}};
  const auto tau = ballTimeOfImpact(a, b, 0.25, 10.0);
  ASSERT_TRUE(tau);
  EXPECT_DOUBLE_EQ(*tau, 9.5 / 4);
}

TEST(TimeOfImpact, SwingingFlipperStrikesABallAtRestOnItsPath) {
  // Left flipper at (0,0): pivot (0.25,0.25), rest pointing down, swinging towards east at
  // ω = −6π. A ball at rest at angle θ = π/4 from the pivot, 1 L out, beside the bar's side:
  // the side facing it reaches the ball when the axis is 0.5/1 rad short of π/4 (sin⁻¹ 0.5).
  SwingingAxis<double> axis;
  axis.pivot = Vec2<double>(0.25, 0.25);
  axis.baseQuarter = 1;
  axis.phi0 = 0;
  axis.omega = -6 * M_PI;
  axis.length = 1.5;
  axis.radius = 0.25;
  const double theta = M_PI / 4;
  const Trajectory<double> ball{{0.25 + std::cos(theta), 0.25 + std::sin(theta)}, {0, 0}, {0, 0}};
  const auto hit = swingingCapsuleTimeOfImpact(ball, 0.25, axis, 1.0 / 12);
  ASSERT_TRUE(hit);
  // The side touches when the perpendicular distance is 0.5: θ_axis = π/4 + asin(0.5).
  const double expected = (M_PI / 2 - (theta + std::asin(0.5))) / (6 * M_PI);
  EXPECT_NEAR(hit->tau, expected, 1e-12);
  EXPECT_TRUE(hit->feature == 0 || hit->feature == 1);
}

TEST(TimeOfImpact, SwingingFlipperTipReachesABallBeyondTheSides) {
  SwingingAxis<double> axis;
  axis.pivot = Vec2<double>(0.25, 0.25);
  axis.baseQuarter = 1;
  axis.omega = -6 * M_PI;
  axis.length = 1.5;
  axis.radius = 0.25;
  // 1.9 L out at θ = π/4: beyond the axis's end, so only the tip reaches it, when the axis is
  // Δ short of θ with 1.5² + 1.9² − 2·1.5·1.9 cos Δ = 0.5².
  const double theta = M_PI / 4, r = 1.9;
  const double delta = std::acos((1.5 * 1.5 + r * r - 0.25) / (2 * 1.5 * r));
  const Trajectory<double> ball{{0.25 + r * std::cos(theta), 0.25 + r * std::sin(theta)}, {0, 0}, {0, 0}};
  const auto hit = swingingCapsuleTimeOfImpact(ball, 0.25, axis, 1.0 / 12);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->feature, 3);
  EXPECT_NEAR(hit->tau, (M_PI / 2 - theta - delta) / (6 * M_PI), 1e-12);
}

}  // namespace
}  // namespace gizmo
