#pragma once
// The fuzzer's only source of randomness: SplitMix64 from an explicit seed. It is ours rather than
// <random>'s distributions because those are implementation-defined (libstdc++ and libc++ draw
// different numbers from the same engine), and a campaign's case k must be the same board on every
// machine of a cluster. Only integer arithmetic and exact scalings of integers: no libm.
#include <cstdint>

namespace gizmo::verify::fuzz {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi] (inclusive); lo <= hi. The tiny modulo bias is irrelevant here.
  int whole(int lo, int hi) {
    const std::uint64_t span = std::uint64_t(std::int64_t(hi) - std::int64_t(lo)) + 1;
    return int(std::int64_t(lo) + std::int64_t(next() % span));
  }
  // Uniform in [0, 1): the top 53 bits, scaled exactly.
  double unit() { return double(next() >> 11) * 0x1.0p-53; }
  double real(double lo, double hi) { return lo + (hi - lo) * unit(); }
  bool chance(int oneIn) { return whole(1, oneIn) == 1; }

 private:
  std::uint64_t state_;
};

// Mixes a campaign seed with a case index into the seed of that case: every case is generated on
// its own, so cases can run in any order, on any thread, in any shard.
inline std::uint64_t caseSeed(std::uint64_t campaignSeed, std::uint64_t index) {
  SeededRandom r(campaignSeed ^ (index * 0xd1b54a32d192ed03ULL));
  r.next();
  return r.next();
}

}  // namespace gizmo::verify::fuzz
