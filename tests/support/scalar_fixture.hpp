#pragma once
// A typed-test fixture over the scalar ladder that runs MPFR cases at 128 bits and restores the
// thread's MPFR precision afterwards, and a scope that does the same for a block of code.
#include <gtest/gtest.h>

#include <array>
#include <type_traits>

#include "gizmo/core/math/scalar.hpp"

namespace gizmo::test {

template <class Real>
class MpfrAware : public ::testing::Test {
 protected:
  void SetUp() override {
    saved_ = MpfrReal::default_precision();
    if constexpr (std::is_same_v<Real, MpfrReal>) setMpfrBits(128);
  }
  void TearDown() override { MpfrReal::default_precision(saved_); }

 private:
  unsigned saved_ = 0;
};

// Computes with MPFR at `bits` for as long as it lives, then restores the thread's precision.
class ScopedMpfrBits {
 public:
  explicit ScopedMpfrBits(long bits) : saved_(MpfrReal::default_precision()) { setMpfrBits(bits); }
  ~ScopedMpfrBits() { MpfrReal::default_precision(saved_); }
  ScopedMpfrBits(const ScopedMpfrBits&) = delete;
  ScopedMpfrBits& operator=(const ScopedMpfrBits&) = delete;

 private:
  unsigned saved_;
};

using Scalars = ::testing::Types<float, double, long double, Float128, MpfrReal>;

// Three doubles that add up to x exactly: each remainder is exact and narrower than the last.
// Lets tests carry a float128 into MPFR without rounding.
inline std::array<double, 3> splitFloat128(const Float128& x) {
  __float128 q = x.backend().value();
  const double d1 = static_cast<double>(q);
  q -= d1;
  const double d2 = static_cast<double>(q);
  q -= d2;
  return {d1, d2, static_cast<double>(q)};
}

}  // namespace gizmo::test
