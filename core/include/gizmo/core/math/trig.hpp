#pragma once
// sin and cos from + - * / only, so that every scalar of the ladder gets the same bits on every
// machine (libm's sin/cos differ between implementations and are not correctly rounded).
//
// Method, for |x| <= 2:
//   * |x| <= 0.78: evaluate the Taylor series of sin and cos at |x| directly.
//   * otherwise:   y = pi/2 - |x| (|y| <= 0.79), then sin|x| = cos y and cos|x| = sin y.
//     pi/2 is held as hi + lo (hi the nearest Real, lo the rest to about twice the precision), so
//     hi - |x| is exact (Sterbenz) and y is known as yh + yl with |yl| <= ulp(yh) / 2 exactly
//     (TwoSum); yl enters through sin(yh + yl) ~ sin yh + yl cos yh and the like.
//   * The series are summed innermost term first (Horner form in y^2) after counting how many
//     terms matter: the first term below epsilonOf<Real>() / 8 of the leading one is the last one
//     kept, with a hard cap of kMaxTerms terms so that the loop always ends. The cosine's y^2/2
//     is taken exactly (Dekker's product), and each result is rounded once, at the end.
//   * The sign of x is applied at the end, so sin(-x) == -sin(x) and cos(-x) == cos(x) exactly.
// Measured error against MPFR's correctly rounded sin/cos: below 0.7 ulp on the points of
// tests/unit/math_trig_test.cpp for every scalar; 0.79 ulp at worst over 2e6 random doubles.
#include <cassert>
#include <limits>
#include <type_traits>
#include <vector>

#include "gizmo/core/math/scalar.hpp"

#if GIZMO_HAS_MULTIPRECISION
#include <mpfr.h>
#endif

