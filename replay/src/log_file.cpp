// Frames, the writer that appends them and the reader that finds them again (log_file.hpp).
#include "gizmo/replay/log_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include "gizmo/core/std_compat.hpp"

#include "gizmo/replay/bytes.hpp"
#include "gizmo/replay/checksum.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_format.hpp"

namespace gizmo::replay {
namespace {

// The frame's type and length seed its checksum: a damaged type or length is caught as surely
// as a damaged payload.
std::uint64_t frameChecksum(std::uint8_t type, std::uint32_t length, std::span<const std::uint8_t> payload) {
  return checksum64(payload, (std::uint64_t(type) << 32) | length);
}

// The same entry, the time compared bit for bit.
bool sameEntry(const ChunkEntry& x, const ChunkEntry& y) {
  return x.offset == y.offset && x.eventsDone == y.eventsDone && x.ticksDone == y.ticksDone &&
         gizmo::bitCast<std::uint64_t>(x.time) == gizmo::bitCast<std::uint64_t>(y.time);
}

std::string typeName(std::uint8_t type) {
  switch (static_cast<FrameType>(type)) {
    case FrameType::Header: return "header";
    case FrameType::Chunk: return "chunk";
    case FrameType::Index: return "index";
  }
  return "unknown";
}

class FileSource final : public ByteSource {
 public:
  explicit FileSource(const std::string& path) : path_(path) {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
      ::close(fd_);
      throw std::runtime_error(path + ": not a regular file");
    }
    size_ = static_cast<std::uint64_t>(st.st_size);
  }
  ~FileSource() override { ::close(fd_); }
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::size_t n, std::uint8_t* out) const override {
    std::size_t done = 0;
    while (done < n) {
      const ssize_t got = ::pread(fd_, out + done, n - done, static_cast<off_t>(offset + done));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) throw std::runtime_error(path_ + ": read failed at byte " + std::to_string(offset + done));
      done += static_cast<std::size_t>(got);
    }
  }

 private:
  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

