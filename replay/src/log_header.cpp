// The header frame's bytes (log_header.hpp, docs/replay-format.md).
#include "gizmo/replay/log_header.hpp"

#include "gizmo/core/std_compat.hpp"

#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/replay/checksum.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_format.hpp"

#ifndef GIZMO_VERSION
#error "GIZMO_VERSION is defined by replay/CMakeLists.txt"
#endif

namespace gizmo::replay {
namespace {

std::span<const std::uint8_t> asBytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

void writeString(ByteWriter& w, const std::string& s) {
  w.varint(s.size());
  w.bytes(s.data(), s.size());
}

std::string readString(ByteReader& r, std::size_t limit, const char* what) {
  const std::size_t at = r.position();
  const std::uint64_t n = r.varint();
  if (n > limit || n > r.remaining()) throw FormatError(std::string("header: ") + what + " longer than the frame", at);
  const auto b = r.span(static_cast<std::size_t>(n));
  return {b.begin(), b.end()};
}

}  // namespace

LogHeader headerFor(const RunRequest& request, const std::string& precision, const std::string& scalar,
                    const std::string& format, std::vector<std::uint8_t> params) {
  LogHeader h;
  h.toolkit = GIZMO_VERSION;
  h.precision = precision;
  h.scalar = scalar;
  h.format = format;
  h.model = request.model;
  h.maxTick = request.maxTick;
  h.duration = request.duration;
  h.keys = request.keys;
  h.board = io::writeTextBoard(request.board);
  h.boardHash = checksum64(asBytes(h.board));
  h.params = std::move(params);
  return h;
}

std::vector<std::uint8_t> encodeHeader(const LogHeader& h) {
  ByteWriter w;
  writeString(w, h.toolkit);
  writeString(w, h.precision);
  writeString(w, h.scalar);
  writeString(w, h.format);
  w.u8(static_cast<std::uint8_t>(h.model));
  w.u64(gizmo::bitCast<std::uint64_t>(h.maxTick));
  w.u64(gizmo::bitCast<std::uint64_t>(h.duration));
  w.varint(h.keys.size());
  for (const TimedKey& k : h.keys) {
    w.u64(gizmo::bitCast<std::uint64_t>(k.time));
    w.svarint(k.key);
    w.u8(k.direction == KeyDirection::Up ? 1 : 0);
  }
  writeString(w, h.board);
  w.u64(h.boardHash);
  w.varint(h.boardWarnings.size());
  for (const std::string& warning : h.boardWarnings) writeString(w, warning);
  w.varint(h.params.size());
  w.bytes(h.params.data(), h.params.size());
  if (h.parent) {
    w.u64(h.parent->parentDigest);
    w.varint(h.parent->event);
  }
  const auto b = w.bytes();
  return {b.begin(), b.end()};
}

LogHeader decodeHeader(std::span<const std::uint8_t> payload, std::uint16_t version) {
  ByteReader r(payload);
  LogHeader h;
  h.toolkit = readString(r, 256, "toolkit version");
  h.precision = readString(r, 256, "precision");
  h.scalar = readString(r, 256, "scalar");
  h.format = readString(r, 256, "scalar format");
  const std::uint8_t model = r.u8();
  if (model > 1) throw FormatError("header: unknown motion model", r.position() - 1);
  h.model = static_cast<MotionModel>(model);
  h.maxTick = gizmo::bitCast<double>(r.u64());
  h.duration = gizmo::bitCast<double>(r.u64());
  const std::size_t at = r.position();
  const std::uint64_t n = r.varint();
  if (n > r.remaining() / 10) throw FormatError("header: more keys than bytes", at);
  for (std::uint64_t i = 0; i < n; ++i) {
    TimedKey k;
    k.time = gizmo::bitCast<double>(r.u64());
    const std::int64_t key = r.svarint();
    if (key < INT32_MIN || key > INT32_MAX) throw FormatError("header: key code out of range", r.position());
    k.key = static_cast<int>(key);
    const std::uint8_t dir = r.u8();
    if (dir > 1) throw FormatError("header: bad key direction", r.position() - 1);
    k.direction = dir ? KeyDirection::Up : KeyDirection::Down;
    h.keys.push_back(k);
  }
  h.board = readString(r, payload.size(), "board");
  h.boardHash = r.u64();
  const std::size_t warningsAt = r.position();
  const std::uint64_t warnings = r.varint();
  if (warnings > r.remaining()) throw FormatError("header: more board warnings than bytes", warningsAt);
  for (std::uint64_t i = 0; i < warnings; ++i) h.boardWarnings.push_back(readString(r, 4096, "board warning"));
  const std::string params = readString(r, 4096, "parameters");
  h.params.assign(params.begin(), params.end());
  if (version >= kBranchFormatVersion) {
    if (r.atEnd())
      throw FormatError("header: a branch log (format version 5) whose header does not name its parent", r.position());
    BranchOrigin parent;
    parent.parentDigest = r.u64();
    parent.event = r.varint();
    h.parent = parent;
  }
  if (!r.atEnd()) throw FormatError("header: bytes after its end", r.position());
  return h;
}

RunRequest requestOf(const LogHeader& h) {
  if (checksum64(asBytes(h.board)) != h.boardHash) throw FormatError("header: the board does not match its hash", 0);
  RunRequest r;
  io::ReadResult read;
  try {
    read = io::readBoardString(h.board, "the log's board");
  } catch (const std::exception& e) {
    throw FormatError(std::string("header: the embedded board does not read: ") + e.what(), 0);
  }
  // The board is in the writer's canonical text, which the build that wrote it reads as written: a
  // warning here means this build reads it otherwise (a kind it was built without, or one from
  // after it), and every gizmo id after the line it leaves out would name another gizmo.
  if (!read.warnings.empty())
    throw FormatError("header: this build does not read the log's board as written: " + io::format(read.warnings[0]),
                      0);
  r.board = std::move(read.board);
  r.model = h.model;
  r.maxTick = h.maxTick;
  r.duration = h.duration;
  r.keys = h.keys;
  if (!(h.maxTick > 0) || !(h.duration >= 0)) throw FormatError("header: bad tick length or duration", 0);
  return r;
}

}  // namespace gizmo::replay
