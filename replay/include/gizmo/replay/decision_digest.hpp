#pragma once
// A 64-bit digest of a chunk's decisions, taken from the board's reports themselves and not from
// their encoding. The recorder writes each chunk's digest into the index; replaying computes it
// again from a re-simulation that encodes nothing, and compares chunk by chunk. Only a chunk
// whose digest differs is encoded and compared record by record (docs/replay-format.md, "Chunk
// digests", defines the words mixed for each report).
#include <algorithm>
#include <cstdint>

#include "gizmo/core/board/observer.hpp"
#include "gizmo/replay/checksum.hpp"
#include "gizmo/replay/scalar_codec.hpp"

namespace gizmo::replay {

template <class Real>
class DecisionDigest {
 public:
  void reset() {
    h_ = kChecksumStart;
    words_ = 0;
  }
  // The digest of the reports since the last reset.
  std::uint64_t value() const { return finishChecksum(h_, words_); }

  void scheduled(const Event<Real>& e) {
    mix(1 | std::uint64_t(e.kind) << 8 | std::uint64_t(std::uint32_t(e.feature)) << 32);
    mix(pair(e.a, e.b));
    scalar(e.time);
  }
  void removed(const Event<Real>& e) {
    mix(2);
    mix(e.sequence);
  }
  void executed(const Event<Real>& e, const EventOutcome<Real>& o) {
    mix(3 | std::uint64_t(o.count) << 8);
    mix(e.sequence);
    for (const BallChange<Real>& c : o.balls()) {
      mix(std::uint64_t(std::uint32_t(c.ball)));
      vec(c.position);
      vec(c.velocityBefore);
      vec(c.velocityAfter);
    }
  }
  void trigger(const Real& t, GizmoId source, GizmoId target) {
    mix(4);
    mix(pair(source, target));
    scalar(t);
  }
  void action(const Real& t, GizmoId target) {
    mix(5 | std::uint64_t(std::uint32_t(target)) << 32);
    scalar(t);
  }
  void input(const Real& t, int key, KeyDirection d) {
    mix(6 | std::uint64_t(d) << 8 | std::uint64_t(std::uint32_t(key)) << 32);
    scalar(t);
  }
  void rule(const Real& t, ModelRule r, GizmoId g, GizmoId other) {
    mix(7 | std::uint64_t(r) << 8);
    mix(pair(g, other));
    scalar(t);
  }
  void tick(const Real& t) {
    mix(8);
    scalar(t);
  }

 private:
  static std::uint64_t pair(std::int32_t low, std::int32_t high) {
    return std::uint64_t(std::uint32_t(low)) | std::uint64_t(std::uint32_t(high)) << 32;
  }
  void mix(std::uint64_t w) {
    h_ = mixChecksumWord(h_, w);
    ++words_;
  }
  void vec(const Vec2<Real>& v) {
    scalar(v.x);
    scalar(v.y);
  }
  // A scalar's exact encoding (ScalarCodec), as words: the bits of a float or double; the raw
  // bytes of the wider fixed-width types; MPFR's exact form. Little-endian, zero-padded.
  void scalar(const Real& v) {
    if constexpr (detail::WordCodec<Real>) {
      mix(std::uint64_t(ScalarCodec<Real>::toBits(v)));
    } else if constexpr (detail::FixedWidthCodec<Real>) {
      bytes(ScalarCodec<Real>::toBytes(v));
    } else {
      ByteWriter w;
      ScalarCodec<Real>::write(w, v);
      mix(w.size());
      bytes(w.bytes());
    }
  }
  template <class Bytes>
  void bytes(const Bytes& b) {
    for (std::size_t at = 0; at < b.size(); at += 8)
      mix(detail::loadLittleEndian(b.data() + at, std::min<std::size_t>(8, b.size() - at)));
  }

  std::uint64_t h_ = kChecksumStart;
  std::uint64_t words_ = 0;
};

}  // namespace gizmo::replay
