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
//
// The page also opens a saved log (its board, settings and run data for the page's timeline) and
// takes it over at a moment: the game then goes on from the parent's state there as a branch
// (startBranch, the code of `gizmo record --from`), recorded live, and saved as a branch log.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "chunk_outbox.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/replay/branch_start.hpp"
#include "gizmo/replay/recorder.hpp"
#include "gizmo/replay/replay.hpp"
#include "play_data.hpp"
#include "render_player_data.hpp"

namespace {

using gizmo::GameBoard;

struct Game {
  gizmo::RunRequest request;          // keys: every input given so far; duration: set when a log is written
  std::vector<std::string> warnings;  // the board reader's, for the log's header
  std::unique_ptr<GameBoard<double>> board;
  ChunkOutbox kept;       // the chunks the game's Recorder has closed, until the page takes them
  bool recording = true;  // off only for timing the core alone (bench/play_speed.mjs)
  std::unique_ptr<gizmo::replay::Recorder<double>> recorder;  // after board and kept: goes first
  std::int64_t ticksDone = 0;
  std::string stopped;               // why the board stopped (a stall), empty while it runs
  double stoppedIn = 0;              // the end of the ticks the board was running when it stopped
  bool memoryShort = false;          // stopped because the module's memory ran short
  std::vector<std::uint8_t> saved;   // the last log gp_save() wrote
  double savedSplit = -1;            // where the page puts the chunks it took into it (−1: saved is whole)
  std::vector<std::uint8_t> handed;  // the chunks gp_take_chunks() handed the page last
  // The log the page opened or took over (the parent of a branch), and, once it is taken over,
  // where: the branch's origin, the request it was taken with, and how many of request.keys are
  // the parent's (those it had applied by the branch point).
  std::unique_ptr<gizmo::replay::OpenedLog> parent;
  std::optional<gizmo::replay::BranchOrigin> origin;
  gizmo::replay::BranchRequest takenAt;
  std::size_t parentKeys = 0;
  double startTime = 0;  // the board time the game's log starts at: 0, or a branch's tick boundary
};

std::unique_ptr<Game> game;
std::vector<std::uint8_t> incoming;  // the bytes of a log the page hands over (gp_buffer)
std::string text;                    // the last message or name list handed to the page
std::vector<double> numbers;         // the last array handed to the page

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
  game->board = gizmo::prepareRun<double>(
      gizmo::RunRequest{game->request.board, game->request.model, game->request.maxTick, 0.0, {}});
  game->kept = ChunkOutbox();
  if (game->recording) {
    game->recorder = std::make_unique<gizmo::replay::Recorder<double>>(game->kept, *game->board);
    game->board->setObserver(game->recorder.get());
  }
  game->ticksDone = 0;
  game->stopped.clear();
  game->memoryShort = false;
  game->request.keys.clear();
  game->origin.reset();
  game->parentKeys = 0;
  game->startTime = 0;
}

