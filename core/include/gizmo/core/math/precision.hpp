#pragma once
// The precisions a run can use, by the names the command line and the logs use, and a
// dispatcher that calls a generic function with the matching scalar type.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "gizmo/core/math/scalar.hpp"

namespace gizmo {

enum class Precision { Float, Double, LongDouble, Float128, Mpfr };

struct PrecisionChoice {
  Precision kind = Precision::Double;
  long mpfrBits = 0;  // for Mpfr only
};

inline const char* const kPrecisionNames = "float, double, long-double, float128, mpfr:BITS (e.g. mpfr:256)";

inline std::optional<PrecisionChoice> parsePrecision(std::string_view name) {
  if (name == "float") return PrecisionChoice{Precision::Float, 0};
  if (name == "double") return PrecisionChoice{Precision::Double, 0};
  if (name == "long-double") return PrecisionChoice{Precision::LongDouble, 0};
  if (name == "float128") return PrecisionChoice{Precision::Float128, 0};
  if (name.substr(0, 5) == "mpfr:") {
    const std::string digits(name.substr(5));
    if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos)
      return std::nullopt;
    const long bits = std::stol(digits);
    if (bits < 24 || bits > 100000) return std::nullopt;
    return PrecisionChoice{Precision::Mpfr, bits};
  }
  return std::nullopt;
}

inline std::string precisionName(const PrecisionChoice& p) {
  switch (p.kind) {
    case Precision::Float: return "float";
    case Precision::Double: return "double";
    case Precision::LongDouble: return "long-double";
    case Precision::Float128: return "float128";
    case Precision::Mpfr: return "mpfr:" + std::to_string(p.mpfrBits);
  }
  return "?";
}

// Calls f.template operator()<Real>() for the chosen scalar. For MPFR the thread's default
// precision is set first.
template <class F>
decltype(auto) withPrecision(const PrecisionChoice& p, F&& f) {
  switch (p.kind) {
    case Precision::Float: return f.template operator()<float>();
    case Precision::Double: return f.template operator()<double>();
    case Precision::LongDouble: return f.template operator()<long double>();
    case Precision::Float128: return f.template operator()<Float128>();
    case Precision::Mpfr:
      setMpfrBits(p.mpfrBits);
      return f.template operator()<MpfrReal>();
  }
  throw std::logic_error("unknown precision");
}

}  // namespace gizmo
