// firstEntry (polynomial gaps) and firstEntrySmooth (rotating-flipper gaps) against exact roots
// and against MPFR references computed independently (dense sampling, then bisection).
#include "gizmo/core/math/roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <optional>
#include <random>
#include <vector>

#include "gizmo/core/geometry/vec2.hpp"
#include "gizmo/core/math/trig.hpp"
#include "support/scalar_fixture.hpp"

namespace {

using gizmo::Float128;
using gizmo::MpfrReal;
using gizmo::Vec2;
namespace gm = gizmo::math;

// ---------------------------------------------------------------------------------------------
// Helpers

using gizmo::test::ScopedMpfrBits;

template <class Real>
Real fd(double d) {
  return gizmo::fromDouble<Real>(d);
}

// The spacing of Real's values around x (x != 0).
template <class Real>
Real ulpOf(const Real& x) {
  using std::frexp;
  using std::ldexp;
  int exponent = 0;
  frexp(x, &exponent);  // x = m 2^exponent, 1/2 <= |m| < 1
  return ldexp(Real(1), exponent - static_cast<int>(gm::detail::precisionBits<Real>()));
}

template <class Real>
double ulpsBetween(const Real& x, double exact) {
  const Real e = fd<Real>(exact);
  return gizmo::toDouble(Real(gizmo::absOf(Real(x - e)) / ulpOf(e)));
}

// scale * prod (t - r): exact for the dyadic roots used here.
template <class Real>
std::array<Real, 5> fromRoots(double scale, std::initializer_list<double> roots) {
  std::array<Real, 5> c{};
  c[0] = fd<Real>(scale);
  int degree = 0;
  for (double r : roots) {
    const Real root = fd<Real>(r);
    for (int i = degree + 1; i >= 1; --i) c[i] = c[i - 1] - root * c[i];
    c[0] = -root * c[0];
    ++degree;
  }
  return c;
}

template <class Real>
std::array<Real, 5> coefficients(double c0, double c1, double c2, double c3, double c4) {
  return {fd<Real>(c0), fd<Real>(c1), fd<Real>(c2), fd<Real>(c3), fd<Real>(c4)};
}

// Exact value of any scalar as a wide MPFR number (the current default precision must be wide).
MpfrReal toBig(float x) { return MpfrReal(static_cast<double>(x)); }
MpfrReal toBig(double x) { return MpfrReal(x); }
MpfrReal toBig(long double x) { return MpfrReal(x); }
MpfrReal toBig(const Float128& x) {
  const std::array<double, 3> d = gizmo::test::splitFloat128(x);
  MpfrReal r = d[0];
  r = r + MpfrReal(d[1]);
  r = r + MpfrReal(d[2]);
  return r;
}
MpfrReal toBig(const MpfrReal& x) {
  MpfrReal r;  // default (wide) precision
  mpfr_set(r.backend().data(), x.backend().data(), MPFR_RNDN);
  return r;
}

constexpr long kReferenceBits = 256;

// All entries (g from > 0 to <= 0) of a gap in (lo, hi]: long double sampling on `samples`
// intervals locates them, MPFR bisection at kReferenceBits pins each to the last point with
// g > 0. The scenarios below keep every dip many samples wide and far above long double noise.
template <class SampleFn, class BigFn>
std::vector<MpfrReal> referenceEntries(const SampleFn& sampled, const BigFn& exact, double lo, double hi, int samples) {
  std::vector<MpfrReal> entries;
  long double previous = sampled(static_cast<long double>(lo));
  long double previousT = lo;
  for (int i = 1; i <= samples; ++i) {
    const long double t = static_cast<long double>(lo) + (static_cast<long double>(hi) - lo) * i / samples;
    const long double value = sampled(t);
    if (previous > 0 && value <= 0) {
      ScopedMpfrBits wide(kReferenceBits);
      MpfrReal a = MpfrReal(previousT);
      MpfrReal b = MpfrReal(t);
      for (int k = 0; k < kReferenceBits + 40; ++k) {
        const MpfrReal m = (a + b) / 2;
        if (exact(m) > 0) {
          a = m;
        } else {
          b = m;
        }
      }
      entries.push_back(a);
    }
    previous = value;
    previousT = t;
  }
  return entries;
}

// x - reference as a double.
template <class Real>
double offset(const Real& x, const MpfrReal& reference) {
  ScopedMpfrBits wide(kReferenceBits);
  const MpfrReal d = toBig(x) - toBig(reference);
  return static_cast<double>(d);
}

// |x - reference| as a double.
template <class Real>
double distance(const Real& x, const MpfrReal& reference) {
  ScopedMpfrBits wide(kReferenceBits);
  const MpfrReal d = toBig(x) - toBig(reference);
  return std::fabs(static_cast<double>(d));
}

using gizmo::test::MpfrAware;
using gizmo::test::Scalars;

// ---------------------------------------------------------------------------------------------
// firstEntry: polynomial gaps

template <class Real>
class FirstEntry : public MpfrAware<Real> {};
TYPED_TEST_SUITE(FirstEntry, Scalars);

// Scalars that hold the random dyadic coefficients below exactly (float does not).
using WideScalars = ::testing::Types<double, long double, Float128, MpfrReal>;
template <class Real>
class FirstEntryWide : public MpfrAware<Real> {};
TYPED_TEST_SUITE(FirstEntryWide, WideScalars);

// Checks that r holds a value within maxUlps of `exact`.
template <class Real>
void expectRootNear(const std::optional<Real>& r, double exact, double maxUlps) {
  ASSERT_TRUE(r.has_value()) << "expected an entry near " << exact;
  EXPECT_LE(ulpsBetween(*r, exact), maxUlps) << "got " << gizmo::toDouble(*r) << ", expected " << exact;
}

TYPED_TEST(FirstEntry, EntryNotExit) {
  using Real = TypeParam;
  const Real lo = 0, hi = 1;
  // Apart, overlapping between 1/4 and 3/4, apart again: the entry is 1/4.
  expectRootNear(gm::firstEntry(fromRoots<Real>(2, {0.25, 0.75}), lo, hi), 0.25, 2);
  // Overlapping, apart between 1/4 and 3/4, overlapping again: 1/4 is an exit, 3/4 the entry.
  expectRootNear(gm::firstEntry(fromRoots<Real>(-2, {0.25, 0.75}), lo, hi), 0.75, 2);
  // Overlapping and receding from the start, never entering again.
  EXPECT_FALSE(gm::firstEntry(fromRoots<Real>(2, {0.25, 0.75}), Real(fd<Real>(0.6)), hi));
}

TYPED_TEST(FirstEntry, QuarticEntriesInOrderAndAccept) {
  using Real = TypeParam;
  // Entries at 1/8 and 5/8, exits at 3/8 and 3/2.
  const auto c = fromRoots<Real>(3, {0.125, 0.375, 0.625, 1.5});
  const Real lo = 0, hi = 2;
  expectRootNear(gm::firstEntry(c, lo, hi), 0.125, 4);

  std::vector<double> seen;
  const auto skipFirst = gm::firstEntry(c, lo, hi, [&](const Real& t) {
    seen.push_back(gizmo::toDouble(t));
    return t > fd<Real>(0.2);
  });
  expectRootNear(skipFirst, 0.625, 4);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_NEAR(seen[0], 0.125, 1e-6);
  EXPECT_NEAR(seen[1], 0.625, 1e-6);

  seen.clear();
  EXPECT_FALSE(gm::firstEntry(c, lo, hi, [&](const Real& t) {
    seen.push_back(gizmo::toDouble(t));
    return false;
  }));
  EXPECT_EQ(seen.size(), 2u);  // both entries offered, neither exit

  // The window ends before the second entry.
  seen.clear();
  EXPECT_FALSE(gm::firstEntry(c, lo, Real(fd<Real>(0.5)), [&](const Real& t) {
    seen.push_back(gizmo::toDouble(t));
    return false;
  }));
  EXPECT_EQ(seen.size(), 1u);
}

TYPED_TEST(FirstEntry, StartingInside) {
  using Real = TypeParam;
  const auto c = fromRoots<Real>(3, {0.125, 0.375, 0.625, 1.5});
  const Real hi = 2;
  // Just after the first entry: overlapping and still approaching -> lo itself, exactly.
  const Real approaching = fd<Real>(0.13);
  const auto r1 = gm::firstEntry(c, approaching, hi);
  ASSERT_TRUE(r1.has_value());
  EXPECT_TRUE(*r1 == approaching);
  // Rejecting lo goes on to the next entry.
  const auto r2 = gm::firstEntry(c, approaching, hi, [&](const Real& t) { return t != approaching; });
  expectRootNear(r2, 0.625, 4);
  // Just before the exit: overlapping but receding -> not lo, but the next entry.
  expectRootNear(gm::firstEntry(c, Real(fd<Real>(0.37)), hi), 0.625, 4);
  // Exactly touching and approaching at lo.
  const Real atRoot = fd<Real>(0.625);
  const auto r3 = gm::firstEntry(c, atRoot, hi);
  ASSERT_TRUE(r3.has_value());
  EXPECT_TRUE(*r3 == atRoot);
  // Exactly touching and receding at lo (an exit): not lo, but the next entry.
  expectRootNear(gm::firstEntry(c, Real(fd<Real>(0.375)), hi), 0.625, 4);
}

TYPED_TEST(FirstEntry, EveryDegree) {
  using Real = TypeParam;
  const Real lo = 0, hi = 1;
  // Degree 0: constant gaps never enter.
  EXPECT_FALSE(gm::firstEntry(coefficients<Real>(1, 0, 0, 0, 0), lo, hi));
  EXPECT_FALSE(gm::firstEntry(coefficients<Real>(-1, 0, 0, 0, 0), lo, hi));
  EXPECT_FALSE(gm::firstEntry(coefficients<Real>(0, 0, 0, 0, 0), lo, hi));
  // Degree 1.
  expectRootNear(gm::firstEntry(coefficients<Real>(1, -2, 0, 0, 0), lo, hi), 0.5, 0);
  EXPECT_FALSE(gm::firstEntry(coefficients<Real>(-1, 2, 0, 0, 0), lo, hi));    // an exit
  EXPECT_FALSE(gm::firstEntry(coefficients<Real>(1, -0.5, 0, 0, 0), lo, hi));  // after hi
  // Reaching 0 exactly at hi while approaching is an entry at hi.
  expectRootNear(gm::firstEntry(coefficients<Real>(1, -1, 0, 0, 0), lo, hi), 1.0, 0);
  // Degree 2, no linear term.
  expectRootNear(gm::firstEntry(coefficients<Real>(1, 0, -4, 0, 0), lo, hi), 0.5, 2);
  // Degree 3: -(t - 1/4)(t - 1/2)(t - 2) is positive before 1/4.
  expectRootNear(gm::firstEntry(fromRoots<Real>(-1, {0.25, 0.5, 2}), lo, hi), 0.25, 4);
  // Degree 4 with a pair of complex roots: (t - 0.75)(t - 3)(t^2 + 1).
  {
    auto c = fromRoots<Real>(1, {0.75, 3});
    // multiply by t^2 + 1
    std::array<Real, 5> d{};
    for (int i = 0; i <= 2; ++i) {
      d[i] = d[i] + c[i];
      d[i + 2] = d[i + 2] + c[i];
    }
    expectRootNear(gm::firstEntry(d, lo, hi), 0.75, 4);
  }
  // Leading zeros below a non-zero lower term.
  expectRootNear(gm::firstEntry(coefficients<Real>(0.25, 0, -1, 0, 0), lo, hi), 0.5, 2);
}

TYPED_TEST(FirstEntry, TouchesAreNotEntries) {
  using Real = TypeParam;
  const Real lo = 0, hi = 1;
  // Tangential touch at 1/2: g = (t - 1/2)^2 >= 0.
  EXPECT_FALSE(gm::firstEntry(fromRoots<Real>(1, {0.5, 0.5}), lo, hi));
  // Tangential touch at hi.
  EXPECT_FALSE(gm::firstEntry(fromRoots<Real>(1, {1, 1}), lo, hi));
  // Tangential touch of a quartic: (t - 1/2)^2 (t^2 + 1).
  EXPECT_FALSE(gm::firstEntry(coefficients<Real>(0.25, -1, 1.25, -1, 1), lo, hi));
  // A near miss and a shallow overlap around the same point.
  EXPECT_FALSE(gm::firstEntry(coefficients<Real>(0.25 + 0x1p-20, -1, 1, 0, 0), lo, hi));
  expectRootNear(gm::firstEntry(coefficients<Real>(0.25 - 0x1p-20, -1, 1, 0, 0), lo, hi), 0.5 - 0x1p-10, 4);
  // An inflection that crosses: -(t - 1/2)^3 goes from > 0 to < 0 through a flat point.
  expectRootNear(gm::firstEntry(fromRoots<Real>(-1, {0.5, 0.5, 0.5}), lo, hi), 0.5, 0);
  // Reaching 0 at hi with zero slope and going negative after: (1 - t)^3.
  expectRootNear(gm::firstEntry(fromRoots<Real>(-1, {1, 1, 1}), lo, hi), 1.0, 0);
}

TYPED_TEST(FirstEntry, NearDoubleRootsGiveTheFirst) {
  using Real = TypeParam;
  // Two roots 2^-30 (about 1e-9) apart, placed where Real resolves the dip between them: the
  // dip is (2^-31)^2 * 12 deep, which must exceed the rounding of g there.
  double base = 0.5;
  double gap = 0x1p-30;
  if constexpr (std::is_same_v<Real, float>) {
    base = 0x1p-6;
    gap = 0x1p-14;
  } else if constexpr (std::is_same_v<Real, double>) {
    base = 0x1p-10;
  } else if constexpr (std::is_same_v<Real, long double>) {
    base = 0x1p-8;
  }
  const auto c = fromRoots<Real>(1, {base, base + gap, 3, 4});
  const auto r = gm::firstEntry(c, Real(0), Real(1));
  expectRootNear(r, base, 4);
  ASSERT_TRUE(r.has_value());
  EXPECT_LT(*r, fd<Real>(base + gap / 2));
  // Rejecting it gives nothing before 1: the second root is an exit.
  EXPECT_FALSE(gm::firstEntry(c, Real(0), Real(1), [&](const Real& t) { return t > fd<Real>(base + gap / 2); }));
  // Mirrored: overlapping before the pair, so the second root of the pair is the entry.
  const auto mirrored = fromRoots<Real>(1, {base, base + gap, 3});
  expectRootNear(gm::firstEntry(mirrored, Real(0), Real(1)), base + gap, 4);
}

TYPED_TEST(FirstEntry, EmptyAndDegenerateWindows) {
  using Real = TypeParam;
  const auto c = fromRoots<Real>(1, {0.25, 0.75});
  EXPECT_FALSE(gm::firstEntry(c, Real(1), Real(0)));                          // hi < lo
  EXPECT_FALSE(gm::firstEntry(c, Real(fd<Real>(0.1)), Real(fd<Real>(0.1))));  // apart at lo = hi
  const Real inside = fd<Real>(0.3);
  const auto r = gm::firstEntry(c, inside, inside);  // overlapping and approaching at lo = hi
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(*r == inside);
}

// Gaps of a falling ball near a circle, as circleTimeOfImpact forms them: from just touching (the
// ball has just bounced off it) to 10^-3 away, slow and fast, leaving and closing, over the
// horizons the board uses.
template <class Real>
struct NearCircleGap {
  std::array<Real, 5> c;
  Real hi;
};
template <class Real>
NearCircleGap<Real> nearCircleGap(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  const double reach = 0.75, gravity = 25;
  const double angle = 3.14159 * unit(rng),
               gapAway = std::ldexp(std::abs(unit(rng)), -int(10 + 30 * std::abs(unit(rng))));
  const double speed = std::ldexp(std::abs(unit(rng)), -int(8 * std::abs(unit(rng))));
  const double heading = 3.14159 * unit(rng);
  const double limit = 0.05 * std::abs(unit(rng)) + 1e-4;
  const Real dx = fd<Real>((reach + gapAway) * std::cos(angle)), dy = fd<Real>((reach + gapAway) * std::sin(angle));
  const Real vx = fd<Real>(speed * std::cos(heading)), vy = fd<Real>(speed * std::sin(heading));
  const Real ay = fd<Real>(gravity), r = fd<Real>(reach);
  return {{Real(dx * dx + dy * dy - r * r), Real(Real(2) * (dx * vx + dy * vy)), Real(vx * vx + vy * vy + dy * ay),
           Real(vy * ay), Real(ay * ay / Real(4))},
          fd<Real>(limit)};
}

// The bounds that settle gaps before the derivative cascade (detail::noEntryByBounds) must give
// exactly the cascade's answer, on near-circle gaps. Fixed seed 23, so the run repeats.
TYPED_TEST(FirstEntryWide, BoundsAnswerAsTheCascadeDoes) {
  using Real = TypeParam;
  std::mt19937_64 rng(23);
  int settledByBounds = 0, entries = 0;
  const int cases = 4000;
  for (int k = 0; k < cases; ++k) {
    const auto [c, hi] = nearCircleGap<Real>(rng);
    const gm::detail::Quartic<Real> g(c);
    const Real gLo = g.value(Real(0));
    if (gLo <= 0 && g.slope(Real(0)) < 0) continue;  // an entry at 0: decided before either
    const auto all = [](const Real&) { return true; };
    const std::optional<Real> cascade = gm::detail::entryByCascade(g, Real(0), hi, gLo, all);
    const std::optional<Real> got = gm::firstEntry(c, Real(0), hi);
    ASSERT_EQ(got.has_value(), cascade.has_value()) << "case " << k;
    if (got) {
      EXPECT_TRUE(*got == *cascade) << "case " << k;
      ++entries;
    }
    settledByBounds += gm::detail::noEntryByBounds(g, hi, gLo) ? 1 : 0;
  }
  // Both kinds are common enough that the comparison means something.
  EXPECT_GT(settledByBounds, cases / 10);
  EXPECT_GT(entries, cases / 10);
}

// Quartic::value answers from plain Horner wherever that settles the sign: it must give the
// sign and the zeros of compensated Horner everywhere, the roots' neighbourhoods included, where
// plain Horner's rounding is as large as g. Near-circle gaps, seed 29; the points: the window's
// ends, 16 random ones, and each entry with the values of Real on either side of it.
TYPED_TEST(FirstEntryWide, ValueHasTheSignOfCompensatedHorner) {
  using Real = TypeParam;
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> share(0, 1);
  int points = 0, plain = 0, nearRoots = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto [c, hi] = nearCircleGap<Real>(rng);
    const gm::detail::Quartic<Real> g(c);
    std::vector<Real> at{Real(0), hi};
    for (int i = 0; i < 16; ++i) at.push_back(Real(hi * fd<Real>(share(rng))));
    if (const std::optional<Real> entry = gm::firstEntry(c, Real(0), hi); entry && Real(0) < *entry) {
      const Real ulp = ulpOf(*entry);
      for (int i = -2; i <= 2; ++i) at.push_back(Real(*entry + Real(i) * ulp));
      ++nearRoots;
    }
    for (const Real& t : at) {
      const Real quick = g.value(t), exact = g.compensatedValue(t);
      ASSERT_EQ(quick > 0, exact > 0) << "case " << k << " t " << gizmo::toDouble(t);
      ASSERT_EQ(quick == 0, exact == 0) << "case " << k << " t " << gizmo::toDouble(t);
      plain += quick == exact ? 0 : 1;  // differing bits: plain Horner answered
      ++points;
    }
  }
  EXPECT_GT(nearRoots, 400);
  std::cout << "[ value ] " << gizmo::scalarName<Real>() << ": " << points << " points, " << plain
            << " answered by plain Horner with other bits than compensated Horner\n";
}

