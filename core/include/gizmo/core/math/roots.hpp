#pragma once
// Certified first-root finding for collision times.
//
// A ball and a feature are described by a gap g(t): positive = apart, zero = touching, negative =
// overlapping. An *entry* is where g crosses from > 0 to <= 0 and goes on below zero:
//   * at t = lo: g(lo) <= 0 and g'(lo) < 0 (already touching or overlapping, and approaching);
//   * at t in (lo, hi]: g > 0 just before t, g(t) <= 0, and g < 0 just after t (for t = hi:
//     g'(hi) < 0, or the first non-zero derivative negative). A tangential touch, where g comes
//     down to 0 and goes back up without becoming negative, is not an entry.
// Candidates are examined in increasing order; the first one `accept(t)` approves is returned,
// rejected ones are skipped and the search goes on after them.
//
// No sampling: nothing here evaluates g on a grid that could step over a short dip. The
// polynomial search splits [lo, hi] at the real roots of g' (found recursively), so that each
// piece is monotone and holds at most one entry; the smooth search excludes intervals only by
// bounds on |g'| and |g''| that hold on the whole interval.
//
// The returned time is the end of the final bracket that lies at or before the entry: either a
// point where g evaluates to exactly 0, or the last point with g > 0, the bracket's other end
// being its neighbouring value of Real. So the time is the last Real before the crossing as g
// is evaluated, a function of g alone and not of the path the search took, and the ball is not
// reported overlapping at it, except in the t = lo case, where it already was, and in the
// noise-level cases below. Accuracy: an ulp plus (error of g as evaluated) / |g'| at the root.
//
// Polynomials are evaluated so that their signs are those of compensated Horner, i.e. of g
// evaluated as if in twice Real's precision, so even two roots 1e-9 apart are told apart in
// double. Smooth gaps are evaluated by the caller's F. Either way decisions follow the signs of
// g as evaluated: where |g| is below its evaluation error (at an exact tangency, say) a touch, a
// near miss and a very shallow dip can be confused.
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gizmo/core/math/scalar.hpp"
#include "gizmo/core/math/trig.hpp"  // detail::twoSum, twoProduct, precisionBits

namespace gizmo::math {

// Default cap on the value and slope evaluations of firstEntrySmooth.
inline constexpr long kSmoothEvaluationCap = 200000;

// Optional in/out statistics of firstEntrySmooth.
struct SmoothSearchInfo {
  long maxEvaluations = kSmoothEvaluationCap;  // in: cap on value() + slope() calls
  long evaluations = 0;                        // out: value() + slope() calls made
  bool capped = false;                         // out: the cap stopped the search; the result is an early guess
};

namespace detail {

// g(t) = c[0] + c[1] t + ... + c[4] t^4, degree = highest non-zero coefficient (0 if none).
template <class Real>
struct Quartic {
  std::array<Real, 5> c;
  int degree = 0;
  Real splitter = splitterOf<Real>();

