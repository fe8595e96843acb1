#include "gizmo/replay/scalar_codec.hpp"

#include "gizmo/replay/format_error.hpp"
#include "hex_float_text.hpp"

namespace gizmo::replay {

namespace detail {

void throwBadControl(std::size_t offset, std::uint8_t control, std::size_t width) {
  throw FormatError("invalid scalar control byte " + std::to_string(control) + " (leading " +
                        std::to_string(control >> 4) + " + trailing " + std::to_string(control & 0x0F) +
                        " zero bytes, for a " + std::to_string(width) + "-byte scalar)",
                    offset);
}

void throwRedundantControl(std::size_t offset) {
  throw FormatError("scalar control byte does not count all zero bytes (non-canonical encoding)", offset);
}

void throwNonCanonicalLongDouble(std::size_t offset) {
  throw FormatError("not a canonical x87 extended value (integer bit disagrees with exponent)", offset);
}

std::string hexFloatText(bool negative, unsigned leading, std::string fractionDigits, long long exponent) {
  while (!fractionDigits.empty() && fractionDigits.back() == '0') fractionDigits.pop_back();
  std::string out = negative ? "-0x" : "0x";
  out += static_cast<char>('0' + leading);
  if (!fractionDigits.empty()) out += '.' + fractionDigits;
  out += exponent < 0 ? "p" : "p+";  // to_string supplies the minus sign
  out += std::to_string(exponent);
  return out;
}

}  // namespace detail

namespace {

// 128 bits as two words, for binary128's fields: unsigned __int128 is missing on the 32-bit
// targets (i686, wasm32). Only what the spellings below use.
struct UInt128 {
  std::uint64_t lo = 0, hi = 0;
  constexpr UInt128(std::uint64_t v = 0) : lo(v) {}  // NOLINT(google-explicit-constructor)
  explicit operator unsigned() const { return static_cast<unsigned>(lo); }
  friend bool operator==(const UInt128&, const UInt128&) = default;
  friend UInt128 operator&(UInt128 a, const UInt128& b) {
    a.lo &= b.lo;
    a.hi &= b.hi;
    return a;
  }
  friend UInt128 operator-(const UInt128& a, const UInt128& b) {
    UInt128 r(a.lo - b.lo);
    r.hi = a.hi - b.hi - (a.lo < b.lo ? 1 : 0);
    return r;
  }
  friend UInt128 operator<<(UInt128 x, unsigned n) {
    if (n >= 64) {
      x.hi = n >= 128 ? 0 : x.lo << (n - 64);
      x.lo = 0;
    } else if (n > 0) {
      x.hi = (x.hi << n) | (x.lo >> (64 - n));
      x.lo <<= n;
    }
    return x;
  }
  friend UInt128 operator>>(UInt128 x, unsigned n) {
    if (n >= 64) {
      x.lo = n >= 128 ? 0 : x.hi >> (n - 64);
      x.hi = 0;
    } else if (n > 0) {
      x.lo = (x.lo >> n) | (x.hi << (64 - n));
      x.hi >>= n;
    }
    return x;
  }
  UInt128& operator<<=(unsigned n) { return *this = *this << n; }
  UInt128& operator>>=(unsigned n) { return *this = *this >> n; }
};

// The little-endian bytes of an IEEE word as one number.
template <std::size_t Width>
UInt128 wordOf(const std::array<std::uint8_t, Width>& bytes) {
  static_assert(Width <= 16);
  UInt128 bits;
  for (std::size_t i = 0; i < Width; ++i) {
    if (i < 8) bits.lo |= std::uint64_t{bytes[i]} << (8 * i);
    else bits.hi |= std::uint64_t{bytes[i]} << (8 * (i - 8));
  }
  return bits;
}

// `bits` bits of `field` as hexadecimal digits, most significant first, padded with zero bits on
// the right to whole digits (the digits of a fraction after the point).
std::string fractionHex(UInt128 field, unsigned bits) {
  const unsigned padding = (4 - bits % 4) % 4;
  field <<= padding;
  const unsigned digits = (bits + padding) / 4;
  std::string out(digits, '0');
  for (unsigned i = 0; i < digits; ++i) {
    out[digits - 1 - i] = "0123456789abcdef"[static_cast<unsigned>(field >> (4 * i)) & 0xFu];
  }
  return out;
}

// Minimal hexadecimal spelling of a NaN payload.
std::string payloadHex(UInt128 field) {
  std::string digits;
  do {
    digits.insert(digits.begin(), "0123456789abcdef"[static_cast<unsigned>(field) & 0xFu]);
    field >>= 4;
  } while (field != 0);
  return digits;
}

std::string nonFiniteText(bool negative, UInt128 fraction) {
  std::string out = negative ? "-" : "";
  if (fraction == 0) return out + "inf";
  return out + "nan(0x" + payloadHex(fraction) + ")";
}

// An IEEE interchange format: sign, biased exponent of exponentBits bits, implicit leading bit.
std::string ieeeText(UInt128 bits, unsigned fractionBits, unsigned exponentBits) {
  const UInt128 fraction = bits & ((UInt128{1} << fractionBits) - 1);
  const unsigned maxBiased = (1u << exponentBits) - 1;
  const unsigned biased = static_cast<unsigned>(bits >> fractionBits) & maxBiased;
  const bool negative = ((bits >> (fractionBits + exponentBits)) & 1) != 0;
  const long long bias = maxBiased >> 1;
  if (biased == maxBiased) return nonFiniteText(negative, fraction);
  if (biased == 0 && fraction == 0) return detail::hexFloatText(negative, 0, "", 0);
  // Subnormals keep a leading 0 and the minimum exponent, as printf's %a does.
  const unsigned leading = biased != 0 ? 1 : 0;
  const long long exponent = (biased != 0 ? biased : 1) - bias;
  return detail::hexFloatText(negative, leading, fractionHex(fraction, fractionBits), exponent);
}

}  // namespace

template <>
std::string exactText<float>(const float& value) {
  return ieeeText(UInt128(ScalarCodec<float>::toBits(value)), 23, 8);
}

template <>
std::string exactText<double>(const double& value) {
  return ieeeText(UInt128(ScalarCodec<double>::toBits(value)), 52, 11);
}

#if GIZMO_HAS_MULTIPRECISION
template <>
std::string exactText<Float128>(const Float128& value) {
  return ieeeText(wordOf(ScalarCodec<Float128>::toBytes(value)), 112, 15);
}
#endif

namespace {

// x87: the integer bit is explicit, so the leading digit is read rather than implied; this also
// spells the non-canonical encodings by the value the FPU gives them. Compiled on every target,
// called only where long double is x87's format.
[[maybe_unused]] std::string x87Text(const std::uint8_t* bytes) {  // the 10 bytes of the raw form
  const std::uint64_t significand = detail::loadLittleEndian(bytes, 8);
  const unsigned signAndExponent = bytes[8] | (unsigned{bytes[9]} << 8);
  const bool negative = (signAndExponent & 0x8000u) != 0;
  const unsigned biased = signAndExponent & 0x7FFFu;
  const std::uint64_t fraction = significand & ((std::uint64_t{1} << 63) - 1);
  const unsigned leading = static_cast<unsigned>(significand >> 63);
  if (biased == 0x7FFFu) return nonFiniteText(negative, fraction);
  if (leading == 0 && fraction == 0) return detail::hexFloatText(negative, 0, "", 0);
  const long long exponent = static_cast<long long>(biased != 0 ? biased : 1) - 16383;
  return detail::hexFloatText(negative, leading, fractionHex(fraction, 63), exponent);
}

}  // namespace

// In this target's format of long double. A double-double is its two doubles, "high + low".
template <>
std::string exactText<long double>(const long double& value) {
  using Codec = ScalarCodec<long double>;
  const auto bytes = Codec::toBytes(value);
  if constexpr (Codec::kX87) {
    return x87Text(bytes.data());
  } else if constexpr (Codec::kDoubleDouble) {
    const UInt128 both = wordOf(bytes);
    return ieeeText(both.lo, 52, 11) + " + " + ieeeText(both.hi, 52, 11);
  } else if constexpr (Codec::kWidth == 8) {
    return ieeeText(wordOf(bytes), 52, 11);
  } else {
    return ieeeText(wordOf(bytes), 112, 15);
  }
}

}  // namespace gizmo::replay
