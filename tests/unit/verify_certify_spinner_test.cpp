// Certified decisions next to turning spinners (docs/verification.md, "Turning spinners"): a run in
// which the turning cross strikes a ball is certified in both models, and decisions built by hand,
// where a turning arm's contact is skipped or claimed on the wrong side, are proven wrong.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/certify.hpp"
#include "support/certify_hand_board.hpp"
#include "support/certify_report_text.hpp"
#include "support/fixture_request.hpp"

namespace gizmo::verify {
namespace {

using test::describe;
using test::eventAt;
using test::settle;

// Counts the hits that stop a spinner: each hit toggles it, so a hit after which it stands still
// was struck by the turning cross.
struct TurningHits : BoardObserver<double> {
  GameBoard<double>* board = nullptr;
  int hits = 0;
  void eventExecuted(const Event<double>& e, const EventOutcome<double>&) override {
    if (e.kind != EventKind::Collision) return;
    const auto* spinner = dynamic_cast<const Spinner<double>*>(&board->gizmo(e.a));
    if (spinner && !spinner->turning()) ++hits;
  }
};

int turningHits(const RunRequest& request) {
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(request);
  TurningHits o;
  o.board = board.get();
  board->setObserver(&o);
  continueRun(*board, request, 0);
  return o.hits;
}

class CertifySpinnerStrike : public ::testing::TestWithParam<MotionModel> {};

// The fixture's balls, shut in a pit over the spinner, are struck by its turning arms again and
// again (95 times in 10 s in the ballistic model, 121 in the classic one).
TEST_P(CertifySpinnerStrike, ATurningCrossStrikingBallsIsCertified) {
  const RunRequest request = test::fixtureRequest("boards/verify/spinner-pit.txt", GetParam(), 10);
  EXPECT_GE(turningHits(request), 40);
  const CertifyReport r = certifyRun(request);
  EXPECT_GT(r.decisions, 500u);
  EXPECT_TRUE(r.allCertified()) << describe(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Models, CertifySpinnerStrike, ::testing::Values(MotionModel::Classic, MotionModel::Ballistic),
                         [](const auto& info) { return std::string(motionModelName(info.param)); });

// A board by hand (support/certify_hand_board.hpp): a spinner at (9, 9), turning from t = 0.2 with
// arm 0 along +x (towards +y at 3.14 rad/s), and a ball lying still 0.8 from the centre at 45°.
// Arm 0's round tip (feature 3; its centre 0.5 from the spinner's) reaches it when the arm has
// turned by 45° − acos(0.8) = 0.1419 rad, at t ≈ 0.2452; a side never does, since a ball 0.8 from
// the centre touching a side would have to lie over the arm, at most 0.5 along it.
test::HandBoard turningSpinnerBoard() {
  detail::LayoutGizmo spinner;
  spinner.name = "S";
  spinner.kind = detail::LayoutKind::Spinner;
  spinner.pivot = Vec2<double>(10, 10);
  const double offset = 0.8 * 0.70710678118654752;
  test::HandBoard board(spinner, Vec2<double>(9, 9), Vec2<double>(10 + offset, 10 + offset), 0.2);
  detail::SpinnerSnapshot ss;
  ss.id = 1;
  ss.turning = true;
  ss.quarter = 0;
  ss.phase = 0;
  ss.t0 = 0.2;
  board.snapshot.spinners = {ss};
  return board;
}

TEST(CertifySpinnerByHand, NoContactBeforeTheArmReachesTheBallIsCertified) {
  const detail::LadderResult r =
      settle(turningSpinnerBoard(), eventAt(0.24, EventKind::EndOfTick), eventAt(0.24, EventKind::EndOfTick));
  EXPECT_EQ(r.outcome.verdict, detail::Verdict::Certified);
}

TEST(CertifySpinnerByHand, AnEndOfTickAfterTheStrikeIsWrong) {
  const detail::LadderResult r =
      settle(turningSpinnerBoard(), eventAt(0.25, EventKind::EndOfTick), eventAt(0.25, EventKind::EndOfTick));
  ASSERT_EQ(r.outcome.verdict, detail::Verdict::Wrong);
  EXPECT_EQ(r.outcome.other.kind, EventKind::Collision);
  EXPECT_EQ(r.outcome.other.a, 1);
  EXPECT_EQ(r.outcome.other.b, 2);
  EXPECT_EQ(r.outcome.other.feature, 3);  // arm 0's tip
  EXPECT_GT(r.outcome.byLo, 0.004);       // 0.25 − 0.2452
  EXPECT_LT(r.outcome.byHi, 0.006);
}

TEST(CertifySpinnerByHand, TheStrikeOfArmZerosTipIsCertified) {
  const detail::LadderResult r = settle(turningSpinnerBoard(), eventAt(0.2452, EventKind::Collision, 1, 2, 3),
                                        eventAt(0.25, EventKind::EndOfTick));
  EXPECT_EQ(r.outcome.verdict, detail::Verdict::Certified);
}

// Arm 0's side 1 never reaches the ball, nor does arm 2's tip (feature 4·2 + 3), on the far side.
TEST(CertifySpinnerByHand, AClaimedContactOfAFeatureThatNeverReachesIsWrong) {
  for (const std::int32_t feature : {1, 11}) {
    const detail::LadderResult r = settle(turningSpinnerBoard(), eventAt(0.2452, EventKind::Collision, 1, 2, feature),
                                          eventAt(0.25, EventKind::EndOfTick));
    EXPECT_EQ(r.outcome.verdict, detail::Verdict::Wrong) << "feature " << feature;
  }
}

}  // namespace
}  // namespace gizmo::verify
