#pragma once
// What differs between the scalars of the precision ladder, in one place. Generic code calls
// these instead of std:: functions so that float, double, long double, float128 and MPFR all
// work; Boost types with expression templates need explicit types, so never write
// `auto x = a * b` in generic code.
#include <cmath>
#include <limits>
#include <string>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>

namespace gizmo {

// MPFR at a precision chosen at run time. Expression templates are off: the simulator's generic
// code then reads like plain arithmetic and cannot keep a dangling expression by accident.
using MpfrReal = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>,
                                               boost::multiprecision::et_off>;
using Float128 = boost::multiprecision::float128;

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

template <class Real>
inline const Real& minOf(const Real& a, const Real& b) { return b < a ? b : a; }
template <class Real>
inline const Real& maxOf(const Real& a, const Real& b) { return a < b ? b : a; }

// The unit roundoff of the type (for MPFR: of the current default precision).
template <class Real>
inline Real epsilonOf() { return std::numeric_limits<Real>::epsilon(); }
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

// π rounded to the type; never computed through libm.
template <class Real>
inline Real piOf() { return boost::math::constants::pi<Real>(); }
template <>
inline MpfrReal piOf<MpfrReal>() {
  MpfrReal p;
  mpfr_const_pi(p.backend().data(), MPFR_RNDN);
  return p;
}

template <class Real>
inline double toDouble(const Real& x) { return static_cast<double>(x); }

template <class Real>
inline Real fromDouble(double d) { return Real(d); }  // exact: every ladder type holds a double

template <class Real> std::string scalarName();
template <> inline std::string scalarName<float>() { return "float"; }
template <> inline std::string scalarName<double>() { return "double"; }
template <> inline std::string scalarName<long double>() { return "long-double"; }
template <> inline std::string scalarName<Float128>() { return "float128"; }
template <> inline std::string scalarName<MpfrReal>() {
  return "mpfr:" + std::to_string(mpfrBits());
}

}  // namespace gizmo
