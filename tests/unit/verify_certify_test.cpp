// Certified decisions (docs/verification.md): fixture runs are certified in full or every
// uncertified decision has its reason; a board built so that double provably decides wrong is
// flagged at exactly that decision, and an mpfr:256 run of it decides the other way; grazes that
// double passes under the graze rule are proven passes (the certifier applies the same rule);
// genuine ties are proven exact (a common root of the gap polynomials, or a scheduled time that is
// a root) and their documented order checked; the exact step's algebra and its ordering of two
// roots the intervals cannot part. Swinging flippers: verify_certify_flipper_test.cpp.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/verify/certify.hpp"
#include "gizmo/verify/certify_exact.hpp"
#include "gizmo/verify/certify_qpoly.hpp"
#include "support/certify_report_text.hpp"
#include "support/fixture_request.hpp"
#include "support/paths.hpp"

namespace gizmo::verify {
namespace {

RunRequest requestFor(const std::string& board, MotionModel model, double seconds) {
  return test::fixtureRequest(board, model, seconds);
}

using test::describe;

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
                      FixtureCase{"boards/gizmos/triangle-180.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/gizmos/booster.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/gizmos/sink.txt", MotionModel::Ballistic, 10},
                      // Balls spawned as it runs join the certifier's layout.
                      FixtureCase{"boards/gizmos/spawner.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/gizmos/spawner.txt", MotionModel::Classic, 10},
                      FixtureCase{"boards/gizmos/portal.txt", MotionModel::Classic, 10},
                      // The end rule at a corner, at the start and after a slide: before the
                      // certifier followed it, each gave a wrong decision in the ballistic model.
                      FixtureCase{"boards/verify/corner-leave.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/verify/corner-leave.txt", MotionModel::Classic, 10},
                      FixtureCase{"boards/verify/corner-slide-off.txt", MotionModel::Ballistic, 10},
                      FixtureCase{"boards/verify/corner-slide-off.txt", MotionModel::Classic, 10}));

// The spec example swings its flippers whenever a circle is hit; the decisions next to a
// swinging flipper are certified like the others.
TEST(CertifyRun, SpecExampleIsCertifiedIncludingNearSwingingFlippers) {
  for (MotionModel model : {MotionModel::Classic, MotionModel::Ballistic}) {
    const CertifyReport r = certifyRun(requestFor("boards/spec-example.txt", model, 20));
    expectAccounted(r);
    EXPECT_TRUE(r.wrong.empty()) << describe(r);
    EXPECT_EQ(r.uncertifiedByReason[std::size_t(UncertifiedReason::Undecided)], 0u) << describe(r);
    EXPECT_EQ(r.uncertifiedByReason[std::size_t(UncertifiedReason::SwingingFlipper)], 0u) << describe(r);
    EXPECT_TRUE(r.allCertified()) << describe(r);
  }
}

// A pile settling in a box (docs/physics.md, "Piles"): balls that settle on a level floor, come
// to rest on balls at rest and wake when a support moves. Every decision is certified, a tie
// proven exact and run in the documented order, or wrong by a rounding error at most: the double
// run takes one hit of a ball in the V's corner 2.8·10⁻¹⁶ s early (event 6652), a call no model
// rule makes.
TEST(CertifyRun, ASettlingPileIsCertifiedOrWrongOnlyByRounding) {
  const CertifyReport r = certifyRun(requestFor("boards/scenes/settling-pile.txt", MotionModel::Ballistic, 10));
  expectAccounted(r);
  EXPECT_GT(r.decisions, 5000u);
  EXPECT_EQ(r.certified() + r.ties.size() + r.wrong.size(), r.decisions) << describe(r);
  EXPECT_LE(r.wrong.size(), 2u) << describe(r);
  for (const WrongDecision& w : r.wrong) EXPECT_LT(w.byAtMost.value, 1e-12) << describe(r);
  EXPECT_EQ(r.provenTies(), r.ties.size()) << describe(r);
  for (const TieDecision& t : r.ties) EXPECT_TRUE(t.orderFollowed) << describe(r);
}

