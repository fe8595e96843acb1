#pragma once
// Exact, portable encodings of the scalars of the precision ladder (gizmo/core/math/scalar.hpp).
//
// ScalarCodec<Real> gives the raw form. Fixed-width types: kWidth bytes holding the IEEE bits
// little-endian (float 4, double 8, Float128 16 = binary128), and for long double its format on
// this target (below: x87's 80-bit extended format in 10 bytes on x86).
//
// writeScalar/readScalar give the compact form the log uses, relative to a base value both sides
// know (typically the previous value of the same quantity). Fixed-width types: x = bytes(value)
// XOR bytes(base), as a kWidth-byte little-endian number. x == 0 is the single control byte 0xFF.
// Otherwise the control byte is (lead << 4) | trail, lead and trail being the counts of zero bytes
// of x at its high and low end, followed by the kWidth - lead - trail bytes between them, lowest
// first. A value with the sign and exponent of its base thus drops its high bytes, and a round
// value (0.05, -50) its zero tail. 0xFF cannot be a real control byte: 15 + 15 >= kWidth.
//
// MpfrReal ignores the base and is written exactly at whatever precision it has (see
// ScalarCodec<MpfrReal>).
#include <algorithm>
#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "gizmo/core/math/scalar.hpp"
#include "gizmo/core/std_compat.hpp"
#include "gizmo/replay/bytes.hpp"

namespace gizmo::replay {

template <class Real>
struct ScalarCodec;

namespace detail {

inline constexpr std::uint8_t kSameAsBase = 0xFF;

[[noreturn, gnu::cold]] void throwBadControl(std::size_t offset, std::uint8_t control, std::size_t width);
[[noreturn, gnu::cold]] void throwRedundantControl(std::size_t offset);
[[noreturn, gnu::cold]] void throwNonCanonicalLongDouble(std::size_t offset);

template <class UInt>
std::array<std::uint8_t, sizeof(UInt)> wordToBytes(UInt bits) {
  std::array<std::uint8_t, sizeof(UInt)> out;
  storeLittleEndian(out.data(), bits, sizeof(UInt));
  return out;
}

}  // namespace detail

template <>
struct ScalarCodec<float> {
  static_assert(std::numeric_limits<float>::is_iec559 && sizeof(float) == 4);
  static constexpr std::size_t kWidth = 4;
  using Bits = std::uint32_t;  // lets the compact form work on one register
  static Bits toBits(float v) { return gizmo::bitCast<Bits>(v); }
  static float fromBits(Bits b) { return gizmo::bitCast<float>(b); }
  static std::array<std::uint8_t, kWidth> toBytes(const float& v) { return detail::wordToBytes(toBits(v)); }
  static float fromBytes(const std::array<std::uint8_t, kWidth>& b) {
    return fromBits(static_cast<Bits>(detail::loadLittleEndian(b.data(), kWidth)));
  }
};

template <>
struct ScalarCodec<double> {
  static_assert(std::numeric_limits<double>::is_iec559 && sizeof(double) == 8);
  static constexpr std::size_t kWidth = 8;
  using Bits = std::uint64_t;
  static Bits toBits(double v) { return gizmo::bitCast<Bits>(v); }
  static double fromBits(Bits b) { return gizmo::bitCast<double>(b); }
  static std::array<std::uint8_t, kWidth> toBytes(const double& v) { return detail::wordToBytes(toBits(v)); }
  static double fromBytes(const std::array<std::uint8_t, kWidth>& b) {
    return fromBits(detail::loadLittleEndian(b.data(), kWidth));
  }
};

// long double in the format this target computes (hardwareFormatOf<long double>(), which the
// log's header names): x87's 80-bit extended format in 10 bytes (bytes 0..7 the 64-bit
// significand with its explicit integer bit, bytes 8..9 the sign bit over the 15-bit biased
// exponent, both little-endian: the value's first 10 bytes in memory on x86, the rest of the
// object being padding); IEEE binary128 in 16 bytes and binary64 in 8, the bit pattern
// little-endian; a double-double (ppc64) in 16 bytes, its high double and then its low one,
// each little-endian.
template <>
struct ScalarCodec<long double> {
  static constexpr std::string_view kFormat = hardwareFormatOf<long double>();
  static constexpr bool kX87 = kFormat == "x87-extended80";
  static constexpr bool kDoubleDouble = kFormat == "double-double";
  static constexpr std::size_t kWidth = kX87 ? 10 : kFormat == "binary64" ? 8 : 16;
  static_assert(sizeof(long double) >= kWidth);
  static_assert(!kX87 || std::endian::native == std::endian::little, "x87 is little-endian");
  static std::array<std::uint8_t, kWidth> toBytes(const long double& v) {
    std::array<std::uint8_t, kWidth> out;
    std::memcpy(out.data(), &v, kWidth);
    if constexpr (std::endian::native == std::endian::big) toLittleEndianOrder(out);
    return out;
  }
  static long double fromBytes(std::array<std::uint8_t, kWidth> b) {
    if constexpr (std::endian::native == std::endian::big) toLittleEndianOrder(b);
    long double v = 0;
    std::memcpy(&v, b.data(), kWidth);
    return v;
  }
  // x87 arithmetic only produces encodings whose integer bit is set exactly when the exponent
  // field is non-zero; the others (unnormals, pseudo-denormals, pseudo-infinities and -NaNs)
  // are invalid operands or aliases. readScalar refuses them, so a decoded value is one the
  // simulator could have computed. Every bit pattern of the other formats is a value.
  static bool isCanonical(const std::array<std::uint8_t, kWidth>& b) {
    if constexpr (!kX87) return true;
    const bool integerBit = (b[7] & 0x80) != 0;
    const unsigned exponent = (b[8] | (unsigned{b[9]} << 8)) & 0x7FFFu;
    return integerBit == (exponent != 0);
  }

