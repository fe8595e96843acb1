#pragma once
// A board's saved state (gizmo/core/board/board_state.hpp) as bytes: a keyframe. Every scalar
// is exact; times are written against the state's own time, numbers of a gizmo against the one
// before, so that a keyframe stays small.
#include "gizmo/core/board/board_state.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/scalar_codec.hpp"

namespace gizmo::replay {

template <class Real>
void writeState(ByteWriter& out, const BoardState<Real>& s) {
  const Real zero(0);
  writeScalar(out, s.now, zero);
  out.varint(s.executedTotal);
  for (std::uint64_t n : s.executed) out.varint(n);
  out.varint(s.eventsInBurst);
  writeScalar(out, s.jamWindowStart, s.now);
  out.varint(s.collisionsInWindow);
  out.varint(s.nextInput);
  out.varint(s.nextSequence);
  out.varint(s.events.size());
  std::uint64_t previous = 0;
  for (const Event<Real>& e : s.events) {
    out.u8(static_cast<std::uint8_t>(e.kind));
    out.svarint(e.a);
    out.svarint(e.b);
    out.svarint(e.feature);
    out.varint(e.sequence - previous);  // ascending: small steps
    previous = e.sequence;
    writeScalar(out, e.time, s.now);
  }
  out.varint(s.gizmos.size());
  for (std::size_t g = 0; g < s.gizmos.size(); ++g) {
    const Box<Real>& b = s.boxes[g];
    writeScalar(out, b.lo.x, zero);
    writeScalar(out, b.lo.y, zero);
    writeScalar(out, b.hi.x, b.lo.x);
    writeScalar(out, b.hi.y, b.lo.y);
    writeScalar(out, s.validUntil[g], s.now);
    const GizmoState<Real>& gs = s.gizmos[g];
    out.varint(gs.reals.size());
    Real base = s.now;
    for (const Real& r : gs.reals) {
      writeScalar(out, r, base);
      base = r;
    }
    out.varint(gs.ints.size());
    for (std::int64_t i : gs.ints) out.svarint(i);
  }
}

template <class Real>
BoardState<Real> readState(ByteReader& in) {
  // Counts are checked against the bytes left, so a corrupt count cannot ask for a huge vector.
  auto count = [&](std::size_t minBytesEach) {
    const std::size_t at = in.position();
    const std::uint64_t n = in.varint();
    if (n > in.remaining() / minBytesEach) throw FormatError("keyframe: a count larger than its bytes", at);
    return static_cast<std::size_t>(n);
  };
  BoardState<Real> s;
  const Real zero(0);
  s.now = readScalar<Real>(in, zero);
  s.executedTotal = in.varint();
  for (std::uint64_t& n : s.executed) n = in.varint();
  s.eventsInBurst = in.varint();
  s.jamWindowStart = readScalar<Real>(in, s.now);
  s.collisionsInWindow = in.varint();
  s.nextInput = in.varint();
  s.nextSequence = in.varint();
  s.events.resize(count(6));
  std::uint64_t previous = 0;
  for (Event<Real>& e : s.events) {
    const std::size_t at = in.position();
    const std::uint8_t kind = in.u8();
    if (kind >= kEventKindCount) throw FormatError("keyframe: unknown event kind", at);
    e.kind = static_cast<EventKind>(kind);
    auto id = [&] {
      const std::int64_t v = in.svarint();
      if (v < INT32_MIN || v > INT32_MAX) throw FormatError("keyframe: number out of range", at);
      return static_cast<std::int32_t>(v);
    };
    e.a = id();
    e.b = id();
    e.feature = id();
    e.sequence = previous + in.varint();
    previous = e.sequence;
    e.time = readScalar<Real>(in, s.now);
  }
  const std::size_t n = count(6);
  s.boxes.resize(n);
  s.validUntil.resize(n);
  s.gizmos.resize(n);
  for (std::size_t g = 0; g < n; ++g) {
    Box<Real>& b = s.boxes[g];
    b.lo.x = readScalar<Real>(in, zero);
    b.lo.y = readScalar<Real>(in, zero);
    b.hi.x = readScalar<Real>(in, b.lo.x);
    b.hi.y = readScalar<Real>(in, b.lo.y);
    s.validUntil[g] = readScalar<Real>(in, s.now);
    GizmoState<Real>& gs = s.gizmos[g];
    gs.reals.resize(count(1));
    Real base = s.now;
    for (Real& r : gs.reals) {
      r = readScalar<Real>(in, base);
      base = r;
    }
    gs.ints.resize(count(1));
    for (std::int64_t& i : gs.ints) i = in.svarint();
  }
  return s;
}

}  // namespace gizmo::replay
