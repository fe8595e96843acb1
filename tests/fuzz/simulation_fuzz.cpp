// libFuzzer target for the simulator itself: the bytes are a small run, simulated in double under
// every invariant of InvariantChecker (no-tunnelling, energy, event-queue); a violation, or a run
// that stops with an error, aborts after printing the run exactly, which libFuzzer and the corpus
// runner report as a crash.
//
// The input is a text board with a small header in front (tests/fuzz/simulation_corpus.cmake
// makes the seed corpus from the fixtures this way):
//
//   run ballistic 0.05 0.5      model (classic|ballistic), maximum tick, duration: the first line
//   0.1 down 32                 a key script (key_script.hpp), up to the line "board"
//   board
//   Square S 5 5                the board in the text format (docs/board-files.md)
//   ...
//
// Inputs the readers refuse, and runs outside the small envelope below, return at once: the readers
// have targets of their own, and a big or long run would cost libFuzzer seconds per input. The
// envelope is the generator's (docs/fuzzing.md, "Generated runs"): gravity up to 1000, friction
// constants up to 5, ball speeds up to 5000 L/s, maximum tick 0.001–0.1 s, and here at most 1 s of
// board time, 8 balls, 64 gizmos and 32 key inputs.
//
// To reproduce a crash: `simulation_corpus_run FILE` in any build, or scripts/simulation-fuzz-check.sh
// FILE, which splits FILE into a board and a key script and checks them with `gizmo fuzz --check`.
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/key_script.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/verify/fuzz/invariants.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"

namespace {

namespace fz = gizmo::verify::fuzz;

constexpr std::size_t kMaxInputBytes = 8192;
constexpr std::size_t kMaxBalls = 8, kMaxGizmos = 64, kMaxKeys = 32;
constexpr double kMaxDuration = 1.0, kMinTick = 0.001, kMaxTick = 0.1;
constexpr double kMaxGravity = 1000, kMaxFriction = 5, kMaxSpeed = 5000;

// The next line of text (without its '\n'), advancing `rest` past it.
std::string_view takeLine(std::string_view& rest) {
  const std::size_t end = rest.find('\n');
  const std::string_view line = rest.substr(0, end);
  rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  return line;
}

std::optional<double> number(std::string_view word) {
  double value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// "run MODEL MAX_TICK DURATION", words separated by one space.
bool readHeader(std::string_view line, gizmo::RunRequest& run) {
  std::string_view words[4];
  for (std::string_view& w : words) {
    const std::size_t space = line.find(' ');
    w = line.substr(0, space);
    line = space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
  }
  if (words[0] != "run" || !line.empty()) return false;
  if (words[1] == "classic") run.model = gizmo::MotionModel::Classic;
  else if (words[1] == "ballistic") run.model = gizmo::MotionModel::Ballistic;
  else return false;
  const std::optional<double> tick = number(words[2]), duration = number(words[3]);
  if (!tick || !duration || !(*tick >= kMinTick && *tick <= kMaxTick) || !(*duration > 0 && *duration <= kMaxDuration))
    return false;
  run.maxTick = *tick;
  run.duration = *duration;
  return true;
}

bool withinEnvelope(const gizmo::BoardSpec& b) {
  if (b.balls.size() > kMaxBalls || b.gizmos.size() > kMaxGizmos) return false;
  if (!(std::fabs(b.gravity) <= kMaxGravity) || !(b.mu >= 0 && b.mu <= kMaxFriction) ||
      !(b.mu2 >= 0 && b.mu2 <= kMaxFriction))
    return false;
  for (const gizmo::BallSpec& ball : b.balls)
    if (!(std::sqrt(ball.vx * ball.vx + ball.vy * ball.vy) <= kMaxSpeed)) return false;
  return true;
}

// The run the bytes describe, or nullopt when they describe none that this target runs.
std::optional<gizmo::RunRequest> readRun(std::string_view input) {
  if (input.size() > kMaxInputBytes) return std::nullopt;
  gizmo::RunRequest run;
  if (!readHeader(takeLine(input), run)) return std::nullopt;
  // The key script runs up to the line "board"; the board is the rest.
  std::string_view board = input;
  std::size_t keysEnd = std::string_view::npos;
  while (!board.empty() && keysEnd == std::string_view::npos) {
    const std::size_t at = std::size_t(board.data() - input.data());
    if (takeLine(board) == "board") keysEnd = at;
  }
  if (keysEnd == std::string_view::npos) return std::nullopt;
  try {
    for (const gizmo::io::KeyInput& k : gizmo::io::readKeyScript(input.substr(0, keysEnd), "fuzz.keys"))
      run.keys.push_back(gizmo::TimedKey{k.time, k.key, k.direction});
    run.board = gizmo::io::readTextBoard(board, "fuzz.txt").board;
  } catch (const gizmo::io::InputError&) {
    return std::nullopt;
  }
  if (run.keys.size() > kMaxKeys || !withinEnvelope(run.board)) return std::nullopt;
  // The reader promises this (text_reader_fuzz checks it); checked again because the simulator
  // must never see an invalid board, whatever the reader does.
  if (!gizmo::checkBoardSpec(run.board).empty()) return std::nullopt;
  return run;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<gizmo::RunRequest> run = readRun(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!run) return 0;
  const std::vector<fz::Invariant> all(std::begin(fz::kAllInvariants), std::end(fz::kAllInvariants));
  const fz::InvariantRun result = fz::checkInvariants<double>(*run, all);
  if (result.violations.empty()) return 0;
  for (const fz::Violation& v : result.violations)
    std::fprintf(stderr, "invariant %s broken: %s\n", std::string(fz::invariantName(v.invariant)).c_str(),
                 v.message.c_str());
  std::fprintf(stderr, "after %llu events; the run:\n%s\n", static_cast<unsigned long long>(result.events),
               fz::describeRun(*run).c_str());
  std::abort();
}
