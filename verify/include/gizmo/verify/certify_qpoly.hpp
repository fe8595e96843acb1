#pragma once
// Polynomials with exact rational coefficients (GMP's mpq through Boost.Multiprecision, the
// core's Rational), for proving ties exactly: a greatest common divisor, and Sturm sequences that
// count distinct real roots between two rationals. The degrees met are small (≤ 8), so plain
// Euclid over the rationals is fast enough and needs no care about coefficient growth.
#include <vector>

#include "gizmo/core/math/scalar.hpp"

namespace gizmo::verify::detail {

// Coefficients, the constant first; the leading one is never 0 (the zero polynomial is empty).
using QPoly = std::vector<Rational>;

void trim(QPoly& p);
QPoly product(const QPoly& a, const QPoly& b);
Rational valueAt(const QPoly& p, const Rational& x);
// The monic greatest common divisor (empty when both are 0).
QPoly gcdOf(QPoly a, QPoly b);

// p, p′, then the negated remainders: the sign changes along it count distinct real roots.
class SturmChain {
 public:
  explicit SturmChain(const QPoly& p);
  // The number of distinct real roots in (a, b]; a < b and p(a) ≠ 0.
  int rootsIn(const Rational& a, const Rational& b) const;

 private:
  int signChangesAt(const Rational& x) const;
  std::vector<QPoly> chain_;
};

}  // namespace gizmo::verify::detail