 private:
  // A big-endian target holds each IEEE word highest byte first (for a double-double, each of
  // its two doubles); the log holds them lowest first. The swap is its own inverse.
  static void toLittleEndianOrder(std::array<std::uint8_t, kWidth>& b) {
    const std::size_t word = kDoubleDouble ? 8 : kWidth;
    for (std::size_t at = 0; at < kWidth; at += word) std::reverse(b.begin() + at, b.begin() + at + word);
  }
};

#if GIZMO_HAS_MULTIPRECISION
template <>
struct ScalarCodec<Float128> {
  static_assert(sizeof(__float128) == 16 && std::endian::native == std::endian::little,
                "__float128 must be IEEE binary128 on a little-endian target");
  static constexpr std::size_t kWidth = 16;
  static std::array<std::uint8_t, kWidth> toBytes(const Float128& v) {
    std::array<std::uint8_t, kWidth> out;
    std::memcpy(out.data(), &v.backend().value(), kWidth);
    return out;
  }
  static Float128 fromBytes(const std::array<std::uint8_t, kWidth>& b) {
    Float128 v;
    std::memcpy(&v.backend().value(), b.data(), kWidth);
    return v;
  }
};

// MPFR values, exactly, in any precision:
//   class byte: 0 zero, 1 regular, 2 +inf, 3 -inf, 4 NaN
//   zero and regular: a sign byte, 0 positive or 1 negative
//   regular: the value is m * 2^e with m an odd positive integer; e as svarint, then the byte
//            count of m as varint, then m's bytes, lowest first (the last byte is non-zero)
// read() makes the value at the thread's current MPFR precision (mpfrBits()). It throws
// FormatError when m has more significant bits than that precision, when the byte count exceeds
// kMaxMantissaBytes, when m is not in the form above, or when the value's exponent is outside
// MPFR's current exponent range.
template <>
struct ScalarCodec<MpfrReal> {
  static constexpr std::size_t kMaxMantissaBytes = std::size_t{1} << 20;
  static void write(ByteWriter& out, const MpfrReal& value);
  static MpfrReal read(ByteReader& in);
};
#endif  // GIZMO_HAS_MULTIPRECISION

namespace detail {

template <class Real>
concept WordCodec = requires {
  typename ScalarCodec<Real>::Bits;
};
template <class Real>
concept FixedWidthCodec = requires {
  ScalarCodec<Real>::kWidth;
};
template <class Real>
concept HasCanonicalCheck = requires(const std::array<std::uint8_t, ScalarCodec<Real>::kWidth>& b) {
  { ScalarCodec<Real>::isCanonical(b) } -> std::same_as<bool>;
};

// The compact XOR form on a word of sizeof(UInt) bytes (float, double), stored at p, which must
// have room for 1 + sizeof(UInt) bytes (the whole word is stored; the bytes past the end are
// overwritten by what follows). Returns the end.
template <class UInt>
[[gnu::always_inline]] inline std::uint8_t* putXorWord(std::uint8_t* p, UInt x) {
  constexpr unsigned kWidth = sizeof(UInt);
  if (x == 0) {
    *p = kSameAsBase;
    return p + 1;
  }
  const unsigned lead = static_cast<unsigned>(std::countl_zero(x)) / 8;
  const unsigned trail = static_cast<unsigned>(std::countr_zero(x)) / 8;
  *p = static_cast<std::uint8_t>(lead << 4 | trail);
  const UInt middle = static_cast<UInt>(x >> (8 * trail));
  storeLittleEndian(p + 1, middle, kWidth);
  return p + 1 + (kWidth - lead - trail);
}

template <class UInt>
inline UInt readXorWord(ByteReader& in) {
  constexpr unsigned kWidth = sizeof(UInt);
  const std::size_t at = in.position();
  const std::uint8_t control = in.u8();
  if (control == kSameAsBase) return 0;
  const unsigned lead = control >> 4;
  const unsigned trail = control & 0x0Fu;
  if (lead + trail >= kWidth) throwBadControl(at, control, kWidth);
  const unsigned count = kWidth - lead - trail;
  const std::uint64_t middle = in.littleEndian(count);
  // Both end bytes non-zero: otherwise a shorter control byte says the same, and every value
  // keeps one encoding.
  if ((middle & 0xFF) == 0 || (middle >> (8 * (count - 1))) == 0) throwRedundantControl(at);
  return static_cast<UInt>(middle << (8 * trail));
}

// The same form on byte arrays (long double, Float128), stored at p (room for 1 + Width bytes).
template <std::size_t Width>
inline std::uint8_t* putXorBytes(std::uint8_t* p, const std::array<std::uint8_t, Width>& value,
                                 const std::array<std::uint8_t, Width>& base) {
  std::array<std::uint8_t, Width> x;
  for (std::size_t i = 0; i < Width; ++i) x[i] = value[i] ^ base[i];
  std::size_t trail = 0;
  while (trail < Width && x[trail] == 0) ++trail;
  if (trail == Width) {
    *p = kSameAsBase;
    return p + 1;
  }
  std::size_t lead = 0;
  while (x[Width - 1 - lead] == 0) ++lead;
  *p = static_cast<std::uint8_t>(lead << 4 | trail);
  std::memcpy(p + 1, x.data() + trail, Width - lead - trail);
  return p + 1 + (Width - lead - trail);
}

template <std::size_t Width>
inline std::array<std::uint8_t, Width> readXorBytes(ByteReader& in, const std::array<std::uint8_t, Width>& base) {
  const std::size_t at = in.position();
  const std::uint8_t control = in.u8();
  if (control == kSameAsBase) return base;
  const std::size_t lead = control >> 4;
  const std::size_t trail = control & 0x0Fu;
  if (lead + trail >= Width) throwBadControl(at, control, Width);
  std::array<std::uint8_t, Width> x{};
  in.bytes(x.data() + trail, Width - lead - trail);
  if (x[trail] == 0 || x[Width - 1 - lead] == 0) throwRedundantControl(at);
  for (std::size_t i = 0; i < Width; ++i) x[i] ^= base[i];
  return x;
}

}  // namespace detail

// The most bytes the compact form of a fixed-width scalar takes; 0 for MpfrReal, whose size
// depends on the value.
template <class Real>
inline constexpr std::size_t kMaxCompactBytes = 0;
template <class Real>
requires detail::FixedWidthCodec<Real>
inline constexpr std::size_t kMaxCompactBytes<Real> = 1 + ScalarCodec<Real>::kWidth;

// The compact form of a fixed-width scalar stored at p, which must have room for
// kMaxCompactBytes<Real>; returns the end. For runs of writes claimed at once (ByteWriter::claim).
template <class Real>
requires detail::FixedWidthCodec<Real>
[[gnu::always_inline]] inline std::uint8_t* putScalar(std::uint8_t* p, const Real& value, const Real& base) {
  using Codec = ScalarCodec<Real>;
  if constexpr (detail::WordCodec<Real>) return detail::putXorWord(p, Codec::toBits(value) ^ Codec::toBits(base));
  else return detail::putXorBytes(p, Codec::toBytes(value), Codec::toBytes(base));
}

// Whether two values have the same encoding: equal and with the same sign of zero (and both
// NaN, whatever their payload, for MPFR, which has one NaN). The encoder uses it wherever an
// equality lets it leave a value out, so that what the reader rebuilds is the same bits.
template <class Real>
inline bool sameEncoding(const Real& a, const Real& b) {
  using Codec = ScalarCodec<Real>;
  if constexpr (detail::WordCodec<Real>) return Codec::toBits(a) == Codec::toBits(b);
  else if constexpr (detail::FixedWidthCodec<Real>) return Codec::toBytes(a) == Codec::toBytes(b);
#if GIZMO_HAS_MULTIPRECISION
  else {
    const mpfr_srcptr x = a.backend().data(), y = b.backend().data();
    if (mpfr_nan_p(x) || mpfr_nan_p(y)) return mpfr_nan_p(x) && mpfr_nan_p(y);
    return mpfr_equal_p(x, y) && mpfr_signbit(x) == mpfr_signbit(y);
  }
#endif
}

// Writes `value` in the compact form relative to `base` (ignored for MpfrReal).
template <class Real>
inline void writeScalar(ByteWriter& out, const Real& value, const Real& base) {
  if constexpr (detail::FixedWidthCodec<Real>) out.commit(putScalar(out.claim(kMaxCompactBytes<Real>), value, base));
  else ScalarCodec<Real>::write(out, value);
}

// Reads what writeScalar(out, value, base) wrote, given the same base; throws FormatError on a
// malformed encoding (the offset is that of the control or class byte).
template <class Real>
inline Real readScalar(ByteReader& in, const Real& base) {
  using Codec = ScalarCodec<Real>;
  if constexpr (detail::WordCodec<Real>) {
    using Bits = typename Codec::Bits;
    return Codec::fromBits(static_cast<Bits>(Codec::toBits(base) ^ detail::readXorWord<Bits>(in)));
  } else if constexpr (detail::FixedWidthCodec<Real>) {
    const std::size_t at = in.position();
    const auto bytes = detail::readXorBytes(in, Codec::toBytes(base));
    if constexpr (detail::HasCanonicalCheck<Real>) {
      if (!Codec::isCanonical(bytes)) detail::throwNonCanonicalLongDouble(at);
    }
    return Codec::fromBytes(bytes);
  } else {
    return Codec::read(in);
  }
}

// The exact value as a hexadecimal floating-point literal, for people comparing states:
// "[-]0x1.<hex digits>p<exponent>" with trailing zero digits dropped (0.1 as a double is
// "0x1.999999999999ap-4"), subnormals as "0x0.<digits>p<minimum exponent>", zeros as "0x0p+0"
// with their sign, "inf"/"-inf", and NaNs with their payload, "nan(0x<fraction field>)" (for MPFR
// just "nan"). MPFR values show their exact value, not their precision.
template <class Real>
std::string exactText(const Real& value);

template <>
std::string exactText<float>(const float& value);
template <>
std::string exactText<double>(const double& value);
template <>
std::string exactText<long double>(const long double& value);
#if GIZMO_HAS_MULTIPRECISION
template <>
std::string exactText<Float128>(const Float128& value);
template <>
std::string exactText<MpfrReal>(const MpfrReal& value);
#endif

}  // namespace gizmo::replay
