// libFuzzer target for the replay log reader: opens the input as a log and walks every decision.
//
// Frame checksums are off so that mutated inputs get past the framing into the decoders (the
// header, the index, chunk preambles, keyframes, records and every scalar form). A FormatError or
// StateError is the reader doing its job; a crash, a sanitizer report, a hang or an exception that
// is not a std::exception is a finding. The log is only read, never simulated: replayLog and
// seekLog re-run the board and would make each input far too slow.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

#include "gizmo/replay/log_file.hpp"
#include "gizmo/replay/replay.hpp"

namespace {

// Larger inputs take long without reaching new code; a sane log of that size has many chunks of
// the same records.
constexpr std::size_t kMaxInputBytes = std::size_t{1} << 20;
// Bounds the time one input may take: a log holds at most a few decisions per byte.
constexpr std::uint64_t kMaxDecisions = 100000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxInputBytes) return 0;
  try {
    std::vector<std::uint8_t> bytes(data, data + size);
    const gizmo::replay::OpenedLog log =
        gizmo::replay::openLog(gizmo::replay::ByteSource::memory(std::move(bytes)), /*verifyChecksums=*/false);
    gizmo::replay::DecisionStream stream(log);
    std::uint64_t seen = 0;
    while (seen < kMaxDecisions && stream.next()) ++seen;
  } catch (const std::exception&) {
    // FormatError, StateError, and the library's other refusals: expected for damaged input.
  }
  return 0;
}
