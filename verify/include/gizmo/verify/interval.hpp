#pragma once
// A closed interval [lo, hi] over double, for certified decisions. Every operation returns an
// interval that holds every exact result of the operation on members of its operands.
//
// Rounding: the processor's rounding mode is set to upward ONCE, by an UpwardRounding scope,
// around a whole batch of interval work; no operation switches the mode. An upper bound is then
// the plain operation (rounded up); a lower bound is the negated upper bound of the negated
// operands (−((−a) − b) is a + b rounded down). The core's own double code must never run
// inside such a scope: it is written for round-to-nearest.
//
// Compile every translation unit that includes this header with -frounding-math: without it the
// compiler may fold −((−a) − b) back into a + b, or evaluate constants at compile time in
// round-to-nearest, and the bounds would silently stop being bounds.
#include <algorithm>
#include <cfenv>
#include <cmath>
#include <limits>

#if defined(__GNUC__) && !defined(__clang__) && !defined(__ROUNDING_MATH__)
#error "interval.hpp needs -frounding-math on this translation unit (see the comment above)"
#endif

namespace gizmo::verify {

// Rounds upward for its lifetime; puts the previous mode back when it ends.
class UpwardRounding {
 public:
  UpwardRounding() : previous_(std::fegetround()) { std::fesetround(FE_UPWARD); }
  ~UpwardRounding() { std::fesetround(previous_); }
  UpwardRounding(const UpwardRounding&) = delete;
  UpwardRounding& operator=(const UpwardRounding&) = delete;

 private:
  int previous_;
};

// Only valid inside an UpwardRounding scope.
class Interval {
 public:
  Interval() = default;
  explicit Interval(double x) : lo_(x), hi_(x) {}
  Interval(double lo, double hi) : lo_(lo), hi_(hi) {}

  double lower() const { return lo_; }
  double upper() const { return hi_; }

  friend Interval operator+(const Interval& a, const Interval& b) {
    return Interval(-((-a.lo_) - b.lo_), a.hi_ + b.hi_);
  }
  friend Interval operator-(const Interval& a, const Interval& b) { return Interval(-(b.hi_ - a.lo_), a.hi_ - b.lo_); }
  friend Interval operator-(const Interval& a) { return Interval(-a.hi_, -a.lo_); }
  friend Interval operator*(const Interval& a, const Interval& b) {
    // Upper: the largest of the four end products rounded up. Lower: the smallest, as minus the
    // largest of the products with one factor negated (each rounded up).
    const double hi = std::max(std::max(a.lo_ * b.lo_, a.lo_ * b.hi_), std::max(a.hi_ * b.lo_, a.hi_ * b.hi_));
    const double nlo =
        std::max(std::max((-a.lo_) * b.lo_, (-a.lo_) * b.hi_), std::max((-a.hi_) * b.lo_, (-a.hi_) * b.hi_));
    return Interval(-nlo, hi);
  }
  friend Interval operator/(const Interval& a, const Interval& b) {
    if (b.lo_ <= 0 && 0 <= b.hi_) return whole();  // the divisor may be 0: nothing is known
    const double hi = std::max(std::max(a.lo_ / b.lo_, a.lo_ / b.hi_), std::max(a.hi_ / b.lo_, a.hi_ / b.hi_));
    const double nlo =
        std::max(std::max((-a.lo_) / b.lo_, (-a.lo_) / b.hi_), std::max((-a.hi_) / b.lo_, (-a.hi_) / b.hi_));
    return Interval(-nlo, hi);
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }
  Interval& operator*=(const Interval& b) { return *this = *this * b; }

  // x², tighter than x·x when x holds 0 (the two factors are the same number).
  friend Interval square(const Interval& x) {
    if (0 <= x.lo_) return Interval(-((-x.lo_) * x.lo_), x.hi_ * x.hi_);
    if (x.hi_ <= 0) return Interval(-((-x.hi_) * x.hi_), x.lo_ * x.lo_);
    return Interval(0, std::max(x.lo_ * x.lo_, x.hi_ * x.hi_));
  }
  // √x over the non-negative part of x (negative members have no root and are dropped).
  friend Interval sqrt(const Interval& x) {
    const double hi = std::sqrt(std::max(x.hi_, 0.0));
    double lo = std::sqrt(std::max(x.lo_, 0.0));
    // sqrt rounded up equals the exact root only when its square (rounded up) gives x back;
    // otherwise the next double down lies below the root.
    if (lo * lo != std::max(x.lo_, 0.0)) lo = std::nextafter(lo, 0.0);
    return Interval(lo, hi);
  }

  // π lies strictly between these neighbouring doubles (0x1.921fb54442d18p+1 is the nearest, below).
  static Interval pi() { return Interval(0x1.921fb54442d18p+1, 0x1.921fb54442d19p+1); }

  static Interval whole() {
    const double inf = std::numeric_limits<double>::infinity();
    return Interval(-inf, inf);
  }
  friend Interval hull(const Interval& a, const Interval& b) {
    return Interval(std::min(a.lo_, b.lo_), std::max(a.hi_, b.hi_));
  }
  friend Interval intersect(const Interval& a, const Interval& b) {
    return Interval(std::max(a.lo_, b.lo_), std::min(a.hi_, b.hi_));
  }
  friend Interval lowerEnd(const Interval& x) { return Interval(x.lo_); }
  friend Interval upperEnd(const Interval& x) { return Interval(x.hi_); }
  // A representable point of x, in the middle as far as rounding allows.
  friend Interval midpoint(const Interval& x) { return Interval(x.lo_ + (x.hi_ - x.lo_) * 0.5); }
  // An upper bound of hi − lo.
  friend double widthUpper(const Interval& x) { return x.hi_ - x.lo_; }

  friend bool certainlyPositive(const Interval& x) { return 0 < x.lo_; }
  friend bool certainlyNegative(const Interval& x) { return x.hi_ < 0; }
  friend bool isExactZero(const Interval& x) { return x.lo_ == 0 && x.hi_ == 0; }
  // Every member of a is below (at most) every member of b.
  friend bool certainlyBefore(const Interval& a, const Interval& b) { return a.hi_ < b.lo_; }
  friend bool certainlyNotAfter(const Interval& a, const Interval& b) { return a.hi_ <= b.lo_; }
  // Bounds as doubles, rounded outwards (already doubles here).
  friend double lowerDouble(const Interval& x) { return x.lo_; }
  friend double upperDouble(const Interval& x) { return x.hi_; }

 private:
  double lo_ = 0, hi_ = 0;
};

}  // namespace gizmo::verify