// The game goes on as a branch of `parent` from `at` (a board time): the parent's state at the
// last tick boundary at or before it, with the parent's keys applied by then, recorded from there.
// Throws (the game as it was) when the branch cannot be taken there.
void takeOver(std::unique_ptr<gizmo::replay::OpenedLog>& parent, double at) {
  gizmo::replay::BranchRequest request;
  request.at.time = at;
  gizmo::replay::BranchStart<double> start = gizmo::replay::startBranch<double>(*parent, request);
  game->recorder.reset();
  game->board = std::move(start.board);
  game->kept = ChunkOutbox();
  game->recorder = std::make_unique<gizmo::replay::Recorder<double>>(
      game->kept, *game->board, gizmo::replay::Recorder<double>::Start{start.ticksDone, start.decisionsDone});
  game->board->setObserver(game->recorder.get());
  game->ticksDone = static_cast<std::int64_t>(start.ticksDone);
  game->stopped.clear();
  game->memoryShort = false;
  game->request.keys = start.run.keys;
  game->parentKeys = start.run.keys.size();
  game->origin = start.origin;
  game->takenAt = request;
  game->startTime = game->board->now();
  game->parent = std::move(parent);
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

// The module's memory is full (an allocation failed: the browser gives WebAssembly no more, or
// the page's ceiling, FILE#max-memory=MB, is reached): the game stops, in the ticks that end at
// `in`. The chunk in progress cannot be closed without memory; it is let go, so that the log can
// be written with what was closed (gp_save).
void stopShortOfMemory(double in) {
  game->stopped = "the page's memory ran short";
  game->memoryShort = true;
  game->stoppedIn = in;
  game->board->setObserver(nullptr);
  game->recorder.reset();
}

// Runs every whole tick that ends at or before `target`.
void advanceTo(double target) {
  if (game->stopped.empty()) {
    const std::int64_t k = ticksBy(target, game->request.maxTick, game->ticksDone);
    if (k > game->ticksDone) {
      try {
        game->board->tickSpan(0.0, game->ticksDone + 1, double(k) * game->request.maxTick);
      } catch (const std::bad_alloc&) {
        stopShortOfMemory(double(k) * game->request.maxTick);
      } catch (const std::exception& e) {
        game->stopped = e.what();
        game->stoppedIn = double(k) * game->request.maxTick;
      }
      game->ticksDone = k;
    }
  }
}

// The keys the game was given since it took its parent over, up to the run's end.
std::vector<gizmo::TimedKey> ownKeys(const gizmo::RunRequest& run) {
  return {run.keys.begin() + std::ptrdiff_t(std::min(game->parentKeys, run.keys.size())), run.keys.end()};
}

// The log of the game so far, recorded again from its start: the board's run from time 0, or
// the branch taken from the parent again (recordBranch, as `gizmo record --from` makes it).
gizmo::replay::RecordResult recordAgain(const gizmo::RunRequest& run, gizmo::replay::ChunkSink& sink) {
  const gizmo::PrecisionChoice precision{gizmo::Precision::Double, 0};
  if (!game->origin) return gizmo::replay::recordRun(run, precision, sink, game->warnings);
  gizmo::replay::BranchRequest again = game->takenAt;
  again.keys = ownKeys(run);
  again.duration = run.duration;
  return gizmo::replay::recordBranch(*game->parent, again, sink).record;
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

// The board as built again at time 0, every input forgotten (and a branch's parent left).
EMSCRIPTEN_KEEPALIVE void gp_restart() {
  if (game) build();
}

// Room for `size` bytes of a log the page hands over (then gp_open_log, gp_take_over or
// gp_check); gp_buffer(0) gives the memory back.
EMSCRIPTEN_KEEPALIVE std::uint8_t* gp_buffer(double size) {
  std::vector<std::uint8_t>(static_cast<std::size_t>(size)).swap(incoming);
  return incoming.data();
}

// Opens the log in gp_buffer()'s bytes (a file the page was given, called `name`) and makes its
// board the game's, built at time 0; the log stays open to be taken over (gp_take_over). Returns 1
// with the page's data in gp_text() (JSON: "game", as `gizmo play` writes it into the page, and
// "run", the log's run as the replay player holds it), or 0 with the reason, the game as it was.
EMSCRIPTEN_KEEPALIVE int gp_open_log(const char* name) {
  try {
    auto log = std::make_unique<gizmo::replay::OpenedLog>(
        gizmo::replay::openLog(gizmo::replay::ByteSource::memory(std::exchange(incoming, {}))));
    if (log->precision.kind != gizmo::Precision::Double)
      throw std::invalid_argument("the log was recorded in " + gizmo::precisionName(log->precision) +
                                  "; the page plays double");
    gizmo::cli::GameSettings settings{name, log->request.board, log->header.boardWarnings, log->request.model,
                                      log->request.maxTick};
    nlohmann::ordered_json page{{"game", gizmo::cli::gameJson(settings)},
                                {"run", gizmo::cli::runJson({name, gizmo::cli::trackRun(*log, 0.0)})},
                                {"branch", log->reader.isBranch()},
                                {"complete", log->reader.end().has_value()}};
    auto next = std::make_unique<Game>();
    next->request = log->request;
    next->warnings = log->header.boardWarnings;
    game = std::move(next);
    build();
    game->parent = std::move(log);
    say(page.dump());
    return 1;
  } catch (const std::exception& e) {
    say(e.what());
    return 0;
  }
}

// Takes a log over at board time `at`, rounded down to a tick end: the log the page opened
// (from_buffer 0), or the log in gp_buffer()'s bytes (from_buffer 1: the game's own log so far,
// which the page joined from the chunks it holds, to rewind). The game goes on from there as a
// branch (startBranch, as `gizmo record --from LOG --at T`); returns 1, or 0 with the reason in
// gp_text(), the game as it was.
EMSCRIPTEN_KEEPALIVE int gp_take_over(double at, int fromBuffer) {
  if (!game) return 0;
  try {
    std::unique_ptr<gizmo::replay::OpenedLog> parent;
    if (fromBuffer) {
      parent = std::make_unique<gizmo::replay::OpenedLog>(
          gizmo::replay::openLog(gizmo::replay::ByteSource::memory(std::exchange(incoming, {}))));
    } else {
      if (!game->parent) throw std::invalid_argument("no log is open");
      parent = std::move(game->parent);
    }
    const double maxTick = game->request.maxTick;
    const double t = double(ticksBy(at, maxTick, 0)) * maxTick;
    try {
      takeOver(parent, t);
    } catch (...) {
      if (!fromBuffer) game->parent = std::move(parent);
      throw;
    }
    advanceTo(t);  // the board at the tick end taken over: the page's keys come after it
    say("");
    return 1;
  } catch (const std::exception& e) {
    say(e.what());
    return 0;
  }
}

// Where the game's log starts (0, or the branch's tick boundary) and, for a branch, the parent's
// events before the branch point (else −1).
EMSCRIPTEN_KEEPALIVE double gp_start_time() { return game ? game->startTime : 0.0; }
EMSCRIPTEN_KEEPALIVE double gp_branch_event() { return game && game->origin ? double(game->origin->event) : -1.0; }

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
  advanceTo(target);
  return game->board->now();
}

EMSCRIPTEN_KEEPALIVE double gp_now() { return game ? game->board->now() : 0.0; }
EMSCRIPTEN_KEEPALIVE double gp_events() { return game ? double(game->board->executedTotal()) : 0.0; }
// The board time the log written now ends at (its header's duration): the present, or, once the
// board stopped, the end of the ticks it stopped in.
EMSCRIPTEN_KEEPALIVE double gp_log_end() { return game ? runSoFar().duration : 0.0; }
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
      switch (gizmo::motionOf(gizmo.kind())) {
        case gizmo::KindMotion::Swings:
          numbers.push_back(static_cast<const gizmo::Flipper<double>&>(gizmo).progressAt(now));
          break;
        case gizmo::KindMotion::Turns:
          numbers.push_back(static_cast<const gizmo::Spinner<double>&>(gizmo).angleAt(now) / gizmo::kSpinnerTurnRate);
          break;
        case gizmo::KindMotion::Still: numbers.push_back(0.0); break;
      }
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
  game->saved.clear();
  game->savedSplit = -1;
  try {
    gizmo::replay::LogWriter writer(game->saved);
    // The header, made now, and every chunk closed (those the page holds go in at savedSplit).
    const auto headerAndChunks = [&] {
      const std::vector<std::uint8_t> header =
          gizmo::replay::recordHeader(runSoFar(), *game->board, game->warnings, game->origin);
      if (game->origin) writer.branchHeader(header);
      else writer.header(header);
      if (game->kept.handedOut() > 0) game->savedSplit = double(game->saved.size());
      game->kept.sendTo(writer);
    };
    if (game->memoryShort && game->recording) {
      // No memory to record the game again: without its end, the log is one cut off after its
      // last complete chunk, which readers take up to there.
      headerAndChunks();
      say("memory ran short: the log holds the game up to its last complete chunk");
      return double(game->saved.size());
    }
    if (!game->stopped.empty() || !game->recorder) {
      const gizmo::replay::RecordResult r = recordAgain(runSoFar(), writer);
      say(r.completed ? "" : "the log records the stop: " + r.error);
      return double(game->saved.size());
    }
    headerAndChunks();
    game->recorder->finishCopy(writer);
    say("");
    return double(game->saved.size());
  } catch (const std::exception& e) {
    game->saved.clear();
    say(e.what());
    return -1;
  }
}

