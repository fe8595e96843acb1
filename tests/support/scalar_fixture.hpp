#pragma once
// A typed-test fixture over the scalar ladder that runs MPFR cases at 128 bits and restores the
// thread's MPFR precision afterwards.
#include <gtest/gtest.h>

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

using Scalars = ::testing::Types<float, double, long double, Float128, MpfrReal>;

}  // namespace gizmo::test