// Four balls meeting in the centre: the symmetric meetings are genuine ties, proven exact and
// run in the documented order.
TEST(CertifyRun, SymmetricMeetingsAreProvenTiesInTheDocumentedOrder) {
  for (MotionModel model : {MotionModel::Classic, MotionModel::Ballistic}) {
    const CertifyReport r = certifyRun(requestFor("boards/scenes/four-balls-meeting.txt", model, 10));
    expectAccounted(r);
    EXPECT_TRUE(r.wrong.empty()) << describe(r);
    ASSERT_FALSE(r.ties.empty());
    EXPECT_EQ(r.provenTies(), r.ties.size()) << describe(r);
    for (const TieDecision& t : r.ties) {
      EXPECT_TRUE(t.orderFollowed) << describe(r);
      EXPECT_EQ(t.within.value, 0.0);
    }
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
const WrongDecision& expectOneWrong(const CertifyReport& r, EventKind executed, EventKind first,
                                    std::int32_t firstFeature) {
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
  EXPECT_GT(w.byAtLeast.value, 0.0);   // the floor comes first by a proven margin …
  EXPECT_LT(w.byAtMost.value, 1e-15);  // … below a double's resolution at t ≈ 2
  EXPECT_GT(w.rungBits, 53);           // so only MPFI could tell
  const std::optional<Event<MpfrReal>> m = firstCollisionMpfr256(request);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->feature, 1);  // mpfr:256: the floor
}

// A ball thrown up beside a flipper lands on its top side from above, though its centre started
// behind that side's line (docs/physics.md, "Edges seen from behind their line"). The certifier
// looks at such an edge as the core does, so the landing is a certified decision, and no earlier
// rival is missed.
TEST(CertifyRun, ALandingOnAnEdgeFromBehindItsLineIsCertified) {
  RunRequest request;
  request.board.gravity = 1000;
  request.board.mu = request.board.mu2 = 0;
  request.board.balls.push_back(
      BallSpec{"B", 12.522527032318791, 18.02436634557278, -105.3627631957021, -72.25506501591016, {}});
  request.board.gizmos.push_back(GizmoSpec{GizmoType::LeftFlipper, "F", 1, 16, 90, 2, 2, {}});
  request.maxTick = 0.2;
  request.duration = 0.12;
  const std::optional<Event<double>> d = firstCollision<double>(request);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->feature, 1);  // the flipper's top side, at rest
  EXPECT_NEAR(d->time, 0.0982, 1e-4);
  const CertifyReport r = certifyRun(request);
  expectAccounted(r);
  EXPECT_TRUE(r.allCertified()) << describe(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
}

// Before the graze rule (docs/physics.md, "Grazes") double predicted a hit on this corner that
// the true path never makes, and the certifier flagged it. Now double passes the corner as
// mpfr:256 does, and the certifier proves the pass right.
TEST(CertifyGraze, GrazingPassAtACornerPassesInDoubleAndMpfrAndIsCertified) {
  const RunRequest request = requestFor("boards/verify/grazing-corner.txt", MotionModel::Ballistic, 1);
  EXPECT_FALSE(firstCollision<double>(request));
  EXPECT_FALSE(firstCollisionMpfr256(request));
  const CertifyReport r = certifyRun(request);
  expectAccounted(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
  EXPECT_TRUE(r.allCertified()) << describe(r);
}

// A path that truly dips into a circle, but so shallowly that it is a graze under the double
// model's rule: double passes, and the certifier, applying the same rule to the true root,
// certifies the pass instead of calling the missed entry a wrong decision. The rule's fraction
// shrinks with the precision, so mpfr:256 hits the circle.
TEST(CertifyGraze, AShallowDipPastACircleIsAGrazeThatTheCertifierProves) {
  for (MotionModel model : {MotionModel::Classic, MotionModel::Ballistic}) {
    const RunRequest request = requestFor("boards/verify/grazing-circle.txt", model, 1);
    EXPECT_FALSE(firstCollision<double>(request));
    const CertifyReport r = certifyRun(request);
    expectAccounted(r);
    EXPECT_TRUE(r.wrong.empty()) << describe(r);
    EXPECT_TRUE(r.allCertified()) << describe(r);
    const std::optional<Event<MpfrReal>> m = firstCollisionMpfr256(request);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->feature, 0);
  }
}

// The path touches the square's corner by a hair. Before the graze rule double let it slip past
// and the certifier flagged that as a missed hit; under the rule it is a graze, which double
// passes and the certifier proves (only with MPFI: the touch is below the double intervals'
// resolution). mpfr:256, whose graze fraction is far smaller, hits the vertex.
TEST(CertifyGraze, BallTouchingACornerByAHairGrazesPastItAndIsCertified) {
  const RunRequest request = requestFor("boards/verify/slips-past-corner.txt", MotionModel::Ballistic, 1);
  EXPECT_FALSE(firstCollision<double>(request));
  const CertifyReport r = certifyRun(request);
  expectAccounted(r);
  EXPECT_TRUE(r.wrong.empty()) << describe(r);
  EXPECT_TRUE(r.allCertified()) << describe(r);
  EXPECT_LT(r.certifiedAtRung.at(0), r.decisions) << describe(r);
  const std::optional<Event<MpfrReal>> m = firstCollisionMpfr256(request);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->feature, 7);
}

