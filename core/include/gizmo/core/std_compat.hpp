#pragma once
// The few C++20 library pieces that one target's C++ library lacks (emscripten 3.1.6's libc++
// 13 has no std::bit_cast and no std::ranges algorithms), written once here and used by every
// target's build, so that no code forks on the library it is compiled with.
#include <algorithm>
#include <cstring>
#include <iterator>
#include <type_traits>

namespace gizmo {

// The same bits seen as another type of the same size, as std::bit_cast gives them (not
// constexpr). Copying the bytes is what std::bit_cast does too; compilers make it a register move.
template <class To, class From>
To bitCast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From), "bitCast needs two types of one size");
  static_assert(std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>,
                "bitCast copies bytes, so both types must be trivially copyable");
  static_assert(std::is_default_constructible_v<To>, "bitCast needs a To to copy into");
  To to;
  std::memcpy(&to, &from, sizeof(To));
  return to;
}

// Whether two ranges hold equal elements in the same order (std::ranges::equal of two ranges).
template <class A, class B>
bool sameElements(const A& a, const B& b) {
  return std::equal(std::begin(a), std::end(a), std::begin(b), std::end(b));
}

}  // namespace gizmo