// An entry is the last value of Real before the crossing: g > 0 there and <= 0 at the next value
// up (compensated Horner, the most accurate evaluation at hand). And it does not depend on where
// the search starts: solveEntry from any start inside a bracket of the crossing ends on it.
TYPED_TEST(FirstEntryWide, EntryIsTheLastValueBeforeTheCrossingFromAnyStart) {
  using Real = TypeParam;
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> share(0, 1);
  int entries = 0, bracketed = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto [c, hi] = nearCircleGap<Real>(rng);
    const gm::detail::Quartic<Real> g(c);
    const std::optional<Real> entry = gm::firstEntry(c, Real(0), hi);
    if (!entry || !(Real(0) < *entry) || g.compensatedValue(*entry) == 0) continue;
    const Real ulp = ulpOf(*entry);
    ASSERT_GT(g.compensatedValue(*entry), 0) << "case " << k;
    ASSERT_LE(g.compensatedValue(Real(*entry + ulp)), 0) << "case " << k;
    ++entries;
    // A bracket a thousandth of the entry wide on either side, where g crosses once.
    const Real a = *entry * fd<Real>(0.999), b = *entry * fd<Real>(1.001);
    if (!(g.value(a) > 0 && g.value(b) < 0 && g.slope(a) < 0 && g.slope(b) < 0)) continue;
    ++bracketed;
    const auto value = [&g](const Real& t) -> Real { return g.value(t); };
    const auto slope = [&g](const Real& t) -> Real { return g.slope(t); };
    const Real fb = g.value(b);
    ASSERT_TRUE(gm::detail::solveEntry(value, slope, a, b, fb) == *entry) << "case " << k << ", from the midpoint";
    for (int i = 0; i < 8; ++i) {
      const Real start = Real(a + Real(b - a) * fd<Real>(share(rng)));
      ASSERT_TRUE(gm::detail::solveEntry(value, slope, a, b, fb, std::optional<Real>(start)) == *entry)
          << "case " << k << ", from " << gizmo::toDouble(start);
    }
  }
  EXPECT_GT(entries, 400);
  EXPECT_GT(bracketed, 200);
}

