#pragma once
// π, sine and cosine for Interval (interval.hpp), for the swinging flipper's gaps. Like every
// Interval operation they are only valid inside an UpwardRounding scope, and they need the same
// -frounding-math (interval.hpp says why).
//
// How the bounds stay bounds:
// - π is the pair of neighbouring doubles around it (Interval::pi; π is irrational, so it is
//   neither).
// - A point x is reduced to r = x − n·π/2 with n an integer near x/(π/2); r is computed in
//   interval arithmetic with the enclosure of π/2, so whatever n is chosen, r holds the exact
//   x − n·π/2. Then sin r and cos r come from their Taylor polynomials evaluated in interval
//   arithmetic plus the Lagrange remainder |r|^(k+1)/(k+1)!, which holds for every r (all
//   derivatives of sin and cos are bounded by 1), and the quadrant n mod 4 picks the signs.
// - Over an interval X the function is monotone between its critical points (multiples of π/2):
//   the range is the hull of the two end points' enclosures and of ±1 wherever a critical point
//   may lie in X. Whether one may is decided on X/(π/2) in interval arithmetic, so a critical
//   point is never missed; one that is not there but cannot be ruled out only widens the result.
#include <cmath>

#include "gizmo/verify/interval.hpp"

namespace gizmo::verify {

namespace trig_detail {

inline Interval halfPi() { return Interval::pi() * Interval(0.5); }  // halving is exact

// Terms kept: sin to r^17, cos to r^18. For |r| ≤ π/4 (what the reduction leaves) the remainders
// are below 1.2e-19 and 4.7e-21, far under an ulp of the results.
inline constexpr int kSinTerms = 8;  // r (1 − r²/(2·3) (1 − r²/(4·5) (…))), 8 nested factors
inline constexpr int kCosTerms = 9;

// |r|^k / k! rounded up: the Lagrange bound on what the truncated series leaves out.
inline double remainderBound(const Interval& r, int k) {
  const double a = std::max(-r.lower(), r.upper());
  double bound = 1.0;
  for (int i = 1; i <= k; ++i) bound = bound * a / double(i);  // upward rounding: stays above
  return bound;
}

// x / c for an exact c > 0: two divisions instead of the general quotient's eight.
inline Interval dividedBy(const Interval& x, double c) { return Interval(-((-x.lower()) / c), x.upper() / c); }

inline Interval sinSeries(const Interval& r) {
  const Interval z = square(r);
  Interval s(1.0);
  for (int k = kSinTerms; k >= 1; --k) s = Interval(1.0) - dividedBy(z * s, double((2 * k) * (2 * k + 1)));
  const double e = remainderBound(r, 2 * kSinTerms + 3);
  return r * s + Interval(-e, e);
}

inline Interval cosSeries(const Interval& r) {
  const Interval z = square(r);
  Interval s(1.0);
  for (int k = kCosTerms; k >= 1; --k) s = Interval(1.0) - dividedBy(z * s, double((2 * k - 1) * (2 * k)));
  const double e = remainderBound(r, 2 * kCosTerms + 2);
  return s + Interval(-e, e);
}

inline Interval unitRange() { return Interval(-1.0, 1.0); }

// sin and cos of the exact value of a double (quadrant: sin(r + nπ/2) is sin r, cos r, −sin r,
// −cos r for n = 0, 1, 2, 3 mod 4; cos likewise shifted by one).
inline void sinCosOfPoint(double x, Interval& sine, Interval& cosine) {
  // Beyond this the reduction's error (n times the width of π/2's enclosure) would swamp r:
  // say nothing rather than something loose.
  if (!(std::fabs(x) < 0x1p40)) {
    sine = cosine = unitRange();
    return;
  }
  // Any integer keeps the bounds valid; the nearest keeps |r| ≤ π/4 and the series short. floor
  // ignores the rounding mode, unlike nearbyint.
  const double n = std::floor(x * 0x1.45f306dc9c883p-1 + 0.5);  // x · 2/π
  const Interval r = Interval(x) - Interval(n) * halfPi();
  const Interval s = sinSeries(r), c = cosSeries(r);
  switch (static_cast<long long>(std::fmod(n, 4.0) + 4.0) % 4) {
    case 0: sine = s, cosine = c; break;
    case 1: sine = c, cosine = -s; break;
    case 2: sine = -s, cosine = -c; break;
    default: sine = -c, cosine = s; break;
  }
  sine = intersect(sine, unitRange());
  cosine = intersect(cosine, unitRange());
}

// The range over X of a function with maxima where n ≡ top and minima where n ≡ top + 2 (mod 4),
// n = x/(π/2), given the enclosures at X's ends.
inline Interval rangeWithCriticalPoints(const Interval& x, const Interval& atLo, const Interval& atHi, int top) {
  Interval range = hull(atLo, atHi);
  const Interval quarters = x / halfPi();
  // More than a full turn, an unbounded X, or one so far out that stepping n by 1 would stall:
  // every value may be taken.
  if (!(quarters.upper() - quarters.lower() < 4.0) || !(std::fabs(quarters.lower()) < 0x1p50)) return unitRange();
  double lo = range.lower(), hi = range.upper();
  for (double n = std::ceil(quarters.lower()); n <= quarters.upper(); n += 1.0) {
    const long long k = (static_cast<long long>(std::fmod(n, 4.0)) + 4) % 4;
    if (k == top) hi = 1.0;
    if (k == (top + 2) % 4) lo = -1.0;
  }
  return Interval(std::max(lo, -1.0), std::min(hi, 1.0));
}

}  // namespace trig_detail

// Both at once: the ends are reduced and expanded once for the two.
inline void sinCos(const Interval& x, Interval& sine, Interval& cosine) {
  Interval sLo, cLo;
  trig_detail::sinCosOfPoint(x.lower(), sLo, cLo);
  if (x.lower() == x.upper()) {
    sine = sLo;
    cosine = cLo;
    return;
  }
  Interval sHi, cHi;
  trig_detail::sinCosOfPoint(x.upper(), sHi, cHi);
  sine = trig_detail::rangeWithCriticalPoints(x, sLo, sHi, 1);
  cosine = trig_detail::rangeWithCriticalPoints(x, cLo, cHi, 0);
}

inline Interval sin(const Interval& x) {
  Interval s, c;
  sinCos(x, s, c);
  return s;
}

inline Interval cos(const Interval& x) {
  Interval s, c;
  sinCos(x, s, c);
  return c;
}

}  // namespace gizmo::verify