// The bytes of the log gp_save() wrote; gp_forget_saved() gives their memory back. When the page
// has taken chunks (gp_take_chunks), they belong at gp_save_split() (the end of the header), in
// the order taken; else −1, and the bytes are the whole log.
EMSCRIPTEN_KEEPALIVE const std::uint8_t* gp_saved() { return game ? game->saved.data() : nullptr; }
EMSCRIPTEN_KEEPALIVE double gp_save_split() { return game ? game->savedSplit : -1.0; }

// Hands the page the oldest chunk closed since it last took one, framed as the log holds it, and
// forgets its bytes (not its place in the log's index): returns its size (0 when none is left),
// the bytes at gp_taken(), kept until gp_forget_taken().
// One chunk at a time: the page takes them until it gets 0 bytes. When there is no memory left
// even for a chunk's index entry, the game stops (as when a tick finds none) and the chunks stay
// in the module, to be written into the log.
EMSCRIPTEN_KEEPALIVE double gp_take_chunks() {
  if (!game) return 0;
  try {
    game->kept.handOut(game->handed);
  } catch (const std::bad_alloc&) {
    if (game->stopped.empty()) stopShortOfMemory(game->board->now());
    return 0;
  }
  return double(game->handed.size());
}
// How many chunks the game's Recorder has closed (handed to the page or not).
EMSCRIPTEN_KEEPALIVE double gp_chunks_closed() { return game ? double(game->kept.closed()) : 0.0; }
EMSCRIPTEN_KEEPALIVE const std::uint8_t* gp_taken() { return game ? game->handed.data() : nullptr; }
// The page has copied the chunks out: their memory goes back.
EMSCRIPTEN_KEEPALIVE void gp_forget_taken() {
  if (game) std::vector<std::uint8_t>().swap(game->handed);
}

