#include "key_names.hpp"

#include <string>

#include "parse_util.hpp"

namespace gizmo::io::detail {
namespace {

struct NamedKey {
  std::string_view name;  // lower case
  int code;
};

constexpr NamedKey kNamedKeys[] = {
    {"space", 32}, {"enter", 10},  {"tab", 9},     {"esc", 27},    {"escape", 27}, {"delete", 127},
    {"shift", 16}, {"ctrl", 17},   {"alt", 18},    {"left", 37},   {"up", 38},     {"right", 39},
    {"down", 40},  {"home", 36},   {"end", 35},    {"insert", 155},
};

}  // namespace

std::optional<int> keyCodeOfName(std::string_view name) {
  const std::string lower = toLowerAscii(name);
  if (lower.size() == 1) {
    const char c = lower[0];
    if (c >= 'a' && c <= 'z') return c - 'a' + 'A';  // VK_A .. VK_Z are the upper-case letters
    if (c >= '0' && c <= '9') return c;              // VK_0 .. VK_9
  }
  if (lower.size() >= 2 && lower.size() <= 3 && lower[0] == 'f') {  // F1 .. F12: 112 ..
    int n = 0;
    for (std::size_t i = 1; i < lower.size(); ++i) {
      if (lower[i] < '0' || lower[i] > '9') return std::nullopt;
      n = n * 10 + (lower[i] - '0');
    }
    if (n >= 1 && n <= 12) return 111 + n;
    return std::nullopt;
  }
  for (const NamedKey& k : kNamedKeys)
    if (k.name == lower) return k.code;
  return std::nullopt;
}

}  // namespace gizmo::io::detail
