#pragma once
// The checksum that guards every part of the replay log.
#include <bit>
#include <cstdint>
#include <span>

namespace gizmo::replay {

// checksum64, exactly (all arithmetic on unsigned 64-bit words, modulo 2^64):
//
//   h = seed XOR 0x9E3779B97F4A7C15
//   for each 8-byte word w of the data, in order, read little-endian (byte i is bits 8i..8i+7);
//   a last partial word of 1..7 bytes is padded with zero bytes at its high end to 8 bytes:
//       h = rotl64(h XOR w, 31) * 0x9FB21C651E98DF25
//   h = h XOR (length of the data in bytes)
//   h = h XOR (h >> 32)
//   h = h * 0xD6E8FEB86659FD93
//   h = h XOR (h >> 32)
//   result = h
//
// rotl64(x, r) = (x << r) | (x >> (64 - r)). The empty input mixes no word at all.
//
// Why it detects every change confined to one 8-byte word (in particular any single corrupted
// byte or bit): each step is a bijection of h — XOR with a fixed word, a rotation, a
// multiplication by an odd constant (invertible modulo 2^64), and x ^ (x >> 32) (its high half
// is unchanged, from which the low half is recovered). Two inputs of the same length that differ
// only in word k give the same h before word k, different values of h XOR w at word k, and from
// there on the same sequence of bijections, hence different results.
std::uint64_t checksum64(std::span<const std::uint8_t> data, std::uint64_t seed = 0);

// Its steps, for digests that mix words as they come (decision_digest.hpp): the start, one word
// mixed in, and the finish given the length.
inline constexpr std::uint64_t kChecksumStart = 0x9E3779B97F4A7C15ULL;
inline std::uint64_t mixChecksumWord(std::uint64_t h, std::uint64_t w) {
  return std::rotl(h ^ w, 31) * 0x9FB21C651E98DF25ULL;
}
inline std::uint64_t finishChecksum(std::uint64_t h, std::uint64_t length) {
  h ^= length;
  h ^= h >> 32;
  h *= 0xD6E8FEB86659FD93ULL;
  return h ^ (h >> 32);
}

}  // namespace gizmo::replay