// Many polynomials from random dyadic roots (exact coefficients, exact signs at dyadic points):
// the expected first accepted entry follows from counting roots.
TYPED_TEST(FirstEntryWide, RandomDyadicPolynomials) {
  using Real = TypeParam;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> grid(-64, 3 * 64);  // multiples of 1/64 in [-1, 3]
  std::uniform_int_distribution<int> degreeOf(1, 4);
  std::uniform_int_distribution<int> coin(0, 1);
  double worstUlps = 0;
  int entriesChecked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int degree = degreeOf(rng);
    std::vector<double> roots;
    while (static_cast<int>(roots.size()) < degree) {
      const double r = grid(rng) / 64.0;
      bool distinct = true;
      for (double q : roots) distinct = distinct && std::fabs(q - r) >= 1.0 / 64;
      if (distinct) roots.push_back(r);
    }
    const double scale = (coin(rng) != 0 ? 1.0 : -1.0) * (1 + grid(rng) % 7);
    std::array<Real, 5> c{};
    c[0] = fd<Real>(scale);
    for (int k = 0; k < degree; ++k) {
      const Real root = fd<Real>(roots[k]);
      for (int i = k + 1; i >= 1; --i) c[i] = c[i - 1] - root * c[i];
      c[0] = -root * c[0];
    }
    double lo = grid(rng) / 64.0;
    double hi = grid(rng) / 64.0;
    if (hi < lo) std::swap(lo, hi);
    // Exact signs from the root list (all values below are small dyadics).
    auto signAt = [&](double t) {  // sign of g(t)
      double s = scale;
      for (double r : roots) s *= (t - r);
      return s;
    };
    auto slopeAt = [&](double t) {
      double sum = 0;
      for (std::size_t i = 0; i < roots.size(); ++i) {
        double p = scale;
        for (std::size_t j = 0; j < roots.size(); ++j)
          if (j != i) p *= (t - roots[j]);
        sum += p;
      }
      return sum;
    };
    std::vector<double> candidates;
    if (signAt(lo) <= 0 && slopeAt(lo) < 0) candidates.push_back(lo);
    std::vector<double> sorted = roots;
    std::sort(sorted.begin(), sorted.end());
    for (double r : sorted) {
      if (!(lo < r && r <= hi)) continue;
      const double before = signAt(r - 1.0 / 256);  // roots are at least 1/64 apart
      const double after = signAt(r + 1.0 / 256);
      if (before > 0 && after < 0) candidates.push_back(r);
    }
    // Reject a random subset of the candidates.
    std::vector<double> rejected;
    for (double t : candidates)
      if (coin(rng) != 0) rejected.push_back(t);
    auto accept = [&](const Real& t) {
      for (double q : rejected)
        if (gizmo::toDouble(gizmo::absOf(Real(t - fd<Real>(q)))) < 1e-9) return false;
      return true;
    };
    std::optional<double> expected;
    for (double t : candidates) {
      if (std::find(rejected.begin(), rejected.end(), t) == rejected.end()) {
        expected = t;
        break;
      }
    }
    const auto got = gm::firstEntry(c, fd<Real>(lo), fd<Real>(hi), accept);
    ASSERT_EQ(got.has_value(), expected.has_value())
        << "trial " << trial << " degree " << degree << " lo " << lo << " hi " << hi;
    if (expected) {
      const double ulps = *expected == 0 ? gizmo::toDouble(gizmo::absOf(*got)) : ulpsBetween(*got, *expected);
      worstUlps = std::max(worstUlps, ulps);
      ++entriesChecked;
      ASSERT_LE(ulps, 4.0) << "trial " << trial << " expected " << *expected;
      // Exact coefficients and compensated evaluation: the answer is never past the root.
      ASSERT_LE(*got, fd<Real>(*expected)) << "trial " << trial;
    }
  }
  EXPECT_GT(entriesChecked, 100);
  std::cout << "[ firstEntry ] " << gizmo::scalarName<Real>() << ": " << entriesChecked << " random entries, worst "
            << worstUlps << " ulp\n";
}

