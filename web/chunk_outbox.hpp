#pragma once
// Where the game's Recorder puts the chunks it closes (docs/play.md, "Memory"). A chunk is kept in
// the module's memory until the page takes it: gp_take_chunks() hands the page every chunk closed
// since, framed as the log holds them, and forgets their bytes, keeping only their index entries
// (a few dozen bytes each); the page keeps them as Blobs, in the browser's storage. A log is then
// written with its header, the chunks the page holds indexed but not written (the page puts them in),
// the chunks still here written, and the chunk in progress with the end (Recorder::finishCopy).
// A page that never takes any (bench/play_speed.mjs) gets whole logs, as KeptChunks gave.
#include <cstdint>
#include <span>
#include <vector>

#include "gizmo/replay/chunk.hpp"
#include "gizmo/replay/log_file.hpp"

class ChunkOutbox final : public gizmo::replay::ChunkSink {
 public:
  void header(std::span<const std::uint8_t>) override {}
  void chunk(std::span<const std::uint8_t> payload, const gizmo::replay::ChunkEntry& entry) override {
    kept_.push_back(Kept{{payload.begin(), payload.end()}, entry});
    keptBytes_ += payload.size();
  }
  void finish(const gizmo::replay::RunEnd&) override {}

  // Every chunk kept here, framed one after another, into `out`; they are the page's from now on.
  void handOut(std::vector<std::uint8_t>& out) {
    for (const Kept& c : kept_) {
      const std::vector<std::uint8_t> frame = gizmo::replay::chunkFrame(c.bytes);
      out.insert(out.end(), frame.begin(), frame.end());
      handed_.push_back(Handed{c.entry, frame.size()});
    }
    std::vector<Kept>().swap(kept_);
    keptBytes_ = 0;
  }
  // The closed chunks into a log: those handed out indexed at their place, the others written.
  void sendTo(gizmo::replay::LogWriter& writer) const {
    for (const Handed& c : handed_) writer.chunkElsewhere(c.entry, c.frameBytes);
    for (const Kept& c : kept_) writer.chunk(c.bytes, c.entry);
  }
  std::size_t handedOut() const { return handed_.size(); }
  std::uint64_t keptBytes() const { return keptBytes_; }
  // What the module holds for the chunks closed: the bytes of those kept, the entries of all.
  std::uint64_t bytesHeld() const {
    return keptBytes_ + (kept_.capacity() * sizeof(Kept)) + handed_.capacity() * sizeof(Handed);
  }

 private:
  struct Kept {
    std::vector<std::uint8_t> bytes;
    gizmo::replay::ChunkEntry entry;
  };
  struct Handed {
    gizmo::replay::ChunkEntry entry;
    std::uint64_t frameBytes = 0;
  };
  std::vector<Kept> kept_;
  std::vector<Handed> handed_;
  std::uint64_t keptBytes_ = 0;
};
