#pragma once
// Little-endian fixed-width integers and LEB128 varints, written into a growing buffer and read
// back with bounds checks. The writer sits on the simulator's hot path (one call per recorded
// number), so every write is inline and only vector growth ever allocates.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace gizmo::replay {

namespace detail {

// Out of line and cold: keeps the throwing code (string building) off the inline fast paths.
[[noreturn, gnu::cold]] void throwUnderflow(std::size_t offset, std::size_t wanted, std::size_t available);
[[noreturn, gnu::cold]] void throwBadVarint(std::size_t offset, const char* problem);

// Stores the low `width` (<= 8) bytes of `value` at `out`, lowest byte first.
inline void storeLittleEndian(std::uint8_t* out, std::uint64_t value, std::size_t width) {
  for (std::size_t i = 0; i < width; ++i) out[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

inline std::uint64_t loadLittleEndian(const std::uint8_t* in, std::size_t width) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < width; ++i) value |= std::uint64_t{in[i]} << (8 * i);
  return value;
}

inline std::uint64_t zigzag(std::int64_t v) {
  // Small magnitudes of either sign become small unsigned numbers: 0, -1, 1, -2 → 0, 1, 2, 3.
  return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}

inline std::int64_t unzigzag(std::uint64_t u) { return static_cast<std::int64_t>((u >> 1) ^ (0 - (u & 1))); }

// LEB128 stored at p, which must have room for kMaxVarintBytes; returns the end.
[[gnu::always_inline]] inline std::uint8_t* putVarint(std::uint8_t* p, std::uint64_t v) {
  while (v >= 0x80) {
    *p++ = static_cast<std::uint8_t>(v | 0x80);
    v >>= 7;
  }
  *p++ = static_cast<std::uint8_t>(v);
  return p;
}

}  // namespace detail

// The longest LEB128 encoding of a 64-bit number: ceil(64 / 7) bytes.
inline constexpr std::size_t kMaxVarintBytes = 10;

// Appends to a buffer it owns. The vector's size is the writer's capacity, and size() counts the
// bytes written: the fast path then never goes through vector::resize or insert, which are out of
// line in libstdc++, only through a comparison and a memcpy-sized store.
class ByteWriter {
 public:
  ByteWriter() = default;
  explicit ByteWriter(std::size_t initialCapacity) : buffer_(initialCapacity) {}

  [[gnu::always_inline]] void u8(std::uint8_t v) {
    ensure(1);
    buffer_[used_++] = v;
  }
  void u16(std::uint16_t v) { littleEndian(v, 2); }
  void u32(std::uint32_t v) { littleEndian(v, 4); }
  void u64(std::uint64_t v) { littleEndian(v, 8); }

  // The low `width` (0..8) bytes of `v`, lowest first.
  [[gnu::always_inline]] void littleEndian(std::uint64_t v, std::size_t width) {
    // Storing all 8 bytes lets the compiler emit one store whatever the width; the bytes beyond
    // `width` lie in spare capacity and are overwritten by the next write.
    ensure(8);
    detail::storeLittleEndian(buffer_.data() + used_, v, 8);
    used_ += width;
  }

  // Unsigned LEB128: 7 bits per byte, lowest group first, high bit set on all but the last byte.
  [[gnu::always_inline]] void varint(std::uint64_t v) { commit(detail::putVarint(claim(kMaxVarintBytes), v)); }

  // Zigzag, then LEB128.
  [[gnu::always_inline]] void svarint(std::int64_t v) { varint(detail::zigzag(v)); }

  [[gnu::always_inline]] void bytes(const void* data, std::size_t count) {
    if (count == 0) return;  // data may then be null, which memcpy does not allow
    ensure(count);
    std::memcpy(buffer_.data() + used_, data, count);
    used_ += count;
  }

  // For a run of writes of bounded total size: claim room once, store through the pointer, then
  // commit where the stores end. Nothing else may write in between.
  [[gnu::always_inline]] std::uint8_t* claim(std::size_t n) {
    ensure(n);
    return buffer_.data() + used_;
  }
  [[gnu::always_inline]] void commit(const std::uint8_t* end) {
    used_ = static_cast<std::size_t>(end - buffer_.data());
  }

