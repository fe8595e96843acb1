// Certified decisions next to swinging flippers (docs/verification.md, "Swinging flippers"): a
// flipper striking a falling ball is certified in both models; a tip crossing into a ball at rest
// by 1e-15 (a graze in double, a hit in mpfr:256) and passing it by 9e-16 (a miss) are certified
// passes, only with MPFI; and decisions built by hand, where a swinging flipper's contact is
// skipped or claimed where there is none, are proven wrong.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/certify.hpp"
#include "gizmo/verify/certify_ladder.hpp"
#include "support/certify_hand_board.hpp"
#include "support/certify_report_text.hpp"
#include "support/fixture_request.hpp"

namespace gizmo::verify {
namespace {

using test::describe;
using test::eventAt;
using test::settle;

std::uint64_t uncertifiedCount(const CertifyReport& r) {
  std::uint64_t n = 0;
  for (std::uint64_t k : r.uncertifiedByReason) n += k;
  return n;
}

// Every executed event of a run, at the chosen scalar.
template <class Real>
struct Executed : BoardObserver<Real> {
  std::vector<Event<Real>> events;
  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>&) override { events.push_back(e); }
};

// The collisions of the run with flipper `flipper` that happen while it swings: between a
// trigger and the stop, which comes exactly 1/12 s after a swing from rest.
std::vector<Event<double>> strikesDuringSwing(const RunRequest& request) {
  Executed<double> o;
  simulate<double>(request, &o);
  std::vector<Event<double>> strikes;
  for (const Event<double>& stop : o.events) {
    if (stop.kind != EventKind::FlipperStop) continue;
    for (const Event<double>& e : o.events)
      if (e.kind == EventKind::Collision && e.a == stop.a && e.time < stop.time && stop.time - 1.0 / 12 < e.time)
        strikes.push_back(e);
  }
  return strikes;
}

class CertifyFlipperStrike : public ::testing::TestWithParam<MotionModel> {};

TEST_P(CertifyFlipperStrike, AFlipperSwingingIntoAFallingBallIsCertified) {
  const RunRequest request = test::fixtureRequest("boards/verify/flipper-strike.txt", GetParam(), 2);
  const std::vector<Event<double>> strikes = strikesDuringSwing(request);
  ASSERT_EQ(strikes.size(), 1u);
  EXPECT_EQ(strikes[0].feature, 0);  // the capsule's upper side
  const CertifyReport r = certifyRun(request);
  EXPECT_GT(r.decisions, 50u);
  EXPECT_TRUE(r.allCertified()) << describe(r);
  EXPECT_EQ(uncertifiedCount(r), 0u) << describe(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
  EXPECT_TRUE(r.ties.empty()) << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Models, CertifyFlipperStrike, ::testing::Values(MotionModel::Classic, MotionModel::Ballistic),
                         [](const auto& info) { return std::string(motionModelName(info.param)); });

// Whether the run's flipper meets anything with its tip (feature 3), at the chosen scalar. The
// flipper is the gizmo whose stop events the run executes.
template <class Real>
bool tipHits(const RunRequest& request) {
  Executed<Real> o;
  simulate<Real>(request, &o);
  GizmoId flipper = kNoGizmo;
  for (const Event<Real>& e : o.events)
    if (e.kind == EventKind::FlipperStop) flipper = e.a;
  for (const Event<Real>& e : o.events)
    if (e.kind == EventKind::Collision && e.a == flipper && e.feature == 3) return true;
  return false;
}

struct GrazeCase {
  const char* board;
  bool crosses;  // the tip's path crosses into the ball (by 1.3e-15 L), or stays out by as much
};

class CertifyFlipperGraze : public ::testing::TestWithParam<GrazeCase> {};

// Double passes the tip by the ball either way: a crossing that shallow is a graze under the
// double model's rule (docs/physics.md, "Grazes"), and the certifier proves both passes right.
// At 256 bits the rule's fraction is 2^-117.5, so mpfr:256 hits the ball where the path crosses.
TEST_P(CertifyFlipperGraze, DoublePassesAndIsCertifiedOnlyWithMpfi) {
  const GrazeCase c = GetParam();
  const RunRequest request = test::fixtureRequest(c.board, MotionModel::Ballistic, 0.5);
  setMpfrBits(256);
  EXPECT_EQ(tipHits<MpfrReal>(request), c.crosses);
  EXPECT_FALSE(tipHits<double>(request));
  const CertifyReport r = certifyRun(request);
  EXPECT_TRUE(r.allCertified()) << describe(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
  // 1e-15 is below what the double intervals resolve on a turning capsule: the graze needs MPFI.
  EXPECT_LT(r.certifiedAtRung.at(0), r.decisions) << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Boards, CertifyFlipperGraze,
                         ::testing::Values(GrazeCase{"boards/verify/flipper-graze-hit.txt", true},
                                           GrazeCase{"boards/verify/flipper-graze-miss.txt", false}),
                         [](const auto& info) { return std::string(info.param.crosses ? "Crosses" : "StaysOut"); });

// A board by hand (support/certify_hand_board.hpp): a left flipper at (9, 12) that starts its
// forward swing from rest at t = 0.2, and a ball lying still at `ball`.
test::HandBoard swingingFlipperBoard(Vec2<double> ball) {
  detail::LayoutGizmo flipper;
  flipper.name = "LF";
  flipper.kind = detail::LayoutKind::Flipper;
  const FlipperLayout f = flipperLayout(GizmoType::LeftFlipper, 0);
  flipper.pivot = Vec2<double>(9, 12) + f.pivot;
  flipper.restQuarter = f.restQuarter;
  flipper.endQuarter = f.endQuarter;
  flipper.forwardSign = f.forwardSign;
  test::HandBoard board(flipper, Vec2<double>(9, 12), ball, 0.2);
  detail::FlipperSnapshot fs;
  fs.id = 1;
  fs.swinging = true;
  fs.quarter = f.restQuarter;
  fs.offset = 0;
  fs.t0 = 0.2;
  fs.turn = f.forwardSign;
  board.snapshot.flippers = {fs};
  return board;
}

// The ball lies on the diagonal 1.63 from the pivot: the bar, turning from down towards east,
// reaches it by t ≈ 0.24.
const Vec2<double> kInTheWay(10.4, 13.4);

TEST(CertifyFlipperByHand, NoContactBeforeTheSwingReachesTheBallIsCertified) {
  const test::HandBoard board = swingingFlipperBoard(kInTheWay);
  const detail::LadderResult r =
      settle(board, eventAt(0.21, EventKind::EndOfTick), eventAt(0.21, EventKind::EndOfTick));
  EXPECT_EQ(r.outcome.verdict, detail::Verdict::Certified);
  EXPECT_EQ(r.rung, 0);
}

TEST(CertifyFlipperByHand, AnEndOfTickAfterTheStrikeIsWrong) {
  const test::HandBoard board = swingingFlipperBoard(kInTheWay);
  const detail::LadderResult r =
      settle(board, eventAt(0.25, EventKind::EndOfTick), eventAt(0.25, EventKind::EndOfTick));
  ASSERT_EQ(r.outcome.verdict, detail::Verdict::Wrong);
  EXPECT_EQ(r.outcome.other.kind, EventKind::Collision);
  EXPECT_EQ(r.outcome.other.a, 1);
  EXPECT_EQ(r.outcome.other.b, 2);
  EXPECT_NE(r.outcome.other.feature, 2);  // a moving feature, not the pivot end
  EXPECT_GT(r.outcome.byLo, 0.0);
}

TEST(CertifyFlipperByHand, AClaimedTipContactOutOfReachIsWrong) {
  const test::HandBoard board =
      swingingFlipperBoard(Vec2<double>(12.5, 13.4));  // 3.4 from the pivot: beyond the tip's reach of 2
  const detail::LadderResult r =
      settle(board, eventAt(0.24, EventKind::Collision, 1, 2, 3), eventAt(0.25, EventKind::EndOfTick));
  ASSERT_EQ(r.outcome.verdict, detail::Verdict::Wrong);
  EXPECT_EQ(r.outcome.other.kind, EventKind::EndOfTick);
}

}  // namespace
}  // namespace gizmo::verify