// Ball under gravity against a circle: g(t) = |p + v t + a t^2/2 - C|^2 - R^2, coefficients
// formed in Real from double inputs; reference: the same gap evaluated in MPFR at 256 bits.
struct Ballistic {
  double px = 5.3, py = 2.1, vx = 3.7, vy = 12.9, ax = 0.0, ay = 25.0;
  double cx = 5.523, cy = 4.796, r = 0.75;

  template <class Real>
  std::array<Real, 5> quartic() const {
    const Vec2<Real> d(Real(fd<Real>(px) - fd<Real>(cx)), Real(fd<Real>(py) - fd<Real>(cy)));
    const Vec2<Real> v(fd<Real>(vx), fd<Real>(vy));
    const Vec2<Real> a(fd<Real>(ax), fd<Real>(ay));
    const Real radius = fd<Real>(r);
    return {Real(gizmo::dot(d, d) - radius * radius), Real(Real(2) * gizmo::dot(d, v)),
            Real(gizmo::dot(v, v) + gizmo::dot(d, a)), gizmo::dot(v, a), Real(gizmo::dot(a, a) / Real(4))};
  }
  template <class Real>
  Real gap(const Real& t) const {  // straight from the geometry
    const Real x = Real(fd<Real>(px) + fd<Real>(vx) * t + fd<Real>(ax) * t * t / Real(2)) - fd<Real>(cx);
    const Real y = Real(fd<Real>(py) + fd<Real>(vy) * t + fd<Real>(ay) * t * t / Real(2)) - fd<Real>(cy);
    return x * x + y * y - fd<Real>(r) * fd<Real>(r);
  }
};

