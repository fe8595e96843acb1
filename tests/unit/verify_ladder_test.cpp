// The precision ladder: exact runs where the scene allows, where they stop and why, and how
// the agreement with the reference grows with the number of bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "gizmo/io/board_file.hpp"
#include "gizmo/verify/ladder.hpp"
#include "gizmo/verify/wide_value.hpp"
#include "support/fixture_request.hpp"

namespace gizmo::verify {
namespace {

RunRequest requestFor(const std::string& board, MotionModel model, double seconds) {
  return test::fixtureRequest("boards/" + board, model, seconds);
}

std::vector<PrecisionChoice> ladderOf(std::initializer_list<const char*> names) {
  std::vector<PrecisionChoice> out;
  for (const char* n : names) out.push_back(*parsePrecision(n));
  return out;
}

const PrecisionResult& row(const LadderReport& report, const std::string& precision) {
  const auto it = std::find_if(report.results.begin(), report.results.end(),
                               [&](const PrecisionResult& r) { return r.precision == precision; });
  if (it == report.results.end()) throw std::runtime_error("no row " + precision);
  return *it;
}

TEST(SceneArithmetic, RationalOnlyWhereNoSquareRootIsBuiltIn) {
  RunRequest r = requestFor("verify/rational-squares.txt", MotionModel::Classic, 1);
  EXPECT_TRUE(sceneArithmetic(r).rationalPossible);
  r.model = MotionModel::Ballistic;
  EXPECT_FALSE(sceneArithmetic(r).rationalPossible);
  EXPECT_NE(sceneArithmetic(r).reason.find("ballistic"), std::string::npos);
  r.model = MotionModel::Classic;
  r.board.mu2 = 0.025;
  EXPECT_NE(sceneArithmetic(r).reason.find("mu2"), std::string::npos);
  const RunRequest spec = requestFor("spec-example.txt", MotionModel::Classic, 1);
  EXPECT_FALSE(sceneArithmetic(spec).rationalPossible);
  // A booster's slanted face has the triangle's irrational normal.
  RunRequest boosted = requestFor("gizmos/booster.txt", MotionModel::Classic, 1);
  boosted.board.mu2 = 0;
  EXPECT_FALSE(sceneArithmetic(boosted).rationalPossible);
  EXPECT_NE(sceneArithmetic(boosted).reason.find("booster U"), std::string::npos) << sceneArithmetic(boosted).reason;
}

TEST(WideValue, HoldsEveryBinaryScalarExactly) {
  // 1 + 2^-300 needs 301 bits: bin100 holds it, and so must its wide copy.
  const Bin100 one = 1;
  const Bin100 tiny = ldexp(one, -300);
  EXPECT_EQ(distance(WideValue::of(Bin100(one + tiny)), WideValue::of(one)), std::ldexp(1.0, -300));
  const Float128 q = Float128(1) + ldexp(Float128(1), -112);
  EXPECT_EQ(distance(WideValue::of(q), WideValue::of(1.0)), std::ldexp(1.0, -112));
  // A rational is rounded only at 512 bits: its distance to the double nearest 1/3 is that
  // double's error, to the last bit of a double.
  const Rational third = Rational(1) / Rational(3);
  EXPECT_EQ(distance(WideValue::of(third), WideValue::of(1.0 / 3.0)),
            static_cast<double>(Rational(Rational(1.0 / 3.0) - third)) * -1.0);
}

// The rational run is the reference of a rational scene; MPFR at 256 bits makes the same
// decisions and its numbers agree with the exact ones to its own precision.
TEST(Ladder, RationalSceneMatchesMpfrToItsPrecision) {
  LadderOptions o;
  o.request = requestFor("verify/rational-squares.txt", MotionModel::Classic, 3.0);
  o.precisions = ladderOf({"double", "float128", "mpfr:128", "mpfr:256", "rational"});
  const LadderReport report = runLadder(o);
  EXPECT_EQ(report.reference, "rational");
  EXPECT_TRUE(report.notes.empty());
  EXPECT_FALSE(report.certified);  // exact throughout: nothing left to certify
  const PrecisionResult& exact = row(report, "rational");
  EXPECT_TRUE(exact.reference);
  EXPECT_TRUE(exact.stopped.empty()) << exact.stopped;
  EXPECT_GT(exact.compared, 50u);
  for (const char* name : {"float128", "mpfr:128", "mpfr:256"}) {
    EXPECT_TRUE(row(report, name).agreesThroughout) << name << ": " << row(report, name).difference;
    EXPECT_EQ(row(report, name).horizonEvents, exact.compared) << name;
  }
  // Each error is at its scalar's precision (times and positions are of order 1 to 20): a few
  // hundred ulps at most, and far above the next rung's.
  for (const char* name : {"mpfr:128", "mpfr:256"}) {
    EXPECT_GT(row(report, name).maxTimeError, 0.0) << name;
    EXPECT_GT(row(report, name).maxPositionError, 0.0) << name;
  }
  EXPECT_LT(row(report, "mpfr:256").maxPositionError, 1e-72);
  EXPECT_LT(row(report, "mpfr:128").maxPositionError, 1e-33);
  EXPECT_GT(row(report, "mpfr:128").maxTimeError, 1e20 * row(report, "mpfr:256").maxTimeError);
  EXPECT_LT(row(report, "float128").maxPositionError, 1e-30);
  EXPECT_LT(row(report, "double").maxPositionError, 1e-12);
}

// A rational run that meets a circle off its centre line needs a square root that is not
// rational: it says after how many events and for which contact, and the reference falls back
// to MPFR, which goes on with the very event the rational run could not take.
TEST(Ladder, RationalRunSaysWhereItNeedsAnIrrationalValue) {
  LadderOptions o;
  o.request = requestFor("verify/rational-until-circle.txt", MotionModel::Classic, 3.0);
  o.precisions = ladderOf({"mpfr:256", "rational"});
  const LadderReport report = runLadder(o);
  EXPECT_EQ(report.reference, "mpfr:256");
  ASSERT_EQ(report.notes.size(), 1u);
  const PrecisionResult& exact = row(report, "rational");
  EXPECT_NE(exact.stopped.find("not a perfect square, for the contact of C with B"), std::string::npos)
      << exact.stopped;
  EXPECT_NE(exact.stopped.find("after " + std::to_string(exact.events) + " events"), std::string::npos)
      << exact.stopped;
  // Exact up to there: every event it made is the reference's, to MPFR's precision.
  EXPECT_EQ(exact.horizonEvents, exact.compared);
  EXPECT_LT(exact.maxPositionError, 1e-72);
  EXPECT_NE(exact.difference.find("this run has ended"), std::string::npos) << exact.difference;
  // The reference's next decision is the tick in which the contact with C is predicted, and
  // the contact itself follows: the MPFR run meets C.
  EXPECT_GT(row(report, "mpfr:256").compared, exact.compared);
}

// An exact run whose numbers outgrow the budget stops there and says so; the reference falls
// back to MPFR, which the exact run matched up to that point.
TEST(Ladder, ExactRunStopsAtItsDigitBudget) {
  LadderOptions o;
  o.request = requestFor("verify/rational-squares.txt", MotionModel::Classic, 3.0);
  o.precisions = ladderOf({"rational"});
  o.exactDigits = 1000;
  const LadderReport report = runLadder(o);
  EXPECT_EQ(report.reference, "mpfr:256");
  const PrecisionResult& exact = row(report, "rational");
  EXPECT_NE(exact.stopped.find("beyond the budget of 1000"), std::string::npos) << exact.stopped;
  EXPECT_GT(exact.compared, 5u);
  EXPECT_EQ(exact.horizonEvents, exact.compared);
  EXPECT_LT(exact.maxPositionError, 1e-72);
}

// A chaotic field: each extra bit keeps the run on the reference's path a little longer.
TEST(Ladder, AgreementHorizonGrowsWithPrecisionOnAChaoticBoard) {
  LadderOptions o;
  o.request = requestFor("verify/chaotic-bumpers.txt", MotionModel::Ballistic, 20.0);
  o.precisions = ladderOf({"float", "double", "long-double", "float128", "bin50", "bin100"});
  const LadderReport report = runLadder(o);
  EXPECT_EQ(report.reference, "mpfr:256");
  std::uint64_t previous = 0;
  for (const PrecisionResult& r : report.results) {
    if (r.precision == "bin100") break;  // may well agree throughout: checked below
    EXPECT_FALSE(r.agreesThroughout) << r.precision;
    EXPECT_GT(r.horizonEvents, previous) << r.precision;
    previous = r.horizonEvents;
  }
  EXPECT_GE(row(report, "bin100").horizonEvents, previous);
  // Before its horizon a run's errors stay small compared to the board: the decisions agree.
  EXPECT_LT(row(report, "double").maxPositionError, 1.0);
}

// Where exact arithmetic is out of reach the check goes on with certified arithmetic: the double
// run's decisions are certified, and a board built so that double takes the wrong one of two
// collisions 4.6e-16 s apart shows it.
TEST(Ladder, CertifiesTheDoubleRunWhereTheSceneCannotBeExact) {
  LadderOptions o;
  o.request = requestFor("verify/near-tie-corner.txt", MotionModel::Ballistic, 2.5);
  o.precisions = ladderOf({"double"});
  const LadderReport report = runLadder(o);
  ASSERT_TRUE(report.certified);
  EXPECT_EQ(report.certified->wrong, 1u);
  EXPECT_EQ(report.certified->certified + report.certified->notCertified + report.certified->ties + 1,
            report.certified->decisions);
  EXPECT_NE(report.certified->firstWrong.find("should have come first"), std::string::npos);
}

}  // namespace
}  // namespace gizmo::verify
