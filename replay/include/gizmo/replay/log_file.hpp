#pragma once
// The replay log as a file of checksummed frames: a header frame, chunk frames, then an index
// frame and a trailer that point at each chunk's keyframe (docs/replay-format.md). Nothing here
// knows what a chunk holds beyond the few numbers of its preamble that the index repeats.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gizmo::replay {

// Where a chunk starts: its place in the file, and how far the run had got at its keyframe.
struct ChunkEntry {
  std::uint64_t offset = 0;      // of the chunk's frame
  std::uint64_t eventsDone = 0;  // events executed before the chunk
  std::uint64_t ticksDone = 0;   // ticks completed before the chunk
  double time = 0;               // the keyframe's board time, rounded to a double
  // The digest of the chunk's decisions (decision_digest.hpp), from the index; absent for a chunk
  // found by walking the frames of a log without its index.
  std::optional<std::uint64_t> digest;
};

// How the recorded run ended.
struct RunEnd {
  bool completed = false;  // false: the run stopped with an error (message says which)
  std::uint64_t events = 0;
  double time = 0;
  std::string message;
};

// Receives the frames of a log being made: a file (LogWriter) or a comparison (replay).
class ChunkSink {
 public:
  virtual ~ChunkSink() = default;
  virtual void header(std::span<const std::uint8_t> payload) = 0;
  // The header of a branch log (format version 5, log_header.hpp: BranchOrigin); a sink that
  // writes the file header writes that version.
  virtual void branchHeader(std::span<const std::uint8_t> payload) { header(payload); }
  // entry.offset is filled in by the sink.
  virtual void chunk(std::span<const std::uint8_t> payload, const ChunkEntry& entry) = 0;
  virtual void finish(const RunEnd& end) = 0;
};

// The numbers every chunk payload starts with (before its keyframe).
struct ChunkPreamble {
  std::uint64_t ticksDone = 0;
  std::uint64_t eventsDone = 0;
  std::uint64_t decisionsDone = 0;  // records in the chunks before
  double time = 0;
  bool hasKeyframe = false;  // false only for the first chunk: the board as built
};
void writePreamble(std::vector<std::uint8_t>& out, const ChunkPreamble& p);
// Reads the preamble at the start of a chunk payload; returns its size in bytes.
std::size_t readPreamble(std::span<const std::uint8_t> payload, ChunkPreamble& p);
// The index entry of a chunk at `offset` with this preamble.
inline ChunkEntry entryOf(const ChunkPreamble& p, std::uint64_t offset) {
  return ChunkEntry{offset, p.eventsDone, p.ticksDone, p.time, std::nullopt};
}

// Writes frames to a file as they come; each chunk reaches the operating system before the next
// is made, so a crash leaves a log that is readable up to its last complete chunk. Or appends
// them to bytes in memory (a web page that hands the log to its user, `gizmo play`).
class LogWriter final : public ChunkSink {
 public:
  explicit LogWriter(
      const std::string& path);  // the file is created by header(); throws std::runtime_error naming the path
  explicit LogWriter(std::vector<std::uint8_t>& memory);
  ~LogWriter() override;
  void header(std::span<const std::uint8_t> payload) override;
  void branchHeader(std::span<const std::uint8_t> payload) override;
  void chunk(std::span<const std::uint8_t> payload, const ChunkEntry& entry) override;
  void finish(const RunEnd& end) override;
  // A chunk whose frame (chunkFrame's bytes) the caller puts into the log at this place itself:
  // the writer counts its bytes and indexes it, and writes nothing (the game page keeps closed
  // chunks out of the module's memory and joins them to the log it saves).
  void chunkElsewhere(const ChunkEntry& entry, std::uint64_t frameBytes);
  std::uint64_t bytesWritten() const { return offset_; }
  std::uint64_t chunksWritten() const { return index_.size(); }

 private:
  void frame(std::uint8_t type, std::span<const std::uint8_t> payload);
  void start(std::uint16_t version);
  bool put(std::span<const std::uint8_t> bytes);  // to the file or the memory; false if it failed
  std::string path_;
  std::FILE* file_ = nullptr;
  std::vector<std::uint8_t>* memory_ = nullptr;
  bool open_ = false;
  std::uint64_t offset_ = 0;
  std::vector<ChunkEntry> index_;
};

// A chunk's frame as LogWriter writes it: its type and length, the payload, its checksum.
std::vector<std::uint8_t> chunkFrame(std::span<const std::uint8_t> payload);

// The bytes of a log, from a file or from memory.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual std::uint64_t size() const = 0;
  // Reads n bytes at offset; the range must be inside size().
  virtual void read(std::uint64_t offset, std::size_t n, std::uint8_t* out) const = 0;
  static std::unique_ptr<ByteSource> file(const std::string& path);  // throws std::runtime_error
  static std::unique_ptr<ByteSource> memory(std::vector<std::uint8_t> bytes);
};

// Opens a log: checks its file header, its header frame, and finds every chunk, through the index
// when the log is complete or by walking the frames when it was cut off. Chunks are checked when
// read. Any byte that does not fit throws FormatError saying what and where.
class LogReader {
 public:
  explicit LogReader(std::unique_ptr<ByteSource> source, bool verifyChecksums = true);

  const std::vector<std::uint8_t>& headerPayload() const { return header_; }
  std::uint16_t formatVersion() const { return version_; }
  // A branch log (format version 5): its header names its parent, its first chunk has a keyframe.
  bool isBranch() const;
  // checksum64 of the whole file's bytes: how a branch log names its parent.
  std::uint64_t fileDigest() const;
  const std::vector<ChunkEntry>& chunks() const { return chunks_; }
  // The chunk's payload, checked against its checksum and its place in the index.
  std::vector<std::uint8_t> chunkPayload(std::size_t i) const;

  // How the run ended; nullopt when the log was cut off before its index.
  const std::optional<RunEnd>& end() const { return end_; }
  // Why the log is incomplete (empty when it is complete): where it stops and what is kept.
  const std::string& truncation() const { return truncation_; }

 private:
  std::vector<std::uint8_t> readFrame(std::uint64_t offset, std::uint8_t type, std::uint64_t* next) const;
  bool readThroughIndex();
  void walkFrames(std::uint64_t from);
  void parseIndex(std::span<const std::uint8_t> payload);

  std::unique_ptr<ByteSource> source_;
  bool verify_;
  std::uint16_t version_ = 0;
  std::vector<std::uint8_t> header_;
  std::uint64_t firstChunk_ = 0, chunksEnd_ = 0;
  std::vector<ChunkEntry> chunks_;
  std::optional<RunEnd> end_;
  std::string truncation_;
};

}  // namespace gizmo::replay
