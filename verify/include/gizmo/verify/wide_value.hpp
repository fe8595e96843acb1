#pragma once
// A value of any ladder scalar held exactly (or, for a rational, to 512 bits), so that the
// difference between two runs' numbers can be taken before anything rounds it: a bin100 run and
// an mpfr:256 run differ around 1e-100, far below what a double difference could show.
#include <mpfr.h>

#include "gizmo/core/math/scalar.hpp"

namespace gizmo::verify {

class WideValue {
 public:
  // Wide enough for every binary scalar of the ladder (bin100 has 334 bits) and for mpfr:BITS
  // up to this many bits; wider MPFR values and rationals are rounded to it.
  static constexpr mpfr_prec_t kBits = 512;

  WideValue() {
    mpfr_init2(v_, kBits);
    mpfr_set_zero(v_, 1);
  }
  ~WideValue() { mpfr_clear(v_); }
  WideValue(const WideValue& o) {
    mpfr_init2(v_, kBits);
    mpfr_set(v_, o.v_, MPFR_RNDN);
  }
  WideValue& operator=(const WideValue& o) {
    mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }

  template <class Real>
  static WideValue of(const Real& x) {
    WideValue w;
    if constexpr (std::is_same_v<Real, MpfrReal>) {
      mpfr_set(w.v_, x.backend().data(), MPFR_RNDN);
    } else if constexpr (std::is_same_v<Real, Rational>) {
      mpfr_set_q(w.v_, x.backend().data(), MPFR_RNDN);
    } else {
      // A binary float is the sum of the doubles that its leading bits round to, each taken
      // off exactly (the remainder has fewer significant bits than Real each time).
      Real rest = x;
      for (int i = 0; i < 8 && rest != Real(0); ++i) {
        const double part = static_cast<double>(rest);
        mpfr_add_d(w.v_, w.v_, part, MPFR_RNDN);
        rest = rest - Real(part);
      }
    }
    return w;
  }

  // |a − b|, rounded to a double only at the end.
  friend double distance(const WideValue& a, const WideValue& b) {
    WideValue d;
    mpfr_sub(d.v_, a.v_, b.v_, MPFR_RNDN);
    return std::fabs(mpfr_get_d(d.v_, MPFR_RNDN));
  }
  // The Euclidean distance between (ax, ay) and (bx, by).
  friend double distance(const WideValue& ax, const WideValue& ay, const WideValue& bx, const WideValue& by) {
    WideValue dx, dy;
    mpfr_sub(dx.v_, ax.v_, bx.v_, MPFR_RNDN);
    mpfr_sub(dy.v_, ay.v_, by.v_, MPFR_RNDN);
    mpfr_hypot(dx.v_, dx.v_, dy.v_, MPFR_RNDN);
    return mpfr_get_d(dx.v_, MPFR_RNDN);
  }
  double toDouble() const { return mpfr_get_d(v_, MPFR_RNDN); }

 private:
  mpfr_t v_;
};

}  // namespace gizmo::verify