  explicit Quartic(const std::array<Real, 5>& coefficients) : c(coefficients) {
    for (int i = 4; i > 0; --i) {
      if (c[i] != 0) {
        degree = i;
        break;
      }
    }
  }
  // g(t), with the sign and the zeros of compensatedValue(t): by plain Horner where that leaves
  // no doubt of them, which is everywhere but near a root. Plain Horner is off by at most
  // gamma_2d = 2d u / (1 - 2d u) times sum |c_i| |t|^i (Higham, Accuracy and Stability, 5.1;
  // u = eps / 2, under 4.01 eps for d = 4), and compensated Horner by u |g| plus
  // gamma_2d^2 times that sum. Beyond 32 eps times the sum, as computed, both have g's sign and
  // neither is zero; the minimum-normal test keeps underflow, whose errors are absolute, out. Only
  // for IEEE formats, whose rounding that bound describes (not ppc64el's double-double).
  Real value(const Real& t) const {
    if constexpr (std::numeric_limits<Real>::is_iec559) {
      Real s = c[degree];
      Real size = absOf(s);
      const Real at = absOf(t);
      for (int i = degree - 1; i >= 0; --i) {
        s = s * t + c[i];
        size = size * at + absOf(c[i]);
      }
      const Real eps = epsilonOf<Real>();
      if (Real(32) * eps * size < absOf(s) && std::numeric_limits<Real>::min() < eps * size) return s;
    }
    return compensatedValue(t);
  }
  // g(t), by compensated Horner (Graillat, Langlois and Louvet): each step's rounding errors are
  // recovered exactly (twoProduct, twoSum) and summed alongside, so the result is as accurate as
  // plain Horner in twice Real's precision. Near a double root, where plain Horner's rounding
  // swamps g, this keeps the sign of g and thus the entry decisions right much closer in.
  Real compensatedValue(const Real& t) const {
    Real s = c[degree];
    Real error = 0;
    for (int i = degree - 1; i >= 0; --i) {
      Real product;
      Real productError;
      twoProduct(s, t, splitter, product, productError);
      Real sumError;
      twoSum(product, c[i], s, sumError);
      error = error * t + (productError + sumError);
    }
    return s + error;
  }
  Quartic derivative() const {
    std::array<Real, 5> d{};
    for (int i = 1; i <= degree; ++i) d[i - 1] = Real(i) * c[i];
    return Quartic(d);
  }
  Real slope(const Real& t) const {
    if (degree == 0) return Real(0);
    Real r = Real(degree) * c[degree];
    for (int i = degree - 1; i >= 1; --i) r = r * t + Real(i) * c[i];
    return r;
  }
};

// Up to three sorted, distinct roots.
template <class Real>
struct RootList {
  std::array<Real, 3> t{};
  int n = 0;
  void addIfNew(const Real& x) {
    if (n == 0 || t[n - 1] < x) t[n++] = x;
  }
};

// Largest iteration count of the bracketing solvers: enough for pure bisection from a bracket
// as wide as its position down to an ulp, twice over.
template <class Real>
inline long solverIterationCap() {
  return 2 * precisionBits<Real>() + 64;
}

// The single entry of a bracket [a, b] with value(a) = fa > 0 >= fb = value(b): safeguarded
// Newton that keeps the bracket. A Newton step is taken when it lands strictly inside the
// bracket and is less than half the step before it (the first: half the bracket); one that
// leaves the bracket gives way to the secant through its ends (the far end may lie next to the
// root, when an earlier step landed just past it), and one that does not halve to the midpoint.
// Once Newton has converged from one side (a step below eps max(|a|, |b|)), the next point lies
// that far across the root, twice as far each time that falls short, to close the far end.
// Stops when value() is exactly 0 (returns that point), when no value of Real lies strictly
// inside the bracket, or after solverIterationCap() steps; then returns a, the last point with
// value > 0, which lies at or before the root. Ending on neighbouring values makes the answer the
// last Real before the crossing whatever the start and the steps (wherever the sign of value()
// changes once there), so a better start or a cheaper value() can only make the search faster,
// never move a decision. (A format whose values can be closer than eps |x|, as ppc64el's
// double-double long double, also stops at a bracket narrower than eps max(|a|, |b|) / 4, which an
// IEEE format's neighbours never are.)
//
// `guess`, when it lies strictly inside the bracket, is where the search starts (a closed-form
// root of a quadratic, or a model of the piece: entryByCascade).
template <class Real, class Value, class Slope>
Real solveEntry(const Value& value, const Slope& slope, Real a, Real b, Real fb,
                const std::optional<Real>& guess = std::nullopt) {
  const Real eps = epsilonOf<Real>();
  const Real two = 2;
  const long cap = solverIterationCap<Real>();
  Real stepBefore = b - a;
  Real probe = 0;  // the last step across a converged root, 0 when the last step was Newton's
  std::optional<Real> fa;
  Real x = guess && a < *guess && *guess < b ? *guess : Real(a + (b - a) / two);
  for (long iteration = 0; iteration < cap && fb != 0; ++iteration) {
    const Real fx = value(x);
    if (fx > 0) {
      a = x;
      fa = fx;
    } else {
      b = x;
      fb = fx;
      if (fb == 0) break;
    }
    const Real mid = a + (b - a) / two;
    if (!(a < mid && mid < b)) break;
    const Real scale = maxOf(absOf(a), absOf(b));
    if (Real(4) * Real(b - a) <= eps * scale) break;
    Real next = mid;
    const Real d = slope(x);
    if (d < 0) {
      Real step = -fx / d;
      const Real minStep = eps * scale;
      if (absOf(step) < minStep) {
        // Converged from one side: step across the root, twice as far as last time if that
        // step fell short, so that the far end comes in after a step or two.
        probe = probe == 0 ? minStep : Real(two * probe);
        step = fx > 0 ? probe : Real(-probe);
      } else {
        probe = 0;
      }
      const Real candidate = x + step;
      const bool inside = a < candidate && candidate < b;
      if (inside && (probe != 0 || two * absOf(step) < stepBefore)) {
        next = candidate;
        stepBefore = absOf(step);
      } else {
        stepBefore = b - a;
        if (!inside && probe == 0 && fa) {
          // Newton overshot the bracket, whose far end may lie next to the root: the secant
          // through the ends goes there in a step where halving the bracket takes fifty.
          const Real secant = a + *fa * (b - a) / (*fa - fb);
          if (a < secant && secant < b) next = secant;
        }
      }
    } else {
      probe = 0;
      stepBefore = b - a;
    }
    x = next;
  }
  return fb == 0 ? b : a;
}

// A root of p in [a, b], given p(a) and p(b) of opposite signs (neither zero).
template <class Real>
Real solveSignChange(const Quartic<Real>& p, const Real& a, const Real& pa, const Real& b, const Real& pb) {
  // Bisection in an exact scalar would never end with the root, only with ever longer
  // rationals near it.
  if constexpr (kExactScalar<Real>)
    throw IrrationalValue("a root of a polynomial of degree " + std::to_string(p.degree) +
                          " (the turning points of a ballistic gap)");
  if (pa > 0) {
    return solveEntry([&p](const Real& t) -> Real { return p.value(t); },
                      [&p](const Real& t) -> Real { return p.slope(t); }, a, b, pb);
  }
  return solveEntry([&p](const Real& t) -> Real { return Real(-p.value(t)); },
                    [&p](const Real& t) -> Real { return Real(-p.slope(t)); }, a, b, Real(-pb));
}

// Real roots of a2 t^2 + a1 t + a0 (a2 != 0), sorted, by the cancellation-free closed form
// q = -(a1 + sign(a1) sqrt(disc)) / 2, roots q / a2 and a0 / q.
template <class Real>
void quadraticRoots(const Real& a2, const Real& a1, const Real& a0, RootList<Real>& out) {
  const Real disc = a1 * a1 - Real(4) * a2 * a0;
  if (disc < 0) return;
  const Real root = sqrtOf(disc);
  const Real two = 2;
  const Real q = a1 < 0 ? Real((root - a1) / two) : Real(-(a1 + root) / two);
  if (q == 0) {  // a1 == 0 and a0 == 0: double root at 0
    out.addIfNew(Real(0));
    return;
  }
  Real r1 = q / a2;
  Real r2 = a0 / q;
  if (r2 < r1) std::swap(r1, r2);
  out.addIfNew(r1);
  out.addIfNew(r2);
}

// The distinct real roots of p (degree <= 3) strictly inside (lo, hi), sorted. Degree <= 2 by
// closed form; degree 3 by splitting at the roots of p' into monotone pieces and solving each
// piece whose ends differ in sign.
template <class Real>
void rootsInside(const Quartic<Real>& p, const Real& lo, const Real& hi, RootList<Real>& out) {
  if (p.degree == 0) return;
  if (p.degree == 1) {
    const Real t = -p.c[0] / p.c[1];
    if (lo < t && t < hi) out.addIfNew(t);
    return;
  }
  if (p.degree == 2) {
    RootList<Real> all;
    quadraticRoots(p.c[2], p.c[1], p.c[0], all);
    for (int i = 0; i < all.n; ++i) {
      if (lo < all.t[i] && all.t[i] < hi) out.addIfNew(all.t[i]);
    }
    return;
  }
  RootList<Real> turns;
  rootsInside(p.derivative(), lo, hi, turns);
  Real a = lo;
  Real pa = p.value(lo);
  for (int i = 0; i <= turns.n; ++i) {
    const Real b = i < turns.n ? turns.t[i] : hi;
    const Real pb = p.value(b);
    if (pb == 0) {
      if (b < hi) out.addIfNew(b);
    } else if ((pa > 0 && pb < 0) || (pa < 0 && pb > 0)) {
      const Real t = solveSignChange(p, a, pa, b, pb);
      if (lo < t && t < hi) out.addIfNew(t);
    }
    a = b;
    pa = pb;
  }
}

// Whether g, zero at t, is negative just after t: its first non-zero derivative there is.
template <class Real>
bool goesNegativeAfter(const Quartic<Real>& g, const Real& t) {
  Quartic<Real> d = g.derivative();
  for (int order = 1; order <= g.degree; ++order) {
    const Real v = d.value(t);
    if (v != 0) return v < 0;
    d = d.derivative();
  }
  return false;
}

// Whether [a, b] is too narrow to split further: narrower than `ulps` eps max(|a|, |b|, floor),
// or without a representable point strictly inside.
template <class Real>
bool tooNarrow(const Real& a, const Real& b, const Real& floor, int ulps) {
  const Real scale = maxOf(maxOf(absOf(a), absOf(b)), floor);
  if (b - a <= Real(ulps) * epsilonOf<Real>() * scale) return true;
  const Real mid = a + (b - a) / Real(2);
  return !(a < mid && mid < b);
}

// Cheap proofs that the derivative cascade (entryByCascade) finds no entry in (0, span], from
// bounds on g and g' over the whole interval (each term c_i t^i lies between 0 and c_i span^i
// there). They decide only what the cascade would decide the same way, so the answer does not
// change: each bound must clear a margin of 16 eps times the sum of the terms' sizes, far above
// the rounding of the bound itself and of the evaluations the cascade would make (compensated
// Horner: eps |g| plus O(eps^2)), so that every value the cascade would compute has the sign
// the bound proves.
template <class Real>
struct ExclusionBounds {
  Real sizes{0};  // sum of |c_i| span^i
  Real terms[5];  // c_i span^i
  ExclusionBounds(const Quartic<Real>& g, const Real& span) {
    Real power(1);
    for (int i = 0; i <= 4; ++i) {
      terms[i] = g.c[i] * power;
      sizes = sizes + absOf(terms[i]);
      power = power * span;
    }
  }
  Real margin(const Real& size) const { return Real(16) * epsilonOf<Real>() * size; }

