// The invariant checker catches what it claims to: fed a board changed behind its back, or a
// decision that the queue never held, it reports the broken invariant (so a passing property
// means something).
#include <gtest/gtest.h>

#include <string>

#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/fuzz/invariants.hpp"

namespace gizmo::verify::fuzz {
namespace {

RunRequest oneFallingBall() {
  RunRequest r;
  r.board.balls.push_back(BallSpec{"B", 10, 10, 0, 0, {}});
  r.duration = 0.2;
  return r;
}

bool reports(const std::vector<Violation>& v, Invariant i) {
  for (const Violation& x : v)
    if (x.invariant == i) return true;
  return false;
}

TEST(FuzzInvariants, AnHonestRunKeepsThemAll) {
  for (MotionModel m : {MotionModel::Ballistic, MotionModel::Classic}) {
    RunRequest r = oneFallingBall();
    r.model = m;
    EXPECT_TRUE(checkInvariants<double>(r, {std::begin(kAllInvariants), std::end(kAllInvariants)}).violations.empty());
  }
}

TEST(FuzzInvariants, AHundredBallsWithFrictionKeepThemAll) {
  // A hundred moving balls with friction tick at every instant of the friction grid together, so
  // the queue keeps their ticks in its lane beside the heap (from 32 heap entries on); the
  // event-queue invariant checks that every pop is still the earliest pending event.
  RunRequest r;
  for (int i = 0; i < 100; ++i)
    r.board.balls.push_back(BallSpec{
        "B" + std::to_string(i), 1.5 + 1.8 * (i % 10), 1.5 + 1.8 * (i / 10), double(i % 7) - 3, double(i % 5) - 2, {}});
  r.duration = 0.3;
  const InvariantRun run = checkInvariants<double>(r, {std::begin(kAllInvariants), std::end(kAllInvariants)});
  EXPECT_TRUE(run.violations.empty()) << run.violations.front().message;
}

TEST(FuzzInvariants, EnergyFromNowhereIsCaught) {
  const RunRequest r = oneFallingBall();
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(r);
  InvariantChecker<double> checker(*board, {Invariant::Energy});
  board->setObserver(&checker);
  board->tick(0.05);
  EXPECT_TRUE(checker.violations().empty());
  // Lifted by 5 L without any event: 125 L²/s² of potential energy that nothing supplied.
  const GizmoId ball = board->ballIds().front();
  ASSERT_FALSE(board->setProperty(ball, "y", PropertyValue(5.0)).has_value());
  board->tick(0.05);
  ASSERT_EQ(checker.violations().size(), 1u);
  EXPECT_NE(checker.violations()[0].message.find("energy rose"), std::string::npos) << checker.violations()[0].message;
}

TEST(FuzzInvariants, AnEventNeverScheduledIsCaught) {
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(oneFallingBall());
  InvariantChecker<double> checker(*board, {Invariant::EventQueue});
  Event<double> ghost;
  ghost.kind = EventKind::Recalculate;
  ghost.sequence = 987654321;
  checker.eventExecuted(ghost, EventOutcome<double>{});
  EXPECT_TRUE(reports(checker.violations(), Invariant::EventQueue));
}

TEST(FuzzInvariants, ABallInsideAGizmoIsCaught) {
  // A board the readers would refuse (the ball overlaps the square), built directly: the state a
  // tunnelling bug would leave.
  RunRequest r = oneFallingBall();
  r.board.gizmos.push_back(GizmoSpec{GizmoType::Square, "S", 10, 10, 0, 1, 1, {}});
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(r);
  InvariantChecker<double> checker(*board, {Invariant::NoTunnelling});
  checker.eventExecuted(Event<double>{}, EventOutcome<double>{});  // an end of tick at time 0
  ASSERT_TRUE(reports(checker.violations(), Invariant::NoTunnelling));
  EXPECT_NE(checker.violations()[0].message.find("inside S"), std::string::npos) << checker.violations()[0].message;
}

}  // namespace
}  // namespace gizmo::verify::fuzz
