// MPFR values as m * 2^e with m odd: the lowest-terms form is unique, so equal values (whatever
// their precision) encode to the same bytes, and the bit length of m says exactly which precision
// the reader needs.
#include <gmp.h>
#include <mpfr.h>

#include <bit>
#include <cstdint>
#include <string>

#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/scalar_codec.hpp"
#include "hex_float_text.hpp"

namespace gizmo::replay {

namespace {

enum MpfrClass : std::uint8_t { kZero = 0, kRegular = 1, kPlusInf = 2, kMinusInf = 3, kNan = 4 };

static_assert(GMP_NAIL_BITS == 0 && sizeof(mp_limb_t) <= 8,
              "the mantissa is written limb by limb as little-endian bytes");
constexpr std::size_t kLimbBytes = sizeof(mp_limb_t);

class Mpz {
 public:
  Mpz() { mpz_init(value_); }
  ~Mpz() { mpz_clear(value_); }
  Mpz(const Mpz&) = delete;
  Mpz& operator=(const Mpz&) = delete;
  mpz_ptr get() { return value_; }

 private:
  mpz_t value_;
};

// |x| = m * 2^exponent with m odd (x regular: finite, non-zero).
std::int64_t oddMantissa(mpfr_srcptr x, Mpz& m) {
  const mpfr_exp_t e = mpfr_get_z_2exp(m.get(), x);
  mpz_abs(m.get(), m.get());
  const mp_bitcnt_t zeros = mpz_scan1(m.get(), 0);
  mpz_tdiv_q_2exp(m.get(), m.get(), zeros);
  return static_cast<std::int64_t>(e) + static_cast<std::int64_t>(zeros);
}

bool readSign(ByteReader& in) {
  const std::size_t at = in.position();
  const std::uint8_t sign = in.u8();
  if (sign > 1) throw FormatError("invalid sign byte " + std::to_string(sign), at);
  return sign == 1;
}

}  // namespace

void ScalarCodec<MpfrReal>::write(ByteWriter& out, const MpfrReal& value) {
  mpfr_srcptr x = value.backend().data();
  if (mpfr_nan_p(x)) {
    out.u8(kNan);
    return;
  }
  const bool negative = mpfr_signbit(x) != 0;
  if (mpfr_inf_p(x)) {
    out.u8(negative ? kMinusInf : kPlusInf);
    return;
  }
  out.u8(mpfr_zero_p(x) ? kZero : kRegular);
  out.u8(negative ? 1 : 0);
  if (mpfr_zero_p(x)) return;

  Mpz m;
  out.svarint(oddMantissa(x, m));
  // Limbs straight into the writer: no export buffer. Only the top limb can have zero bytes.
  const std::size_t limbs = mpz_size(m.get());
  const mp_limb_t top = mpz_getlimbn(m.get(), limbs - 1);
  const std::size_t topBytes = (static_cast<std::size_t>(std::bit_width(top)) + 7) / 8;
  out.varint((limbs - 1) * kLimbBytes + topBytes);
  for (std::size_t i = 0; i + 1 < limbs; ++i) out.littleEndian(mpz_getlimbn(m.get(), i), kLimbBytes);
  out.littleEndian(top, topBytes);
}

MpfrReal ScalarCodec<MpfrReal>::read(ByteReader& in) {
  const std::size_t classAt = in.position();
  const std::uint8_t kind = in.u8();
  MpfrReal result;  // at the thread's current precision
  mpfr_ptr x = result.backend().data();
  switch (kind) {
    case kNan: mpfr_set_nan(x); return result;
    case kPlusInf:
    case kMinusInf: mpfr_set_inf(x, kind == kPlusInf ? 1 : -1); return result;
    case kZero: mpfr_set_zero(x, readSign(in) ? -1 : 1); return result;
    case kRegular: break;
    default: throw FormatError("invalid MPFR value class " + std::to_string(kind), classAt);
  }

  const bool negative = readSign(in);
  const std::size_t exponentAt = in.position();
  const std::int64_t exponent = in.svarint();
  const std::size_t countAt = in.position();
  const std::uint64_t count = in.varint();
  if (count == 0 || count > kMaxMantissaBytes) {
    throw FormatError(
        "MPFR mantissa byte count " + std::to_string(count) + " outside 1.." + std::to_string(kMaxMantissaBytes),
        countAt);
  }
  const std::size_t mantissaAt = in.position();
  const std::span<const std::uint8_t> bytes = in.span(static_cast<std::size_t>(count));
  if (bytes.back() == 0) throw FormatError("MPFR mantissa has a zero top byte", mantissaAt);
  if ((bytes.front() & 1) == 0) throw FormatError("MPFR mantissa is even (not in lowest terms)", mantissaAt);

  const std::int64_t bits = static_cast<std::int64_t>(8 * (count - 1)) + std::bit_width(bytes.back());
  const long precision = mpfrBits();
  if (bits > precision) {
    throw FormatError("MPFR mantissa of " + std::to_string(bits) + " bits does not fit the current precision of " +
                          std::to_string(precision) + " bits",
                      mantissaAt);
  }
  // MPFR's exponent E puts |x| in [2^(E-1), 2^E): E = exponent + bits. Compared without forming
  // the sum, which could overflow for a hostile exponent.
  const std::int64_t emin = mpfr_get_emin();
  const std::int64_t emax = mpfr_get_emax();
  if (exponent < emin - bits || exponent > emax - bits) {
    throw FormatError("MPFR exponent " + std::to_string(exponent) + " outside the current range", exponentAt);
  }

  Mpz m;
  mpz_import(m.get(), bytes.size(), -1, 1, 0, 0, bytes.data());
  if (negative) mpz_neg(m.get(), m.get());
  // Exact (ternary 0): m fits the precision and the exponent the range, both checked above.
  mpfr_set_z_2exp(x, m.get(), static_cast<mpfr_exp_t>(exponent), MPFR_RNDN);
  return result;
}

template <>
std::string exactText<MpfrReal>(const MpfrReal& value) {
  mpfr_srcptr x = value.backend().data();
  if (mpfr_nan_p(x)) return "nan";
  const bool negative = mpfr_signbit(x) != 0;
  if (mpfr_inf_p(x)) return negative ? "-inf" : "inf";
  if (mpfr_zero_p(x)) return detail::hexFloatText(negative, 0, "", 0);

  Mpz m;
  const std::int64_t exponent = oddMantissa(x, m);
  // m = 1.f in binary with fractionBits bits after the point; pad f on the right to whole digits.
  const std::size_t fractionBits = mpz_sizeinbase(m.get(), 2) - 1;
  mpz_clrbit(m.get(), fractionBits);
  const std::size_t padding = (4 - fractionBits % 4) % 4;
  mpz_mul_2exp(m.get(), m.get(), padding);
  const std::size_t digitCount = (fractionBits + padding) / 4;
  std::string digits;
  if (digitCount != 0) {
    std::string raw(mpz_sizeinbase(m.get(), 16) + 2, '\0');
    mpz_get_str(raw.data(), 16, m.get());
    raw.resize(std::char_traits<char>::length(raw.c_str()));
    digits = std::string(digitCount - raw.size(), '0') + raw;  // restore leading zero digits
  }
  return detail::hexFloatText(negative, 1, digits, exponent + static_cast<std::int64_t>(fractionBits));
}

}  // namespace gizmo::replay
