// The simulator inside `gizmo play`'s page (docs/play.md): the same core, board reader and log
// writer as the native command, compiled by the wasm32 cross build, behind a few C functions that
// the page's script calls. One game at a time.
//
// Board time moves in whole ticks of the run's grid (tick k ends at k·maxTick, counted from 0, as
// `gizmo record` and `gizmo replay` tick): a frame asks for a board time and the board runs every
// whole tick up to it, so the game's decisions are the ones a run of the same board and inputs to
// the same end makes, and the log (board, model, max tick, inputs, end) replays them exactly.
// Every decision goes into the game's log as it is made (the Recorder of `gizmo record`); the
// header, which holds the inputs and the end, is written when the log is saved.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/replay/recorder.hpp"
#include "gizmo/replay/replay.hpp"

namespace {

using gizmo::GameBoard;

struct Game {
  gizmo::RunRequest request;  // keys: every input given so far; duration: set when a log is written
  std::vector<std::string> warnings;  // the board reader's, for the log's header
  std::unique_ptr<GameBoard<double>> board;
  gizmo::replay::KeptChunks kept;  // the chunks the game's Recorder has closed
  bool recording = true;  // off only for timing the core alone (bench/play_speed.mjs)
  std::unique_ptr<gizmo::replay::Recorder<double>> recorder;  // after board and kept: goes first
  std::int64_t ticksDone = 0;
  std::string stopped;  // why the board stopped (a stall), empty while it runs
  double stoppedIn = 0;  // the end of the ticks the board was running when it stopped
  std::vector<std::uint8_t> saved;  // the last log gp_save() wrote
};

std::unique_ptr<Game> game;
std::string text;             // the last message or name list handed to the page
std::vector<double> numbers;  // the last array handed to the page

const char* say(std::string message) {
  text = std::move(message);
  return text.c_str();
}

// The last k whose tick end k·maxTick is at or before t (k ≥ ticks already done); a t that is not
// a number, or beyond 2^53 ticks, leaves the count as it is.
std::int64_t ticksBy(double t, double maxTick, std::int64_t done) {
  const double q = std::floor(t / maxTick);
  if (!(q >= 0 && q < 9.0e15)) return done;
  std::int64_t k = std::max<std::int64_t>(done, static_cast<std::int64_t>(q));
  while (double(k + 1) * maxTick <= t) ++k;
  while (k > done && double(k) * maxTick > t) --k;
  return k;
}

void build() {
  game->recorder.reset();
  game->board = gizmo::prepareRun<double>(gizmo::RunRequest{game->request.board, game->request.model,
                                                           game->request.maxTick, 0.0, {}});
  game->kept = gizmo::replay::KeptChunks();
  if (game->recording) {
    game->recorder = std::make_unique<gizmo::replay::Recorder<double>>(game->kept, *game->board);
    game->board->setObserver(game->recorder.get());
  }
  game->ticksDone = 0;
  game->stopped.clear();
  game->request.keys.clear();
}

// The run so far as a request: its end is the board's present (or, once the board stopped, the
// end of the ticks it stopped in), its inputs those given by then.
gizmo::RunRequest runSoFar() {
  gizmo::RunRequest r = game->request;
  r.duration = game->stopped.empty() ? game->board->now() : game->stoppedIn;
  r.keys.clear();
  for (const gizmo::TimedKey& k : game->request.keys)
    if (k.time <= r.duration) r.keys.push_back(k);
  return r;
}

}  // namespace