TYPED_TEST(FirstEntry, BallisticBallAgainstCircle) {
  using Real = TypeParam;
  const Ballistic b;
  const std::vector<MpfrReal> reference = referenceEntries(
      [&](long double t) { return b.gap(t); }, [&](const MpfrReal& t) { return b.gap(t); }, 0.0, 0.5, 20000);
  ASSERT_EQ(reference.size(), 1u);
  const auto got = gm::firstEntry(b.quartic<Real>(), Real(0), Real(fd<Real>(0.5)));
  ASSERT_TRUE(got.has_value());
  const double error = distance(*got, reference[0]);
  // The coefficients are rounded in Real (c0 = |d|^2 - R^2 cancels a little), so allow a few
  // ulps of the root more than for exact coefficients.
  const double eps = gizmo::toDouble(gizmo::epsilonOf<Real>());
  EXPECT_LE(error, 8 * eps * 0.14) << "root " << gizmo::toDouble(*got);
  std::cout << "[ firstEntry ] " << gizmo::scalarName<Real>() << ": ballistic root " << gizmo::toDouble(*got)
            << ", error " << error << " = " << error / (eps * 0.14) << " eps*t\n";
}

// ---------------------------------------------------------------------------------------------
// firstEntrySmooth: a ball against a rotating flipper

