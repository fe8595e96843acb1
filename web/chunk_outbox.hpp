#pragma once
// Where the game's Recorder puts the chunks it closes (docs/play.md, "Memory"). A chunk is framed
// as the log holds it when it closes and kept in the module's memory until the page takes it:
// gp_take_chunks() hands the page the oldest chunk's frame (moved out, not copied, so that handing
// out needs no memory when none is left) and the module keeps only its index entry (a few dozen
// bytes); the page keeps the frames as Blobs, in the browser's storage. A log is then written with
// its header, the chunks the page holds indexed but not written (the page puts them in), the
// chunks still here written, and the chunk in progress with the end (Recorder::finishCopy).
// A page that never takes any (bench/play_speed.mjs) gets whole logs, as KeptChunks gave.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gizmo/replay/chunk.hpp"
#include "gizmo/replay/log_file.hpp"
#include "gizmo/replay/log_format.hpp"

class ChunkOutbox final : public gizmo::replay::ChunkSink {
 public:
  void header(std::span<const std::uint8_t>) override {}
  void chunk(std::span<const std::uint8_t> payload, const gizmo::replay::ChunkEntry& entry) override {
    kept_.push_back(Kept{gizmo::replay::chunkFrame(payload), entry});
    keptBytes_ += kept_.back().frame.size();
  }
  void finish(const gizmo::replay::RunEnd&) override {}

  // The oldest chunk kept here, its frame moved into `out` (emptied first, left empty when none is
  // kept); it is the page's from now on. Throws std::bad_alloc, nothing changed, when even its
  // index entry finds no memory.
  void handOut(std::vector<std::uint8_t>& out) {
    std::vector<std::uint8_t>().swap(out);
    if (kept_.empty()) return;
    handed_.push_back(Handed{kept_.front().entry, kept_.front().frame.size()});
    keptBytes_ -= kept_.front().frame.size();
    out.swap(kept_.front().frame);
    kept_.erase(kept_.begin());
  }
  // The closed chunks into a log: those handed out indexed at their place, the others written.
  void sendTo(gizmo::replay::LogWriter& writer) const {
    using gizmo::replay::kFrameChecksumSize, gizmo::replay::kFrameHeaderSize;
    for (const Handed& c : handed_) writer.chunkElsewhere(c.entry, c.frameBytes);
    for (const Kept& c : kept_)
      writer.chunk(std::span(c.frame).subspan(kFrameHeaderSize, c.frame.size() - kFrameHeaderSize - kFrameChecksumSize),
                   c.entry);
  }
  std::size_t handedOut() const { return handed_.size(); }
  // How many chunks the Recorder has closed: those handed out and those kept.
  std::size_t closed() const { return handed_.size() + kept_.size(); }
  std::uint64_t keptBytes() const { return keptBytes_; }
  // What the module holds for the chunks closed: the frames of those kept, the entries of all.
  std::uint64_t bytesHeld() const {
    return keptBytes_ + (kept_.capacity() * sizeof(Kept)) + handed_.capacity() * sizeof(Handed);
  }

 private:
  struct Kept {
    std::vector<std::uint8_t> frame;
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
