// ExactDyadic (core/src/exact_dyadic.hpp), which decides the board check's geometry exactly in
// both builds, against GMP's rationals on the predicates' own shapes: differences of doubles
// multiplied to degree four, compared. And π rounded to each hardware float, against Boost.
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <random>

#include "../../core/src/exact_dyadic.hpp"
#include "gizmo/core/math/scalar.hpp"

namespace gizmo {
namespace {

using detail::ExactDyadic;

// A double of a random magnitude (2^-60 … 2^60, now and then subnormal or zero), random sign.
double randomDouble(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 19);
  std::uniform_real_distribution<double> unit(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  const double sign = rng() % 2 ? -1.0 : 1.0;
  switch (kind(rng)) {
    case 0: return 0.0;
    case 1: return sign * std::ldexp(unit(rng), -1070);  // subnormal
    case 2: return sign * std::ldexp(unit(rng), 900);
    case 3: return sign * std::ldexp(std::round(unit(rng) * 8), -2);  // a gizmo vertex: quarters
    default: return sign * std::ldexp(unit(rng), exponent(rng));
  }
}

int signOf(const Rational& r) { return r.sign(); }

TEST(ExactDyadic, AgreesWithRationalsOnDegreeFourPredicates) {
  const std::uint64_t seed = 20261201;
  std::mt19937_64 rng(seed);
  SCOPED_TRACE("seed " + std::to_string(seed));
  for (int trial = 0; trial < 20000; ++trial) {
    double v[8];
    for (double& x : v) x = randomDouble(rng);
    // c = (b − a)(q − a') − (b' − a')(p − a), then c·c against r·r·(d·d): segmentCloserThan's shape.
    const ExactDyadic e[8] = {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
    const Rational q[8] = {Rational(v[0]), Rational(v[1]), Rational(v[2]), Rational(v[3]),
                           Rational(v[4]), Rational(v[5]), Rational(v[6]), Rational(v[7])};
    const ExactDyadic ec = (e[1] - e[0]) * (e[3] - e[2]) - (e[5] - e[4]) * (e[6] - e[0]);
    const Rational qc = (q[1] - q[0]) * (q[3] - q[2]) - (q[5] - q[4]) * (q[6] - q[0]);
    ASSERT_EQ(ec.sign(), signOf(qc)) << "trial " << trial;
    const ExactDyadic left = ec * ec, right = e[7] * e[7] * (e[1] * e[1] + e[2] * e[2]);
    const Rational qLeft = qc * qc, qRight = q[7] * q[7] * (q[1] * q[1] + q[2] * q[2]);
    ASSERT_EQ(left < right, qLeft < qRight) << "trial " << trial;
    ASSERT_EQ(left <= right, qLeft <= qRight) << "trial " << trial;
    ASSERT_EQ(left > right, qLeft > qRight) << "trial " << trial;
    ASSERT_EQ(left >= right, qLeft >= qRight) << "trial " << trial;
  }
}

TEST(ExactDyadic, SeesTheSmallestDifferences) {
  const double a = 0.1, next = std::nextafter(0.1, 1.0);
  EXPECT_EQ((ExactDyadic(next) - ExactDyadic(a)).sign(), 1);
  EXPECT_EQ((ExactDyadic(a) - ExactDyadic(a)).sign(), 0);
  // (1 + 2^-52)² − 1 − 2^-51 = 2^-104, far below a double's rounding of it.
  const ExactDyadic one(1.0), ulp(std::ldexp(1.0, -52));
  const ExactDyadic x = one + ulp;
  EXPECT_EQ((x * x - one - ExactDyadic(std::ldexp(1.0, -51))).sign(), 1);
  EXPECT_TRUE(x * x - one - ExactDyadic(std::ldexp(1.0, -51)) <= ExactDyadic(std::ldexp(1.0, -104)));
  EXPECT_TRUE(x * x - one - ExactDyadic(std::ldexp(1.0, -51)) >= ExactDyadic(std::ldexp(1.0, -104)));
  EXPECT_EQ((ExactDyadic(-0.0) - ExactDyadic(0.0)).sign(), 0);
  EXPECT_THROW(ExactDyadic(std::nan("")), std::domain_error);
}

// The portable build has no Boost: its π for the hardware floats must be the one the full build
// had from Boost's constants, or every flipper's log would change.
TEST(PiOf, IsBoostsConstantInEveryHardwareFloat) {
  EXPECT_EQ(piOf<float>(), boost::math::constants::pi<float>());
  EXPECT_EQ(piOf<double>(), boost::math::constants::pi<double>());
  EXPECT_EQ(piOf<long double>(), boost::math::constants::pi<long double>());
}

}  // namespace
}  // namespace gizmo