  // Bytes written since construction or the last clear().
  std::size_t size() const noexcept { return used_; }
  std::span<const std::uint8_t> bytes() const noexcept { return {buffer_.data(), used_}; }
  // Forgets the bytes but keeps the capacity, so a writer reused per chunk stops allocating.
  void clear() noexcept { used_ = 0; }
  void reserve(std::size_t capacity) {
    if (capacity > buffer_.size()) buffer_.resize(capacity);
  }

 private:
  [[gnu::always_inline]] void ensure(std::size_t extra) {
    if (buffer_.size() - used_ < extra) grow(extra);
  }
  // Out of line and cold, so that the writes above stay small enough to inline.
  [[gnu::noinline, gnu::cold]] void grow(std::size_t extra) {
    std::size_t capacity = buffer_.size() < 64 ? 64 : buffer_.size() * 2;
    if (capacity - used_ < extra) capacity = used_ + extra;
    buffer_.resize(capacity);
  }

  std::vector<std::uint8_t> buffer_;
  std::size_t used_ = 0;
};

// Reads what ByteWriter writes. Every read checks its bounds and throws FormatError, with the
// offset (within `data`) where the failing item starts, instead of reading past the end.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> data) noexcept : data_(data) {}

  std::uint8_t u8() {
    need(1);
    return data_[pos_++];
  }
  std::uint16_t u16() { return static_cast<std::uint16_t>(littleEndian(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(littleEndian(4)); }
  std::uint64_t u64() { return littleEndian(8); }

  // The inverse of ByteWriter::littleEndian: `width` (0..8) bytes, lowest first.
  std::uint64_t littleEndian(std::size_t width) {
    need(width);
    const std::uint64_t v = detail::loadLittleEndian(data_.data() + pos_, width);
    pos_ += width;
    return v;
  }

  // Refuses, besides a truncated varint, one of more than 10 bytes, one whose value needs more
  // than 64 bits, and a redundant encoding (a last byte of 0 after the first): every number has
  // exactly one encoding, so re-encoding what was read gives back the same bytes.
  std::uint64_t varint() {
    if (pos_ < data_.size() && data_[pos_] < 0x80) return data_[pos_++];  // 0..127: one byte
    const std::size_t start = pos_;
    std::uint64_t value = 0;
    for (unsigned shift = 0;; shift += 7) {
      if (pos_ == data_.size()) detail::throwBadVarint(start, "truncated varint");
      const std::uint8_t b = data_[pos_++];
      if (shift == 63) {  // the 10th byte may only hold the top bit of the value
        if (b & 0x80) detail::throwBadVarint(start, "varint longer than 10 bytes");
        if (b > 1) detail::throwBadVarint(start, "varint overflows 64 bits");
      }
      value |= std::uint64_t{b & 0x7Fu} << shift;
      if ((b & 0x80) == 0) {
        if (b == 0 && shift != 0) detail::throwBadVarint(start, "varint with a redundant zero byte");
        return value;
      }
    }
  }

  std::int64_t svarint() { return detail::unzigzag(varint()); }

  void bytes(void* out, std::size_t count) {
    need(count);
    if (count != 0) std::memcpy(out, data_.data() + pos_, count);
    pos_ += count;
  }

  // The next `count` bytes, without copying; the reader moves past them.
  std::span<const std::uint8_t> span(std::size_t count) {
    need(count);
    const std::span<const std::uint8_t> s = data_.subspan(pos_, count);
    pos_ += count;
    return s;
  }

  std::size_t remaining() const noexcept { return data_.size() - pos_; }
  std::size_t position() const noexcept { return pos_; }
  bool atEnd() const noexcept { return pos_ == data_.size(); }

 private:
  void need(std::size_t count) const {
    if (data_.size() - pos_ < count) detail::throwUnderflow(pos_, count, data_.size() - pos_);
  }

  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
};

}  // namespace gizmo::replay
