// ExactDyadic's arithmetic: schoolbook, on 32-bit limbs. The board check's numbers have a few
// limbs (a ball centre's 53 bits, gizmo vertices of a few bits), so nothing cleverer pays.
#include "exact_dyadic.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "gizmo/core/std_compat.hpp"

namespace gizmo::detail {
namespace {

using Limbs = std::vector<std::uint32_t>;

void trimTop(Limbs& m) {
  while (!m.empty() && m.back() == 0) m.pop_back();
}

// m · 2^shift.
Limbs shiftedLeft(const Limbs& m, std::uint64_t shift) {
  const std::size_t whole = static_cast<std::size_t>(shift / 32);
  const unsigned bits = static_cast<unsigned>(shift % 32);
  Limbs out(whole, 0);
  out.reserve(whole + m.size() + 1);
  std::uint32_t carry = 0;
  for (std::uint32_t limb : m) {
    out.push_back(bits ? (limb << bits) | carry : limb);
    carry = bits ? limb >> (32 - bits) : 0;
  }
  if (carry) out.push_back(carry);
  return out;
}

// -1, 0 or 1 as a < b, a == b or a > b (magnitudes without zero top limbs).
int compareMagnitudes(const Limbs& a, const Limbs& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

Limbs addMagnitudes(const Limbs& a, const Limbs& b) {
  const Limbs& longer = a.size() >= b.size() ? a : b;
  const Limbs& shorter = a.size() >= b.size() ? b : a;
  Limbs out(longer.size() + 1, 0);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < longer.size(); ++i) {
    carry += std::uint64_t{longer[i]} + (i < shorter.size() ? shorter[i] : 0);
    out[i] = static_cast<std::uint32_t>(carry);
    carry >>= 32;
  }
  out[longer.size()] = static_cast<std::uint32_t>(carry);
  trimTop(out);
  return out;
}

// a − b for a ≥ b.
Limbs subtractMagnitudes(const Limbs& a, const Limbs& b) {
  Limbs out(a.size(), 0);
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int64_t d = std::int64_t{a[i]} - (i < b.size() ? b[i] : 0) - borrow;
    borrow = d < 0;
    if (d < 0) d += std::int64_t{1} << 32;
    out[i] = static_cast<std::uint32_t>(d);
  }
  trimTop(out);
  return out;
}

}  // namespace

ExactDyadic::ExactDyadic(bool negative, Limbs limbs, std::int64_t exponent)
    : negative_(negative), limbs_(std::move(limbs)), exponent_(exponent) {
  trimTop(limbs_);
  if (limbs_.empty()) {
    negative_ = false;
    exponent_ = 0;
    return;
  }
  // Make the magnitude odd, so that every value has one form and stays as short as it can.
  std::size_t zeroLimbs = 0;
  while (limbs_[zeroLimbs] == 0) ++zeroLimbs;
  const unsigned bits = static_cast<unsigned>(std::countr_zero(limbs_[zeroLimbs]));
  if (zeroLimbs == 0 && bits == 0) return;
  Limbs odd(limbs_.size() - zeroLimbs, 0);
  for (std::size_t i = zeroLimbs; i < limbs_.size(); ++i) {
    const std::uint64_t pair = limbs_[i] | (i + 1 < limbs_.size() ? std::uint64_t{limbs_[i + 1]} << 32 : 0);
    odd[i - zeroLimbs] = static_cast<std::uint32_t>(pair >> bits);
  }
  trimTop(odd);
  limbs_ = std::move(odd);
  exponent_ += 32 * static_cast<std::int64_t>(zeroLimbs) + bits;
}

ExactDyadic::ExactDyadic(double v) {
  if (!std::isfinite(v)) throw std::domain_error("ExactDyadic: not a finite number");
  const std::uint64_t bits = gizmo::bitCast<std::uint64_t>(v);
  const std::uint64_t field = (bits >> 52) & 0x7FF;
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  const std::uint64_t m = field == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
  const std::int64_t e = field == 0 ? -1074 : static_cast<std::int64_t>(field) - 1075;
  *this = ExactDyadic(bits >> 63 != 0, Limbs{static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(m >> 32)}, e);
}

ExactDyadic ExactDyadic::sum(const ExactDyadic& a, const ExactDyadic& b, bool negateB) {
  const bool bNegative = negateB ? !b.negative_ : b.negative_;
  if (b.limbs_.empty()) return a;
  if (a.limbs_.empty()) return ExactDyadic(bNegative, b.limbs_, b.exponent_);
  // Both on the smaller exponent: the other magnitude moves left by the difference.
  const std::int64_t e = std::min(a.exponent_, b.exponent_);
  const Limbs x = shiftedLeft(a.limbs_, static_cast<std::uint64_t>(a.exponent_ - e));
  const Limbs y = shiftedLeft(b.limbs_, static_cast<std::uint64_t>(b.exponent_ - e));
  if (a.negative_ == bNegative) return ExactDyadic(a.negative_, addMagnitudes(x, y), e);
  const int order = compareMagnitudes(x, y);
  if (order == 0) return ExactDyadic();
  return order > 0 ? ExactDyadic(a.negative_, subtractMagnitudes(x, y), e)
                   : ExactDyadic(bNegative, subtractMagnitudes(y, x), e);
}

ExactDyadic operator+(const ExactDyadic& a, const ExactDyadic& b) { return ExactDyadic::sum(a, b, false); }
ExactDyadic operator-(const ExactDyadic& a, const ExactDyadic& b) { return ExactDyadic::sum(a, b, true); }

ExactDyadic operator*(const ExactDyadic& a, const ExactDyadic& b) {
  if (a.limbs_.empty() || b.limbs_.empty()) return ExactDyadic();
  Limbs out(a.limbs_.size() + b.limbs_.size(), 0);
  for (std::size_t i = 0; i < a.limbs_.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.limbs_.size(); ++j) {
      carry += std::uint64_t{a.limbs_[i]} * b.limbs_[j] + out[i + j];
      out[i + j] = static_cast<std::uint32_t>(carry);
      carry >>= 32;
    }
    out[i + b.limbs_.size()] = static_cast<std::uint32_t>(carry);
  }
  return ExactDyadic(a.negative_ != b.negative_, std::move(out), a.exponent_ + b.exponent_);
}

}  // namespace gizmo::detail
