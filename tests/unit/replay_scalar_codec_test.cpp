// Scalar encodings: raw bytes, the compact form relative to a base, exact text, for every scalar
// of the ladder. Round trips compare bytes (or mpfr_equal_p plus the sign), so -0 and NaN
// payloads count. Random values come from std::mt19937_64 with kSeed, which each such test traces.
#include "gizmo/replay/scalar_codec.hpp"

#include <gtest/gtest.h>
#include <quadmath.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "gizmo/core/std_compat.hpp"
#include "gizmo/replay/bytes.hpp"
#include "gizmo/replay/format_error.hpp"
#include "support/scalar_fixture.hpp"

namespace {

using gizmo::Float128;
using gizmo::MpfrReal;
using gizmo::replay::ByteReader;
using gizmo::replay::ByteWriter;
using gizmo::replay::exactText;
using gizmo::replay::FormatError;
using gizmo::replay::readScalar;
using gizmo::replay::ScalarCodec;
using gizmo::replay::writeScalar;
using Bytes = std::vector<std::uint8_t>;

constexpr std::uint64_t kSeed = 0x5EED2024;

std::string seedTrace() { return "mt19937_64 seed " + std::to_string(kSeed); }

template <class Real>
Bytes compact(const Real& value, const Real& base) {
  ByteWriter w;
  writeScalar(w, value, base);
  return Bytes(w.bytes().begin(), w.bytes().end());
}

// ---------------------------------------------------------------------------------------------
// Fixed-width types

template <class Real>
class FixedWidthCodec : public ::testing::Test {};
using FixedWidthScalars = ::testing::Types<float, double, long double, Float128>;
TYPED_TEST_SUITE(FixedWidthCodec, FixedWidthScalars);

template <class Real>
using RawBytes = std::array<std::uint8_t, ScalarCodec<Real>::kWidth>;

template <class Real>
RawBytes<Real> raw(const Real& v) {
  return ScalarCodec<Real>::toBytes(v);
}

// Sets the x87 integer bit from the exponent, as arithmetic would (a no-op for IEEE types).
template <class Real>
void canonicalize(RawBytes<Real>& b) {
  if constexpr (std::is_same_v<Real, long double>) {
    const bool normalOrSpecial = ((b[8] | (b[9] << 8)) & 0x7FFF) != 0;
    b[7] = static_cast<std::uint8_t>((b[7] & 0x7F) | (normalOrSpecial ? 0x80 : 0));
  }
}

template <class Real>
Real randomValue(std::mt19937_64& rng) {
  RawBytes<Real> b;
  for (std::uint8_t& byte : b) byte = static_cast<std::uint8_t>(rng());
  canonicalize<Real>(b);
  return ScalarCodec<Real>::fromBytes(b);
}

// `value` with a few of its low significand bytes changed: the sort of base the log sees.
template <class Real>
Real nearbyValue(const Real& value, std::mt19937_64& rng) {
  RawBytes<Real> b = raw(value);
  const std::size_t changed = 1 + rng() % (b.size() / 2);
  for (std::size_t i = 0; i < changed; ++i) b[i] = static_cast<std::uint8_t>(rng());
  canonicalize<Real>(b);
  return ScalarCodec<Real>::fromBytes(b);
}

template <class Real>
std::vector<Real> specialValues() {
  using Limits = std::numeric_limits<Real>;
  const Real one = 1;
  std::vector<Real> out = {Real(0),
                           -Real(0),
                           one,
                           -one,
                           Real(-50),
                           one / Real(20),  // 0.05, correctly rounded in the type
                           Real(1.25),
                           Limits::min(),
                           Limits::denorm_min(),
                           Limits::min() / Real(3),  // an inexact subnormal: many bits set
                           -Limits::denorm_min(),
                           Limits::max(),
                           Limits::lowest(),
                           Limits::infinity(),
                           -Limits::infinity(),
                           Limits::quiet_NaN(),
                           -Limits::quiet_NaN()};
  // A quiet NaN with a payload in its low bytes.
  RawBytes<Real> nan = raw(Limits::quiet_NaN());
  nan[0] = 0xA5;
  nan[1] = 0x5A;
  out.push_back(ScalarCodec<Real>::fromBytes(nan));
  return out;
}

template <class Real>
void expectCompactRoundTrip(const Real& value, const Real& base) {
  const Bytes bytes = compact(value, base);
  ASSERT_GE(bytes.size(), 1u);
  ASSERT_LE(bytes.size(), 1 + ScalarCodec<Real>::kWidth);
  ByteReader r(bytes);
  const Real back = readScalar(r, base);
  EXPECT_EQ(raw(back), raw(value)) << exactText(value) << " against base " << exactText(base);
  EXPECT_TRUE(r.atEnd());
  if (raw(value) == raw(base)) {
    EXPECT_EQ(bytes, Bytes{0xFF});
  }
}

TYPED_TEST(FixedWidthCodec, RawBytesRoundTrip) {
  using Real = TypeParam;
  for (const Real& v : specialValues<Real>()) {
    SCOPED_TRACE(exactText(v));
    EXPECT_EQ(raw(ScalarCodec<Real>::fromBytes(raw(v))), raw(v));
  }
}

TYPED_TEST(FixedWidthCodec, SpecialValuesAgainstVariousBases) {
  using Real = TypeParam;
  const std::vector<Real> values = specialValues<Real>();
  for (const Real& value : values) {
    for (const Real& base : values) expectCompactRoundTrip(value, base);
  }
}

TYPED_TEST(FixedWidthCodec, RandomValuesAgainstVariousBases) {
  using Real = TypeParam;
  SCOPED_TRACE(seedTrace());
  std::mt19937_64 rng(kSeed);
  for (int i = 0; i < 3000; ++i) {
    const Real value = randomValue<Real>(rng);
    expectCompactRoundTrip(value, value);
    expectCompactRoundTrip(value, Real(0));
    expectCompactRoundTrip(value, randomValue<Real>(rng));
    const Real near = nearbyValue(value, rng);
    expectCompactRoundTrip(value, near);
    expectCompactRoundTrip(near, value);
  }
}

TYPED_TEST(FixedWidthCodec, SizesOfTypicalValues) {
  using Real = TypeParam;
  EXPECT_EQ(compact(Real(1.25), Real(1.25)), Bytes{0xFF});
  // A round value keeps only its sign, exponent and top significand bits.
  EXPECT_LE(compact(Real(-50), Real(0)).size(), ScalarCodec<Real>::kWidth <= 8 ? 3u : 4u);
  // Neighbours (same sign and exponent) drop their high bytes: 1 + 1/1024 against 1.
  const Real one = 1;
  EXPECT_LT(compact(one + one / Real(1024), one).size(), 1 + ScalarCodec<Real>::kWidth);
}

TYPED_TEST(FixedWidthCodec, InvalidControlBytesThrow) {
  using Real = TypeParam;
  constexpr std::size_t kWidth = ScalarCodec<Real>::kWidth;
  const Real base = 3;
  auto offsetOfFailure = [&](const Bytes& bytes) -> std::uint64_t {
    ByteReader r(bytes);
    r.u8();  // a byte before the scalar: offsets are relative to the whole buffer
    try {
      readScalar(r, base);
    } catch (const FormatError& e) {
      return e.offset();
    }
    ADD_FAILURE() << "no FormatError";
    return 0;
  };
  auto withPayload = [](std::uint8_t control, std::size_t count, std::uint8_t fill) {
    Bytes b(2 + count, fill);
    b[0] = 0x00;
    b[1] = control;
    return b;
  };
  // lead + trail >= width, in every combination that is not 0xFF.
  for (unsigned lead = 0; lead < 16; ++lead) {
    for (unsigned trail = 0; trail < 16; ++trail) {
      if (lead + trail < kWidth || (lead == 15 && trail == 15)) continue;
      SCOPED_TRACE("lead " + std::to_string(lead) + " trail " + std::to_string(trail));
      EXPECT_EQ(offsetOfFailure(withPayload(static_cast<std::uint8_t>(lead << 4 | trail), 16, 1)), 1u);
    }
  }
  // Zero bytes at either end of the middle part: the control byte should have counted them.
  Bytes lowZero = withPayload(0x00, kWidth, 0x11);
  lowZero[2] = 0;
  EXPECT_EQ(offsetOfFailure(lowZero), 1u);
  Bytes highZero = withPayload(0x00, kWidth, 0x11);
  highZero.back() = 0;
  EXPECT_EQ(offsetOfFailure(highZero), 1u);
  // Truncated middle bytes.
  EXPECT_EQ(offsetOfFailure(withPayload(0x00, kWidth - 1, 0x11)), 2u);
}

TYPED_TEST(FixedWidthCodec, ExactTextReadsBackToTheSameValue) {
  using Real = TypeParam;
  SCOPED_TRACE(seedTrace());
  std::mt19937_64 rng(kSeed);
  std::vector<Real> values = specialValues<Real>();
  for (int i = 0; i < 2000; ++i) values.push_back(randomValue<Real>(rng));
  for (const Real& v : values) {
    const std::string text = exactText(v);
    using std::isnan;
    if (isnan(v)) {
      EXPECT_NE(text.find("nan(0x"), std::string::npos) << text;
      continue;
    }
    Real back;
    if constexpr (std::is_same_v<Real, float>) back = std::strtof(text.c_str(), nullptr);
    if constexpr (std::is_same_v<Real, double>) back = std::strtod(text.c_str(), nullptr);
    if constexpr (std::is_same_v<Real, long double>) back = std::strtold(text.c_str(), nullptr);
    if constexpr (std::is_same_v<Real, Float128>) back = Float128(strtoflt128(text.c_str(), nullptr));
    EXPECT_EQ(raw(back), raw(v)) << text;
  }
}

TEST(ReplayScalarCodec, DoubleBytesAreIeeeLittleEndian) {
  EXPECT_EQ(ScalarCodec<double>::toBytes(1.0), (std::array<std::uint8_t, 8>{0, 0, 0, 0, 0, 0, 0xF0, 0x3F}));
  EXPECT_EQ(ScalarCodec<float>::toBytes(-2.0f), (std::array<std::uint8_t, 4>{0, 0, 0, 0xC0}));
  // x87: significand with explicit integer bit, then sign and exponent 0x3FFF.
  EXPECT_EQ(ScalarCodec<long double>::toBytes(-1.0L),
            (std::array<std::uint8_t, 10>{0, 0, 0, 0, 0, 0, 0, 0x80, 0xFF, 0xBF}));
  std::array<std::uint8_t, 16> one{};
  one[14] = 0xFF;
  one[15] = 0x3F;
  EXPECT_EQ(ScalarCodec<Float128>::toBytes(Float128(1)), one);
}

TEST(ReplayScalarCodec, CompactFormBytes) {
  EXPECT_EQ(compact(1.25, 1.25), Bytes{0xFF});
  // -50 = 0xC049000000000000: six zero bytes at the low end.
  EXPECT_EQ(compact(-50.0, 0.0), (Bytes{0x06, 0x49, 0xC0}));
  // 1 + 2^-52 against 1: one differing byte at the bottom.
  EXPECT_EQ(compact(1.0 + 0x1p-52, 1.0), (Bytes{0x70, 0x01}));
}

TEST(ReplayScalarCodec, NonCanonicalLongDoubleIsRefused) {
  // An "unnormal": exponent 0x3FFF with the integer bit clear. Against base 0 the control byte
  // covers all ten bytes.
  const Bytes b = {0x00, 0x01, 0, 0, 0, 0, 0, 0, 0x40, 0xFF, 0x3F};
  ByteReader r(b);
  EXPECT_THROW(readScalar(r, 0.0L), FormatError);
}

TEST(ReplayScalarCodec, ExactTextSpellings) {
  EXPECT_EQ(exactText(0.1), "0x1.999999999999ap-4");
  EXPECT_EQ(exactText(1.0), "0x1p+0");
  EXPECT_EQ(exactText(-0.0), "-0x0p+0");
  EXPECT_EQ(exactText(0.0), "0x0p+0");
  EXPECT_EQ(exactText(std::numeric_limits<double>::denorm_min()), "0x0.0000000000001p-1022");
  EXPECT_EQ(exactText(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(exactText(0.1f), "0x1.99999ap-4");
  EXPECT_EQ(exactText(0.1L), "0x1.999999999999999ap-4");
  EXPECT_EQ(exactText(Float128("0.1")), "0x1.999999999999999999999999999ap-4");
  EXPECT_EQ(exactText(std::numeric_limits<Float128>::quiet_NaN()), "nan(0x8000000000000000000000000000)");
}

TEST(ReplayScalarCodec, DoubleExactTextMatchesPrintf) {
  SCOPED_TRACE(seedTrace());
  std::mt19937_64 rng(kSeed);
  for (int i = 0; i < 5000; ++i) {
    const double d = gizmo::bitCast<double>(rng());
    if (!std::isfinite(d)) continue;
    char text[64];
    std::snprintf(text, sizeof text, "%a", d);
    EXPECT_EQ(exactText(d), text);
  }
}

// ---------------------------------------------------------------------------------------------
// MPFR

using gizmo::test::ScopedMpfrBits;

// A value using every bit of the current precision (top and bottom bits set), times 2^exponent.
MpfrReal randomMpfr(std::mt19937_64& rng, long exponentRange) {
  const long bits = gizmo::mpfrBits();
  std::vector<std::uint64_t> words(static_cast<std::size_t>((bits + 63) / 64));
  for (std::uint64_t& w : words) w = rng();
  mpz_t m;
  mpz_init(m);
  mpz_import(m, words.size(), -1, sizeof(std::uint64_t), 0, 0, words.data());
  mpz_fdiv_r_2exp(m, m, static_cast<mp_bitcnt_t>(bits));
  mpz_setbit(m, static_cast<mp_bitcnt_t>(bits - 1));
  if (rng() % 2) mpz_setbit(m, 0);
  if (rng() % 2) mpz_neg(m, m);
  MpfrReal x;
  const long exponent = static_cast<long>(rng() % static_cast<std::uint64_t>(2 * exponentRange + 1)) - exponentRange;
  EXPECT_EQ(mpfr_set_z_2exp(x.backend().data(), m, exponent, MPFR_RNDN), 0);
  mpz_clear(m);
  return x;
}

void expectSameMpfr(const MpfrReal& a, const MpfrReal& b) {
  mpfr_srcptr x = a.backend().data();
  mpfr_srcptr y = b.backend().data();
  if (mpfr_nan_p(x)) {
    EXPECT_TRUE(mpfr_nan_p(y));
    return;
  }
  EXPECT_TRUE(mpfr_equal_p(x, y)) << exactText(a) << " vs " << exactText(b);
  EXPECT_EQ(mpfr_signbit(x) != 0, mpfr_signbit(y) != 0) << exactText(a);
}

MpfrReal decode(const Bytes& bytes) {
  ByteReader r(bytes);
  MpfrReal x = readScalar(r, MpfrReal(0));
  EXPECT_TRUE(r.atEnd());
  return x;
}

std::vector<MpfrReal> mpfrSpecialValues() {
  std::vector<MpfrReal> out = {
      MpfrReal(0), -MpfrReal(0), MpfrReal(1), MpfrReal(-50), MpfrReal(1) / MpfrReal(20), gizmo::piOf<MpfrReal>()};
  MpfrReal x;
  mpfr_set_inf(x.backend().data(), 1);
  out.push_back(x);
  mpfr_set_inf(x.backend().data(), -1);
  out.push_back(x);
  mpfr_set_nan(x.backend().data());
  out.push_back(x);
  // The extremes of the exponent range.
  mpfr_set_ui_2exp(x.backend().data(), 1, mpfr_get_emin() - 1, MPFR_RNDN);
  out.push_back(x);
  mpfr_set_ui_2exp(x.backend().data(), 3, mpfr_get_emax() - 2, MPFR_RNDN);
  out.push_back(-x);
  return out;
}

TEST(ReplayMpfrCodec, RoundTripsAtSeveralPrecisions) {
  SCOPED_TRACE(seedTrace());
  std::mt19937_64 rng(kSeed);
  for (long bits : {53L, 113L, 256L}) {
    ScopedMpfrBits precision(bits);
    SCOPED_TRACE("mpfr bits " + std::to_string(gizmo::mpfrBits()));
    std::vector<MpfrReal> values = mpfrSpecialValues();
    for (int i = 0; i < 1000; ++i) values.push_back(randomMpfr(rng, 5000));
    for (const MpfrReal& v : values) {
      const Bytes bytes = compact(v, MpfrReal(7));
      expectSameMpfr(decode(bytes), v);
    }
  }
}

TEST(ReplayMpfrCodec, EncodingDependsOnTheValueOnly) {
  Bytes at53;
  {
    ScopedMpfrBits precision(53);
    at53 = compact(MpfrReal(-50), MpfrReal(0));
  }
  ScopedMpfrBits precision(256);
  EXPECT_EQ(compact(MpfrReal(-50), MpfrReal(0)), at53);
  // -50 = -25 * 2^1: class 1, sign 1, e = 1 (svarint 2), one byte, 25.
  EXPECT_EQ(at53, (Bytes{1, 1, 2, 1, 25}));
  EXPECT_EQ(compact(-MpfrReal(0), MpfrReal(0)), (Bytes{0, 1}));
}

TEST(ReplayMpfrCodec, WiderValueDoesNotFitANarrowerPrecision) {
  Bytes pi;
  MpfrReal wide;
  {
    ScopedMpfrBits precision(256);
    wide = gizmo::piOf<MpfrReal>();
    pi = compact(wide, MpfrReal(0));
  }
  {
    ScopedMpfrBits precision(53);
    ByteReader r(pi);
    EXPECT_THROW(readScalar(r, MpfrReal(0)), FormatError);
  }
  ScopedMpfrBits precision(512);  // but a wider one holds it exactly
  expectSameMpfr(decode(pi), wide);
}

TEST(ReplayMpfrCodec, MalformedEncodingsThrow) {
  ScopedMpfrBits precision(113);
  auto expectFailureAt = [](const Bytes& bytes, std::uint64_t offset) {
    ByteReader r(bytes);
    try {
      readScalar(r, MpfrReal(0));
      ADD_FAILURE() << "no FormatError";
    } catch (const FormatError& e) {
      EXPECT_EQ(e.offset(), offset) << e.what();
    }
  };
  expectFailureAt({5}, 0);                          // unknown class
  expectFailureAt({0, 2}, 1);                       // zero with a bad sign
  expectFailureAt({1, 0, 0, 0}, 3);                 // no mantissa bytes
  expectFailureAt({1, 0, 0, 1, 4}, 4);              // even mantissa
  expectFailureAt({1, 0, 0, 2, 1, 0}, 4);           // zero top byte
  expectFailureAt({1, 0, 0, 1}, 4);                 // truncated mantissa
  expectFailureAt({1, 0, 0, 0x81, 0x80, 0x40}, 3);  // 1 MiB + 1 bytes
  expectFailureAt({}, 0);

  ByteWriter huge;
  huge.u8(1);
  huge.u8(0);
  huge.svarint(std::int64_t{1} << 40);  // beyond MPFR's exponent range
  huge.varint(1);
  huge.u8(1);
  expectFailureAt(Bytes(huge.bytes().begin(), huge.bytes().end()), 2);
}

TEST(ReplayMpfrCodec, ExactText) {
  ScopedMpfrBits precision(256);
  EXPECT_EQ(exactText(MpfrReal(1) / MpfrReal(8)), "0x1p-3");
  EXPECT_EQ(exactText(MpfrReal(3)), "0x1.8p+1");
  EXPECT_EQ(exactText(MpfrReal(-0.1)), "-0x1.999999999999ap-4");  // the double, exactly
  EXPECT_EQ(exactText(-MpfrReal(0)), "-0x0p+0");
  SCOPED_TRACE(seedTrace());
  std::mt19937_64 rng(kSeed);
  for (int i = 0; i < 500; ++i) {
    const MpfrReal v = randomMpfr(rng, 100000);
    MpfrReal back;
    ASSERT_EQ(mpfr_set_str(back.backend().data(), exactText(v).c_str(), 0, MPFR_RNDN), 0);
    expectSameMpfr(back, v);
  }
}

}  // namespace
