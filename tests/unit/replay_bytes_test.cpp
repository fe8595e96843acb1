// ByteWriter/ByteReader: fixed-width and varint round trips at the edges of their ranges, and
// every way a reader can be handed bad bytes.
#include "gizmo/replay/bytes.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "gizmo/replay/format_error.hpp"

namespace {

using gizmo::replay::ByteReader;
using gizmo::replay::ByteWriter;
using gizmo::replay::FormatError;
using Bytes = std::vector<std::uint8_t>;

Bytes written(const ByteWriter& w) { return Bytes(w.bytes().begin(), w.bytes().end()); }

// Runs `read` on `bytes` and returns the FormatError's offset, failing if nothing is thrown.
template <class Read>
std::uint64_t failureOffset(const Bytes& bytes, Read read) {
  ByteReader r(bytes);
  try {
    read(r);
  } catch (const FormatError& e) {
    return e.offset();
  }
  ADD_FAILURE() << "no FormatError";
  return ~std::uint64_t{0};
}

TEST(ReplayBytes, FixedWidthIsLittleEndian) {
  ByteWriter w;
  w.u8(0xAB);
  w.u16(0x1234);
  w.u32(0x89ABCDEF);
  w.u64(0x0102030405060708ULL);
  EXPECT_EQ(written(w), (Bytes{0xAB, 0x34, 0x12, 0xEF, 0xCD, 0xAB, 0x89, 8, 7, 6, 5, 4, 3, 2, 1}));
  EXPECT_EQ(w.size(), 15u);

  const Bytes bytes = written(w);
  ByteReader r(bytes);
  EXPECT_EQ(r.u8(), 0xAB);
  EXPECT_EQ(r.u16(), 0x1234);
  EXPECT_EQ(r.u32(), 0x89ABCDEFu);
  EXPECT_EQ(r.u64(), 0x0102030405060708ULL);
  EXPECT_TRUE(r.atEnd());
}

TEST(ReplayBytes, VarintEncodingsAtEdges) {
  struct Case {
    std::uint64_t value;
    Bytes bytes;
  };
  const Case cases[] = {
      {0, {0x00}},
      {1, {0x01}},
      {127, {0x7F}},
      {128, {0x80, 0x01}},
      {300, {0xAC, 0x02}},
      {16383, {0xFF, 0x7F}},
      {16384, {0x80, 0x80, 0x01}},
      {std::uint64_t{1} << 63, {0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x01}},
      {UINT64_MAX, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x01}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.value);
    ByteWriter w;
    w.varint(c.value);
    EXPECT_EQ(written(w), c.bytes);
    ByteReader r(c.bytes);
    EXPECT_EQ(r.varint(), c.value);
    EXPECT_TRUE(r.atEnd());
  }
}

TEST(ReplayBytes, SvarintZigzagAndRoundTrips) {
  ByteWriter w;
  w.svarint(0);
  w.svarint(-1);
  w.svarint(1);
  w.svarint(-64);
  w.svarint(64);
  EXPECT_EQ(written(w), (Bytes{0x00, 0x01, 0x02, 0x7F, 0x80, 0x01}));

  const std::int64_t values[] = {0,   1,    -1,        63,        -64,           64,           -65, 127,
                                 128, -128, INT64_MAX, INT64_MIN, INT64_MIN + 1, INT64_MAX - 1};
  ByteWriter all;
  for (std::int64_t v : values) all.svarint(v);
  const Bytes bytes = written(all);
  ByteReader r(bytes);
  for (std::int64_t v : values) EXPECT_EQ(r.svarint(), v);
  EXPECT_TRUE(r.atEnd());

  ByteWriter extreme;
  extreme.svarint(INT64_MIN);  // zigzag: UINT64_MAX, the longest encoding
  EXPECT_EQ(extreme.size(), 10u);
}

TEST(ReplayBytes, ManyVarintsRoundTripAcrossGrowth) {
  // Every bit length, and values around every 7-bit boundary, in one buffer that grows many times.
  std::vector<std::uint64_t> values;
  for (unsigned bits = 0; bits < 64; ++bits) {
    const std::uint64_t p = std::uint64_t{1} << bits;
    values.insert(values.end(), {p - 1, p, p + 1, ~p});
  }
  ByteWriter w;
  for (std::uint64_t v : values) {
    w.varint(v);
    w.svarint(static_cast<std::int64_t>(v));
  }
  const Bytes bytes = written(w);
  ByteReader r(bytes);
  for (std::uint64_t v : values) {
    EXPECT_EQ(r.varint(), v);
    EXPECT_EQ(r.svarint(), static_cast<std::int64_t>(v));
  }
  EXPECT_TRUE(r.atEnd());
}

