#pragma once
// The replay log's constants: every number here is written into files, so none may change
// without a new format version (docs/replay-format.md describes the bytes).
#include <cstdint>
#include <string_view>

namespace gizmo::replay {

inline constexpr std::string_view kMagic = "GIZMOLOG";
inline constexpr std::string_view kTrailerMagic = "GIZMOEND";
inline constexpr std::uint16_t kFormatVersion = 4;
// A branch log (a run taken over at a moment of another log, `gizmo record --from`): version 4
// with the header's parent fields, and a keyframe in its first chunk too. Every other log is
// still written as version 4, byte for byte as before.
inline constexpr std::uint16_t kBranchFormatVersion = 5;
inline constexpr std::size_t kFileHeaderSize = 12;  // magic, u16 version, u16 reserved
inline constexpr std::size_t kFrameHeaderSize = 5;  // u8 type, u32 payload length
inline constexpr std::size_t kFrameChecksumSize = 8;
inline constexpr std::size_t kTrailerSize = 16;  // u64 index frame offset, trailer magic
// No frame of a sane log comes near this; a larger length is corruption, not a big run.
inline constexpr std::uint32_t kMaxFramePayload = 1u << 30;

enum class FrameType : std::uint8_t { Header = 'H', Chunk = 'C', Index = 'I' };

// A chunk is closed at the first tick boundary after its records pass this many bytes (or
// eight times its keyframe, for boards whose state is large).
inline constexpr std::size_t kChunkTargetBytes = 64 * 1024;

// Record tags. A tag with the high bit clear is an event scheduled: bits 0–2 its kind, bits
// 3–5 how its time is written (TimeForm), bit 6 set when a, b and feature are all written
// (otherwise only the fields its kind uses, see scheduledFields).
inline constexpr std::uint8_t kScheduledAllFields = 0x40;
enum class TimeForm : std::uint8_t {
  Now = 0,           // the current time
  NowPlusTick = 1,   // now + maxTick
  FrictionGrid = 2,  // k · frictionStep, varint k
  TickGrid = 3,      // k · maxTick, varint k
  Explicit = 4,      // a scalar, written against now
};

// Tags with the high bit set: the type in bits 4–6, details in bits 0–3.
enum class RecordType : std::uint8_t {
  Removed = 0x80,   // bits 0–3: sequence distance (15: a varint follows)
  Executed = 0x90,  // bit 3: ball a changed, bit 2: ball b changed, bits 0–1: distance (3: varint)
  Trigger = 0xA0,
  Action = 0xB0,
  Input = 0xC0,  // bit 0: key up
  Rule = 0xD0,   // bits 0–3: the model rule
  Tick = 0xE0,
  Time = 0xF0,  // the current time moves without an event (never in a normal run)
};

}  // namespace gizmo::replay