// What the module holds for the game's recording: the closed chunks it keeps and the index
// entries of all, the chunks last handed out, and the log last written.
EMSCRIPTEN_KEEPALIVE double gp_held_bytes() {
  if (!game) return 0;
  return double(game->kept.bytesHeld() + game->handed.capacity() + game->saved.capacity());
}
EMSCRIPTEN_KEEPALIVE void gp_forget_saved() {
  if (game) std::vector<std::uint8_t>().swap(game->saved);
}

// The page's own check of the log gp_save() wrote (from_buffer 0), or of the log in gp_buffer()'s
// bytes (from_buffer 1: the page joined the chunks it holds into it), as `gizmo replay` makes it:
// the log's board and inputs run again and every decision compared; the log recorded again from
// them (`gizmo record`'s recordRun, or recordBranch for a branch), which must give the same bytes;
// then, when the log ends at the board's present, every ball the log has there compared with the
// game's, bit for bit. 1 identical, 0 not, −1 the log does not read; gp_text() says what was found.
EMSCRIPTEN_KEEPALIVE int gp_check(int fromBuffer) {
  if (!game) return -1;
  const std::vector<std::uint8_t>& written = fromBuffer ? incoming : game->saved;
  try {
    const gizmo::replay::OpenedLog log = gizmo::replay::openLog(gizmo::replay::ByteSource::memory(written));
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
      recordAgain(runSoFar(), writer);
    }
    const std::string command = game->origin ? "gizmo record --from" : "gizmo record";
    if (again != written) {
      say(summary + ", but the log is not the one " + command + " writes of its board and inputs");
      return 0;
    }
    summary += ", byte for byte the log " + command + " writes of them";
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
