// The same board in every scalar of the ladder: each hits the reference numbers to its own
// precision, and the classic model's stacked-ball time stays within one maximum tick.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using test::ballAt;
using test::emptyBoard;
using test::gizmoAt;

// The absorber catches the dropped ball at t = √(2·7.75/25); returns that time.
template <class Real>
Real dropTime() {
  BoardSpec s = emptyBoard(25, 0, 0);
  s.gizmos.push_back(gizmoAt(GizmoType::Absorber, "A", 0, 19, 0, 20, 1));
  s.balls.push_back(ballAt("B", 1, 11));
  auto board = test::build<Real>(s);
  test::Recorder<Real> rec;
  board->setObserver(&rec);
  board->tick(Real(1));
  for (const auto& e : rec.executed)
    if (e.event.kind == EventKind::Collision) return e.event.time;
  ADD_FAILURE() << "no collision";
  return Real(0);
}

template <class Real>
void expectDropTime(double relativeTolerance) {
  const Real exact = sqrtOf(Real(Real(2) * Real(7.75) / Real(25)));
  const Real t = dropTime<Real>();
  EXPECT_LE(toDouble(Real(absOf(Real(t - exact)) / exact)), relativeTolerance) << scalarName<Real>();
}

// A handful of ulps of each type: the time is one closed-form root.
// epsilonOf is 2^(1 - digits) for every hardware float: numeric_limits' epsilon for the IEEE
// formats, and the same for ppc64el's double-double, where numeric_limits says 2^-1074. The
// next value after 1 is 1 + epsilon, and half of it is lost to rounding (to even).
template <class Real>
void expectUnitRoundoff() {
  const Real one(1), eps = epsilonOf<Real>();
  EXPECT_EQ(eps, std::ldexp(one, 1 - std::numeric_limits<Real>::digits)) << scalarName<Real>();
  EXPECT_GT(Real(one + eps), one) << scalarName<Real>();
  EXPECT_EQ(Real(one + Real(eps / 2)), one) << scalarName<Real>();
  if (std::numeric_limits<Real>::is_iec559) {
    EXPECT_EQ(eps, std::numeric_limits<Real>::epsilon()) << scalarName<Real>();
  }
}

TEST(PrecisionLadder, EpsilonIsTheUnitRoundoffOfEachHardwareFloat) {
  expectUnitRoundoff<float>();
  expectUnitRoundoff<double>();
  expectUnitRoundoff<long double>();
}

TEST(PrecisionLadder, DropTimeToEachTypesPrecision) {
  expectDropTime<float>(8 * 1.2e-7);
  expectDropTime<double>(8 * 2.3e-16);
  expectDropTime<long double>(8 * 1.1e-19);
  expectDropTime<Float128>(8 * 1.0e-34);
  expectDropTime<Bin50>(8 * toDouble(epsilonOf<Bin50>()));
  expectDropTime<Bin100>(8 * toDouble(epsilonOf<Bin100>()));
  setMpfrBits(256);
  expectDropTime<MpfrReal>(8 * 1.8e-77);
  setMpfrBits(53);
}

// The drop time is √0.62: an exact run says so instead of rounding it.
TEST(PrecisionLadder, RationalRunRefusesAnIrrationalTime) {
  try {
    dropTime<Rational>();
    ADD_FAILURE() << "the rational run rounded an irrational time";
  } catch (const IrrationalValue& e) {
    EXPECT_NE(std::string(e.what()).find("not a perfect square"), std::string::npos) << e.what();
  }
}

TEST(PrecisionLadder, RationalSquareRootIsExactOrRefused) {
  EXPECT_EQ(sqrtOf(Rational(9) / Rational(16)), Rational(3) / Rational(4));
  EXPECT_EQ(sqrtOf(Rational(0)), Rational(0));
  EXPECT_THROW(sqrtOf(Rational(2)), IrrationalValue);
  EXPECT_THROW(sqrtOf(Rational(4) / Rational(3)), IrrationalValue);  // only the numerator is a square
  EXPECT_THROW(sqrtOf(Rational(-4)), IrrationalValue);
  EXPECT_THROW(piOf<Rational>(), IrrationalValue);
}

// The same drop in the classic model moves in straight lines between ticks: every time is a
// linear root, and the rational run lands on the absorber exactly where the rules put it.
TEST(PrecisionLadder, RationalClassicDropIsExact) {
  BoardSpec s = emptyBoard(25, 0, 0);
  s.gizmos.push_back(gizmoAt(GizmoType::Absorber, "A", 0, 19, 0, 20, 1));
  s.balls.push_back(ballAt("B", 1, 11));
  auto board = test::build<Rational>(s, MotionModel::Classic, 0.05);
  test::Recorder<Rational> rec;
  board->setObserver(&rec);
  board->tick(Rational(1));
  const auto hit = std::find_if(rec.executed.begin(), rec.executed.end(),
                                [](const auto& e) { return e.event.kind == EventKind::Collision; });
  ASSERT_NE(hit, rec.executed.end());
  // The ball reaches y = 18.75 moving at a tick's constant speed: the time is rational, and its
  // gap is exactly 0 there.
  const Ball<Rational>& ball = *board->gizmo(*board->find("B")).asBall();
  EXPECT_EQ(hit->outcome.balls()[0].position.y, Rational(75) / Rational(4));
  EXPECT_TRUE(ball.captured());
}

TEST(PrecisionLadder, HigherPrecisionAgreesWithDoubleToDoublesPrecision) {
  const double d = dropTime<double>();
  const Float128 q = dropTime<Float128>();
  EXPECT_NEAR(d, toDouble(q), 4 * 2.3e-16);
  EXPECT_NE(Float128(d), q);  // and it is genuinely more precise
}

TEST(ReferenceNumbers, FiveStackedBallsClassicWithinOneTick) {
  BoardSpec s = emptyBoard(25, 0, 0);
  for (int i = 0; i < 5; ++i) s.balls.push_back(ballAt("B" + std::to_string(i), 10, 9 - i));
  auto board = test::build(s, MotionModel::Classic, 0.05);
  test::Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(1.5);
  const GizmoId lowest = *board->find("B0");
  for (const auto& e : rec.executed)
    if (e.event.kind == EventKind::Collision && (e.event.a == lowest || e.event.b == lowest)) {
      EXPECT_EQ(e.event.a, GameBoard<double>::outerWallsId());
      EXPECT_NEAR(e.event.time, 0.927362, 0.05);
      return;
    }
  ADD_FAILURE() << "the lowest ball never reached the floor";
}

}  // namespace
}  // namespace gizmo