class MemorySource final : public ByteSource {
 public:
  explicit MemorySource(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {}
  std::uint64_t size() const override { return bytes_.size(); }
  void read(std::uint64_t offset, std::size_t n, std::uint8_t* out) const override {
    if (n) std::memcpy(out, bytes_.data() + offset, n);
  }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace

std::unique_ptr<ByteSource> ByteSource::file(const std::string& path) { return std::make_unique<FileSource>(path); }
std::unique_ptr<ByteSource> ByteSource::memory(std::vector<std::uint8_t> bytes) {
  return std::make_unique<MemorySource>(std::move(bytes));
}

// --- chunk preamble -----------------------------------------------------------------------------

void writePreamble(std::vector<std::uint8_t>& out, const ChunkPreamble& p) {
  ByteWriter w;
  w.varint(p.ticksDone);
  w.varint(p.eventsDone);
  w.varint(p.decisionsDone);
  w.u64(gizmo::bitCast<std::uint64_t>(p.time));
  w.u8(p.hasKeyframe ? 1 : 0);
  const auto b = w.bytes();
  out.insert(out.end(), b.begin(), b.end());
}

std::size_t readPreamble(std::span<const std::uint8_t> payload, ChunkPreamble& p) {
  ByteReader r(payload);
  p.ticksDone = r.varint();
  p.eventsDone = r.varint();
  p.decisionsDone = r.varint();
  p.time = gizmo::bitCast<double>(r.u64());
  const std::uint8_t k = r.u8();
  if (k > 1) throw FormatError("chunk preamble: bad keyframe flag", r.position() - 1);
  p.hasKeyframe = k == 1;
  return r.position();
}

// --- writing ------------------------------------------------------------------------------------

// The file is created when the header comes: a run that fails before it leaves no file.
LogWriter::LogWriter(const std::string& path) : path_(path) {}

LogWriter::LogWriter(std::vector<std::uint8_t>& memory) : path_("the log in memory"), memory_(&memory) {}

// The file header, with the format version the header frame is written in.
void LogWriter::start(std::uint16_t version) {
  if (open_ || offset_ != 0) throw std::logic_error("log header already written");
  if (!memory_) {
    file_ = std::fopen(path_.c_str(), "wb");
    if (!file_) throw std::runtime_error(path_ + ": cannot create: " + std::strerror(errno));
  }
  open_ = true;
  ByteWriter w;
  w.bytes(kMagic.data(), kMagic.size());
  w.u16(version);
  w.u16(0);
  if (!put(w.bytes())) throw std::runtime_error(path_ + ": write failed: " + std::strerror(errno));
  offset_ = w.size();
}

bool LogWriter::put(std::span<const std::uint8_t> bytes) {
  if (memory_) {
    memory_->insert(memory_->end(), bytes.begin(), bytes.end());
    return true;
  }
  return std::fwrite(bytes.data(), 1, bytes.size(), file_) == bytes.size();
}

LogWriter::~LogWriter() {
  if (file_) std::fclose(file_);  // unfinished: no index, read as cut off
}

namespace {

// What comes before and after a frame's payload: its type and length, and its checksum.
void frameParts(std::uint8_t type, std::span<const std::uint8_t> payload, ByteWriter& head, ByteWriter& tail,
                const std::string& what) {
  if (payload.size() > kMaxFramePayload) throw std::runtime_error(what + ": a chunk too large for the log format");
  const auto length = static_cast<std::uint32_t>(payload.size());
  head.u8(type);
  head.u32(length);
  tail.u64(frameChecksum(type, length, payload));
}

}  // namespace

std::vector<std::uint8_t> chunkFrame(std::span<const std::uint8_t> payload) {
  ByteWriter head, tail;
  frameParts(std::uint8_t(FrameType::Chunk), payload, head, tail, "chunkFrame");
  std::vector<std::uint8_t> out(head.bytes().begin(), head.bytes().end());
  out.insert(out.end(), payload.begin(), payload.end());
  out.insert(out.end(), tail.bytes().begin(), tail.bytes().end());
  return out;
}

void LogWriter::frame(std::uint8_t type, std::span<const std::uint8_t> payload) {
  if (!open_) throw std::logic_error("log already finished");
  ByteWriter head, tail;
  frameParts(type, payload, head, tail, path_);
  const bool ok = put(head.bytes()) && put(payload) && put(tail.bytes()) && (memory_ || std::fflush(file_) == 0);
  if (!ok) throw std::runtime_error(path_ + ": write failed: " + std::strerror(errno));
  offset_ += head.size() + payload.size() + tail.size();
}

void LogWriter::header(std::span<const std::uint8_t> payload) {
  start(kFormatVersion);
  frame(std::uint8_t(FrameType::Header), payload);
}

void LogWriter::branchHeader(std::span<const std::uint8_t> payload) {
  start(kBranchFormatVersion);
  frame(std::uint8_t(FrameType::Header), payload);
}

void LogWriter::chunk(std::span<const std::uint8_t> payload, const ChunkEntry& entry) {
  ChunkEntry e = entry;
  e.offset = offset_;
  frame(std::uint8_t(FrameType::Chunk), payload);
  index_.push_back(e);
}

void LogWriter::chunkElsewhere(const ChunkEntry& entry, std::uint64_t frameBytes) {
  if (!open_) throw std::logic_error("log already finished");
  ChunkEntry e = entry;
  e.offset = offset_;
  offset_ += frameBytes;
  index_.push_back(e);
}

void LogWriter::finish(const RunEnd& end) {
  const std::uint64_t indexOffset = offset_;
  ByteWriter w;
  w.varint(index_.size());
  ChunkEntry prev;
  for (const ChunkEntry& e : index_) {
    w.varint(e.offset - prev.offset);
    w.varint(e.eventsDone - prev.eventsDone);
    w.varint(e.ticksDone - prev.ticksDone);
    w.u64(gizmo::bitCast<std::uint64_t>(e.time));
    w.u64(e.digest.value_or(0));
    prev = e;
  }
  w.u8(end.completed ? 1 : 0);
  w.varint(end.events);
  w.u64(gizmo::bitCast<std::uint64_t>(end.time));
  w.varint(end.message.size());
  w.bytes(end.message.data(), end.message.size());
  frame(std::uint8_t(FrameType::Index), w.bytes());
  ByteWriter t;
  t.u64(indexOffset);
  t.bytes(kTrailerMagic.data(), kTrailerMagic.size());
  const bool ok = put(t.bytes()) && (memory_ || std::fclose(file_) == 0);
  file_ = nullptr;
  open_ = false;
  offset_ += t.size();
  if (!ok) throw std::runtime_error(path_ + ": write failed: " + std::strerror(errno));
}

// --- reading ------------------------------------------------------------------------------------

LogReader::LogReader(std::unique_ptr<ByteSource> source, bool verifyChecksums)
    : source_(std::move(source)), verify_(verifyChecksums) {
  const std::uint64_t size = source_->size();
  if (size < kFileHeaderSize) throw FormatError("not a gizmo replay log: too short", 0);
  std::uint8_t head[kFileHeaderSize];
  source_->read(0, kFileHeaderSize, head);
  if (std::memcmp(head, kMagic.data(), kMagic.size()) != 0) throw FormatError("not a gizmo replay log: bad magic", 0);
  ByteReader r(std::span<const std::uint8_t>(head, kFileHeaderSize));
  r.span(kMagic.size());
  version_ = r.u16();
  if (version_ > kBranchFormatVersion)
    throw FormatError("log format version " + std::to_string(version_) + " is newer than this build reads (" +
                          std::to_string(kBranchFormatVersion) + ")",
                      8);
  if (version_ == 0) throw FormatError("log format version 0 does not exist", 8);
  if (version_ < kFormatVersion)
    throw FormatError("log format version " + std::to_string(version_) + " is older than this build reads (" +
                          std::to_string(kFormatVersion) + "); record the run again",
                      8);
  if (r.u16() != 0) throw FormatError("reserved bytes are not zero", 10);
  if (size == kFileHeaderSize) throw FormatError("the log ends before its header frame", size);
  header_ = readFrame(kFileHeaderSize, std::uint8_t(FrameType::Header), &firstChunk_);
  if (!readThroughIndex()) walkFrames(firstChunk_);
}

std::vector<std::uint8_t> LogReader::readFrame(std::uint64_t offset, std::uint8_t type, std::uint64_t* next) const {
  const std::uint64_t size = source_->size();
  if (offset > size || size - offset < kFrameHeaderSize + kFrameChecksumSize)
    throw FormatError("the " + typeName(type) + " frame is cut off", offset);
  std::uint8_t head[kFrameHeaderSize];
  source_->read(offset, kFrameHeaderSize, head);
  ByteReader r(std::span<const std::uint8_t>(head, kFrameHeaderSize));
  const std::uint8_t got = r.u8();
  const std::uint32_t length = r.u32();
  if (got != type)
    throw FormatError("expected a " + typeName(type) + " frame, found type " + std::to_string(got), offset);
  if (length > kMaxFramePayload) throw FormatError("absurd frame length " + std::to_string(length), offset + 1);
  if (size - offset - kFrameHeaderSize - kFrameChecksumSize < length)
    throw FormatError("the " + typeName(type) + " frame is cut off", offset);
  std::vector<std::uint8_t> payload(length);
  source_->read(offset + kFrameHeaderSize, length, payload.data());
  std::uint8_t sum[kFrameChecksumSize];
  source_->read(offset + kFrameHeaderSize + length, kFrameChecksumSize, sum);
  ByteReader s(std::span<const std::uint8_t>(sum, kFrameChecksumSize));
  if (verify_ && s.u64() != frameChecksum(type, length, payload))
    throw FormatError("the " + typeName(type) + " frame is corrupt (checksum mismatch)", offset);
  if (next) *next = offset + kFrameHeaderSize + length + kFrameChecksumSize;
  return payload;
}

bool LogReader::readThroughIndex() {
  const std::uint64_t size = source_->size();
  if (size < firstChunk_ + kTrailerSize) return false;
  std::uint8_t trailer[kTrailerSize];
  source_->read(size - kTrailerSize, kTrailerSize, trailer);
  if (std::memcmp(trailer + 8, kTrailerMagic.data(), kTrailerMagic.size()) != 0) return false;
  ByteReader r(std::span<const std::uint8_t>(trailer, kTrailerSize));
  const std::uint64_t indexOffset = r.u64();
  if (indexOffset < firstChunk_ || indexOffset >= size - kTrailerSize)
    throw FormatError("the trailer points outside the log", size - kTrailerSize);
  std::uint64_t next = 0;
  const std::vector<std::uint8_t> index = readFrame(indexOffset, std::uint8_t(FrameType::Index), &next);
  if (next != size - kTrailerSize) throw FormatError("the index frame does not end at the trailer", indexOffset);
  parseIndex(index);
  chunksEnd_ = indexOffset;
  std::uint64_t previous = 0;
  for (std::size_t i = 0; i < chunks_.size(); ++i) {
    const std::uint64_t at = chunks_[i].offset;
    const bool ordered = i == 0 ? at == firstChunk_ : at > previous;
    if (!ordered || at >= indexOffset)
      throw FormatError("the index places chunk " + std::to_string(i) + " wrongly", indexOffset);
    previous = at;
  }
  if (chunks_.empty() && indexOffset != firstChunk_) throw FormatError("the index lists no chunks", indexOffset);
  return true;
}

void LogReader::parseIndex(std::span<const std::uint8_t> payload) {
  ByteReader r(payload);
  const std::uint64_t n = r.varint();
  if (n > r.remaining() / 19) throw FormatError("index: more chunks than bytes", 0);
  chunks_.clear();
  ChunkEntry prev;
  for (std::uint64_t i = 0; i < n; ++i) {
    ChunkEntry e;
    e.offset = prev.offset + r.varint();
    e.eventsDone = prev.eventsDone + r.varint();
    e.ticksDone = prev.ticksDone + r.varint();
    e.time = gizmo::bitCast<double>(r.u64());
    e.digest = r.u64();
    chunks_.push_back(e);
    prev = e;
  }
  RunEnd end;
  const std::uint8_t completed = r.u8();
  if (completed > 1) throw FormatError("index: bad run status", r.position() - 1);
  end.completed = completed == 1;
  end.events = r.varint();
  end.time = gizmo::bitCast<double>(r.u64());
  const std::uint64_t len = r.varint();
  if (len > r.remaining()) throw FormatError("index: message longer than the frame", r.position());
  const auto text = r.span(static_cast<std::size_t>(len));
  end.message.assign(text.begin(), text.end());
  if (!r.atEnd()) throw FormatError("index: bytes after the run's end", r.position());
  end_ = end;
}

void LogReader::walkFrames(std::uint64_t from) {
  const std::uint64_t size = source_->size();
  std::uint64_t at = from;
  chunks_.clear();
  auto cutOff = [&](const std::string& where) {
    truncation_ = "the log is cut off " + where + " (byte " + std::to_string(at) + " of " + std::to_string(size) +
                  "); its " + std::to_string(chunks_.size()) + " complete chunks are read";
    chunksEnd_ = at;
  };
  for (;;) {
    if (at == size) return cutOff("after a chunk, before its index");
    if (size - at < kFrameHeaderSize) return cutOff("inside a frame header");
    std::uint8_t head[kFrameHeaderSize];
    source_->read(at, kFrameHeaderSize, head);
    ByteReader r(std::span<const std::uint8_t>(head, kFrameHeaderSize));
    const std::uint8_t type = r.u8();
    const std::uint32_t length = r.u32();
    if (type != std::uint8_t(FrameType::Chunk) && type != std::uint8_t(FrameType::Index))
      throw FormatError("unknown frame type " + std::to_string(type), at);
    if (length > kMaxFramePayload) throw FormatError("absurd frame length " + std::to_string(length), at + 1);
    if (size - at < kFrameHeaderSize + std::uint64_t(length) + kFrameChecksumSize)
      return cutOff(type == std::uint8_t(FrameType::Chunk) ? "inside chunk " + std::to_string(chunks_.size())
                                                           : "inside its index");
    std::uint64_t next = 0;
    const std::vector<std::uint8_t> payload = readFrame(at, type, &next);
    if (type == std::uint8_t(FrameType::Index)) {
      // A complete index without a readable trailer: either the trailer is cut off, or damaged.
      const std::vector<ChunkEntry> walked = chunks_;
      parseIndex(payload);
      if (!std::equal(walked.begin(), walked.end(), chunks_.begin(), chunks_.end(), sameEntry))
        throw FormatError("the index disagrees with the chunks", at);
      chunksEnd_ = at;  // the index's entries are the walked ones, with their digests
      if (size - next >= kTrailerSize) throw FormatError("the trailer is corrupt", size - kTrailerSize);
      at = next;
      truncation_ = "the log's trailer is cut off; all " + std::to_string(chunks_.size()) + " chunks are read";
      return;
    }
    ChunkPreamble p;
    readPreamble(payload, p);
    chunks_.push_back(entryOf(p, at));
    at = next;
  }
}

std::vector<std::uint8_t> LogReader::chunkPayload(std::size_t i) const {
  const ChunkEntry& e = chunks_.at(i);
  std::uint64_t next = 0;
  std::vector<std::uint8_t> payload = readFrame(e.offset, std::uint8_t(FrameType::Chunk), &next);
  const std::uint64_t expected = i + 1 < chunks_.size() ? chunks_[i + 1].offset : chunksEnd_;
  if (next != expected)
    throw FormatError("chunk " + std::to_string(i) + " does not end where the next begins", e.offset);
  ChunkPreamble p;
  readPreamble(payload, p);
  if (!sameEntry(entryOf(p, e.offset), e) || p.hasKeyframe != (i > 0 || isBranch()))
    throw FormatError("chunk " + std::to_string(i) + " disagrees with the index", e.offset);
  return payload;
}

bool LogReader::isBranch() const { return version_ >= kBranchFormatVersion; }

std::uint64_t LogReader::fileDigest() const {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(source_->size()));
  source_->read(0, bytes.size(), bytes.data());
  return checksum64(bytes);
}

}  // namespace gizmo::replay