TEST(CertifyTie, DiagonalIntoTheCornerIsAProvenTieInTheDocumentedOrder) {
  for (MotionModel model : {MotionModel::Classic, MotionModel::Ballistic}) {
    const CertifyReport r = certifyRun(requestFor("boards/verify/genuine-tie-corner.txt", model, 2.5));
    expectAccounted(r);
    EXPECT_TRUE(r.wrong.empty()) << describe(r);
    ASSERT_EQ(r.ties.size(), 1u) << describe(r);
    const TieDecision& t = r.ties[0];
    EXPECT_TRUE(t.proven) << describe(r);  // not merely within 2^-512
    EXPECT_EQ(t.within.value, 0.0);
    EXPECT_TRUE(t.alsoTied.empty());
    EXPECT_EQ(t.executed.feature, 1);  // the floor ran first …
    EXPECT_EQ(t.other.feature, 2);     // … tied with the right wall
    EXPECT_TRUE(t.orderFollowed);
    EXPECT_NEAR(t.time.value, 1.95, 1e-12);  // (19.75 − 10) / 5
  }
}

// A collision at exactly a tick boundary: proven tied with the scheduled events there (the
// recalculation runs before the end of tick), and run before them, as collisions come first.
TEST(CertifyTie, AWallHitAtATickBoundaryIsAProvenTieWithTheScheduledEvents) {
  for (MotionModel model : {MotionModel::Classic, MotionModel::Ballistic}) {
    RunRequest request = requestFor("boards/verify/tie-at-tick.txt", model, 1.5);
    request.maxTick = 0.0625;
    const CertifyReport r = certifyRun(request);
    expectAccounted(r);
    EXPECT_TRUE(r.wrong.empty()) << describe(r);
    ASSERT_EQ(r.ties.size(), 1u) << describe(r);
    const TieDecision& t = r.ties[0];
    EXPECT_TRUE(t.proven);
    EXPECT_EQ(t.time.value, 1.0);
    EXPECT_EQ(t.executed.kind, EventKind::Collision);
    EXPECT_EQ(t.executed.feature, 2);  // the right wall
    EXPECT_EQ(t.other.kind, EventKind::Recalculate);
    EXPECT_TRUE(t.orderFollowed);
  }
}

// The report tells proven ties from ties within the top rung's resolution, as text and JSON.
TEST(CertifyTie, TheReportTellsProvenTiesFromTiesWithinAResolution) {
  const CertifyReport r = certifyRun(requestFor("boards/verify/genuine-tie-corner.txt", MotionModel::Ballistic, 2.5));
  EXPECT_EQ(r.provenTies(), 1u);
  const std::string text = describe(r);
  EXPECT_NE(text.find("ties: 1 (proven exact: 1, within 2^-512 only: 0;"), std::string::npos) << text;
  EXPECT_NE(text.find("proven exactly equal"), std::string::npos) << text;
  const std::string json = certifyReportJson(r);
  EXPECT_NE(json.find("\"ties_proven\": 1"), std::string::npos) << json;
  EXPECT_NE(json.find("\"proven\": true"), std::string::npos) << json;
}