extern "C" {

// Reads the board (its text form) and builds it at time 0. warnings: what the native reader read
// leniently in the board's file, one a line, kept in every log. model: 0 classic, 1 ballistic.
// record: 1 to record every decision as the game goes (the page), 0 to time the core alone.
// Returns 1, or 0 with the reader's located error in gp_text().
EMSCRIPTEN_KEEPALIVE int gp_load(const char* boardText, const char* name, const char* warnings, int model,
                                 double maxTick, int record) {
  try {
    if (!(maxTick > 0)) throw std::invalid_argument("the maximum tick must be positive");
    const gizmo::io::ReadResult r = gizmo::io::readBoardString(boardText, name);
    game = std::make_unique<Game>();
    game->request.board = r.board;
    game->request.model = model == 0 ? gizmo::MotionModel::Classic : gizmo::MotionModel::Ballistic;
    game->request.maxTick = maxTick;
    game->recording = record != 0;
    for (const gizmo::io::Diagnostic& d : r.warnings) game->warnings.push_back(gizmo::io::format(d));
    for (std::string_view rest = warnings; !rest.empty();) {
      const std::size_t end = std::min(rest.find('\n'), rest.size());
      if (end > 0) game->warnings.emplace_back(rest.substr(0, end));
      rest.remove_prefix(std::min(end + 1, rest.size()));
    }
    build();
    say("");
    return 1;
  } catch (const std::exception& e) {
    game.reset();
    say(e.what());
    return 0;
  }
}

// The board as built again at time 0, every input forgotten.
EMSCRIPTEN_KEEPALIVE void gp_restart() {
  if (game) build();
}

// A key pressed (up = 0) or released (up = 1) at board time `time`, which must be later than the
// board's present (the ticks up to it are not yet run): 1 taken, 0 not (the page tries again at
// the next frame's time).
EMSCRIPTEN_KEEPALIVE int gp_key(int key, int up, double time) {
  if (!game || !game->stopped.empty() || !(time > game->board->now())) return 0;
  const gizmo::KeyDirection d = up ? gizmo::KeyDirection::Up : gizmo::KeyDirection::Down;
  game->board->scheduleInput(time, key, d);
  game->request.keys.push_back(gizmo::TimedKey{time, key, d});
  return 1;
}

// Runs every whole tick that ends at or before `target`; returns the board's time.
EMSCRIPTEN_KEEPALIVE double gp_advance(double target) {
  if (!game) return 0;
  if (game->stopped.empty()) {
    const std::int64_t k = ticksBy(target, game->request.maxTick, game->ticksDone);
    if (k > game->ticksDone) {
      try {
        game->board->tickSpan(0.0, game->ticksDone + 1, double(k) * game->request.maxTick);
      } catch (const std::exception& e) {
        game->stopped = e.what();
        game->stoppedIn = double(k) * game->request.maxTick;
      }
      game->ticksDone = k;
    }
  }
  return game->board->now();
}

EMSCRIPTEN_KEEPALIVE double gp_now() { return game ? game->board->now() : 0.0; }
EMSCRIPTEN_KEEPALIVE double gp_events() { return game ? double(game->board->executedTotal()) : 0.0; }
EMSCRIPTEN_KEEPALIVE const char* gp_stopped() { return say(game ? game->stopped : ""); }
EMSCRIPTEN_KEEPALIVE const char* gp_text() { return text.c_str(); }

// The balls' names, one a line, in the order of gp_balls().
EMSCRIPTEN_KEEPALIVE const char* gp_ball_names() {
  std::string names;
  if (game)
    for (gizmo::GizmoId id : game->board->ballIds()) names += game->board->gizmo(id).name() + "\n";
  return say(names);
}

// How many balls the board has: spawners add balls as it runs.
EMSCRIPTEN_KEEPALIVE double gp_ball_count() { return game ? double(game->board->ballIds().size()) : 0.0; }

// x, y, vx, vy of each ball at the board's present: the doubles the simulator holds.
EMSCRIPTEN_KEEPALIVE const double* gp_balls() {
  numbers.clear();
  if (game) {
    const double now = game->board->now();
    for (gizmo::GizmoId id : game->board->ballIds()) {
      const gizmo::Ball<double>& b = *game->board->gizmo(id).asBall();
      const gizmo::Vec2<double> p = b.positionAt(now), v = b.velocityAt(now);
      numbers.insert(numbers.end(), {p.x, p.y, v.x, v.y});
    }
  }
  return numbers.data();
}

// Each gizmo's swing at the present, by gizmo id: a flipper's swing progress, the seconds a
// spinner has turned (its angle over its rate; 0 for the others). The page draws them at their
// angles from it, as the replay player does from a log.
EMSCRIPTEN_KEEPALIVE const double* gp_swings() {
  numbers.clear();
  if (game) {
    const double now = game->board->now();
    for (std::size_t g = 0; g < game->board->gizmoCount(); ++g) {
      const auto& gizmo = game->board->gizmo(gizmo::GizmoId(g));
      const bool flipper = gizmo.kind() == gizmo::GizmoKind::LeftFlipper || gizmo.kind() == gizmo::GizmoKind::RightFlipper;
      if (flipper) numbers.push_back(static_cast<const gizmo::Flipper<double>&>(gizmo).progressAt(now));
      else if (gizmo.kind() == gizmo::GizmoKind::Spinner)
        numbers.push_back(static_cast<const gizmo::Spinner<double>&>(gizmo).angleAt(now) / gizmo::kSpinnerTurnRate);
      else numbers.push_back(0.0);
    }
  }
  return numbers.data();
}

// Writes the game so far (from time 0 to the present) as a replay log into the module's memory,
// with the log writer of `gizmo record`: the header (the board, the inputs given, the present as
// the end), the chunks recorded so far and the one in progress. Returns its size in bytes (the
// bytes at gp_saved()), or −1 with the reason in gp_text(). A board that stopped mid-tick (a
// stall) left its recording mid-tick, and a game loaded without recording has none: their log is
// recorded again from the inputs (to the same stop).
EMSCRIPTEN_KEEPALIVE double gp_save() {
  if (!game) return -1;
  const gizmo::PrecisionChoice precision{gizmo::Precision::Double, 0};
  game->saved.clear();
  try {
    gizmo::replay::LogWriter writer(game->saved);
    if (!game->stopped.empty() || !game->recorder) {
      const gizmo::replay::RecordResult r = gizmo::replay::recordRun(runSoFar(), precision, writer, game->warnings);
      say(r.completed ? "" : "the log records the stop: " + r.error);
      return double(game->saved.size());
    }
    writer.header(gizmo::replay::recordHeader(runSoFar(), precision, game->warnings));
    game->kept.sendTo(writer);
    game->recorder->finishCopy(writer);
    say("");
    return double(game->saved.size());
  } catch (const std::exception& e) {
    game->saved.clear();
    say(e.what());
    return -1;
  }
}

// The bytes of the log gp_save() wrote; gp_forget_saved() gives their memory back.
EMSCRIPTEN_KEEPALIVE const std::uint8_t* gp_saved() { return game ? game->saved.data() : nullptr; }
EMSCRIPTEN_KEEPALIVE void gp_forget_saved() {
  if (game) std::vector<std::uint8_t>().swap(game->saved);
}

// The page's own check of the log gp_save() wrote, as `gizmo replay` makes it: the log's board and
// inputs run again and every decision compared; the log recorded again from them, which must give
// the same bytes; then, when the log ends at the board's present, every ball the log has there
// compared with the game's, bit for bit. 1 identical, 0 not, −1 the log does not read;
// gp_text() says what was found.
EMSCRIPTEN_KEEPALIVE int gp_check() {
  if (!game) return -1;
  try {
    const gizmo::replay::OpenedLog log = gizmo::replay::openLog(gizmo::replay::ByteSource::memory(game->saved));
    const gizmo::replay::ReplayReport r = gizmo::replay::replayLog(log);
    if (!r.identical) {
      say("differs after " + std::to_string(r.decisions) + " decisions: " + r.where);
      return 0;
    }
    std::string summary = "identical: " + std::to_string(r.events) + " events replay exactly as recorded";
    // The log the game recorded as it went, against the one `gizmo record` makes of its board and
    // inputs: the same bytes.
    std::vector<std::uint8_t> again;
    {
      gizmo::replay::LogWriter writer(again);
      gizmo::replay::recordRun(log.request, log.precision, writer, log.header.boardWarnings);
    }
    if (again != game->saved) {
      say(summary + ", but the log is not the one gizmo record writes of its board and inputs");
      return 0;
    }
    summary += ", byte for byte the log gizmo record writes of them";
    if (log.request.duration == game->board->now()) {
      gizmo::replay::SeekTarget at;
      at.time = log.request.duration;
      const gizmo::replay::StateView s = gizmo::replay::seekLog(log, at);
      const double* live = gp_balls();
      for (std::size_t i = 0; i < s.balls.size(); ++i)
        if (s.balls[i].x.value != live[4 * i] || s.balls[i].y.value != live[4 * i + 1] ||
            s.balls[i].vx.value != live[4 * i + 2] || s.balls[i].vy.value != live[4 * i + 3]) {
          say("the log replays identical, but at its end ball " + s.balls[i].name + " is not where the game has it");
          return 0;
        }
      summary += "; every ball at its end is where the game has it";
    }
    say(summary);
    return 1;
  } catch (const std::exception& e) {
    say(e.what());
    return -1;
  }
}

}  // extern "C"
