#pragma once
// Doubles to and from decimal text, as std::to_chars and std::from_chars give them: the board
// writer's canonical numbers (part of every replay log's header, so they must be the same bytes
// on every machine) and the readers' numbers. The C++ library of Debian's emscripten (3.1.6, LLVM
// 14's libc++) lacks the floating-point overloads, so every target makes the same results from
// printf and strtod, both correctly rounded in the C libraries of every target (docs/determinism.md);
// tests/unit/core_decimal_text_test.cpp checks them against std::to_chars and std::from_chars.
#include <string>
#include <string_view>

namespace gizmo {

// The shortest decimal that reads back to v (finite), in fixed or scientific notation, whichever
// is shorter, fixed on a tie: std::to_chars(first, last, v).
std::string shortestDecimal(double v);
// The same digits, always in fixed notation: std::to_chars(first, last, v, chars_format::fixed).
std::string shortestFixedDecimal(double v);

enum class DecimalParse { Ok, Malformed, OutOfRange };
// Reads all of `text`, a decimal number without a leading '+' (std::from_chars with
// chars_format::general); `value` is set only when Ok.
DecimalParse parseDecimalDouble(std::string_view text, double& value);

}  // namespace gizmo
