// The booster (docs/physics.md, "Gizmos other programs added"): its shape, its response computed
// by hand, and its cap.
#include <gtest/gtest.h>

#include <cmath>

#include "gizmo/core/gizmos/booster.hpp"
#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using namespace test;

// d-g-n's BoosterGizmo.java: corners (x, y), (x + 1, y + 1), (x, y + 1) at rest; each Rotate
// turns it a quarter clockwise about its centre.
TEST(Booster, ItsShapeIsTheTriangleWithTheRightAngleAtTheLowerLeft) {
  const Shape<double> s = restShape<double>(gizmoAt(GizmoType::Booster, "U", 9, 12));
  ASSERT_EQ(s.circles.size(), 3u);
  EXPECT_EQ(s.circles[0].centre, Vec2<double>(9, 13));
  EXPECT_EQ(s.circles[1].centre, Vec2<double>(9, 12));
  EXPECT_EQ(s.circles[2].centre, Vec2<double>(10, 13));
  const Shape<double> turned = restShape<double>(gizmoAt(GizmoType::Booster, "U", 9, 12, 90));
  EXPECT_EQ(turned.circles[0].centre, Vec2<double>(9, 12));
  EXPECT_EQ(turned.circles[1].centre, Vec2<double>(10, 12));
  EXPECT_EQ(turned.circles[2].centre, Vec2<double>(9, 13));
}

TEST(Booster, DoublesUpToTheCapAndNoFurther) {
  using B = Booster<double>;
  EXPECT_EQ(B::boosted(Vec2<double>(3, -4)), Vec2<double>(6, -8));
  EXPECT_EQ(B::boosted(Vec2<double>(-2500, 0)), Vec2<double>(-5000, 0));  // exactly 5000 L/s
  EXPECT_EQ(B::boosted(Vec2<double>(-std::nextafter(2500.0, 3000.0), 0)), std::nullopt);
  EXPECT_EQ(B::boosted(Vec2<double>(1500, 2000)), Vec2<double>(3000, 4000));  // |2v| = 5000
  EXPECT_EQ(B::boosted(Vec2<double>(1500, std::nextafter(2000.0, 3000.0))), std::nullopt);
  EXPECT_EQ(B::boosted(Vec2<double>(0, 0)), std::nullopt);
}

// Without gravity, a ball at (9.5, 10) falling at 10 L/s meets the slanted face y − x = 3 when
// its centre is 0.25 from it: at y = 12.5 − 0.25·√2, after (2.5 − 0.25·√2)/10 s. The face's
// normal is (1, −1)/√2, so the reflection turns (0, 10) into (10, 0), and the boost makes it
// (20, 0).
TEST(Booster, ASlantedHitByHand) {
  BoardSpec spec = emptyBoard(0, 0, 0);
  spec.gizmos.push_back(gizmoAt(GizmoType::Booster, "U", 9, 12));
  spec.balls.push_back(ballAt("B", 9.5, 10, 0, 10));
  auto board = build(spec);
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.3);
  const GizmoId u = *board->find("U"), b = *board->find("B");
  const std::vector<Recorder<double>::Executed> hits = rec.ofKind(EventKind::Collision);
  ASSERT_EQ(hits.size(), 1u);
  const Recorder<double>::Executed& hit = hits[0];
  EXPECT_EQ(hit.event.a, u);
  EXPECT_NEAR(hit.event.time, (2.5 - 0.25 * std::sqrt(2.0)) / 10, 1e-15);
  EXPECT_EQ(rec.countRule(BoosterRule::Boosted), 1);
  const Vec2<double> v = board->ballById(b).velocityAt(board->now());
  EXPECT_NEAR(v.x, 20, 1e-12);
  EXPECT_NEAR(v.y, 0, 1e-12);
}

// Along an axis everything is exact: a ball at 2500 L/s leaves the upright face at exactly
// 5000 L/s; one a single ulp faster is reflected and keeps its speed.
TEST(Booster, TheCapOnAnUprightFace) {
  for (const double speed : {2500.0, std::nextafter(2500.0, 3000.0)}) {
    BoardSpec spec = emptyBoard(0, 0, 0);
    spec.gizmos.push_back(gizmoAt(GizmoType::Booster, "U", 9, 12));
    spec.balls.push_back(ballAt("B", 3.5, 12.75, speed, 0));
    auto board = build(spec);
    Recorder<double> rec;
    board->setObserver(&rec);
    board->tick(0.00224);  // the hit comes at 5.25 / speed, 0.0021 s; the wall no sooner than 0.0045 s
    ASSERT_EQ(rec.ofKind(EventKind::Collision).size(), 1u) << speed;
    const bool doubled = speed == 2500.0;
    EXPECT_EQ(rec.countRule(BoosterRule::Boosted), doubled ? 1 : 0) << speed;
    EXPECT_EQ(board->ballById(*board->find("B")).velocityAt(board->now()), Vec2<double>(doubled ? -5000.0 : -speed, 0))
        << speed;
  }
}

// A hit on a booster fires its trigger like any bumper's.
TEST(Booster, ItsHitsTrigger) {
  BoardSpec spec = emptyBoard(0, 0, 0);
  spec.gizmos.push_back(gizmoAt(GizmoType::Booster, "U", 9, 12));
  spec.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "F", 2, 2));
  spec.connections.push_back(ConnectSpec{"U", "F", {}});
  spec.balls.push_back(ballAt("B", 3.5, 12.75, 10, 0));
  auto board = build(spec);
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(1.0);
  ASSERT_FALSE(rec.triggers.empty());
  EXPECT_EQ(rec.triggers[0], std::make_pair(*board->find("U"), *board->find("F")));
}

}  // namespace
}  // namespace gizmo