namespace gizmo::math {

namespace detail {

// pi/2 as a sum of doubles, each the rounding of what the previous ones leave; the sum is good to
// about 2^-270, enough for lo to be accurate when Real is float128.
inline constexpr double kHalfPiParts[5] = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54, -0x1.f1976b7ed8fbcp-110,
                                           0x1.4cf98e804177dp-164, 0x1.31d89cd9128a5p-218};

#if GIZMO_HAS_MULTIPRECISION
// pi/2 as a sum of doubles from MPFR's correctly rounded pi, for scalars wider than the table
// above (cpp_bin_float 50 and 100): enough parts to hold `bits` bits. Computed once per width.
inline std::vector<double> halfPiPartsFromMpfr(long bits) {
  mpfr_t rest;
  mpfr_init2(rest, static_cast<mpfr_prec_t>(bits));
  mpfr_const_pi(rest, MPFR_RNDN);
  mpfr_div_2ui(rest, rest, 1, MPFR_RNDN);  // exact
  std::vector<double> parts;
  for (long covered = 0; covered < bits && mpfr_zero_p(rest) == 0; covered += 53) {
    const double part = mpfr_get_d(rest, MPFR_RNDN);
    parts.push_back(part);
    mpfr_sub_d(rest, rest, part, MPFR_RNDN);  // exact: the part is rest's leading bits
  }
  mpfr_clear(rest);
  return parts;
}
#endif

// hi + lo = the sum of the parts, hi the nearest Real and lo the rest (the parts are each the
// rounding of what the previous ones leave, so hi is within an ulp of their sum).
template <class Real>
inline void sumHalfPiParts(const double* parts, std::size_t count, Real& hi, Real& lo) {
  Real sum = fromDouble<Real>(parts[0]);
  for (std::size_t i = 1; i < count; ++i) sum = sum + fromDouble<Real>(parts[i]);
  hi = sum;
  Real rest = fromDouble<Real>(parts[0]) - hi;  // exact (Sterbenz)
  for (std::size_t i = 1; i < count; ++i) rest = rest + fromDouble<Real>(parts[i]);
  lo = rest;
}

// hi + lo = pi/2 to about twice Real's precision, hi within an ulp of pi/2.
template <class Real>
inline void halfPiSplit(Real& hi, Real& lo) {
  constexpr int digits = std::numeric_limits<Real>::digits;
  if constexpr (digits < 53) {
    // Narrower than double: do the subtraction in double, where hi and the parts are exact.
    hi = static_cast<Real>(kHalfPiParts[0]);
    double rest = kHalfPiParts[0] - static_cast<double>(hi);  // exact (Sterbenz)
    rest = (rest + kHalfPiParts[1]) + kHalfPiParts[2];
    lo = static_cast<Real>(rest);
  } else if constexpr (digits <= 113) {
    sumHalfPiParts(kHalfPiParts, 5, hi, lo);
  } else {
#if GIZMO_HAS_MULTIPRECISION
    static const std::vector<double> parts = halfPiPartsFromMpfr(2L * digits + 64);
    sumHalfPiParts(parts.data(), parts.size(), hi, lo);
#else
    static_assert(digits <= 113, "the portable build's scalars are at most 113 bits wide");
#endif
  }
}

#if GIZMO_HAS_MULTIPRECISION
// MPFR: the precision is chosen at run time, so take pi from MPFR itself (a correctly rounded
// constant, not a libm call) at twice the working precision plus a margin.
inline void halfPiSplit(MpfrReal& hi, MpfrReal& lo) {
  const long bits = mpfrBits();
  mpfr_t wide;
  mpfr_init2(wide, static_cast<mpfr_prec_t>(2 * bits + 64));
  mpfr_const_pi(wide, MPFR_RNDN);
  mpfr_div_2ui(wide, wide, 1, MPFR_RNDN);  // exact
  MpfrReal h;
  MpfrReal l;
  mpfr_set(h.backend().data(), wide, MPFR_RNDN);
  mpfr_sub(wide, wide, h.backend().data(), MPFR_RNDN);  // exact: wide has the room
  mpfr_set(l.backend().data(), wide, MPFR_RNDN);
  mpfr_clear(wide);
  hi = h;
  lo = l;
}
#endif

// Bits of Real's significand.
template <class Real>
inline long precisionBits() {
#if GIZMO_HAS_MULTIPRECISION
  if constexpr (std::is_same_v<Real, MpfrReal>) return mpfrBits();
  else
#endif
    return std::numeric_limits<Real>::digits;
}

// s + e == a + b exactly, s the rounded sum (Knuth's TwoSum; no condition on the magnitudes).
template <class Real>
inline void twoSum(const Real& a, const Real& b, Real& s, Real& e) {
  s = a + b;
  const Real bVirtual = s - a;
  const Real aVirtual = s - bVirtual;
  e = (a - aVirtual) + (b - bVirtual);
}

// 2^ceil(p/2) + 1 for Real's p-bit significand: the constant of Veltkamp's splitting.
template <class Real>
inline Real splitterOf() {
  // An exact scalar has no rounding error to recover: splitter 0 makes twoProduct's error term 0.
  if constexpr (kExactScalar<Real>) {
    return Real(0);
  } else {
    using std::ldexp;
    const int half = static_cast<int>((precisionBits<Real>() + 1) / 2);
    return ldexp(Real(1), half) + Real(1);  // exact
  }
}

// p + e == a * b exactly, p the rounded product (Dekker's product with Veltkamp's splitting,
// which needs round-to-nearest, no overflow and no fused multiply-add: -ffp-contract=off).
// `splitter` is splitterOf<Real>().
template <class Real>
inline void twoProduct(const Real& a, const Real& b, const Real& splitter, Real& p, Real& e) {
  const Real ta = splitter * a;
  const Real aHigh = ta - (ta - a);
  const Real aLow = a - aHigh;
  const Real tb = splitter * b;
  const Real bHigh = tb - (tb - b);
  const Real bLow = b - bHigh;
  p = a * b;
  e = (((aHigh * bHigh - p) + aHigh * bLow) + aLow * bHigh) + aLow * bLow;
}

// Most series terms ever summed; 4096 terms reach below 2^-40000 at |y| = 0.8.
inline constexpr int kMaxTerms = 4096;

// The Taylor series of sin y and cos y for |y| <= 0.8, in pieces that let callers round once:
//   sin y = y - sinTail,   cos y ~ cosHigh + cosLow (|cosLow| a few ulps of cosHigh at most).
// The leading y^2/2 of the cosine is taken exactly (twoProduct, twoSum), since at |y| ~ 0.8 it is
// a third of the result; the rest of each series is summed innermost term first (Horner form in
// y^2) after counting how many terms matter.
template <class Real>
inline void sinCosSeries(const Real& y, Real& sinTail, Real& cosHigh, Real& cosLow) {
  Real y2;
  Real y2Error;
  twoProduct(y, y, splitterOf<Real>(), y2, y2Error);
  const Real one = 1;
  // Number of terms: stop at the first cosine term y^(2k) / (2k)! below eps/8 (the sine terms
  // relative to y are smaller still).
  const Real threshold = epsilonOf<Real>() / 8;
  int n = 1;
  Real term = y2 / 2;
  while (n < kMaxTerms && term > threshold) {
    ++n;
    const Real denominator = Real((2 * n - 1) * (2 * n));
    term = term * y2 / denominator;
  }
  // sin y = y - y^2 y/3! ps,  ps = 1 - y^2/(4*5) (1 - y^2/(6*7) (...))
  // cos y = 1 - y^2/2! + y^2/2! y^2/(3*4) pc,  pc = 1 - y^2/(5*6) (1 - y^2/(7*8) (...))
  Real ps = one;
  Real pc = one;
  for (int k = n; k >= 2; --k) {
    const Real ds = Real((2 * k) * (2 * k + 1));
    ps = one - y2 * ps / ds;
    if (k >= 3) {
      const Real dc = Real((2 * k - 1) * (2 * k));
      pc = one - y2 * pc / dc;
    }
  }
  const Real two = 2;
  const Real six = 6;
  const Real twelve = 12;
  sinTail = y * (y2 * ps / six);
  // y^2/2 == half + halfError exactly; 1 - half == cosHigh + headError exactly.
  const Real half = y2 / two;
  const Real halfError = y2Error / two;
  Real headError;
  twoSum(one, Real(-half), cosHigh, headError);
  const Real fourthOrder = half * (y2 * pc / twelve);  // y^4/24 (...)
  cosLow = (headError - halfError) + fourthOrder;
}

}  // namespace detail

