// Certified decisions (docs/verification.md): fixture runs are certified in full or every
// uncertified decision has its reason; boards built so that double provably decides wrong are
// flagged at exactly that decision, and an mpfr:256 run of the same board decides the other way;
// a genuine tie is recognised and its documented order checked.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "support/fixture_request.hpp"
#include "gizmo/verify/certify.hpp"

namespace gizmo::verify {
namespace {

RunRequest requestFor(const std::string& board, MotionModel model, double seconds) {
  return test::fixtureRequest(board, model, seconds);
}

std::string describe(const CertifyReport& r) {
  std::ostringstream out;
  printCertifyReport(out, r);
  return out.str();
}

// Every decision is accounted for: certified, a tie, wrong, or uncertified with a reason.
void expectAccounted(const CertifyReport& r) {
  std::uint64_t uncertified = 0;
  for (std::uint64_t n : r.uncertifiedByReason) uncertified += n;
  EXPECT_EQ(r.certified() + r.ties.size() + r.wrong.size() + uncertified, r.decisions) << describe(r);
}

struct FixtureCase {
  const char* board;
  MotionModel model;
  double seconds;
};

class CertifyFixtures : public ::testing::TestWithParam<FixtureCase> {};

// These boards have no swinging flipper near a ball, no tie and no rounding-level call: every
// decision is certified, and (nothing being that close) by the double intervals alone.
TEST_P(CertifyFixtures, EveryDecisionIsCertifiedWithDoubleIntervals) {
  const FixtureCase c = GetParam();
  const CertifyReport r = certifyRun(requestFor(c.board, c.model, c.seconds));
  EXPECT_GT(r.decisions, 50u);
  EXPECT_EQ(r.certifiedAtRung.at(0), r.decisions) << describe(r);
  EXPECT_TRUE(r.allCertified());
  EXPECT_TRUE(r.wrong.empty());
  EXPECT_TRUE(r.ties.empty());
}

INSTANTIATE_TEST_SUITE_P(
    Boards, CertifyFixtures,
    ::testing::Values(FixtureCase{"boards/scenes/fast-ball-500.txt", MotionModel::Classic, 10},
                      FixtureCase{"boards/scenes/fast-ball-500.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/scenes/rolling-ball.txt", MotionModel::Classic, 10},
                      FixtureCase{"boards/scenes/rolling-ball.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/scenes/resting-ball.txt", MotionModel::Ballistic, 4},
                      FixtureCase{"boards/gizmos/absorber.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/gizmos/circle.txt", MotionModel::Classic, 10},
                      FixtureCase{"boards/gizmos/triangle-180.txt", MotionModel::Ballistic, 10}));

// The spec example swings its flippers whenever a circle is hit: the decisions a swinging
// flipper could affect are reported as such, never as certified; all others are certified.
TEST(CertifyRun, SpecExampleIsCertifiedExceptNearSwingingFlippers) {
  for (MotionModel model : {MotionModel::Classic, MotionModel::Ballistic}) {
    const CertifyReport r = certifyRun(requestFor("boards/spec-example.txt", model, 20));
    expectAccounted(r);
    EXPECT_TRUE(r.wrong.empty()) << describe(r);
    EXPECT_EQ(r.uncertifiedByReason[std::size_t(UncertifiedReason::Undecided)], 0u) << describe(r);
    EXPECT_EQ(r.certified() + r.uncertifiedByReason[std::size_t(UncertifiedReason::SwingingFlipper)], r.decisions);
    EXPECT_GT(r.certified(), r.decisions * 9 / 10);
  }
}

// Four balls meeting in the centre: the symmetric meetings are genuine ties, run in the
// documented order.
TEST(CertifyRun, SymmetricMeetingsAreTiesInTheDocumentedOrder) {
  const CertifyReport r = certifyRun(requestFor("boards/scenes/four-balls-meeting.txt", MotionModel::Ballistic, 10));
  expectAccounted(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
  ASSERT_FALSE(r.ties.empty());
  for (const TieDecision& t : r.ties) {
    EXPECT_TRUE(t.orderFollowed) << describe(r);
    EXPECT_LT(t.within.value, 1e-100);  // settled only at the top of the ladder
  }
}

// The first collision a run executes, at the chosen scalar.
template <class Real>
struct FirstCollision : BoardObserver<Real> {
  std::optional<Event<Real>> first;
  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>&) override {
    if (!first && e.kind == EventKind::Collision) first = e;
  }
};

template <class Real>
std::optional<Event<Real>> firstCollision(const RunRequest& request) {
  FirstCollision<Real> o;
  simulate<Real>(request, &o);
  return o.first;
}

std::optional<Event<MpfrReal>> firstCollisionMpfr256(const RunRequest& request) {
  setMpfrBits(256);
  return firstCollision<MpfrReal>(request);
}

// Exactly one decision is wrong, and it is `executed` where `first` should have come first.
const WrongDecision& expectOneWrong(const CertifyReport& r, EventKind executed, EventKind first, std::int32_t firstFeature) {
  expectAccounted(r);
  EXPECT_EQ(r.wrong.size(), 1u) << describe(r);
  EXPECT_TRUE(r.ties.empty()) << describe(r);
  const WrongDecision& w = r.wrong.at(0);
  EXPECT_EQ(w.executed.kind, executed);
  EXPECT_EQ(w.shouldHaveComeFirst.kind, first);
  if (first == EventKind::Collision) {
    EXPECT_EQ(w.shouldHaveComeFirst.feature, firstFeature);
  }
  EXPECT_GE(w.byAtLeast.value, 0.0);
  EXPECT_LE(w.byAtLeast.value, w.byAtMost.value);
  return w;
}

TEST(CertifyWrong, NearTieOfTwoWallsIsFlaggedAndMpfrHitsTheFloorFirst) {
  const RunRequest request = requestFor("boards/verify/near-tie-corner.txt", MotionModel::Ballistic, 2.5);
  const std::optional<Event<double>> d = firstCollision<double>(request);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->feature, 2);  // double: the right wall
  const CertifyReport r = certifyRun(request);
  const WrongDecision& w = expectOneWrong(r, EventKind::Collision, EventKind::Collision, 1);
  EXPECT_EQ(w.executed.feature, 2);
  EXPECT_EQ(w.time.value, d->time);
  EXPECT_GT(w.byAtLeast.value, 0.0);  // the floor comes first by a proven margin …
  EXPECT_LT(w.byAtMost.value, 1e-15);  // … below a double's resolution at t ≈ 2
  EXPECT_GT(w.rungBits, 53);           // so only MPFI could tell
  const std::optional<Event<MpfrReal>> m = firstCollisionMpfr256(request);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->feature, 1);  // mpfr:256: the floor
}

