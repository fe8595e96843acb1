// The broad phase: its id set, which lists the candidates of a ball in id order without repeats,
// and the wide balls, whose swept boxes span too many cells to be listed in each.
#include <gtest/gtest.h>

#include <vector>

#include "gizmo/core/board/id_set.hpp"
#include "support/board_builder.hpp"

namespace gizmo {
namespace {

TEST(IdSet, ListsItsMembersOnceInAscendingOrderAndEmpties) {
  IdSet set;
  set.reset(300);
  for (GizmoId id : {200, 3, 64, 63, 3, 299, 0, 64, 127, 128}) set.insert(id);
  std::vector<GizmoId> out{-7};  // drained members are appended
  set.drainInto(out);
  EXPECT_EQ(out, (std::vector<GizmoId>{-7, 0, 3, 63, 64, 127, 128, 200, 299}));
  out.clear();
  set.drainInto(out);
  EXPECT_TRUE(out.empty());
  set.insert(5);
  set.drainInto(out);
  EXPECT_EQ(out, (std::vector<GizmoId>{5}));
}

// A ball at 5000 L/s sweeps the board's whole width in one 0.05 s horizon: a wide ball, listed
// apart from the cells. Two of them, head-on from the two ends, are each other's candidates:
// their edges meet after 16.5 / 10000 s, and they exchange their velocities.
TEST(BroadPhase, TwoWideBallsMeet) {
  BoardSpec spec = test::emptyBoard(0, 0, 0);
  spec.balls.push_back(test::ballAt("B1", 1.5, 10, 5000, 0));
  spec.balls.push_back(test::ballAt("B2", 18.5, 10, -5000, 0));
  auto board = test::build(spec);
  test::Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.0034);  // each then reaches its wall at 0.00355 s
  const std::vector<test::Recorder<double>::Executed> hits = rec.ofKind(EventKind::Collision);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].event.time, 16.5 / 10000, 1e-15);
  EXPECT_EQ(board->ballById(*board->find("B2")).velocityAt(board->now()), Vec2<double>(5000, 0));
}

// A flipper that starts to swing is paired with the balls near it from its own side, the wide
// ones included: B falls at 100 L/s past the flipper's rest position (a 0.1 s horizon: its box
// spans 2 × 12 cells), and the flipper, pressed at 0.001 s, swings into its path. B's own
// predictions run until 0.1 s, so only the flipper's side can find the hit before then.
TEST(BroadPhase, ASwingingFlipperFindsAWideBall) {
  BoardSpec spec = test::emptyBoard(0, 0, 0);
  spec.gizmos.push_back(test::gizmoAt(GizmoType::LeftFlipper, "F", 10, 10));
  spec.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "F", {}});
  spec.balls.push_back(test::ballAt("B", 11, 5, 0, 100));
  auto board = test::build(spec, MotionModel::Ballistic, 0.1);
  board->scheduleInput(0.001, 32, KeyDirection::Down);
  test::Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(0.09);
  const GizmoId f = *board->find("F");
  bool hitFlipper = false;
  for (const test::Recorder<double>::Executed& e : rec.ofKind(EventKind::Collision))
    hitFlipper = hitFlipper || e.event.a == f || e.event.b == f;
  EXPECT_TRUE(hitFlipper);
  EXPECT_LT(board->ballById(*board->find("B")).positionAt(board->now()).y, 11.0);
}

}  // namespace
}  // namespace gizmo
