// sinCos against MPFR's own correctly rounded sin and cos, for every scalar of the ladder.
#include "gizmo/core/math/trig.hpp"
#include "support/scalar_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <mpfr.h>

namespace {

using gizmo::Float128;
using gizmo::MpfrReal;

// An mpfr_t that cleans up after itself.
class Big {
 public:
  explicit Big(long bits) { mpfr_init2(v_, static_cast<mpfr_prec_t>(bits)); }
  ~Big() { mpfr_clear(v_); }
  Big(const Big&) = delete;
  Big& operator=(const Big&) = delete;
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }

 private:
  mpfr_t v_;
};

// Exact conversions of each scalar into an MPFR value that is wide enough.
void assign(Big& dst, float x) { mpfr_set_flt(dst.get(), x, MPFR_RNDN); }
void assign(Big& dst, double x) { mpfr_set_d(dst.get(), x, MPFR_RNDN); }
void assign(Big& dst, long double x) { mpfr_set_ld(dst.get(), x, MPFR_RNDN); }
void assign(Big& dst, const Float128& x) {
  const std::array<double, 3> d = gizmo::test::splitFloat128(x);
  mpfr_set_d(dst.get(), d[0], MPFR_RNDN);
  mpfr_add_d(dst.get(), dst.get(), d[1], MPFR_RNDN);
  mpfr_add_d(dst.get(), dst.get(), d[2], MPFR_RNDN);
}
void assign(Big& dst, const MpfrReal& x) { mpfr_set(dst.get(), x.backend().data(), MPFR_RNDN); }
// cpp_bin_float: the doubles its leading bits round to, each taken off exactly.
template <class Real>
requires std::is_same_v<Real, gizmo::Bin50> || std::is_same_v<Real, gizmo::Bin100>
void assign(Big& dst, const Real& x) {
  mpfr_set_zero(dst.get(), 1);
  Real rest = x;
  for (int i = 0; i < 8 && rest != 0; ++i) {
    const double part = static_cast<double>(rest);
    mpfr_add_d(dst.get(), dst.get(), part, MPFR_RNDN);
    rest = rest - Real(part);
  }
}

template <class Real>
long precisionBits() {
  if constexpr (std::is_same_v<Real, MpfrReal>) {
    return gizmo::mpfrBits();
  } else {
    return std::numeric_limits<Real>::digits;
  }
}

// |computed - truth| in units of the last place of truth at `bits` bits.
double ulpError(const Big& truth, const Big& computed, long bits, long work) {
  if (mpfr_zero_p(truth.get())) return mpfr_zero_p(computed.get()) ? 0.0 : 1e300;
  Big diff(work);
  mpfr_sub(diff.get(), computed.get(), truth.get(), MPFR_RNDN);
  mpfr_abs(diff.get(), diff.get(), MPFR_RNDN);
  const mpfr_exp_t e = mpfr_get_exp(truth.get());  // truth = m 2^e, 1/2 <= |m| < 1
  mpfr_mul_2si(diff.get(), diff.get(), static_cast<long>(bits - e), MPFR_RNDN);
  return mpfr_get_d(diff.get(), MPFR_RNDN);
}

// Points of [-2, 2] worth checking: the special ones, both sides of the reduction threshold,
// around pi/2 and pi/4, and many random ones with all bits of Real in use.
template <class Real>
std::vector<Real> samplePoints(int randomCount) {
  std::vector<Real> xs;
  const Real eps = gizmo::epsilonOf<Real>();
  const Real one = 1;
  const Real halfPi = gizmo::piOf<Real>() / Real(2);
  const Real quarterPi = gizmo::piOf<Real>() / Real(4);
  for (double d : {0.0, 1e-30, 1e-20, 1e-10, 1e-5, 1e-3, 0.1, 0.5, 0.78, 0.7800000001, 1.0, 1.5, 1.9999999, 2.0}) {
    xs.push_back(gizmo::fromDouble<Real>(d));
  }
  for (int k = -20; k <= 20; ++k) {
    const Real factor = one + Real(k) * eps;
    xs.push_back(halfPi * factor);
    xs.push_back(quarterPi * factor);
    xs.push_back(gizmo::fromDouble<Real>(0.78) * factor);
  }
  xs.push_back(Real(2) * (one - eps));
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> coarse(0.0, 2.0);
  std::uniform_real_distribution<double> fine(-1.0, 1.0);
  for (int i = 0; i < randomCount; ++i) {
    // The second part fills the bits below a double's for the wide scalars.
    Real x =
        gizmo::fromDouble<Real>(coarse(rng)) + gizmo::fromDouble<Real>(fine(rng)) * gizmo::fromDouble<Real>(0x1p-53);
    if (x > Real(2)) x = Real(2);
    if (x < Real(0)) x = -x;
    xs.push_back(x);
  }
  // Small arguments at every scale.
  for (int i = 0; i < randomCount / 10; ++i) {
    const double scale = std::ldexp(1.0, -static_cast<int>(i % 60));
    xs.push_back(gizmo::fromDouble<Real>(coarse(rng) * scale));
  }
  std::vector<Real> all;
  for (const Real& x : xs) {
    all.push_back(x);
    all.push_back(-x);
  }
  return all;
}

template <class Real>
class SinCosTest : public gizmo::test::MpfrAware<Real> {};
TYPED_TEST_SUITE(SinCosTest, gizmo::test::Scalars);