// Scenario in doubles: pivot P, ball centre c(t) = c0 + v t + a t^2/2, flipper direction
// u(t) = (cos th(t), sin th(t)) with th(t) = th0 + w t; gap = cross(c(t) - P, u(t)) - R (the
// signed distance from the flipper's line, minus the radius).
struct FlipperScenario {
  double px = 0, py = 0, cx = 0, cy = 0, vx = 0, vy = 0, ax = 0, ay = 0, th0 = 0, w = 0, r = 0;

  // A scenario where, at tStar, the ball sits at `along` along the flipper and `offset` off its
  // line, with gap slope `slope` and (if slope == 0) gap curvature `curvature`.
  static FlipperScenario make(double tStar, double thStar, double w, double along, double offset, double r,
                              double slope, double curvature, double ay) {
    FlipperScenario s;
    const double ux = std::cos(thStar), uy = std::sin(thStar);
    const double mx = uy, my = -ux;  // cross(m, u) = 1
    const double dx = along * ux + offset * mx, dy = along * uy + offset * my;
    // g' = cross(c', u) + w along; g'' = cross(a, u) + 2 w cross(c', n) - w^2 offset.
    const double crossAu = 0.0 * uy - ay * ux;
    const double gamma = (curvature - crossAu + w * w * offset) / (2 * w);
    const double cdx = (slope - w * along) * mx + gamma * ux;
    const double cdy = (slope - w * along) * my + gamma * uy;
    s.ay = ay;
    s.vx = cdx;
    s.vy = cdy - ay * tStar;
    s.cx = dx - s.vx * tStar;
    s.cy = dy - s.vy * tStar - 0.5 * ay * tStar * tStar;
    s.th0 = thStar - w * tStar;
    s.w = w;
    s.r = r;
    return s;
  }

  long double sampled(long double t) const {
    const long double x = cx + vx * t + ax * t * t / 2 - px;
    const long double y = cy + vy * t + ay * t * t / 2 - py;
    const long double th = th0 + w * t;
    return x * std::sin(th) - y * std::cos(th) - r;
  }
  MpfrReal exact(const MpfrReal& t) const {
    const MpfrReal x = MpfrReal(cx) + MpfrReal(vx) * t + MpfrReal(ax) * t * t / 2 - MpfrReal(px);
    const MpfrReal y = MpfrReal(cy) + MpfrReal(vy) * t + MpfrReal(ay) * t * t / 2 - MpfrReal(py);
    const MpfrReal th = MpfrReal(th0) + MpfrReal(w) * t;
    return x * sin(th) - y * cos(th) - MpfrReal(r);
  }
};

// The gap of a FlipperScenario in Real, with sinCos, and the bounds firstEntrySmooth needs.
template <class Real>
struct FlipperGap {
  Vec2<Real> pivot, c0, v, a;
  Real th0, w, r;

  explicit FlipperGap(const FlipperScenario& s)
      : pivot(fd<Real>(s.px), fd<Real>(s.py)),
        c0(fd<Real>(s.cx), fd<Real>(s.cy)),
        v(fd<Real>(s.vx), fd<Real>(s.vy)),
        a(fd<Real>(s.ax), fd<Real>(s.ay)),
        th0(fd<Real>(s.th0)),
        w(fd<Real>(s.w)),
        r(fd<Real>(s.r)) {}

