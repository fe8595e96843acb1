// The interval types enclose the exact results of their operations: checked against MPFR at
// high precision over seeded random operands, and for point operands they give exactly the
// directed roundings of the exact result (the tightest double bounds). π, sine and cosine (for
// the swinging flippers) enclose MPFR's correctly rounded values, near the multiples of π/2 too,
// and over intervals take the extremes ±1 wherever the interval holds one.
// Built with -frounding-math (interval.hpp needs it).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "gizmo/verify/interval.hpp"
#include "gizmo/verify/interval_trig.hpp"
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
  checkEnclosure<Interval>(
      "Interval", [](const Interval& i) { return i.lower(); }, [](const Interval& i) { return i.upper(); });
}

TEST(VerifyInterval, MpfiIntervalsEncloseEveryMemberResult) {
  for (long bits : {128L, 1024L}) {
    MpfiInterval::setWorkingBits(bits);
    checkEnclosure<MpfiInterval>(
        "MpfiInterval", [](const MpfiInterval& i) { return lowerDouble(i); },
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

// sin x or cos x rounded to a double in the direction rnd (MPFR rounds correctly: these are the
// tightest double bounds of the exact value).
double trigRounded(bool sine, double x, mpfr_rnd_t rnd) {
  mpfr_t a, r;
  mpfr_init2(a, 53);
  mpfr_init2(r, 53);
  mpfr_set_d(a, x, MPFR_RNDN);
  if (sine) mpfr_sin(r, a, rnd);
  else mpfr_cos(r, a, rnd);
  const double d = mpfr_get_d(r, rnd);
  mpfr_clear(a);
  mpfr_clear(r);
  return d;
}

// The double nearest to k·π/2 (from a 256-bit π).
double nearestQuarterTurn(int k) {
  mpfr_t v;
  mpfr_init2(v, 256);
  mpfr_const_pi(v, MPFR_RNDN);
  mpfr_mul_si(v, v, k, MPFR_RNDN);
  mpfr_div_2ui(v, v, 1, MPFR_RNDN);
  const double d = mpfr_get_d(v, MPFR_RNDN);
  mpfr_clear(v);
  return d;
}

// Arguments of every scale, and the doubles nearest the multiples of π/2 with their neighbours,
// where the reduction cancels most and the extremes sit.
std::vector<double> trigArguments() {
  std::mt19937_64 rng(kSeed + 2);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 12);
  std::vector<double> xs{0.0, -0.0, 0x1p-1074, -0x1p-600, 1.0, -1.0};
  for (int i = 0; i < 4000; ++i) xs.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  for (int k = -64; k <= 64; ++k) {
    double x = nearestQuarterTurn(k);
    for (int step = 0; step < 3; ++step) x = std::nextafter(x, -1e300);
    for (int step = 0; step < 7; ++step, x = std::nextafter(x, 1e300)) xs.push_back(x);
  }
  return xs;
}

template <class I>
void checkTrigOfPoints(const char* name, std::function<double(const I&)> lower, std::function<double(const I&)> upper) {
  for (double x : trigArguments()) {
    I s, c;
    {
      UpwardRounding upward;
      s = sin(I(x));
      c = cos(I(x));
    }
    ASSERT_LE(lower(s), trigRounded(true, x, MPFR_RNDD)) << name << " sin " << std::hexfloat << x;
    ASSERT_GE(upper(s), trigRounded(true, x, MPFR_RNDU)) << name << " sin " << std::hexfloat << x;
    ASSERT_LE(lower(c), trigRounded(false, x, MPFR_RNDD)) << name << " cos " << std::hexfloat << x;
    ASSERT_GE(upper(c), trigRounded(false, x, MPFR_RNDU)) << name << " cos " << std::hexfloat << x;
    // Tight, not merely [−1, 1]: a few ulps, plus what reducing by an enclosed π/2 costs.
    const double allowed = 1e-15 * (1.0 + std::fabs(x));
    ASSERT_LE(upper(s) - lower(s), allowed) << name << " sin " << std::hexfloat << x;
    ASSERT_LE(upper(c) - lower(c), allowed) << name << " cos " << std::hexfloat << x;
  }
}

TEST(VerifyIntervalTrig, DoubleSinAndCosOfPointsEncloseMpfr) {
  checkTrigOfPoints<Interval>(
      "Interval", [](const Interval& i) { return i.lower(); }, [](const Interval& i) { return i.upper(); });
}

TEST(VerifyIntervalTrig, MpfiSinAndCosOfPointsEncloseMpfr) {
  MpfiInterval::setWorkingBits(128);
  checkTrigOfPoints<MpfiInterval>(
      "MpfiInterval", [](const MpfiInterval& i) { return lowerDouble(i); },
      [](const MpfiInterval& i) { return upperDouble(i); });
}

// Over [a, b]: the values at the ends, at members in between, and at the doubles nearest every
// multiple of π/2 inside (where sin or cos is ±1 to within 1e-32) all lie in the result.
template <class I>
void checkTrigOfIntervals(const char* name, std::function<double(const I&)> lower,
                          std::function<double(const I&)> upper) {
  std::mt19937_64 rng(kSeed + 3);
  std::uniform_real_distribution<double> start(-40.0, 40.0), unit(0.0, 1.0);
  const double widths[] = {1e-12, 1e-3, 0.3, 1.6, 3.2, 7.0};
  for (int trial = 0; trial < 3000; ++trial) {
    const double a = start(rng), b = a + widths[trial % 6] * unit(rng);
    I s, c;
    {
      UpwardRounding upward;
      s = sin(I(a, b));
      c = cos(I(a, b));
    }
    ASSERT_GE(lower(s), -1.0);
    ASSERT_LE(upper(c), 1.0);
    std::vector<double> members{a, b};
    for (int i = 0; i < 6; ++i) members.push_back(std::clamp(a + (b - a) * unit(rng), a, b));
    for (int k = -30; k <= 30; ++k) {
      const double q = nearestQuarterTurn(k);
      if (a <= q && q <= b) members.push_back(q);
    }
    for (double x : members) {
      ASSERT_LE(lower(s), trigRounded(true, x, MPFR_RNDD)) << name << " sin over [" << a << ", " << b << "] at " << x;
      ASSERT_GE(upper(s), trigRounded(true, x, MPFR_RNDU)) << name << " sin over [" << a << ", " << b << "] at " << x;
      ASSERT_LE(lower(c), trigRounded(false, x, MPFR_RNDD)) << name << " cos over [" << a << ", " << b << "] at " << x;
      ASSERT_GE(upper(c), trigRounded(false, x, MPFR_RNDU)) << name << " cos over [" << a << ", " << b << "] at " << x;
    }
  }
}

TEST(VerifyIntervalTrig, DoubleSinAndCosOfIntervalsEncloseEveryMember) {
  checkTrigOfIntervals<Interval>(
      "Interval", [](const Interval& i) { return i.lower(); }, [](const Interval& i) { return i.upper(); });
}

TEST(VerifyIntervalTrig, MpfiSinAndCosOfIntervalsEncloseEveryMember) {
  MpfiInterval::setWorkingBits(128);
  checkTrigOfIntervals<MpfiInterval>(
      "MpfiInterval", [](const MpfiInterval& i) { return lowerDouble(i); },
      [](const MpfiInterval& i) { return upperDouble(i); });
}

TEST(VerifyIntervalTrig, AnIntervalHoldingAnExtremeReachesItExactly) {
  UpwardRounding upward;
  EXPECT_EQ(sin(Interval(1.5, 1.6)).upper(), 1.0);     // π/2 inside
  EXPECT_LT(sin(Interval(1.5, 1.6)).lower(), 0.9975);  // sin 1.5 = 0.99749…
  EXPECT_EQ(cos(Interval(3.0, 3.3)).lower(), -1.0);    // π inside
  EXPECT_EQ(cos(Interval(-0.1, 0.1)).upper(), 1.0);
  const Interval turn = sin(Interval(0.0, 7.0));  // more than a turn: everything
  EXPECT_EQ(turn.lower(), -1.0);
  EXPECT_EQ(turn.upper(), 1.0);
  const Interval away = sin(Interval(0.2, 1.4));  // monotone: no extreme added
  EXPECT_LT(away.upper(), 0.9855);                // sin 1.4 = 0.98545…
}

TEST(VerifyIntervalTrig, PiLiesStrictlyInsideItsEnclosures) {
  mpfr_t pi;
  mpfr_init2(pi, kExactBits);
  mpfr_const_pi(pi, MPFR_RNDN);  // 2400 bits: far finer than the bounds compared with
  const Interval d = Interval::pi();
  EXPECT_GT(mpfr_cmp_d(pi, d.lower()), 0);
  EXPECT_LT(mpfr_cmp_d(pi, d.upper()), 0);
  EXPECT_EQ(std::nextafter(d.lower(), 4.0), d.upper());  // neighbouring doubles
  MpfiInterval::setWorkingBits(256);
  const MpfiInterval m = MpfiInterval::pi();
  mpfr_t bound;
  mpfr_init2(bound, kExactBits);
  mpfi_get_left(bound, m.raw());
  EXPECT_LT(mpfr_cmp(bound, pi), 0);
  mpfi_get_right(bound, m.raw());
  EXPECT_GT(mpfr_cmp(bound, pi), 0);
  mpfr_clear(bound);
  mpfr_clear(pi);
}

}  // namespace
}  // namespace gizmo::verify