template <class Real>
int randomCountFor() {
  if constexpr (std::is_same_v<Real, MpfrReal>) return 1500;
  if constexpr (std::is_same_v<Real, Float128>) return 4000;
  if constexpr (std::is_same_v<Real, gizmo::Bin50> || std::is_same_v<Real, gizmo::Bin100>) return 600;
  return 12000;
}

// The bound every scalar meets; the measured worst cases are printed for the record.
constexpr double kMaxUlps = 1.0;

template <class Real>
void checkAgainstMpfr(long truthBits) {
  const long bits = precisionBits<Real>();
  ASSERT_GE(truthBits, bits + 60);
  const std::vector<Real> xs = samplePoints<Real>(randomCountFor<Real>());
  Big bx(truthBits), bs(truthBits), bc(truthBits), gs(truthBits), gc(truthBits);
  double worstSin = 0;
  double worstCos = 0;
  for (const Real& x : xs) {
    Real s;
    Real c;
    gizmo::math::sinCos(x, s, c);
    assign(bx, x);
    mpfr_sin_cos(bs.get(), bc.get(), bx.get(), MPFR_RNDN);
    assign(gs, s);
    assign(gc, c);
    const double es = ulpError(bs, gs, bits, truthBits);
    const double ec = ulpError(bc, gc, bits, truthBits);
    worstSin = std::max(worstSin, es);
    worstCos = std::max(worstCos, ec);
    ASSERT_LE(es, kMaxUlps) << "sin at x = " << gizmo::toDouble(x);
    ASSERT_LE(ec, kMaxUlps) << "cos at x = " << gizmo::toDouble(x);
  }
  std::cout << "[ sinCos ] " << gizmo::scalarName<Real>() << ": " << xs.size() << " points, worst sin " << worstSin
            << " ulp, worst cos " << worstCos << " ulp\n";
}

TYPED_TEST(SinCosTest, WithinOneUlpOfMpfr) { checkAgainstMpfr<TypeParam>(200); }

// Boost's own binary floats, wider than the table of pi/2's parts: their pi/2 comes from MPFR.
TEST(SinCosWide, Bin50AndBin100WithinOneUlpOfMpfr) {
  checkAgainstMpfr<gizmo::Bin50>(300);
  checkAgainstMpfr<gizmo::Bin100>(500);
}

TYPED_TEST(SinCosTest, PythagoreanIdentity) {
  using Real = TypeParam;
  const Real eps = gizmo::epsilonOf<Real>();
  for (const Real& x : samplePoints<Real>(1000)) {
    Real s;
    Real c;
    gizmo::math::sinCos(x, s, c);
    const Real defect = gizmo::absOf(Real(s * s + c * c - Real(1)));
    ASSERT_LE(defect, Real(3) * eps) << "x = " << gizmo::toDouble(x);
  }
}

TYPED_TEST(SinCosTest, OddAndEvenExactly) {
  using Real = TypeParam;
  for (const Real& x : samplePoints<Real>(1000)) {
    Real s1, c1, s2, c2;
    gizmo::math::sinCos(x, s1, c1);
    const Real minusX = -x;
    gizmo::math::sinCos(minusX, s2, c2);
    ASSERT_TRUE(s2 == -s1) << "x = " << gizmo::toDouble(x);
    ASSERT_TRUE(c2 == c1) << "x = " << gizmo::toDouble(x);
  }
}

TYPED_TEST(SinCosTest, SpecialValues) {
  using Real = TypeParam;
  Real s, c;
  gizmo::math::sinCos(Real(0), s, c);
  EXPECT_TRUE(s == Real(0));
  EXPECT_TRUE(c == Real(1));
  // Below sqrt(eps) the cubic term is under half an ulp: sin x rounds to x and cos x to 1.
  const Real tiny = gizmo::fromDouble<Real>(1e-20);
  gizmo::math::sinCos(tiny, s, c);
  EXPECT_TRUE(s == tiny);
  EXPECT_TRUE(c == Real(1));
  // Near pi/2 the cosine is the tiny difference between pi/2 and its rounding: MPFR agrees
  // (checked above); here check its sign and size.
  const Real halfPi = gizmo::piOf<Real>() / Real(2);
  gizmo::math::sinCos(halfPi, s, c);
  EXPECT_TRUE(s == Real(1));
  EXPECT_LT(gizmo::absOf(c), gizmo::epsilonOf<Real>());
}

TYPED_TEST(SinCosTest, Deterministic) {
  using Real = TypeParam;
  const Real x = gizmo::fromDouble<Real>(1.2345678901234567);
  Real s1, c1, s2, c2;
  gizmo::math::sinCos(x, s1, c1);
  gizmo::math::sinCos(x, s2, c2);
  EXPECT_TRUE(s1 == s2);
  EXPECT_TRUE(c1 == c2);
}

// A wider MPFR, where the series needs many more terms.
TEST(SinCosMpfrWide, WithinOneUlpAt300Bits) {
  const unsigned saved = MpfrReal::default_precision();
  gizmo::setMpfrBits(300);
  checkAgainstMpfr<MpfrReal>(500);
  MpfrReal::default_precision(saved);
}

// libm-free double sin/cos also agree with the platform's libm to within its usual accuracy:
// a plain sanity check that the MPFR comparison above is wired correctly.
TEST(SinCosSanity, CloseToLibm) {
  for (double x = -2.0; x <= 2.0; x += 0.001) {
    double s, c;
    gizmo::math::sinCos(x, s, c);
    EXPECT_NEAR(s, std::sin(x), 4e-16);
    EXPECT_NEAR(c, std::cos(x), 4e-16);
  }
}

}  // namespace