  Vec2<Real> centre(const Real& t) const {
    const Real half = t * t / Real(2);
    return c0 + v * t + a * half;
  }
  Vec2<Real> direction(const Real& t) const {
    Real s, c;
    gm::sinCos(Real(th0 + w * t), s, c);
    return Vec2<Real>(c, s);
  }
  Real value(const Real& t) const { return gizmo::cross(Vec2<Real>(centre(t) - pivot), direction(t)) - r; }
  Real slope(const Real& t) const {
    const Vec2<Real> u = direction(t);
    const Vec2<Real> du = Vec2<Real>(-u.y, u.x) * w;
    const Vec2<Real> velocity = v + a * t;
    return gizmo::cross(velocity, u) + gizmo::cross(Vec2<Real>(centre(t) - pivot), du);
  }
  // Bounds on [lo, hi], padded by 2^-20 relative against rounding.
  Real speedBound(const Real& lo, const Real& hi) const {
    return gizmo::length(v) + gizmo::length(a) * gizmo::maxOf(gizmo::absOf(lo), gizmo::absOf(hi));
  }
  Real reachBound(const Real& lo, const Real& hi) const {
    const Real m = lo + (hi - lo) / Real(2);
    return gizmo::length(Vec2<Real>(centre(m) - pivot)) + speedBound(lo, hi) * (hi - lo) / Real(2);
  }
  static Real pad(const Real& x) { return x * fd<Real>(1 + 0x1p-20); }
  Real slopeBound(const Real& lo, const Real& hi) const {
    return pad(speedBound(lo, hi) + gizmo::absOf(w) * reachBound(lo, hi));
  }
  Real curvatureBound(const Real& lo, const Real& hi) const {
    return pad(gizmo::length(a) + Real(2) * gizmo::absOf(w) * speedBound(lo, hi) + w * w * reachBound(lo, hi));
  }
};

template <class Real>
class FirstEntrySmooth : public MpfrAware<Real> {};
TYPED_TEST_SUITE(FirstEntrySmooth, Scalars);

// Tolerance on a root of a gap of size ~1 with slope ~s: the gap's rounding over the slope.
template <class Real>
double rootTolerance(double slope) {
  return 8 * gizmo::toDouble(gizmo::epsilonOf<Real>()) / slope;
}

// A ball falling onto a flipper swinging up: gap slope -5 L/s at the hit, t ~ 0.04 s.
FlipperScenario hitScenario() { return FlipperScenario::make(0.04, 0.3, 15.0, 1.0, 0.25, 0.25, -5.0, 0.0, 25.0); }
// The ball skims the flipper: the gap dips 1e-6 below zero for about 6e-5 s around t = 0.05005.
FlipperScenario dipScenario() {
  return FlipperScenario::make(0.05005, 0.3, 15.0, 1.0, 0.25 - 1e-6, 0.25, 0.0, 2000.0, 0.0);
}

// Solves a scenario with exactly one entry in [0, 0.1] and checks it against the MPFR reference
// to the root tolerance implied by the gap's slope there.
template <class Real>
void expectSingleSmoothEntry(const FlipperScenario& s, double slopeAtEntry, const char* what) {
  const auto reference = referenceEntries([&](long double t) { return s.sampled(t); },
                                          [&](const MpfrReal& t) { return s.exact(t); }, 0.0, 0.1, 100000);
  ASSERT_EQ(reference.size(), 1u);
  const FlipperGap<Real> gap(s);
  gm::SmoothSearchInfo info;
  const auto got = gm::firstEntrySmooth(
      gap, Real(0), Real(fd<Real>(0.1)), [](const Real&) { return true; }, &info);
  ASSERT_TRUE(got.has_value());
  EXPECT_FALSE(info.capped);
  const double error = distance(*got, reference[0]);
  EXPECT_LE(error, rootTolerance<Real>(slopeAtEntry)) << "root " << gizmo::toDouble(*got);
  std::cout << "[ smooth ] " << gizmo::scalarName<Real>() << ": " << what << " at " << gizmo::toDouble(*got)
            << ", error " << error << " s, " << info.evaluations << " evaluations\n";
}

TYPED_TEST(FirstEntrySmooth, FlipperHit) { expectSingleSmoothEntry<TypeParam>(hitScenario(), 5.0, "hit"); }

// At the entry the slope is about sqrt(2 * 1e-6 * 2000) = 0.063.
TYPED_TEST(FirstEntrySmooth, ShortDipIsFound) { expectSingleSmoothEntry<TypeParam>(dipScenario(), 0.063, "dip entry"); }

TEST(FirstEntrySmoothScenario, CoarseSamplingMissesTheDip) {
  // What makes ShortDipIsFound meaningful: 1000 evenly spaced samples never see the overlap.
  const FlipperScenario s = dipScenario();
  for (int i = 0; i <= 1000; ++i) ASSERT_GT(s.sampled(0.1L * i / 1000), 0) << "sample " << i;
}

