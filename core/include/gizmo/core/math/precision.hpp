#pragma once
// The precisions a run can use, by the names the command line and the logs use, and a
// dispatcher that calls a generic function with the matching scalar type.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "gizmo/core/math/scalar.hpp"

namespace gizmo {

enum class Precision { Float, Double, LongDouble, Float128, Mpfr, Bin50, Bin100, Rational };

struct PrecisionChoice {
  Precision kind = Precision::Double;
  long mpfrBits = 0;  // for Mpfr only
};

inline const char* const kPrecisionNames =
    "float, double, long-double, float128, bin50, bin100, mpfr:BITS (e.g. mpfr:256), rational";

inline std::optional<PrecisionChoice> parsePrecision(std::string_view name) {
  if (name == "float") return PrecisionChoice{Precision::Float, 0};
  if (name == "double") return PrecisionChoice{Precision::Double, 0};
  if (name == "long-double") return PrecisionChoice{Precision::LongDouble, 0};
  if (name == "float128") return PrecisionChoice{Precision::Float128, 0};
  if (name == "bin50") return PrecisionChoice{Precision::Bin50, 0};
  if (name == "bin100") return PrecisionChoice{Precision::Bin100, 0};
  if (name == "rational") return PrecisionChoice{Precision::Rational, 0};
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
    case Precision::Bin50: return "bin50";
    case Precision::Bin100: return "bin100";
    case Precision::Rational: return "rational";
  }
  return "?";
}

// Whether a run at this precision can be recorded: the replay log has an exact encoding for
// these scalars (replay/scalar_codec.hpp).
inline bool recordable(const PrecisionChoice& p) {
  return p.kind == Precision::Float || p.kind == Precision::Double || p.kind == Precision::LongDouble ||
         p.kind == Precision::Float128 || p.kind == Precision::Mpfr;
}

// The precisions this build can run: every one in the full build, the hardware floats in the
// portable build (GIZMO_PORTABLE).
inline bool builtHere(const PrecisionChoice& p) {
  return GIZMO_HAS_MULTIPRECISION || p.kind == Precision::Float || p.kind == Precision::Double ||
         p.kind == Precision::LongDouble;
}

inline std::string notBuiltHereMessage(const PrecisionChoice& p) {
  return "this is the portable build of gizmo, which has float, double and long-double: " + precisionName(p) +
         " needs the full build (docs/determinism.md)";
}

[[noreturn]] inline void throwNotBuiltHere(const PrecisionChoice& p) {
  throw std::invalid_argument(notBuiltHereMessage(p));
}

// Calls f.template operator()<Real>() for the chosen scalar, among those a log can hold; throws
// std::invalid_argument for the others. For MPFR the thread's default precision is set first.
template <class F>
decltype(auto) withRecordablePrecision(const PrecisionChoice& p, F&& f) {
  switch (p.kind) {
    case Precision::Float: return f.template operator()<float>();
    case Precision::Double: return f.template operator()<double>();
    case Precision::LongDouble: return f.template operator()<long double>();
#if GIZMO_HAS_MULTIPRECISION
    case Precision::Float128: return f.template operator()<Float128>();
    case Precision::Mpfr: setMpfrBits(p.mpfrBits); return f.template operator()<MpfrReal>();
#endif
    default:
      if (recordable(p)) throwNotBuiltHere(p);
      throw std::invalid_argument("a " + precisionName(p) + " run cannot be recorded: the log format has no " +
                                  "encoding for it (record with float, double, long-double, float128 or mpfr:BITS)");
  }
}

// The same for every scalar of the ladder.
template <class F>
decltype(auto) withPrecision(const PrecisionChoice& p, F&& f) {
  switch (p.kind) {
#if GIZMO_HAS_MULTIPRECISION
    case Precision::Bin50: return f.template operator()<Bin50>();
    case Precision::Bin100: return f.template operator()<Bin100>();
    case Precision::Rational: return f.template operator()<Rational>();
#endif
    default:
      if (!builtHere(p)) throwNotBuiltHere(p);
      return withRecordablePrecision(p, std::forward<F>(f));
  }
}

}  // namespace gizmo
