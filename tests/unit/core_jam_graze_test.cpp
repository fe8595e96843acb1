// The jam rule's meetings of two balls (docs/physics.md, "Jam"): two jammed balls that merely
// graze are let through for that instant, and the pair skips its contact at that instant; a pair
// struck twice at one instant comes to rest. Both found by campaign seed 20261203, case 4731: a
// ball in a pile grazed two balls at one instant, and with one remembered graze per ball the two
// pairs overwrote each other and were predicted, grazed and predicted again a million times; then
// a wall, two balls and a wall passed a sliver of velocity back and forth at one instant.
#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "gizmo/core/gizmos/ball.hpp"
#include "support/stub_board.hpp"

namespace gizmo {
namespace {

// Three balls on a jammed board. A in the middle, at rest; B and C touch it on either side, sliding
// past it upwards and closing on it at a ten-thousandth of their speed: more than a graze of the
// path (docs/physics.md, "Grazes"), less than a thousandth, which the jam lets through. Nothing
// presses the balls together (no gravity): their meetings are grazes.
std::vector<test::StubBall> jammedBalls(Vec2<double> bVelocity = {-1e-4, 1}) {
  return {{"A", {10, 10}, {0, 0}}, {"B", {10.5, 10}, bVelocity}, {"C", {9.5, 10}, {1e-4, 1}}};
}

Contact<double> touchingNow() { return Contact<double>{0, 0, EventKind::Collision}; }

bool contactAtPresent(const Ball<double>& a, const Ball<double>& b, const PhysicsParams<double>& params) {
  const std::optional<Contact<double>> c = a.timeUntilCollision(b, 0, 1, params);
  return c && c->time == 0;
}

TEST(JamGraze, ABallGrazingTwoBallsAtOneInstantSkipsBothContacts) {
  test::StubBoard board(jammedBalls(), 0, true);
  Ball<double>& a = board.balls[0];
  Ball<double>& b = board.balls[1];
  Ball<double>& c = board.balls[2];
  ASSERT_TRUE(contactAtPresent(a, b, board.params()));  // the scene: both pairs touch and close
  ASSERT_TRUE(contactAtPresent(a, c, board.params()));
  a.collide(b, touchingNow(), board);
  a.collide(c, touchingNow(), board);
  EXPECT_EQ(board.rules, (std::vector<ModelRule>{ModelRule::Jammed, ModelRule::Jammed}));
  EXPECT_EQ(b.velocityAt(0), Vec2<double>(-1e-4, 1));  // let through, unchanged
  EXPECT_FALSE(contactAtPresent(a, b, board.params())) << "the first graze was forgotten";
  EXPECT_FALSE(contactAtPresent(a, c, board.params()));
}

TEST(JamGraze, BothGrazesSurviveASavedAndRestoredState) {
  test::StubBoard board(jammedBalls(), 0, true);
  Ball<double>& a = board.balls[0];
  Ball<double>& b = board.balls[1];
  Ball<double>& c = board.balls[2];
  a.collide(b, touchingNow(), board);
  a.collide(c, touchingNow(), board);
  GizmoState<double> saved;
  a.saveState(saved);

  struct ThreeBalls final : GizmoIdCheck {
    bool isBall(std::int64_t id) const override { return id >= 0 && id < 3; }
    bool isGizmo(std::int64_t id) const override { return isBall(id); }
  } ids;
  Ball<double> restored("A", {0, 0}, {0, 0});
  restored.setId(a.id());
  GizmoStateReader<double> reader(saved);
  restored.restoreState(reader, ids);
  reader.expectEnd();
  EXPECT_FALSE(contactAtPresent(restored, b, board.params()));
  EXPECT_FALSE(contactAtPresent(restored, c, board.params()));
}

// A pair struck a second time at one instant while jammed (something pushed one of them straight
// back into the other) comes to rest: solved pair by pair, such a chain converges only after
// millions of rounds at one instant (campaign seed 20261203, case 4731).
TEST(JamGraze, APairStruckTwiceAtOneInstantWhileJammedComesToRest) {
  const Vec2<double> headOn(-0.001, 0.0001);  // closing slowly, nearly head-on: a hit, not a graze
  test::StubBoard board(jammedBalls(headOn), 0, true);
  Ball<double>& a = board.balls[0];
  Ball<double>& b = board.balls[1];
  a.collide(b, touchingNow(), board);
  EXPECT_EQ(board.rules, std::vector<ModelRule>{ModelRule::Jammed});
  EXPECT_FALSE(a.wedged());
  EXPECT_NEAR(b.velocityAt(0).x, 0, 1e-18);  // both left with their mean normal velocity, below restSpeed: none
  // A wall behind b turns it back into a at the same instant.
  b.setVelocity(0, b.positionAt(0), headOn, board);
  a.collide(b, touchingNow(), board);
  EXPECT_TRUE(a.wedged());
  EXPECT_TRUE(b.wedged());
  EXPECT_EQ(a.velocityAt(0), Vec2<double>(0, 0));
  EXPECT_EQ(b.velocityAt(0), Vec2<double>(0, 0));
  // Struck once, at another instant, a pair is struck as any jammed pair is.
  test::StubBoard other(jammedBalls(headOn), 0, true);
  other.balls[0].collide(other.balls[1], touchingNow(), other);
  EXPECT_FALSE(other.balls[0].wedged());
}

TEST(JamGraze, AGrazeCountsOnlyAtItsOwnInstant) {
  test::StubBoard board(jammedBalls(), 0, true);
  Ball<double>& a = board.balls[0];
  Ball<double>& b = board.balls[1];
  a.collide(b, touchingNow(), board);
  // The same pair seen from a later instant (here: placed back in contact by hand) is a contact
  // again: the graze excused one instant, not the pair.
  b.setState(1, {10.5, 10}, {-1e-4, 1}, board.params());
  a.setState(1, {10, 10}, {0, 0}, board.params());
  const std::optional<Contact<double>> later = a.timeUntilCollision(b, 1, 2, board.params());
  ASSERT_TRUE(later.has_value());
  EXPECT_EQ(later->time, 1);
}

}  // namespace
}  // namespace gizmo
