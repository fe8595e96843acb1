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
// their edges meet after 16.5 / 10000 s, and they exchange their velocities. Classic: a ballistic
// ball that fast is swept for 1/128 of the tick (sweepSpan) and is never wide; a classic one is
// swept to the first event queued, at the start the tick's end.
TEST(BroadPhase, TwoWideBallsMeet) {
  BoardSpec spec = test::emptyBoard(0, 0, 0);
  spec.balls.push_back(test::ballAt("B1", 1.5, 10, 5000, 0));
  spec.balls.push_back(test::ballAt("B2", 18.5, 10, -5000, 0));
  auto board = test::build(spec, MotionModel::Classic);
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
// predictions run until 0.1 s, so only the flipper's side can find the hit before then. In the
// classic model: a ballistic ball that fast is swept for an eighth of the tick (sweepSpan, below)
// and is no longer wide; a classic one is swept to the first event queued, here the tick's end.
TEST(BroadPhase, ASwingingFlipperFindsAWideBall) {
  BoardSpec spec = test::emptyBoard(0, 0, 0);
  spec.gizmos.push_back(test::gizmoAt(GizmoType::LeftFlipper, "F", 10, 10));
  spec.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "F", {}});
  spec.balls.push_back(test::ballAt("B", 11, 5, 0, 100));
  auto board = test::build(spec, MotionModel::Classic, 0.1);
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

// A fast ballistic ball is swept for the maximum tick halved until its path reaches no further
// than 4 L, its speed's part within 2 L (docs/physics.md, "Broad phase"), and recalculated at that
// horizon: at 1000 L/s and a tick of 0.05 s, 0.05/32 = 0.0015625 s (1.5625 L; 0.05/16 would take
// it 3.125 L). At 40 L/s the whole tick (2 L) is within it; at 41 L/s half of it.
TEST(BroadPhase, AFastBallIsSweptOverAShorterHorizon) {
  for (const auto& [speed, span] : {std::pair{1000.0, 0.05 / 32}, std::pair{40.0, 0.05}, std::pair{41.0, 0.025}}) {
    BoardSpec spec = test::emptyBoard(0, 0, 0);
    spec.balls.push_back(test::ballAt("B", 10, 10, speed, 0));
    auto board = test::build(spec, MotionModel::Ballistic, 0.05);
    test::Recorder<double> rec;
    board->setObserver(&rec);
    board->tick(0.001);
    double firstRecalculation = -1;
    for (const Event<double>& e : board->pendingEvents())
      if (e.kind == EventKind::Recalculate) firstRecalculation = e.time;
    EXPECT_EQ(firstRecalculation, span) << speed << " L/s";
  }
}

}  // namespace
}  // namespace gizmo
