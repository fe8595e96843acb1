#pragma once
// The input format of simulation_fuzz (a small run as text) and its reader, apart from the target
// so that a test can check what it accepts (simulation_input_test.cpp):
//
//   run ballistic 0.05 0.5      model (classic|ballistic), maximum tick, duration: the first line
//   0.1 down 32                 a key script (key_script.hpp), up to the line "board"
//   board
//   Square S 5 5                the board in the text format (docs/board-files.md)
//   ...
//
// readRun returns nothing for inputs the readers refuse and for runs outside a small envelope, the
// generator's (docs/fuzzing.md, "Generated runs"): gravity up to 1000, friction constants up to 5,
// ball speeds up to 5000 L/s, maximum tick 0.001–0.1 s; and here at most 1 s of board time, 8
// balls, 64 gizmos and 32 key inputs, so that a run takes milliseconds.
#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string_view>
#include <system_error>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/key_script.hpp"
#include "gizmo/io/text_reader.hpp"

namespace gizmo::fuzzing::simulation {

constexpr std::size_t kMaxInputBytes = 8192;
constexpr std::size_t kMaxRunBalls = 8, kMaxRunGizmos = 64, kMaxKeys = 32;
constexpr double kMaxDuration = 1.0, kMinTick = 0.001, kMaxTick = 0.1;
constexpr double kMaxGravity = 1000, kMaxFriction = 5, kMaxSpeed = 5000;

// The next line of text (without its '\n'), advancing `rest` past it.
inline std::string_view takeLine(std::string_view& rest) {
  const std::size_t end = rest.find('\n');
  const std::string_view line = rest.substr(0, end);
  rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  return line;
}

inline std::optional<double> number(std::string_view word) {
  double value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// "run MODEL MAX_TICK DURATION", words separated by one space.
inline bool readHeader(std::string_view line, gizmo::RunRequest& run) {
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

inline bool withinEnvelope(const gizmo::BoardSpec& b) {
  if (b.balls.size() > kMaxRunBalls || b.gizmos.size() > kMaxRunGizmos) return false;
  if (!(std::fabs(b.gravity) <= kMaxGravity) || !(b.mu >= 0 && b.mu <= kMaxFriction) ||
      !(b.mu2 >= 0 && b.mu2 <= kMaxFriction))
    return false;
  for (const gizmo::BallSpec& ball : b.balls)
    if (!(std::sqrt(ball.vx * ball.vx + ball.vy * ball.vy) <= kMaxSpeed)) return false;
  return true;
}

// The run the bytes describe, or nullopt when they describe none that this target runs.
inline std::optional<gizmo::RunRequest> readRun(std::string_view input) {
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

}  // namespace gizmo::fuzzing::simulation