  // g' > 0 on [0, span]: g' >= c1 + sum over i >= 2 of min(0, i c_i span^(i-1)). Then g has no
  // turning point there, and the cascade's one piece [0, span] is decided by its ends' signs.
  bool increasing(const Real& span) const {
    if (!(Real(0) < span)) return false;
    Real low = terms[1];
    Real size = absOf(terms[1]);
    for (int i = 2; i <= 4; ++i) {
      const Real slopeTerm = Real(i) * terms[i];  // i c_i span^i = span * (i c_i span^(i-1))
      low = low + minOf(Real(0), slopeTerm);
      size = size + absOf(slopeTerm);
    }
    return margin(size) < low;
  }

  // g > 0 on [0, span]: the quadratic part c0 + c1 t + c2 t^2, minimised exactly over the
  // interval, plus min(0, c_i span^i) for the cubic and quartic terms.
  bool positive(const Quartic<Real>& g, const Real& span) const {
    Real low = minOf(terms[0], Real(terms[0] + terms[1] + terms[2]));
    if (Real(0) < g.c[2]) {
      const Real vertex = -g.c[1] / (Real(2) * g.c[2]);
      if (Real(0) < vertex && vertex < span) low = minOf(low, Real(g.c[0] - g.c[1] * g.c[1] / (Real(4) * g.c[2])));
    }
    low = low + minOf(Real(0), terms[3]) + minOf(Real(0), terms[4]);
    return margin(sizes) < low;
  }
};

// Whether the bounds prove that the cascade (entryByCascade) finds no entry of g in (0, hi];
// gLo = g(0) as evaluated. A ball that just left a surface, or passes near one while moving away,
// gives such gaps: without the proof each costs a derivative cascade with a Newton search for a
// turning point.
template <class Real>
bool noEntryByBounds(const Quartic<Real>& g, const Real& hi, const Real& gLo) {
  if (g.degree <= 2) return false;  // the cascade is a closed form there already
  const ExclusionBounds<Real> bounds(g, hi);
  if (bounds.positive(g, hi)) return true;  // every value the cascade computes is > 0
  // Increasing throughout, for a quartic: every value of g' that the cascade computes (at the
  // ends and at the closed-form roots of g'') is then > 0, so it finds no turning point and
  // decides its one piece [0, hi] by the signs at its ends, as here. (A cubic's turning points
  // come from a closed form that rounding could move into the interval: the bound is not used.)
  return g.degree == 4 && bounds.increasing(hi) && !(gLo > 0 && g.value(hi) <= 0);
}

// The derivative cascade over [lo, hi] (see firstEntry), given gLo = g(lo) as evaluated.
template <class Real, class Accept>
std::optional<Real> entryByCascade(const Quartic<Real>& g, const Real& lo, const Real& hi, const Real& gLo,
                                   Accept&& accept) {
  const std::array<Real, 5>& c = g.c;
  RootList<Real> turns;
  rootsInside(g.derivative(), lo, hi, turns);
  // Up to degree 2 the closed form gives the roots to an ulp or two; they seed the bracketed
  // search, which still decides the answer.
  // They are worked out when a piece first holds an entry: an exact scalar needs a root's square
  // root only where there is an entry to report.
  RootList<Real> direct;
  bool directKnown = false;
  // Beyond degree 2 the search starts where a simple model of the piece crosses zero: at an end
  // that is a turning point (g' = 0 there) g starts like a parabola, so the parabola with its
  // vertex there through the other end; otherwise the secant through the ends. The guess only
  // saves steps: the entry is the same from any start (solveEntry).
  auto guessIn = [&](const Real& a, const Real& b, const Real& ga, const Real& gb, bool aTurns,
                     bool bTurns) -> std::optional<Real> {
    if (!directKnown) {
      if (g.degree == 1) direct.addIfNew(Real(-c[0] / c[1]));
      if (g.degree == 2) quadraticRoots(c[2], c[1], c[0], direct);
      directKnown = true;
    }
    for (int k = 0; k < direct.n; ++k)
      if (a <= direct.t[k] && direct.t[k] <= b) return direct.t[k];
    if (g.degree > 2 && gb < ga) {
      if constexpr (!kExactScalar<Real>) {
        if (aTurns) return Real(a + (b - a) * sqrtOf(Real(ga / (ga - gb))));
        if (bTurns) return Real(b - (b - a) * sqrtOf(Real(-gb / (ga - gb))));
      }
      return Real(a + ga * (b - a) / (ga - gb));
    }
    return std::nullopt;
  };
  Real a = lo;
  Real ga = gLo;
  for (int i = 0; i <= turns.n; ++i) {
    const Real b = i < turns.n ? turns.t[i] : hi;
    const Real gb = g.value(b);
    if (ga > 0 && gb <= 0 && (gb < 0 || goesNegativeAfter(g, b))) {
      Real t = b;
      if (gb != 0) {
        const std::optional<Real> guess = guessIn(a, b, ga, gb, i > 0, i < turns.n);
        if constexpr (kExactScalar<Real>) {
          // An exact scalar takes the closed-form root as it is: it is the entry, or the entry
          // is not rational (quadraticRoots has thrown already for a surd) and no search could
          // give it exactly.
          if (!guess || g.value(*guess) != 0)
            throw IrrationalValue("the root of a gap polynomial of degree " + std::to_string(g.degree));
          t = *guess;
        } else {
          t = solveEntry([&g](const Real& x) -> Real { return g.value(x); },
                         [&g](const Real& x) -> Real { return g.slope(x); }, a, b, gb, guess);
        }
      }
      if (accept(t)) return t;
    }
    a = b;
    ga = gb;
  }
  return std::nullopt;
}

}  // namespace detail

// First entry of the polynomial gap g(t) = c[0] + c[1] t + ... + c[4] t^4 in [lo, hi] (leading
// coefficients may be 0) that `accept` approves; nullopt if none (or if hi < lo).
//
// Derivative cascade: the real roots of g' inside (lo, hi) split [lo, hi] into monotone pieces;
// a piece [a, b] with g(a) > 0 >= g(b) holds exactly one entry (when g(b) == 0 it is b, provided
// g goes negative after b), which solveEntry brackets to a few ulps. The roots of g' come the same
// way from those of g'' (closed form for degree <= 2, cancellation-free).
// Before the cascade, cheap bounds (detail::noEntryByBounds) settle the gaps that provably have
// no entry in (0, hi]; they give the answer the cascade would.
template <class Real, class Accept>
std::optional<Real> firstEntry(const std::array<Real, 5>& c, const Real& lo, const Real& hi, Accept&& accept) {
  const detail::Quartic<Real> g(c);
  const Real gLo = g.value(lo);
  if (gLo <= 0 && g.slope(lo) < 0 && accept(lo)) return lo;
  if (!(lo < hi) || g.degree == 0) return std::nullopt;
  if (lo == Real(0) && detail::noEntryByBounds(g, hi, gLo)) return std::nullopt;
  return detail::entryByCascade(g, lo, hi, gLo, accept);
}

// The same, accepting every candidate.
template <class Real>
std::optional<Real> firstEntry(const std::array<Real, 5>& c, const Real& lo, const Real& hi) {
  return firstEntry(c, lo, hi, [](const Real&) { return true; });
}

// First entry in [lo, hi] of a smooth gap g that `accept` approves; nullopt if none.
//
// F provides, for t, a, b in [lo, hi]:
//   Real value(const Real& t) const;                      g(t)
//   Real slope(const Real& t) const;                      g'(t)
//   Real slopeBound(const Real& a, const Real& b) const;      >= sup |g'| on [a, b]
//   Real curvatureBound(const Real& a, const Real& b) const;  >= sup |g''| on [a, b]
// The bounds must hold for g as evaluated too: pad them by a relative margin well above the
// rounding of value() and slope().
//
// Leftmost-first subdivision. On [a, b] with midpoint m and half-width w:
//   * |g(m)| > slopeBound w, or |g(m)| > |g'(m)| w + curvatureBound w^2 / 2: g has no zero on
//     [a, b] (|g(t) - g(m)| is at most the right-hand side for every t there), so no entry: skip.
//   * |g'(m)| > curvatureBound w: g' has no zero on [a, b], g is monotone. If it decreases and
//     g(a) > 0 >= g(b), the one entry is solved as in firstEntry; otherwise there is none.
//   * otherwise split, and examine the left half first.
// An interval narrower than 4 eps max(|a|, |b|, hi - lo) is decided by the signs at its ends
// (entry if g(a) > 0 and g(b) < 0, or g(b) == 0 with g'(b) < 0; the candidate is a, or b when
// g(b) == 0).
//
// Why no entry is skipped: every interval is either proven free of zeros (or monotone) by bounds
// that hold on all of it, or split; no point is ever assumed to stand for its neighbours, so
// there are no samples to fall between. Intervals are finished left to right, so candidates come
// in increasing order. And the sign of g is carried from each decided interval to the next: were
// an exclusion wrong because value() rounds (possible only where |g| is at the level of its
// rounding error), a change from > 0 to <= 0 between two neighbouring intervals is still
// reported, at their common end.
//
// Cost cap: when the value() + slope() calls reach the cap (info->maxEvaluations, default
// kSmoothEvaluationCap) the search stops and returns the left end of the first undecided
// interval, without consulting accept. No entry lies before that time, so it is a conservative,
// early answer; info->capped tells it apart. A tangency where g'' also vanishes can need this.
template <class Real, class F, class Accept>
std::optional<Real> firstEntrySmooth(const F& f, const Real& lo, const Real& hi, Accept&& accept,
                                     SmoothSearchInfo* info = nullptr) {
  long evaluations = 0;
  const long cap = info != nullptr ? info->maxEvaluations : kSmoothEvaluationCap;
  auto value = [&](const Real& t) -> Real {
    ++evaluations;
    return f.value(t);
  };
  auto slope = [&](const Real& t) -> Real {
    ++evaluations;
    return f.slope(t);
  };
  auto finish = [&](std::optional<Real> result, bool capped) -> std::optional<Real> {
    if (info != nullptr) {
      info->evaluations = evaluations;
      info->capped = capped;
    }
    return result;
  };

  const Real gLo = value(lo);
  if (gLo <= 0 && slope(lo) < 0 && accept(lo)) return finish(lo, false);
  if (!(lo < hi)) return finish(std::nullopt, false);

  const Real two = 2;
  const Real span = hi - lo;
  struct Interval {
    Real a, b;
  };
  std::vector<Interval> pending;  // the top is the leftmost undecided interval
  pending.push_back(Interval{lo, hi});
  // Whether g > 0 at the frontier (the left end of the top interval), as the decisions so far
  // found it. A decision that starts with g <= 0 where the previous one ended with g > 0 can only
  // come from rounding in value() (an exclusion wrong at noise level); the entry is then at the
  // frontier, and is reported there rather than lost.
  bool positive = gLo > 0;
  while (!pending.empty()) {
    if (evaluations >= cap) return finish(pending.back().a, true);
    const Real a = pending.back().a;
    const Real b = pending.back().b;
    pending.pop_back();

    if (detail::tooNarrow(a, b, span, 4)) {
      const Real ga = value(a);
      const Real gb = value(b);
      std::optional<Real> candidate;
      if (positive && !(ga > 0)) {
        candidate = a;
      } else if (ga > 0 && (gb < 0 || (gb == 0 && slope(b) < 0))) {
        candidate = gb == 0 ? b : a;
      }
      positive = gb > 0;
      if (candidate && accept(*candidate)) return finish(candidate, false);
      continue;
    }

    const Real w = (b - a) / two;
    const Real m = a + w;
    const Real gm = value(m);
    const Real distance = absOf(gm);
    bool zeroFree = distance > f.slopeBound(a, b) * w;
    Real sm = 0;
    Real curvature = 0;
    if (!zeroFree) {
      sm = slope(m);
      curvature = f.curvatureBound(a, b);
      zeroFree = distance > absOf(sm) * w + curvature * w * w / two;
    }
    if (zeroFree) {  // g keeps the sign of g(m) on all of [a, b]
      const bool positiveHere = gm > 0;
      const bool signChange = positive && !positiveHere;
      positive = positiveHere;
      if (signChange && accept(a)) return finish(a, false);
      continue;
    }
    if (absOf(sm) > curvature * w) {  // g' keeps its sign on [a, b]: g is monotone
      const Real ga = value(a);
      const Real gb = value(b);
      std::optional<Real> candidate;
      if (positive && !(ga > 0)) {
        candidate = a;
      } else if (sm < 0 && ga > 0 && gb <= 0) {
        // The one entry; strictly decreasing through b, so g(b) == 0 is an entry too.
        candidate = gb == 0 ? b : detail::solveEntry(value, slope, a, b, gb);
      }
      positive = gb > 0;
      if (candidate && accept(*candidate)) return finish(candidate, false);
      continue;
    }
    pending.push_back(Interval{m, b});
    pending.push_back(Interval{a, m});
  }
  return finish(std::nullopt, false);
}

// The same, accepting every candidate.
template <class Real, class F>
std::optional<Real> firstEntrySmooth(const F& f, const Real& lo, const Real& hi) {
  return firstEntrySmooth(f, lo, hi, [](const Real&) { return true; });
}

}  // namespace gizmo::math
