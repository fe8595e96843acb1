#pragma once
// Variations of a run that a user brought (`gizmo fuzz BOARD`, docs/fuzzing.md, "Fuzzing your own
// board"): each case departs from the user's board and key input by a few random changes, and a
// failure is shrunk back toward the user's run, so that what is reported is the smallest departure
// from it that still fails.
//
// A departure is kept as data (what was added, taken out, moved or scaled), not only as the run
// it makes: shrinking undoes or halves its parts one at a time, and the report says them in words.
// Deterministic like the generator: the same (base, seed, options) gives the same departure on
// every machine (SeededRandom only, and the core's own trigonometry for the one angle it needs).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gizmo/core/math/precision.hpp"
#include "gizmo/core/run/run.hpp"

namespace gizmo::verify::fuzz {

// Each range is a flag of `gizmo fuzz BOARD`; 0 (or false) switches that variation off.
struct VariationOptions {
  double keyPressesPer10s = 4;  // --vary-keys: presses added, on average, per 10 s of board time
  double position = 0.25;       // --vary-position: L a ball may move (where it still fits)
  double speed = 10;            // --vary-speed: % a moving ball's speed may change
  double angle = 10;            // --vary-angle: degrees a moving ball's direction may turn
  double kick = 1;              // --vary-kick: L/s a ball at rest may be given
  double gravity = 20;          // --vary-gravity: % gravity may change
  double friction = 50;         // --vary-friction: % each friction constant may change
  bool model = true;            // --vary-model: one case in four runs the other motion model
  bool maxTick = true;          // --vary-max-tick: one case in four halves or doubles the maximum tick
  // --vary-scalar: one case in four runs in the other of double and long double. Off unless asked:
  // long double is a different format on each kind of machine (x87's 80 bits, binary128, or double
  // itself), so such a campaign's digest holds only among machines of one kind.
  bool scalar = false;
  // Shrinking cuts no run shorter than this: a tick or two, or the time the user's expectations
  // need to be decided (a run cut before it would break them by ending).
  double shortestRun = 0.05;
};

// One key press the variation added: down at `down`, up at `up` (up == down: a tap within one
// instant), repeated `repeats` times `period` apart (a fast repeat).
struct AddedPress {
  int key = 0;
  double down = 0, up = 0;
  int repeats = 1;
  double period = 0;
};

struct BallDeparture {
  std::size_t ball = 0;           // index in the board's balls
  double dx = 0, dy = 0;          // moved, L
  double speedFactor = 1;         // speed scaled
  double turn = 0;                // tan(θ/2) of the turn of its direction (rational rotation, no libm)
  double kickVx = 0, kickVy = 0;  // added to a ball at rest
};

struct Departure {
  std::vector<AddedPress> added;
  std::vector<std::size_t> removed;                   // indices of the base's key events taken out
  std::vector<std::pair<std::size_t, double>> moved;  // a base key event and its new time
  std::vector<BallDeparture> balls;
  double gravityFactor = 1, muFactor = 1, mu2Factor = 1;
  bool otherModel = false;
  double maxTickFactor = 1;        // 1, 1/2 or 2
  bool otherScalar = false;        // long double for a double run, and the other way round
  std::optional<double> duration;  // a shorter run (only shrinking sets it)

  bool empty() const;
};

// The departure of case `seed` (none for the user's own run, which a campaign checks as case 0).
Departure randomDeparture(const RunRequest& base, std::uint64_t seed, const VariationOptions& options);
// The run a departure makes of the base: keys merged in time order, balls moved and relaunched.
RunRequest applyDeparture(const RunRequest& base, const Departure& d);
// The scalar a departure's run is checked in, from the base's (Double or LongDouble).
Precision scalarOf(Precision base, const Departure& d);

// Departures strictly closer to the base than `d`, boldest first: every added press gone, half of
// them, each one; each removed or moved event given back; each ball's change undone, then halved;
// gravity, friction, model and maximum tick restored; a shorter run.
std::vector<Departure> departuresCloser(const RunRequest& base, const Departure& d, double shortestRun);

struct ShrunkDeparture {
  Departure departure;
  std::size_t steps = 0, tries = 0;
};
// Greedy, as minimise() in run_shrinker.hpp: the first closer departure whose run still fails,
// again from it, until none does or `fails` has been called `budget` times.
// `fails` is given the candidate's run and the candidate itself (whose scalar it may need).
ShrunkDeparture shrinkDeparture(const RunRequest& base, const Departure& failing,
                                const std::function<bool(const RunRequest&, const Departure&)>& fails,
                                std::size_t budget, double shortestRun);

// The departure in words a player reads: "key 32 down at 1.25 s, up at 1.4 s; B launched 0.8 %
// faster, turned 2.1° anticlockwise; gravity 27.5 (25 on the board)". "none: the board as given"
// for an empty one.
std::string describeDeparture(const RunRequest& base, const Departure& d, Precision baseScalar = Precision::Double);

// The keys a board connects to its gizmos, each once, in increasing order.
std::vector<int> connectedKeys(const BoardSpec& board);

}  // namespace gizmo::verify::fuzz
