// The interval types enclose the exact results of their operations: checked against MPFR at
// high precision over seeded random operands, and for point operands they give exactly the
// directed roundings of the exact result (the tightest double bounds).
// Built with -frounding-math (interval.hpp needs it).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <functional>
#include <random>

#include "gizmo/verify/interval.hpp"
#include "gizmo/verify/mpfi_interval.hpp"

namespace gizmo::verify {
namespace {

constexpr std::uint64_t kSeed = 20240611;
constexpr mpfr_prec_t kExactBits = 2400;  // holds every sum and product of two doubles exactly

// An exact (or, for ÷ and √, a 2400-bit directed) value of op(x, y).
struct Exact {
  mpfr_t v;
  Exact() { mpfr_init2(v, kExactBits); }
  ~Exact() { mpfr_clear(v); }
};

enum class Op { Add, Sub, Mul, Div, Sqrt, Square };
const char* opName(Op op) {
  switch (op) {
    case Op::Add: return "+";
    case Op::Sub: return "-";
    case Op::Mul: return "*";
    case Op::Div: return "/";
    case Op::Sqrt: return "sqrt";
    case Op::Square: return "square";
  }
  return "?";
}

// op(x, y) rounded in the direction rnd at kExactBits.
void exactOp(Op op, double x, double y, mpfr_rnd_t rnd, Exact& out) {
  Exact a, b;
  mpfr_set_d(a.v, x, MPFR_RNDN);
  mpfr_set_d(b.v, y, MPFR_RNDN);
  switch (op) {
    case Op::Add: mpfr_add(out.v, a.v, b.v, rnd); break;
    case Op::Sub: mpfr_sub(out.v, a.v, b.v, rnd); break;
    case Op::Mul: mpfr_mul(out.v, a.v, b.v, rnd); break;
    case Op::Div: mpfr_div(out.v, a.v, b.v, rnd); break;
    case Op::Sqrt: mpfr_sqrt(out.v, a.v, rnd); break;
    case Op::Square: mpfr_sqr(out.v, a.v, rnd); break;
  }
}

template <class I>
I apply(Op op, const I& x, const I& y) {
  switch (op) {
    case Op::Add: return x + y;
    case Op::Sub: return x - y;
    case Op::Mul: return x * y;
    case Op::Div: return x / y;
    case Op::Sqrt: return sqrt(x);
    case Op::Square: return square(x);
  }
  return x;
}

// Operands of every scale and sign, with some exact halves, integers and near-ties.
double randomOperand(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-40, 40);
  switch (rng() % 6) {
    case 0: return double(int(rng() % 41) - 20);
    case 1: return double(int(rng() % 41) - 20) / 4.0;
    case 2: return std::nextafter(1.0, rng() % 2 ? 2.0 : 0.0);
    default: return std::ldexp(mantissa(rng), exponent(rng));
  }
}

constexpr Op kOps[] = {Op::Add, Op::Sub, Op::Mul, Op::Div, Op::Sqrt, Op::Square};

TEST(VerifyInterval, PointOperandsGiveTheDirectedRoundingsOfTheExactResult) {
  std::printf("seed %llu\n", static_cast<unsigned long long>(kSeed));
  std::mt19937_64 rng(kSeed);
  for (int trial = 0; trial < 20000; ++trial) {
    const Op op = kOps[trial % 6];
    double x = randomOperand(rng), y = randomOperand(rng);
    if (op == Op::Sqrt) x = std::fabs(x);
    if (op == Op::Div && y == 0) y = 1.5;
    Interval r;
    {
      UpwardRounding upward;
      r = apply(op, Interval(x), Interval(y));
    }
    Exact lo, hi;
    exactOp(op, x, y, MPFR_RNDD, lo);
    exactOp(op, x, y, MPFR_RNDU, hi);
    // The tightest double bounds: the exact value rounded down and up to double.
    const double wantLo = mpfr_get_d(lo.v, MPFR_RNDD), wantHi = mpfr_get_d(hi.v, MPFR_RNDU);
    ASSERT_EQ(r.lower(), wantLo) << std::hexfloat << x << " " << opName(op) << " " << y;
    ASSERT_EQ(r.upper(), wantHi) << std::hexfloat << x << " " << opName(op) << " " << y;
  }
}

// Interval operands: every exact result of members lies in the result. Checked at the end
// points and at random members (the extremes of + − × ÷ √ x² over a box lie at its corners,
// except x² through 0, whose minimum 0 is a member tried below).
template <class I>
void checkEnclosure(const char* name, std::function<double(const I&)> lower, std::function<double(const I&)> upper) {
  std::mt19937_64 rng(kSeed + 1);
  for (int trial = 0; trial < 5000; ++trial) {
    const Op op = kOps[trial % 6];
    double a = randomOperand(rng), b = randomOperand(rng), c = randomOperand(rng), d = randomOperand(rng);
    if (b < a) std::swap(a, b);
    if (d < c) std::swap(c, d);
    if (op == Op::Sqrt) {
      a = std::fabs(a);
      b = std::fabs(b);
      if (b < a) std::swap(a, b);
    }
    if (op == Op::Div && c <= 0 && 0 <= d) c = d = 3.0;
    I r;
    {
      UpwardRounding upward;  // harmless for MPFI, needed for Interval
      r = apply(op, I(a, b), I(c, d));
    }
    std::uniform_real_distribution<double> t(0.0, 1.0);
    const double xs[] = {a, b, std::clamp(a + (b - a) * t(rng), a, b), (a <= 0 && 0 <= b) ? 0.0 : a};
    const double ys[] = {c, d, std::clamp(c + (d - c) * t(rng), c, d), d};
    for (double x : xs)
      for (double y : ys) {
        Exact lo, hi;
        exactOp(op, x, y, MPFR_RNDD, lo);
        exactOp(op, x, y, MPFR_RNDU, hi);
        // lower ≤ exact ≤ upper, tested with the 2400-bit directed values around the exact one.
        ASSERT_GE(mpfr_cmp_d(lo.v, lower(r)), 0) << name << " lower bound above " << x << " " << opName(op) << " " << y;
        ASSERT_LE(mpfr_cmp_d(hi.v, upper(r)), 0) << name << " upper bound below " << x << " " << opName(op) << " " << y;
      }
  }
}

TEST(VerifyInterval, DoubleIntervalsEncloseEveryMemberResult) {
  checkEnclosure<Interval>("Interval", [](const Interval& i) { return i.lower(); },
                           [](const Interval& i) { return i.upper(); });
}

TEST(VerifyInterval, MpfiIntervalsEncloseEveryMemberResult) {
  for (long bits : {128L, 1024L}) {
    MpfiInterval::setWorkingBits(bits);
    checkEnclosure<MpfiInterval>("MpfiInterval", [](const MpfiInterval& i) { return lowerDouble(i); },
                                 [](const MpfiInterval& i) { return upperDouble(i); });
  }
}

TEST(VerifyInterval, UpwardRoundingIsSetOnceAndRestored) {
  ASSERT_EQ(std::fegetround(), FE_TONEAREST);
  {
    UpwardRounding upward;
    EXPECT_EQ(std::fegetround(), FE_UPWARD);
  }
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
}

TEST(VerifyInterval, ADivisorThatMayBeZeroGivesTheWholeLine) {
  UpwardRounding upward;
  const Interval q = Interval(1.0) / Interval(-1.0, 2.0);
  EXPECT_TRUE(std::isinf(q.lower()) && q.lower() < 0);
  EXPECT_TRUE(std::isinf(q.upper()) && q.upper() > 0);
}

TEST(VerifyInterval, TheSquareOfAnIntervalThroughZeroStartsAtZero) {
  UpwardRounding upward;
  const Interval s = square(Interval(-2.0, 3.0));
  EXPECT_EQ(s.lower(), 0.0);
  EXPECT_EQ(s.upper(), 9.0);
  const Interval p = Interval(-2.0, 3.0) * Interval(-2.0, 3.0);  // the two factors taken apart
  EXPECT_EQ(p.lower(), -6.0);
}

}  // namespace
}  // namespace gizmo::verify
