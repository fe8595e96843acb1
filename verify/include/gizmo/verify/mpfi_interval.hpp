#pragma once
// An interval over MPFR numbers (MPFI) at a precision chosen at run time, with the interface of
// Interval (interval.hpp), so that one certification kernel serves both: the double intervals
// first, then this at 128, 256, … bits for the decisions they could not settle. MPFI rounds each
// bound outwards itself; it needs no rounding mode of the processor.
#include <mpfi.h>

#include <utility>

namespace gizmo::verify {

class MpfiInterval {
 public:
  // The precision of every MpfiInterval made from now on, on this thread (bits).
  static void setWorkingBits(long bits) { bits_() = bits; }
  static long workingBits() { return bits_(); }

  MpfiInterval() {
    mpfi_init2(v_, bits_());
    mpfi_set_si(v_, 0);
  }
  explicit MpfiInterval(double x) {
    mpfi_init2(v_, bits_());
    mpfi_set_d(v_, x);
  }
  MpfiInterval(double lo, double hi) {
    mpfi_init2(v_, bits_());
    mpfi_interv_d(v_, lo, hi);
  }
  MpfiInterval(const MpfiInterval& o) {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_set(v_, o.v_);
  }
  MpfiInterval(MpfiInterval&& o) noexcept {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_swap(v_, o.v_);
  }
  MpfiInterval& operator=(const MpfiInterval& o) {
    if (this != &o) {
      mpfi_set_prec(v_, mpfi_get_prec(o.v_));
      mpfi_set(v_, o.v_);
    }
    return *this;
  }
  MpfiInterval& operator=(MpfiInterval&& o) noexcept {
    mpfi_swap(v_, o.v_);
    return *this;
  }
  ~MpfiInterval() { mpfi_clear(v_); }

  friend MpfiInterval operator+(const MpfiInterval& a, const MpfiInterval& b) { return op(mpfi_add, a, b); }
  friend MpfiInterval operator-(const MpfiInterval& a, const MpfiInterval& b) { return op(mpfi_sub, a, b); }
  friend MpfiInterval operator*(const MpfiInterval& a, const MpfiInterval& b) { return op(mpfi_mul, a, b); }
  friend MpfiInterval operator/(const MpfiInterval& a, const MpfiInterval& b) {
    if (mpfi_has_zero(b.v_)) return whole();  // as Interval: a divisor that may be 0 says nothing
    return op(mpfi_div, a, b);
  }
  friend MpfiInterval operator-(const MpfiInterval& a) {
    MpfiInterval r;
    mpfi_neg(r.v_, a.v_);
    return r;
  }
  MpfiInterval& operator+=(const MpfiInterval& b) { return *this = *this + b; }
  MpfiInterval& operator-=(const MpfiInterval& b) { return *this = *this - b; }
  MpfiInterval& operator*=(const MpfiInterval& b) { return *this = *this * b; }

  friend MpfiInterval square(const MpfiInterval& x) {
    MpfiInterval r;
    mpfi_sqr(r.v_, x.v_);
    return r;
  }
  friend MpfiInterval sqrt(const MpfiInterval& x) {
    // Negative members have no root and are dropped, as in Interval.
    MpfiInterval clipped = x;
    if (mpfr_sgn(&clipped.v_->left) < 0) mpfr_set_zero(&clipped.v_->left, 1);
    if (mpfr_sgn(&clipped.v_->right) < 0) mpfr_set_zero(&clipped.v_->right, 1);
    MpfiInterval r;
    mpfi_sqrt(r.v_, clipped.v_);
    return r;
  }

  // MPFI encloses π, sin and cos rigorously at the working precision (outward rounding), over
  // any interval argument.
  static MpfiInterval pi() {
    MpfiInterval r;
    mpfi_const_pi(r.v_);
    return r;
  }
  friend MpfiInterval sin(const MpfiInterval& x) {
    MpfiInterval r;
    mpfi_sin(r.v_, x.v_);
    return r;
  }
  friend MpfiInterval cos(const MpfiInterval& x) {
    MpfiInterval r;
    mpfi_cos(r.v_, x.v_);
    return r;
  }
  friend void sinCos(const MpfiInterval& x, MpfiInterval& sine, MpfiInterval& cosine) {
    sine = sin(x);
    cosine = cos(x);
  }

  static MpfiInterval whole() {
    MpfiInterval r;
    mpfr_set_inf(&r.v_->left, -1);
    mpfr_set_inf(&r.v_->right, 1);
    return r;
  }
  friend MpfiInterval hull(const MpfiInterval& a, const MpfiInterval& b) {
    MpfiInterval r;
    mpfi_union(r.v_, a.v_, b.v_);
    return r;
  }
  friend MpfiInterval intersect(const MpfiInterval& a, const MpfiInterval& b) {
    MpfiInterval r;
    mpfi_intersect(r.v_, a.v_, b.v_);
    return r;
  }
  friend MpfiInterval lowerEnd(const MpfiInterval& x) {
    MpfiInterval r;
    mpfi_set_fr(r.v_, &x.v_->left);
    return r;
  }
  friend MpfiInterval upperEnd(const MpfiInterval& x) {
    MpfiInterval r;
    mpfi_set_fr(r.v_, &x.v_->right);
    return r;
  }
  friend MpfiInterval midpoint(const MpfiInterval& x) {
    mpfr_t m;
    mpfr_init2(m, bits_());
    mpfi_mid(m, x.v_);
    MpfiInterval r;
    mpfi_set_fr(r.v_, m);  // exact: m has the working precision
    mpfr_clear(m);
    return r;
  }
  friend double widthUpper(const MpfiInterval& x) {
    mpfr_t w;
    mpfr_init2(w, 64);
    mpfr_sub(w, &x.v_->right, &x.v_->left, MPFR_RNDU);
    const double d = mpfr_get_d(w, MPFR_RNDU);
    mpfr_clear(w);
    return d;
  }

  friend bool certainlyPositive(const MpfiInterval& x) { return mpfr_sgn(&x.v_->left) > 0; }
  friend bool certainlyNegative(const MpfiInterval& x) { return mpfr_sgn(&x.v_->right) < 0; }
  friend bool isExactZero(const MpfiInterval& x) { return mpfr_zero_p(&x.v_->left) && mpfr_zero_p(&x.v_->right); }
  friend bool certainlyBefore(const MpfiInterval& a, const MpfiInterval& b) {
    return mpfr_less_p(&a.v_->right, &b.v_->left);
  }
  friend bool certainlyNotAfter(const MpfiInterval& a, const MpfiInterval& b) {
    return mpfr_lessequal_p(&a.v_->right, &b.v_->left);
  }
  friend double lowerDouble(const MpfiInterval& x) { return mpfr_get_d(&x.v_->left, MPFR_RNDD); }
  friend double upperDouble(const MpfiInterval& x) { return mpfr_get_d(&x.v_->right, MPFR_RNDU); }

  mpfi_srcptr raw() const { return v_; }

 private:
  template <class F>
  static MpfiInterval op(F f, const MpfiInterval& a, const MpfiInterval& b) {
    MpfiInterval r;
    f(r.v_, a.v_, b.v_);
    return r;
  }
  static long& bits_() {
    thread_local long bits = 128;
    return bits;
  }

  mpfi_t v_;
};

}  // namespace gizmo::verify
