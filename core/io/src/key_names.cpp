#include "key_names.hpp"

#include <string>

#include "parse_util.hpp"

namespace gizmo::io::detail {
namespace {

struct NamedKey {
  std::string_view name;  // lower case, without '_' and '-'
  int code;               // Java's virtual key code (java.awt.event.KeyEvent), which the format writes
};

// The names Java (VK_BACK_SPACE), JavaFX (BACK_SPACE, DIGIT1) and the browsers (Backspace, ArrowLeft,
// KeyA, Digit1, ShiftLeft) give keys, once lower-cased, stripped of '_' and '-' and of the prefixes
// and sides keyCodeOfName takes off.
constexpr NamedKey kNamedKeys[] = {
    {"backspace", 8},    {"tab", 9},          {"enter", 10},      {"return", 10},       {"shift", 16},
    {"ctrl", 17},        {"control", 17},     {"alt", 18},        {"pause", 19},        {"caps", 20},
    {"capslock", 20},    {"esc", 27},         {"escape", 27},     {"space", 32},        {"spacebar", 32},
    {"pageup", 33},      {"pagedown", 34},    {"end", 35},        {"home", 36},         {"left", 37},
    {"up", 38},          {"right", 39},       {"down", 40},       {"comma", 44},        {"minus", 45},
    {"period", 46},      {"slash", 47},       {"semicolon", 59},  {"equals", 61},       {"equal", 61},
    {"openbracket", 91}, {"bracketleft", 91}, {"backslash", 92},  {"closebracket", 93}, {"bracketright", 93},
    {"multiply", 106},   {"add", 107},        {"subtract", 109},  {"decimal", 110},     {"divide", 111},
    {"delete", 127},     {"insert", 155},     {"backquote", 192}, {"quote", 222},
};

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

std::optional<int> letterOrDigit(std::string_view s) {
  if (s.size() != 1) return std::nullopt;
  const char c = s[0];
  if (c >= 'a' && c <= 'z') return c - 'a' + 'A';  // VK_A .. VK_Z are the upper-case letters
  if (c >= '0' && c <= '9') return c;              // VK_0 .. VK_9
  return std::nullopt;
}

// PREFIX followed by a number n in [low, high]: the code firstCode + (n − low).
std::optional<int> numbered(std::string_view s, std::string_view prefix, int low, int high, int firstCode) {
  if (!startsWith(s, prefix) || s.size() == prefix.size() || s.size() > prefix.size() + 2) return std::nullopt;
  int n = 0;
  for (const char c : s.substr(prefix.size())) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + (c - '0');
  }
  if (n < low || n > high) return std::nullopt;
  return firstCode + n - low;
}

std::optional<int> plainName(std::string_view s) {
  if (const std::optional<int> c = letterOrDigit(s)) return c;
  if (const std::optional<int> f = numbered(s, "f", 1, 12, 112)) return f;     // F1 .. F12
  if (const std::optional<int> n = numbered(s, "numpad", 0, 9, 96)) return n;  // NUMPAD0 .. NUMPAD9
  for (const NamedKey& k : kNamedKeys)
    if (k.name == s) return k.code;
  return std::nullopt;
}

}  // namespace

std::optional<int> keyCodeOfName(std::string_view name) {
  std::string s;
  for (const char c : toLowerAscii(name))
    if (c != '_' && c != '-') s += c;
  if (const std::optional<int> c = plainName(s)) return c;
  std::string_view v = s;
  if (startsWith(v, "vk")) v.remove_prefix(2);                           // Java: VK_LEFT
  else if (startsWith(v, "key") && v.size() == 4) v.remove_prefix(3);    // browsers' codes: KeyA
  else if (startsWith(v, "digit") && v.size() == 6) v.remove_prefix(5);  // JavaFX and browsers: DIGIT1
  else if (startsWith(v, "arrow")) v.remove_prefix(5);                   // browsers: ArrowLeft
  for (const std::string_view side : {"left", "right"})                  // browsers' codes: ShiftLeft, ControlRight
    if (v.size() > side.size() && v.substr(v.size() - side.size()) == side) {
      const std::string_view base = v.substr(0, v.size() - side.size());
      if (base == "shift" || base == "control" || base == "alt") return plainName(base);
    }
  return plainName(v);
}

}  // namespace gizmo::io::detail
