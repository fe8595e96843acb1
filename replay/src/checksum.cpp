#include "gizmo/replay/checksum.hpp"

#include <bit>
#include <cstring>

namespace gizmo::replay {

namespace {

// memcpy rather than a pointer cast: the data has no alignment guarantee, and compilers turn a
// fixed 8-byte memcpy into a single load.
inline std::uint64_t loadWord(const std::uint8_t* p) {
  std::uint64_t w;
  std::memcpy(&w, p, sizeof w);
  if constexpr (std::endian::native == std::endian::big) w = __builtin_bswap64(w);
  return w;
}

}  // namespace

std::uint64_t checksum64(std::span<const std::uint8_t> data, std::uint64_t seed) {
  std::uint64_t h = seed ^ kChecksumStart;
  const std::uint8_t* p = data.data();
  const std::size_t fullWords = data.size() / 8;
  for (std::size_t i = 0; i < fullWords; ++i) h = mixChecksumWord(h, loadWord(p + 8 * i));

  const std::size_t tail = data.size() % 8;
  if (tail != 0) {
    std::uint8_t padded[8] = {};
    std::memcpy(padded, p + 8 * fullWords, tail);
    h = mixChecksumWord(h, loadWord(padded));
  }

  return finishChecksum(h, static_cast<std::uint64_t>(data.size()));
}

}  // namespace gizmo::replay
