// gizmo/core/decimal_text.hpp makes the board text of every log from printf and strtod, on every
// target; here, on the host, its results must be exactly std::to_chars's and std::from_chars's.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "gizmo/core/decimal_text.hpp"
#include "gizmo/core/std_compat.hpp"

namespace gizmo {
namespace {

std::string toCharsText(double v) {
  char buf[512];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::string toCharsFixedText(double v) {
  char buf[512];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed).ptr);
}

// Doubles of every kind a board holds and more: any bit pattern (finite), cell coordinates in
// twentieths and thousandths, powers of two and ten, and the extremes.
std::vector<double> samples() {
  std::vector<double> out = {0.0,
                             -0.0,
                             1.0,
                             -1.0,
                             0.05,
                             0.1,
                             0.3,
                             25.0,
                             0.025,
                             1e22,
                             1e23,
                             5e-324,
                             2.2250738585072014e-308,
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::min(),
                             std::ldexp(1.0, 60),
                             123456789012345678.0,
                             9007199254740993.0};
  std::mt19937_64 rng(20261202);
  while (out.size() < 60000) {
    const double v = bitCast<double>(rng());
    if (std::isfinite(v)) out.push_back(v);
  }
  for (int k = -4000; k <= 4000; ++k) {
    out.push_back(k / 20.0);
    out.push_back(k / 1000.0);
  }
  for (int e = -320; e <= 308; ++e) out.push_back(std::pow(10.0, e));
  for (int e = -1074; e <= 1023; ++e) out.push_back(std::ldexp(1.0, e));
  return out;
}

TEST(DecimalText, ShortestIsToCharsText) {
  for (const double v : samples()) {
    ASSERT_EQ(shortestDecimal(v), toCharsText(v)) << std::hexfloat << v;
    ASSERT_EQ(shortestFixedDecimal(v), toCharsFixedText(v)) << std::hexfloat << v;
  }
}

TEST(DecimalText, ParseIsFromChars) {
  for (const double v : samples()) {
    const std::string text = toCharsText(v);
    double ours = 0;
    ASSERT_EQ(parseDecimalDouble(text, ours), DecimalParse::Ok) << text;
    ASSERT_EQ(bitCast<std::uint64_t>(ours), bitCast<std::uint64_t>(v)) << text;
  }
  // Text that is not the shortest form: more digits than a double holds, halfway cases.
  for (const char* text : {"0.1000000000000000055511151231257827", "9007199254740993", "2.4703282292062328e-324",
                           "1.7976931348623158e308", "4.9406564584124654e-324", "1e-320", "0.000"}) {
    double ours = 0, theirs = 0;
    ASSERT_EQ(parseDecimalDouble(text, ours), DecimalParse::Ok) << text;
    const std::string_view s(text);
    std::from_chars(s.data(), s.data() + s.size(), theirs);
    EXPECT_EQ(bitCast<std::uint64_t>(ours), bitCast<std::uint64_t>(theirs)) << text;
  }
}

TEST(DecimalText, OutOfRangeAndMalformedAreSaidSo) {
  double v = 7;
  EXPECT_EQ(parseDecimalDouble("1e400", v), DecimalParse::OutOfRange);
  EXPECT_EQ(parseDecimalDouble("-1e400", v), DecimalParse::OutOfRange);
  EXPECT_EQ(parseDecimalDouble("1e-400", v), DecimalParse::OutOfRange);
  EXPECT_EQ(parseDecimalDouble("", v), DecimalParse::Malformed);
  EXPECT_EQ(parseDecimalDouble("1.5x", v), DecimalParse::Malformed);
  EXPECT_EQ(v, 7) << "the value is set only when the text reads";
}

}  // namespace
}  // namespace gizmo
