#pragma once
// What differs between the scalars of the precision ladder, in one place. Generic code calls
// these instead of std:: functions so that every scalar of the ladder works: float, double,
// long double, float128, cpp_bin_float 50 and 100, MPFR, and exact rationals. Boost types with
// expression templates need explicit types, so never write `auto x = a * b` in generic code.
//
// The portable build (CMake option GIZMO_PORTABLE, docs/determinism.md) has the hardware floats
// only, float, double and long double, and needs no Boost.Multiprecision, GMP, MPFR or quadmath,
// so that it compiles for any CPU and for WebAssembly. GIZMO_HAS_MULTIPRECISION says which build
// this is; what needs those libraries is inside `#if GIZMO_HAS_MULTIPRECISION`.
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#ifdef GIZMO_PORTABLE
#define GIZMO_HAS_MULTIPRECISION 0
#else
#define GIZMO_HAS_MULTIPRECISION 1
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/gmp.hpp>
#include <boost/multiprecision/mpfr.hpp>
#endif

namespace gizmo {

// Whether the scalar computes without rounding (then there are no error terms to recover and
// no tolerance is ever needed). Only the rationals do.
template <class Real>
inline constexpr bool kExactScalar = false;

// An exact run needed a value that is not rational. `what` says which, in words.
class IrrationalValue : public std::runtime_error {
 public:
  explicit IrrationalValue(const std::string& what) : std::runtime_error(what) {}
};

template <class Real>
inline Real sqrtOf(const Real& x) {
  using std::sqrt;
  return sqrt(x);  // IEEE 754 rounds sqrt exactly; Boost's types find theirs by ADL
}

template <class Real>
inline Real absOf(const Real& x) {
  using std::abs;
  return abs(x);
}

// By value for the hardware floats, so that the compiler selects with minsd/maxsd rather than a
// branch on a comparison that is often a coin toss; by reference for the library types, whose
// copies cost. Either way the same operand is chosen.
template <class Real>
using ChosenOf = std::conditional_t<std::is_floating_point_v<Real>, Real, const Real&>;
template <class Real>
inline ChosenOf<Real> minOf(const Real& a, const Real& b) {
  return b < a ? b : a;
}
template <class Real>
inline ChosenOf<Real> maxOf(const Real& a, const Real& b) {
  return a < b ? b : a;
}

// The unit roundoff of the type (for MPFR: of the current default precision): 2^(1 - digits), the
// gap between 1 and the next value of a format with `digits` significand bits. That is what
// numeric_limits::epsilon() gives for the IEEE formats, but not for ppc64el's double-double
// long double, where GCC gives the smallest subnormal (1 plus it is a double-double), which
// would make every tolerance built on it zero; halving from 1 is exact in every format.
template <class Real>
inline Real epsilonOf() {
  static const Real epsilon = [] {
    Real e(1);
    for (int bit = 1; bit < std::numeric_limits<Real>::digits; ++bit) e /= 2;
    return e;
  }();
  return epsilon;
}

// π rounded to the type; never computed through libm. For the hardware floats the compiler
// rounds this literal (more digits than any of their formats holds) to long double, and the
// cast rounds that once more: π's bits are nowhere near a tie at 24, 53, 64 or 113 bits, so the
// result is π correctly rounded (a unit test compares it with Boost's constants).
template <class Real>
inline Real piOf() {
  static_assert(std::is_floating_point_v<Real>, "the multiprecision scalars have their own piOf");
  return static_cast<Real>(3.14159265358979323846264338327950288419716939937510582097494459230781640628620899863L);
}

template <class Real>
inline double toDouble(const Real& x) {
  return static_cast<double>(x);
}

template <class Real>
inline Real fromDouble(double d) {
  return Real(d);
}  // exact: every ladder type holds a double

template <class Real>
std::string scalarName();
template <>
inline std::string scalarName<float>() {
  return "float";
}
template <>
inline std::string scalarName<double>() {
  return "double";
}
template <>
inline std::string scalarName<long double>() {
  return "long-double";
}

// The binary format of a hardware floating-point type, as the replay log names it. The same
// scalar name means different formats on different machines (long double is x87's 80-bit
// extended format on x86, IEEE binary128 on aarch64, riscv64, s390x and wasm32, a pair of
// doubles on ppc64el), and a log is only replayed where its format is the one computed.
template <class Real>
constexpr const char* hardwareFormatOf() {
  using L = std::numeric_limits<Real>;
  static_assert(std::is_floating_point_v<Real> && L::radix == 2, "a binary hardware floating-point type");
  if constexpr (L::is_iec559 && L::digits == 24 && L::max_exponent == 128) return "binary32";
  else if constexpr (L::is_iec559 && L::digits == 53 && L::max_exponent == 1024) return "binary64";
  else if constexpr (L::digits == 64 && L::max_exponent == 16384) return "x87-extended80";
  else if constexpr (L::digits == 113 && L::max_exponent == 16384) return "binary128";
  else if constexpr (L::digits == 106 && L::max_exponent == 1024) return "double-double";
  else static_assert(L::digits == 0, "a floating-point format the replay log has no name for");
}

// The exact format of a scalar's values: the hardware format, or the library's name for the
// others (whose scalar name already says their precision).
template <class Real>
inline std::string scalarFormat() {
  if constexpr (std::is_floating_point_v<Real>) return hardwareFormatOf<Real>();
  else return scalarName<Real>();
}

#if GIZMO_HAS_MULTIPRECISION

// MPFR at a precision chosen at run time. Expression templates are off: the simulator's generic
// code then reads like plain arithmetic and cannot keep a dangling expression by accident.
using MpfrReal =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off>;
using Float128 = boost::multiprecision::float128;
// Boost's own binary floats of 50 and 100 decimal digits (168 and 334 bits), expression templates
// off for the same reason.
using Bin50 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>, boost::multiprecision::et_off>;
using Bin100 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<100>, boost::multiprecision::et_off>;
// Exact rationals (GMP's mpq). A run in rationals is exact for as long as every value it needs is
// rational; the first one that is not (a square root that is not a perfect square, π) throws
// IrrationalValue, so that an exact run never silently becomes an approximate one.
using Rational = boost::multiprecision::number<boost::multiprecision::gmp_rational, boost::multiprecision::et_off>;

template <>
inline constexpr bool kExactScalar<Rational> = true;

// A rational for a message: its value to 17 digits and how long its numerator and denominator
// are (an exact run's numbers can have thousands of digits).
inline std::string approximately(const Rational& x) {
  const mpq_srcptr q = x.backend().data();
  char value[40];
  std::snprintf(value, sizeof value, "%.17g", x.convert_to<double>());
  return std::string(value) + " (a rational of " + std::to_string(mpz_sizeinbase(mpq_numref(q), 10)) + "/" +
         std::to_string(mpz_sizeinbase(mpq_denref(q), 10)) + " digits)";
}

// A rational's square root is rational exactly when its numerator and denominator (in lowest
// terms) are perfect squares.
template <>
inline Rational sqrtOf<Rational>(const Rational& x) {
  const mpq_srcptr q = x.backend().data();
  if (mpq_sgn(q) < 0) throw IrrationalValue("the square root of a negative number");
  if (!mpz_perfect_square_p(mpq_numref(q)) || !mpz_perfect_square_p(mpq_denref(q)))
    throw IrrationalValue("the square root of " + approximately(x) + ", not a perfect square");
  Rational root;
  mpz_sqrt(mpq_numref(root.backend().data()), mpq_numref(q));
  mpz_sqrt(mpq_denref(root.backend().data()), mpq_denref(q));
  return root;  // already in lowest terms: the roots of coprime squares are coprime
}

template <>
inline Rational epsilonOf<Rational>() {
  return Rational(0);
}
// Bits of a freshly made MpfrReal: the precision the current thread computes with.
inline long mpfrBits() {
  MpfrReal probe;
  return static_cast<long>(mpfr_get_prec(probe.backend().data()));
}
// Selects the MPFR precision for this thread's new values, in bits (Boost counts decimal digits;
// we round up so that at least `bits` bits are kept).
inline void setMpfrBits(long bits) {
  MpfrReal::default_precision(static_cast<unsigned>((bits * 30103L + 99999L) / 100000L));
}
template <>
inline MpfrReal epsilonOf<MpfrReal>() {
  MpfrReal one = 1;
  return boost::multiprecision::ldexp(one, static_cast<int>(1 - mpfrBits()));
}

template <>
inline Float128 piOf<Float128>() {
  return boost::math::constants::pi<Float128>();
}
template <>
inline Bin50 piOf<Bin50>() {
  return boost::math::constants::pi<Bin50>();
}
template <>
inline Bin100 piOf<Bin100>() {
  return boost::math::constants::pi<Bin100>();
}
template <>
inline MpfrReal piOf<MpfrReal>() {
  MpfrReal p;
  mpfr_const_pi(p.backend().data(), MPFR_RNDN);
  return p;
}

template <>
inline Rational piOf<Rational>() {
  throw IrrationalValue("π (the angle of a swinging flipper)");
}

template <>
inline std::string scalarName<Float128>() {
  return "float128";
}
template <>
inline std::string scalarName<Bin50>() {
  return "bin50";
}
template <>
inline std::string scalarName<Bin100>() {
  return "bin100";
}
template <>
inline std::string scalarName<Rational>() {
  return "rational";
}
template <>
inline std::string scalarName<MpfrReal>() {
  return "mpfr:" + std::to_string(mpfrBits());
}
// Boost's float128 is __float128: IEEE binary128.
template <>
inline std::string scalarFormat<Float128>() {
  return "binary128";
}

#endif  // GIZMO_HAS_MULTIPRECISION

}  // namespace gizmo
