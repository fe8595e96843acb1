#include "gizmo/replay/scalar_codec.hpp"

#include "gizmo/replay/format_error.hpp"
#include "hex_float_text.hpp"

namespace gizmo::replay {

namespace detail {

void throwBadControl(std::size_t offset, std::uint8_t control, std::size_t width) {
  throw FormatError("invalid scalar control byte " + std::to_string(control) + " (leading " +
                        std::to_string(control >> 4) + " + trailing " +
                        std::to_string(control & 0x0F) + " zero bytes, for a " +
                        std::to_string(width) + "-byte scalar)",
                    offset);
}

void throwRedundantControl(std::size_t offset) {
  throw FormatError("scalar control byte does not count all zero bytes (non-canonical encoding)",
                    offset);
}

void throwNonCanonicalLongDouble(std::size_t offset) {
  throw FormatError("not a canonical x87 extended value (integer bit disagrees with exponent)",
                    offset);
}

std::string hexFloatText(bool negative, unsigned leading, std::string fractionDigits,
                         long long exponent) {
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

using UInt128 = unsigned __int128;

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
  return ieeeText(ScalarCodec<float>::toBits(value), 23, 8);
}

template <>
std::string exactText<double>(const double& value) {
  return ieeeText(ScalarCodec<double>::toBits(value), 52, 11);
}

template <>
std::string exactText<Float128>(const Float128& value) {
  const auto bytes = ScalarCodec<Float128>::toBytes(value);
  UInt128 bits = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i) bits |= UInt128{bytes[i]} << (8 * i);
  return ieeeText(bits, 112, 15);
}

// x87: the integer bit is explicit, so the leading digit is read rather than implied; this also
// spells the non-canonical encodings by the value the FPU gives them.
template <>
std::string exactText<long double>(const long double& value) {
  const auto bytes = ScalarCodec<long double>::toBytes(value);
  const std::uint64_t significand = detail::loadLittleEndian(bytes.data(), 8);
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

}  // namespace gizmo::replay