TEST(CertifyWrong, GrazingPassAtACornerIsFlaggedAndMpfrMissesTheCorner) {
  const RunRequest request = requestFor("boards/verify/grazing-corner.txt", MotionModel::Ballistic, 1);
  const std::optional<Event<double>> d = firstCollision<double>(request);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->feature, 7);  // double: the square's lower-left vertex
  const CertifyReport r = certifyRun(request);
  const WrongDecision& w = expectOneWrong(r, EventKind::Collision, EventKind::Recalculate, -1);
  EXPECT_EQ(w.executed.feature, 7);
  EXPECT_EQ(w.time.value, d->time);
  EXPECT_FALSE(firstCollisionMpfr256(request));  // mpfr:256: no collision at all
}

TEST(CertifyWrong, BallSlippingPastACornerIsFlaggedAndMpfrStopsIt) {
  const RunRequest request = requestFor("boards/verify/slips-past-corner.txt", MotionModel::Ballistic, 1);
  EXPECT_FALSE(firstCollision<double>(request));  // double: it slips past
  const CertifyReport r = certifyRun(request);
  const WrongDecision& w = expectOneWrong(r, EventKind::Recalculate, EventKind::Collision, 7);
  EXPECT_GT(w.byAtLeast.value, 0.0);
  const std::optional<Event<MpfrReal>> m = firstCollisionMpfr256(request);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->feature, 7);  // mpfr:256: it hits the vertex
  // The run executed the recalculation after the true contact time, by the proven margin.
  EXPECT_NEAR(w.time.value - toDouble(m->time), w.byAtLeast.value, 1e-12);
}

TEST(CertifyTie, DiagonalIntoTheCornerIsAGenuineTieInTheDocumentedOrder) {
  const CertifyReport r = certifyRun(requestFor("boards/verify/genuine-tie-corner.txt", MotionModel::Ballistic, 2.5));
  expectAccounted(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
  ASSERT_EQ(r.ties.size(), 1u) << describe(r);
  const TieDecision& t = r.ties[0];
  EXPECT_EQ(t.executed.feature, 1);  // the floor ran first …
  EXPECT_EQ(t.other.feature, 2);     // … tied with the right wall
  EXPECT_TRUE(t.orderFollowed);
  EXPECT_NEAR(t.time.value, 1.95, 1e-12);  // (19.75 − 10) / 5
}

TEST(CertifyLog, RefusesALogThatIsNotOfADoubleRun) {
  replay::OpenedLog log = replay::openLog(std::string(GIZMO_FIXTURES_DIR) + "/logs/four-balls-meeting-3s-ballistic-long-double.gzlog");
  EXPECT_THROW(certifyLog(log), CertifyError);
}

TEST(CertifyLog, CertifiesADoubleLogsRunAndPrintsTextAndJson) {
  replay::OpenedLog log = replay::openLog(std::string(GIZMO_FIXTURES_DIR) + "/logs/spec-example-5s-ballistic-double.gzlog");
  const CertifyReport r = certifyLog(log);
  expectAccounted(r);
  EXPECT_EQ(r.model, "ballistic");
  EXPECT_TRUE(r.wrong.empty());
  const std::string text = describe(r);
  EXPECT_NE(text.find("certified with double intervals"), std::string::npos);
  const std::string json = certifyReportJson(r);
  EXPECT_NE(json.find("\"decisions\": " + std::to_string(r.decisions)), std::string::npos);
}

}  // namespace
}  // namespace gizmo::verify
