#pragma once
// The one spelling of exact hexadecimal floating-point text shared by every scalar's exactText.
#include <string>

namespace gizmo::replay::detail {

// "[-]0x<leading>[.<fraction>]p<+|-><exponent>"; fractionDigits are the hexadecimal digits after
// the point (trailing zeros are dropped here). A zero is written "0x0p+0" by the caller passing
// leading 0, no digits and exponent 0.
std::string hexFloatText(bool negative, unsigned leading, std::string fractionDigits, long long exponent);

}  // namespace gizmo::replay::detail
