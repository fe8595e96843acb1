#pragma once
// ExactDyadic: a number ±m · 2^e, m an integer of any length, exact under +, − and ×. Every
// finite double is one, so the board check's geometric predicates (polynomials of degree four
// in doubles) are decided without rounding and without a multiprecision library: the same code
// serves the full build and the portable one (docs/determinism.md), which has no GMP.
#include <cstdint>
#include <vector>

namespace gizmo::detail {

class ExactDyadic {
 public:
  ExactDyadic() = default;  // zero
  ExactDyadic(double v);    // NOLINT(google-explicit-constructor): v must be finite; exact

  int sign() const { return limbs_.empty() ? 0 : (negative_ ? -1 : 1); }

  friend ExactDyadic operator+(const ExactDyadic& a, const ExactDyadic& b);
  friend ExactDyadic operator-(const ExactDyadic& a, const ExactDyadic& b);
  friend ExactDyadic operator*(const ExactDyadic& a, const ExactDyadic& b);
  friend bool operator<(const ExactDyadic& a, const ExactDyadic& b) { return (a - b).sign() < 0; }
  friend bool operator>(const ExactDyadic& a, const ExactDyadic& b) { return (a - b).sign() > 0; }
  friend bool operator<=(const ExactDyadic& a, const ExactDyadic& b) { return (a - b).sign() <= 0; }
  friend bool operator>=(const ExactDyadic& a, const ExactDyadic& b) { return (a - b).sign() >= 0; }

 private:
  using Limbs = std::vector<std::uint32_t>;  // the magnitude m, lowest limb first, no zero top limb
  ExactDyadic(bool negative, Limbs limbs, std::int64_t exponent);
  static ExactDyadic sum(const ExactDyadic& a, const ExactDyadic& b, bool negateB);

  bool negative_ = false;
  Limbs limbs_;                // empty for zero
  std::int64_t exponent_ = 0;  // the value is ±limbs_ · 2^exponent_, limbs_ odd (or zero)
};

}  // namespace gizmo::detail