// s = sin x and c = cos x for |x| <= 2 (callers guarantee it; checked by assert). Deterministic:
// a pure function of x built from + - * / on Real only.
template <class Real>
inline void sinCos(const Real& x, Real& s, Real& c) {
  assert(absOf(x) <= Real(2));
  const bool negative = x < 0;
  const Real ax = absOf(x);
  const Real reductionThreshold = fromDouble<Real>(0.78);
  Real sinA;
  Real cosA;
  if (ax <= reductionThreshold) {
    Real sinTail;
    Real cosHigh;
    Real cosLow;
    detail::sinCosSeries(ax, sinTail, cosHigh, cosLow);
    sinA = ax - sinTail;
    cosA = cosHigh + cosLow;
  } else {
    Real hi;
    Real lo;
    detail::halfPiSplit(hi, lo);
    const Real a = hi - ax;  // exact: ax in [0.78, 2] lies within [hi/2, 2 hi]
    Real yh;
    Real yl;
    detail::twoSum(a, lo, yh, yl);  // pi/2 - ax == yh + yl, to about twice Real's precision
    Real sinTail;
    Real cosHigh;
    Real cosLow;
    detail::sinCosSeries(yh, sinTail, cosHigh, cosLow);
    // sin x = cos(yh + yl) ~ cos yh - yl sin yh,  cos x = sin(yh + yl) ~ sin yh + yl cos yh;
    // |yl| is below half an ulp of yh, so the yl^2 terms are far below the rounding. The
    // corrections join the small parts so that each result is rounded once, at the end.
    const Real sinYh = yh - sinTail;
    const Real cosYh = cosHigh + cosLow;
    const Real sinSmall = cosLow - yl * sinYh;
    const Real cosSmall = sinTail - yl * cosYh;
    sinA = cosHigh + sinSmall;
    cosA = yh - cosSmall;
  }
  s = negative ? Real(-sinA) : sinA;
  c = cosA;
}

}  // namespace gizmo::math
