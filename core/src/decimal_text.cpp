// The text std::to_chars and std::from_chars give for doubles, made from printf and strtod on every
// target (decimal_text.hpp): one C++ library lacks the floating-point overloads, and one code
// path everywhere is what keeps the board text of a log the same bytes on every machine.
#include "gizmo/core/decimal_text.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace gizmo {

namespace {

// v's shortest round-trip digits d1 d2 … dn and exponent e: |v| = d1.d2…dn × 10^e, as
// std::to_chars chooses them: the fewest digits that read back to v, and of those the nearest.
// printf's %e rounds correctly, so at each length it gives the nearest decimal; where that one
// does not read back, the next one up or down may, since a power of two's rounding interval
// reaches twice as far above it as below (2^-1017 is 7.120236347223045e-307, whose nearest
// 16-digit decimal ...044 reads back to another double).
struct Digits {
  bool negative = false;
  std::string digits;
  int exponent = 0;
};

bool readsBack(const Digits& d, double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%s%c.%se%d", d.negative ? "-" : "", d.digits[0], d.digits.c_str() + 1, d.exponent);
  return std::strtod(text, nullptr) == v;
}

// The decimal `step` (+1 or -1) units of the last digit away from d, with as many digits, or one
// more or fewer where a carry or borrow crosses a power of ten.
Digits neighbour(Digits d, int step) {
  unsigned long long n = std::strtoull(d.digits.c_str(), nullptr, 10);
  n = step > 0 ? n + 1 : n - 1;
  const std::size_t before = d.digits.size();
  d.digits = std::to_string(n);
  d.exponent += static_cast<int>(d.digits.size()) - static_cast<int>(before);
  return d;
}

Digits shortestDigits(double v) {
  Digits d;
  d.negative = std::signbit(v);
  if (v == 0) {
    d.digits = "0";
    return d;
  }
  char buf[64];
  for (int precision = 0; precision < 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*e", precision, v);
    Digits nearest;
    nearest.negative = d.negative;
    const char* p = buf + (d.negative ? 1 : 0);
    for (; *p != 'e'; ++p)
      if (*p != '.') nearest.digits += *p;
    nearest.exponent = std::atoi(p + 1);
    if (readsBack(nearest, v)) return nearest;
    for (const int step : {1, -1}) {
      const Digits other = neighbour(nearest, step);
      if (other.digits != "0" && other.digits.size() == nearest.digits.size() && readsBack(other, v)) return other;
    }
  }
  // 17 digits always read back.
  std::snprintf(buf, sizeof buf, "%.16e", v);
  const char* p = buf + (d.negative ? 1 : 0);
  for (; *p != 'e'; ++p)
    if (*p != '.') d.digits += *p;
  d.exponent = std::atoi(p + 1);
  return d;
}

// In fixed notation a whole number is written with all its digits, exactly (as std::to_chars
// does: 2^60 is 1152921504606846976, not 1152921504606847000), which printf's %.0f gives.
std::string fixedText(double v, const Digits& d) {
  const int n = static_cast<int>(d.digits.size());
  std::string out = d.negative ? "-" : "";
  if (d.exponent >= n - 1) {
    char whole[400];
    std::snprintf(whole, sizeof whole, "%.0f", v);
    return whole;
  }
  if (d.exponent >= 0) return out + d.digits.substr(0, d.exponent + 1) + "." + d.digits.substr(d.exponent + 1);
  return out + "0." + std::string(static_cast<std::size_t>(-d.exponent - 1), '0') + d.digits;
}

std::string scientificText(const Digits& d) {
  std::string out = d.negative ? "-" : "";
  out += d.digits.substr(0, 1);
  if (d.digits.size() > 1) out += "." + d.digits.substr(1);
  char exponent[16];
  std::snprintf(exponent, sizeof exponent, "e%c%02d", d.exponent < 0 ? '-' : '+',
                d.exponent < 0 ? -d.exponent : d.exponent);
  return out + exponent;
}

}  // namespace

std::string shortestDecimal(double v) {
  const Digits d = shortestDigits(v);
  std::string fixed = fixedText(v, d), scientific = scientificText(d);
  return scientific.size() < fixed.size() ? scientific : fixed;
}

std::string shortestFixedDecimal(double v) { return fixedText(v, shortestDigits(v)); }

// The text is a decimal number already (the readers check its syntax first); strtod reads it as
// from_chars would. Both call a number out of range when it overflows or rounds to zero; strtod
// also sets ERANGE for a subnormal result, which from_chars returns.
DecimalParse parseDecimalDouble(std::string_view text, double& value) {
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(copy.c_str(), &end);
  if (copy.empty() || end != copy.c_str() + copy.size()) return DecimalParse::Malformed;
  if (errno == ERANGE && (v == 0 || std::isinf(v))) return DecimalParse::OutOfRange;
  value = v;
  return DecimalParse::Ok;
}

}  // namespace gizmo