TEST(ReplayBytes, TruncatedVarintThrowsAtItsStart) {
  EXPECT_EQ(failureOffset({0x05, 0x80},
                          [](ByteReader& r) {
                            r.u8();
                            r.varint();
                          }),
            1u);
  EXPECT_EQ(failureOffset({0xFF, 0xFF, 0xFF}, [](ByteReader& r) { r.varint(); }), 0u);
  EXPECT_EQ(failureOffset({}, [](ByteReader& r) { r.varint(); }), 0u);
  EXPECT_EQ(failureOffset({}, [](ByteReader& r) { r.svarint(); }), 0u);
}

TEST(ReplayBytes, OverlongAndOverflowingVarintsThrow) {
  Bytes eleven(10, 0x80);
  eleven.push_back(0x00);
  EXPECT_EQ(failureOffset(eleven, [](ByteReader& r) { r.varint(); }), 0u);

  Bytes overflow(9, 0xFF);
  overflow.push_back(0x02);  // bit 64
  EXPECT_EQ(failureOffset(overflow, [](ByteReader& r) { r.varint(); }), 0u);

  Bytes tenthFull(9, 0xFF);
  tenthFull.push_back(0x7F);
  EXPECT_EQ(failureOffset(tenthFull, [](ByteReader& r) { r.varint(); }), 0u);

  // A value with a redundant zero top group has a shorter encoding and is refused.
  EXPECT_EQ(failureOffset({0x80, 0x00}, [](ByteReader& r) { r.varint(); }), 0u);
  EXPECT_EQ(failureOffset({0x81, 0x80, 0x00}, [](ByteReader& r) { r.varint(); }), 0u);
}

TEST(ReplayBytes, UnderflowThrowsWithOffsetAndMessage) {
  const Bytes three = {1, 2, 3};
  EXPECT_EQ(failureOffset(three, [](ByteReader& r) { r.u32(); }), 0u);
  EXPECT_EQ(failureOffset(three,
                          [](ByteReader& r) {
                            r.u8();
                            r.u16();
                            r.u8();
                          }),
            3u);
  EXPECT_EQ(failureOffset(three,
                          [](ByteReader& r) {
                            r.u8();
                            r.u64();
                          }),
            1u);
  EXPECT_EQ(failureOffset(three, [](ByteReader& r) { r.span(4); }), 0u);
  EXPECT_EQ(failureOffset(three,
                          [](ByteReader& r) {
                            std::uint8_t out[4];
                            r.bytes(out, 4);
                          }),
            0u);

  ByteReader r(three);
  r.u8();
  try {
    r.u16();
    r.u16();
    FAIL() << "no FormatError";
  } catch (const FormatError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("at byte 3"), std::string::npos) << what;
    EXPECT_NE(what.find("need 2"), std::string::npos) << what;
  }
}

TEST(ReplayBytes, SpanBytesAndPosition) {
  ByteWriter w;
  const char text[] = "gizmo";
  w.bytes(text, 5);
  w.bytes(nullptr, 0);
  w.u8(9);
  const Bytes bytes = written(w);
  ByteReader r(bytes);
  EXPECT_EQ(r.remaining(), 6u);
  const auto s = r.span(2);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], 'g');
  EXPECT_EQ(s[1], 'i');
  EXPECT_EQ(r.position(), 2u);
  char rest[3];
  r.bytes(rest, 3);
  EXPECT_EQ(std::string(rest, 3), "zmo");
  EXPECT_FALSE(r.atEnd());
  EXPECT_EQ(r.u8(), 9);
  EXPECT_TRUE(r.atEnd());
  EXPECT_EQ(r.remaining(), 0u);
  EXPECT_TRUE(r.span(0).empty());
}

TEST(ReplayBytes, ClearKeepsWritingFromTheStart) {
  ByteWriter w;
  for (int i = 0; i < 1000; ++i) w.u64(static_cast<std::uint64_t>(i));
  EXPECT_EQ(w.size(), 8000u);
  w.clear();
  EXPECT_EQ(w.size(), 0u);
  w.u16(0xBEEF);
  EXPECT_EQ(written(w), (Bytes{0xEF, 0xBE}));
}

}  // namespace
