#pragma once
// A chunk's payload: its preamble, its keyframe (the board's full state and that state's hash;
// absent in the first chunk, which starts from the board as built) and then its records.
#include <optional>

#include "gizmo/replay/checksum.hpp"
#include "gizmo/replay/log_file.hpp"
#include "gizmo/replay/record_codec.hpp"
#include "gizmo/replay/state_codec.hpp"

namespace gizmo::replay {

// The state's bytes as written in a keyframe, and the hash a keyframe carries.
template <class Real>
std::vector<std::uint8_t> stateBytes(const BoardState<Real>& s) {
  ByteWriter w;
  writeState(w, s);
  const auto b = w.bytes();
  return {b.begin(), b.end()};
}
inline std::uint64_t stateHash(std::span<const std::uint8_t> bytes) { return checksum64(bytes); }

template <class Real>
struct OpenedChunk {
  ChunkPreamble preamble;
  std::optional<BoardState<Real>> keyframe;
  std::uint64_t keyframeHash = 0;
  std::size_t recordsAt = 0;  // where the records start in the payload
};

// A chunk's preamble and its keyframe's bytes (empty in the first chunk), checked against the
// keyframe's hash but not decoded.
struct ChunkStart {
  ChunkPreamble preamble;
  std::span<const std::uint8_t> keyframe;
  std::size_t keyframeAt = 0;  // where the keyframe's length is in the payload
  std::uint64_t keyframeHash = 0;
  std::size_t recordsAt = 0;  // where the records start in the payload
};
inline ChunkStart readChunkStart(std::span<const std::uint8_t> payload) {
  ChunkStart c;
  ByteReader r(payload);
  r.span(readPreamble(payload, c.preamble));
  if (c.preamble.hasKeyframe) {
    c.keyframeAt = r.position();
    const std::uint64_t n = r.varint();
    if (n > r.remaining()) throw FormatError("keyframe longer than its chunk", c.keyframeAt);
    c.keyframe = r.span(static_cast<std::size_t>(n));
    c.keyframeHash = r.u64();
    if (stateHash(c.keyframe) != c.keyframeHash) throw FormatError("keyframe does not match its hash", c.keyframeAt);
  }
  c.recordsAt = r.position();
  return c;
}

// Reads a chunk's preamble and keyframe, checking the keyframe against its hash.
template <class Real>
OpenedChunk<Real> openChunk(std::span<const std::uint8_t> payload) {
  const ChunkStart start = readChunkStart(payload);
  OpenedChunk<Real> c;
  c.preamble = start.preamble;
  c.keyframeHash = start.keyframeHash;
  c.recordsAt = start.recordsAt;
  if (c.preamble.hasKeyframe) {
    ByteReader s(start.keyframe);
    c.keyframe = readState<Real>(s);
    if (!s.atEnd()) throw FormatError("keyframe: bytes after the state", start.keyframeAt + s.position());
  }
  return c;
}

// A decoder positioned at the chunk's first record, its context set from the keyframe.
template <class Real>
class ChunkRecords {
 public:
  ChunkRecords(std::span<const std::uint8_t> payload, const OpenedChunk<Real>& c, const PhysicsParams<Real>& params,
               std::size_t maxQueued)
      : reader_(payload), decoder_(reader_, params, maxQueued) {
    reader_.span(c.recordsAt);
    if (c.keyframe) decoder_.reset(c.keyframe->now, c.keyframe->events, c.keyframe->nextSequence);
    else decoder_.reset(Real(0), {}, 0);
  }
  bool atEnd() const { return decoder_.atEnd(); }
  Decision<Real> next() { return decoder_.next(); }
  std::size_t position() const { return reader_.position(); }

 private:
  ByteReader reader_;
  RecordDecoder<Real> decoder_;
};

}  // namespace gizmo::replay