// Two entries 3.7e-3 s apart: g = (s - A)(s - B), s = cos(th0 + w t), A = 1 - 2^-12,
// B = 1 - 2^-13; s rises through A (entry), through B (exit), peaks, falls through B (entry) and A
// (exit).
template <class Real>
struct CosinePairGap {
  Real th0 = fd<Real>(-0.5), w = fd<Real>(10), lowA = fd<Real>(1 - 0x1p-12), lowB = fd<Real>(1 - 0x1p-13);
  Real cosine(const Real& t, Real* sine = nullptr) const {
    Real s, c;
    gm::sinCos(Real(th0 + w * t), s, c);
    if (sine != nullptr) *sine = s;
    return c;
  }
  Real value(const Real& t) const {
    const Real c = cosine(t);
    return (c - lowA) * (c - lowB);
  }
  Real slope(const Real& t) const {
    Real s;
    const Real c = cosine(t, &s);
    return -w * s * (Real(2) * c - lowA - lowB);
  }
  Real slopeBound(const Real&, const Real&) const { return w * Real(3); }
  Real curvatureBound(const Real&, const Real&) const { return w * w * Real(5); }
};

long double cosinePairSampled(long double t) {
  const long double c = std::cos(-0.5L + 10 * t);
  return (c - (1 - 0x1p-12L)) * (c - (1 - 0x1p-13L));
}
MpfrReal cosinePairExact(const MpfrReal& t) {
  const MpfrReal c = cos(MpfrReal(-0.5) + MpfrReal(10) * t);
  return (c - MpfrReal(1 - 0x1p-12)) * (c - MpfrReal(1 - 0x1p-13));
}

TYPED_TEST(FirstEntrySmooth, TwoCloseEntries) {
  using Real = TypeParam;
  const auto reference = referenceEntries(cosinePairSampled, cosinePairExact, 0.0, 0.1, 100000);
  ASSERT_EQ(reference.size(), 2u);
  EXPECT_LT(distance(reference[1], reference[0]), 4e-3);
  const CosinePairGap<Real> gap;
  const Real lo = 0, hi = fd<Real>(0.1);
  // At the entries g' = c' (c - A) + c' (c - B) with c - A or c - B zero: the root is where
  // c(t) = cos(th(t)) meets A or B, c' ~ w sin(th) ~ 0.2; c has a rounding error of about eps.
  const double tolerance = 8 * gizmo::toDouble(gizmo::epsilonOf<Real>()) / 0.15;
  const auto first = gm::firstEntrySmooth(gap, lo, hi);
  ASSERT_TRUE(first.has_value());
  EXPECT_LE(distance(*first, reference[0]), tolerance);
  std::vector<double> offered;
  const auto second = gm::firstEntrySmooth(gap, lo, hi, [&](const Real& t) {
    offered.push_back(gizmo::toDouble(t));
    return offered.size() > 1;
  });
  ASSERT_TRUE(second.has_value());
  EXPECT_LE(distance(*second, reference[1]), tolerance);
  ASSERT_EQ(offered.size(), 2u);
  EXPECT_LT(offered[0], offered[1]);
  std::cout << "[ smooth ] " << gizmo::scalarName<Real>() << ": close entries at " << gizmo::toDouble(*first) << " and "
            << gizmo::toDouble(*second) << ", errors " << distance(*first, reference[0]) << " and "
            << distance(*second, reference[1]) << " s\n";
  // Rejecting both leaves nothing: the crossings between are exits.
  EXPECT_FALSE(gm::firstEntrySmooth(gap, lo, hi, [](const Real&) { return false; }));
}

TYPED_TEST(FirstEntrySmooth, StartsTouchingAndApproaching) {
  using Real = TypeParam;
  const FlipperScenario s = hitScenario();
  const FlipperGap<Real> gap(s);
  // Slightly past the hit: overlapping and still approaching -> lo itself.
  const Real lo = fd<Real>(0.041);
  const auto got = gm::firstEntrySmooth(gap, lo, Real(fd<Real>(0.1)));
  ASSERT_TRUE(got.has_value());
  EXPECT_TRUE(*got == lo);
}

TYPED_TEST(FirstEntrySmooth, NearMissHasNoEntry) {
  using Real = TypeParam;
  // Like the dip, but the ball stays 1e-6 clear.
  const FlipperScenario s = FlipperScenario::make(0.05005, 0.3, 15.0, 1.0, 0.25 + 1e-6, 0.25, 0.0, 2000.0, 0.0);
  const FlipperGap<Real> gap(s);
  gm::SmoothSearchInfo info;
  EXPECT_FALSE(gm::firstEntrySmooth(
      gap, Real(0), Real(fd<Real>(0.1)), [](const Real&) { return true; }, &info));
  EXPECT_FALSE(info.capped);
  EXPECT_LT(info.evaluations, 5000);
}

TYPED_TEST(FirstEntrySmooth, EvaluationCapGivesAnEarlyAnswer) {
  using Real = TypeParam;
  const FlipperScenario s = dipScenario();
  const auto reference = referenceEntries([&](long double t) { return s.sampled(t); },
                                          [&](const MpfrReal& t) { return s.exact(t); }, 0.0, 0.1, 100000);
  ASSERT_EQ(reference.size(), 1u);
  const FlipperGap<Real> gap(s);
  for (long cap : {1L, 5L, 20L, 50L}) {
    gm::SmoothSearchInfo info;
    info.maxEvaluations = cap;
    const auto got = gm::firstEntrySmooth(
        gap, Real(0), Real(fd<Real>(0.1)), [](const Real&) { return true; }, &info);
    ASSERT_TRUE(got.has_value()) << "cap " << cap;
    EXPECT_TRUE(info.capped) << "cap " << cap;
    EXPECT_GE(info.evaluations, cap);
    // Conservative: never after the true entry.
    EXPECT_LE(offset(*got, reference[0]), 0.0) << "cap " << cap;
    EXPECT_GE(*got, Real(0));
  }
}

}  // namespace