namespace exact {

using detail::QPoly;

QPoly poly(std::initializer_list<long> c) {
  QPoly p;
  for (long x : c) p.push_back(Rational(x));
  detail::trim(p);
  return p;
}

TEST(CertifyExact, TheGcdOfTwoPolynomialsIsTheirCommonFactor) {
  // (s − 1)(s − 2) and (s − 1)(s + 3)(2s − 5): the monic gcd is s − 1.
  const QPoly a = poly({2, -3, 1});
  const QPoly b = detail::product(poly({-3, 2, 1}), poly({-5, 2}));
  EXPECT_EQ(detail::gcdOf(a, b), poly({-1, 1}));
  EXPECT_EQ(detail::gcdOf(a, poly({-3, 1})), poly({1}));  // coprime: a constant
}

TEST(CertifyExact, SturmCountsDistinctRootsInAHalfOpenInterval) {
  // (s − 1)²(s − 2)(s + 1): distinct roots −1, 1, 2; the double root counts once.
  const QPoly p =
      detail::product(detail::product(poly({-1, 1}), poly({-1, 1})), detail::product(poly({-2, 1}), poly({1, 1})));
  const detail::SturmChain chain(p);
  EXPECT_EQ(chain.rootsIn(Rational(-3), Rational(3)), 3);
  EXPECT_EQ(chain.rootsIn(Rational(0), Rational(3)), 2);
  EXPECT_EQ(chain.rootsIn(Rational(3, 2), Rational(5, 2)), 1);
  EXPECT_EQ(chain.rootsIn(Rational(-1, 2), Rational(1, 2)), 0);
  // s² − 2: √2 lies in (1.41421356, 1.41421357], not in (1.41421357, 2].
  const detail::SturmChain root2(poly({-2, 0, 1}));
  EXPECT_EQ(root2.rootsIn(Rational(141421356, 100000000), Rational(141421357, 100000000)), 1);
  EXPECT_EQ(root2.rootsIn(Rational(141421357, 100000000), Rational(2)), 0);
}

// The near tie of near-tie-corner.txt handed to the exact step as if no rung had parted the two
// walls: it orders them exactly (the floor first, by under 1e-15 s) when asked to, and does not
// call them a tie.
TEST(CertifyExact, RootsTheIntervalsCannotPartAreOrderedExactly) {
  detail::BoardLayout layout;
  detail::LayoutGizmo walls;
  walls.id = 0;
  walls.shape = outerWallsShape<double>();
  detail::LayoutGizmo ball;
  ball.id = 1;
  ball.kind = detail::LayoutKind::Ball;
  layout.gizmos = {walls, ball};
  layout.balls = {1};
  layout.ballIndex = {-1, 0};
  detail::BoardSnapshot snap;
  detail::BallSnapshot b;
  b.id = 1;
  b.p = Vec2<double>(10.0, 10.000000000000023);
  b.v = Vec2<double>(5.0, 4.999999999999989);
  snap.balls = {b};
  detail::DecisionInput in;
  in.executed.kind = EventKind::Collision;
  in.executed.a = 0;
  in.executed.b = 1;
  in.executed.feature = 2;  // the right wall
  in.executed.time = 1.95;
  in.hasNextScheduled = true;
  in.nextScheduled.time = 2.0;
  detail::RungOutcome undecided;
  undecided.ownLo = 1.9;
  undecided.ownHi = 1.96;
  undecided.overlaps.push_back(
      detail::Overlap{detail::EventKey{EventKind::Collision, 0, 1, 1}, false, true, true, 1.9, 1.96});
  EXPECT_FALSE(detail::settleExactly(layout, snap, in, undecided, false));  // distinct: no tie
  const std::optional<detail::RungOutcome> exact = detail::settleExactly(layout, snap, in, undecided, true);
  ASSERT_TRUE(exact);
  EXPECT_EQ(exact->verdict, detail::Verdict::Wrong);
  EXPECT_EQ(exact->other.feature, 1);  // the floor
  // The floor's time exactly, (19.75 − y) / vy, is before the right wall's, (19.75 − x) / vx, by
  // an amount the proven bounds hold.
  const Rational floor = (Rational(19.75) - Rational(b.p.y)) / Rational(b.v.y);
  const Rational wall = (Rational(19.75) - Rational(b.p.x)) / Rational(b.v.x);
  const Rational by = wall - floor;
  EXPECT_GT(exact->byLo, 0.0);
  EXPECT_LE(Rational(exact->byLo), by);
  EXPECT_LE(by, Rational(exact->byHi));
  EXPECT_LT(exact->byHi, 1e-14);
  // The same walls claimed in the other order are certified exactly.
  in.executed.feature = 1;
  undecided.overlaps[0].key.feature = 2;
  const std::optional<detail::RungOutcome> right = detail::settleExactly(layout, snap, in, undecided, true);
  ASSERT_TRUE(right);
  EXPECT_EQ(right->verdict, detail::Verdict::Certified);
}

}  // namespace exact

TEST(CertifyLog, RefusesALogThatIsNotOfADoubleRun) {
  replay::OpenedLog log = replay::openLog(test::fixturePath("logs/four-balls-meeting-3s-ballistic-long-double.gzlog"));
  EXPECT_THROW(certifyLog(log), CertifyError);
}

TEST(CertifyLog, CertifiesADoubleLogsRunAndPrintsTextAndJson) {
  replay::OpenedLog log = replay::openLog(test::fixturePath("logs/spec-example-5s-ballistic-double.gzlog"));
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
