// checksum64: the fast implementation against the algorithm as documented in checksum.hpp
// (written here the slow, literal way), and the detection properties the log relies on.
#include "gizmo/replay/checksum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace {

using gizmo::replay::checksum64;
using Bytes = std::vector<std::uint8_t>;

constexpr std::uint64_t kSeed = 20240611;

Bytes randomBytes(std::size_t n, std::mt19937_64& rng) {
  Bytes out(n);
  for (std::uint8_t& b : out) b = static_cast<std::uint8_t>(rng());
  return out;
}

// checksum.hpp's description, step by step, one byte at a time.
std::uint64_t literalChecksum(const Bytes& data, std::uint64_t seed) {
  auto rotl = [](std::uint64_t x, unsigned r) { return (x << r) | (x >> (64 - r)); };
  std::uint64_t h = seed ^ 0x9E3779B97F4A7C15ULL;
  for (std::size_t start = 0; start < data.size(); start += 8) {
    std::uint64_t w = 0;
    for (std::size_t i = 0; i < 8 && start + i < data.size(); ++i) {
      w |= std::uint64_t{data[start + i]} << (8 * i);
    }
    h = rotl(h ^ w, 31) * 0x9FB21C651E98DF25ULL;
  }
  h ^= data.size();
  h ^= h >> 32;
  h *= 0xD6E8FEB86659FD93ULL;
  h ^= h >> 32;
  return h;
}

TEST(ReplayChecksum, MatchesTheDocumentedAlgorithm) {
  SCOPED_TRACE("mt19937_64 seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  for (std::size_t n = 0; n <= 80; ++n) {
    const Bytes data = randomBytes(n, rng);
    const std::uint64_t seed = n % 3 == 0 ? 0 : rng();
    EXPECT_EQ(checksum64(data, seed), literalChecksum(data, seed)) << "length " << n;
  }
}

TEST(ReplayChecksum, EverySingleBitFlipChangesIt) {
  SCOPED_TRACE("mt19937_64 seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  Bytes data = randomBytes(200, rng);
  const std::uint64_t original = checksum64(data);
  for (std::size_t byte = 0; byte < data.size(); ++byte) {
    for (unsigned bit = 0; bit < 8; ++bit) {
      data[byte] ^= static_cast<std::uint8_t>(1u << bit);
      EXPECT_NE(checksum64(data), original) << "byte " << byte << " bit " << bit;
      data[byte] ^= static_cast<std::uint8_t>(1u << bit);
    }
  }
  EXPECT_EQ(checksum64(data), original);
}

TEST(ReplayChecksum, AnyChangeWithinOneWordChangesIt) {
  SCOPED_TRACE("mt19937_64 seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  for (std::size_t n : {1u, 7u, 8u, 9u, 63u, 200u}) {
    const Bytes data = randomBytes(n, rng);
    const std::uint64_t original = checksum64(data, 5);
    for (int trial = 0; trial < 500; ++trial) {
      Bytes changed = data;
      const std::size_t word = rng() % ((n + 7) / 8);
      const std::size_t end = std::min(n, 8 * word + 8);
      bool differs = false;
      for (std::size_t i = 8 * word; i < end; ++i) {
        changed[i] = static_cast<std::uint8_t>(rng());
        differs = differs || changed[i] != data[i];
      }
      if (differs) {
        EXPECT_NE(checksum64(changed, 5), original) << "length " << n << " word " << word;
      }
    }
  }
}

TEST(ReplayChecksum, ZeroRunsOfDifferentLengthsDiffer) {
  std::set<std::uint64_t> seen;
  for (std::size_t n = 0; n <= 256; ++n) {
    EXPECT_TRUE(seen.insert(checksum64(Bytes(n, 0))).second) << "length " << n;
  }
}

TEST(ReplayChecksum, SeedChangesIt) {
  const Bytes data = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  std::set<std::uint64_t> seen;
  for (std::uint64_t seed = 0; seed < 64; ++seed) {
    EXPECT_TRUE(seen.insert(checksum64(data, seed)).second) << "seed " << seed;
    EXPECT_NE(checksum64(Bytes{}, seed), checksum64(Bytes{}, seed ^ (std::uint64_t{1} << 63)));
  }
}

TEST(ReplayChecksum, UnalignedDataGivesTheSameResult) {
  SCOPED_TRACE("mt19937_64 seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  const Bytes data = randomBytes(100, rng);
  for (std::size_t offset = 0; offset < 8; ++offset) {
    const Bytes copy(data.begin() + static_cast<std::ptrdiff_t>(offset), data.end());
    EXPECT_EQ(checksum64(std::span<const std::uint8_t>(data).subspan(offset)), checksum64(copy));
  }
}

}  // namespace
