#include "gizmo/verify/fuzz/variations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/math/trig.hpp"
#include "gizmo/verify/fuzz/seeded_random.hpp"

namespace gizmo::verify::fuzz {
namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string seconds(double t) { return number(t) + " s"; }

const char* directionName(KeyDirection d) { return d == KeyDirection::Down ? "down" : "up"; }

// tan(θ/2) of the largest turn, from the core's deterministic sine and cosine: every machine
// draws the same turns from the same seed.
double halfTurnTangent(double degrees) {
  double s = 0, c = 1;
  math::sinCos(degrees * (3.14159265358979323846 / 360.0), s, c);
  return c > 0 ? s / c : 0;
}

// Rotation by the angle whose half-angle tangent is t: cos = (1 − t²)/(1 + t²), sin = 2t/(1 + t²).
void rotate(double t, double& vx, double& vy) {
  const double d = 1 + t * t, c = (1 - t * t) / d, s = 2 * t / d;
  const double x = c * vx - s * vy, y = s * vx + c * vy;
  vx = x, vy = y;
}

// A point uniform in the disc of radius r (rejection from the square: integer draws only).
void inDisc(SeededRandom& r, double radius, double& x, double& y) {
  do {
    x = r.real(-1, 1), y = r.real(-1, 1);
  } while (x * x + y * y > 1);
  x *= radius, y *= radius;
}

// A ball's change: moved, turned, scaled, kicked.
void applyBallChange(BallSpec& ball, const BallDeparture& b) {
  ball.x += b.dx, ball.y += b.dy;
  rotate(b.turn, ball.vx, ball.vy);
  ball.vx = ball.vx * b.speedFactor + b.kickVx;
  ball.vy = ball.vy * b.speedFactor + b.kickVy;
}

double effectiveDuration(const RunRequest& base, const Departure& d) {
  return d.duration ? *d.duration : base.duration;
}

bool sameBallChange(const BallDeparture& b) {
  return b.dx == 0 && b.dy == 0 && b.speedFactor == 1 && b.turn == 0 && b.kickVx == 0 && b.kickVy == 0;
}

// The departure with one of its changes other than keys given back, for each such change: each
// ball's, gravity, each friction constant, the maximum tick, the model.
std::vector<Departure> eachChangeGivenBack(const Departure& d) {
  std::vector<Departure> out;
  for (std::size_t i = 0; i < d.balls.size(); ++i) {
    out.push_back(d);
    out.back().balls.erase(out.back().balls.begin() + std::ptrdiff_t(i));
  }
  for (double Departure::*f :
       {&Departure::gravityFactor, &Departure::muFactor, &Departure::mu2Factor, &Departure::maxTickFactor})
    if (d.*f != 1) {
      out.push_back(d);
      out.back().*f = 1;
    }
  if (d.otherModel) {
    out.push_back(d);
    out.back().otherModel = false;
  }
  if (d.otherScalar) {
    out.push_back(d);
    out.back().otherScalar = false;
  }
  return out;
}

}  // namespace

bool Departure::empty() const {
  return added.empty() && removed.empty() && moved.empty() && std::all_of(balls.begin(), balls.end(), sameBallChange) &&
         gravityFactor == 1 && muFactor == 1 && mu2Factor == 1 && !otherModel && maxTickFactor == 1 && !otherScalar &&
         !duration;
}

std::vector<int> connectedKeys(const BoardSpec& board) {
  std::set<int> keys;
  for (const KeyConnectSpec& k : board.keyConnections) keys.insert(k.key);
  return {keys.begin(), keys.end()};
}

Departure randomDeparture(const RunRequest& base, std::uint64_t seed, const VariationOptions& o) {
  SeededRandom r(seed);
  Departure d;
  const double duration = base.duration;
  const std::vector<int> keys = connectedKeys(base.board);
  if (!keys.empty() && o.keyPressesPer10s > 0 && duration > 0) {
    // About keyPressesPer10s presses per 10 s, at least one: uniform in 1..2n.
    const double mean = o.keyPressesPer10s * duration / 10;
    const int most = std::max(1, int(std::min(2 * mean, 1000.0) + 0.5));
    const int count = r.whole(1, most);
    for (int i = 0; i < count; ++i) {
      AddedPress p;
      p.key = keys[std::size_t(r.whole(0, int(keys.size()) - 1))];
      p.down = r.real(0, duration);
      // One press in four on a tick boundary, where a key meets the end of a tick.
      if (r.chance(4) && base.maxTick > 0) p.down = std::floor(p.down / base.maxTick) * base.maxTick;
      switch (r.whole(0, 3)) {
        case 0: p.up = p.down; break;                      // a tap within one instant
        case 1: p.up = p.down + r.real(0.01, 0.5); break;  // a press
        case 2: p.up = -1; break;                          // held to the end
        default:                                           // a fast repeat
          p.repeats = r.whole(2, 6);
          p.period = r.real(0.02, 0.1);
          p.up = p.down + p.period / 2;
      }
      d.added.push_back(p);
    }
  }
  if (!base.keys.empty() && o.keyPressesPer10s > 0) {
    if (r.chance(3)) d.removed.push_back(std::size_t(r.whole(0, int(base.keys.size()) - 1)));
    if (r.chance(3)) {
      const std::size_t k = std::size_t(r.whole(0, int(base.keys.size()) - 1));
      if (std::find(d.removed.begin(), d.removed.end(), k) == d.removed.end())
        d.moved.emplace_back(k, std::max(0.0, base.keys[k].time + r.real(-0.5, 0.5)));
    }
  }
  // Each ball's change is drawn whole (place, speed, direction, kick) and kept only where the
  // board, with the changes before it, has no problem it did not have (an overlap, or a ball at
  // rest in an absorber set moving): up to four draws, else the ball is left as it was.
  const std::size_t problems = checkBoardSpec(base.board).size();
  const double turn = o.angle > 0 ? halfTurnTangent(std::min(o.angle, 179.0)) : 0;
  BoardSpec varied = base.board;  // with the ball changes kept so far
  for (std::size_t i = 0; i < base.board.balls.size(); ++i) {
    if (!r.chance(2)) continue;
    const BallSpec& ball = base.board.balls[i];
    for (int attempt = 0; attempt < 4; ++attempt) {
      BallDeparture b;
      b.ball = i;
      if (o.position > 0) inDisc(r, o.position, b.dx, b.dy);
      if (ball.vx != 0 || ball.vy != 0) {
        if (o.speed > 0) b.speedFactor = 1 + r.real(-o.speed, o.speed) / 100;
        if (o.angle > 0) b.turn = r.real(-turn, turn);
      } else if (o.kick > 0) {
        inDisc(r, o.kick, b.kickVx, b.kickVy);
      }
      if (sameBallChange(b)) break;
      // With the changes of the balls before it: two balls moved toward each other may each fit
      // alone and overlap together (found on a real board of 269 balls).
      BoardSpec tried = varied;
      applyBallChange(tried.balls[i], b);
      if (checkBoardSpec(tried).size() <= problems) {
        d.balls.push_back(b);
        varied = std::move(tried);
        break;
      }
    }
  }
  if (o.gravity > 0 && base.board.gravity != 0 && r.chance(2))
    d.gravityFactor = 1 + r.real(-o.gravity, o.gravity) / 100;
  if (o.friction > 0 && (base.board.mu != 0 || base.board.mu2 != 0) && r.chance(2)) {
    d.muFactor = 1 + r.real(-o.friction, o.friction) / 100;
    d.mu2Factor = 1 + r.real(-o.friction, o.friction) / 100;
  }
  if (o.model && r.chance(4)) d.otherModel = true;
  if (o.maxTick && r.chance(4)) d.maxTickFactor = r.chance(2) ? 0.5 : 2;
  if (o.scalar && r.chance(4)) d.otherScalar = true;  // drawn last: campaigns without it draw as before
  return d;
}

Precision scalarOf(Precision base, const Departure& d) {
  if (!d.otherScalar) return base;
  return base == Precision::LongDouble ? Precision::Double : Precision::LongDouble;
}

RunRequest applyDeparture(const RunRequest& base, const Departure& d) {
  RunRequest run = base;
  if (d.duration) run.duration = *d.duration;
  std::vector<TimedKey> keys;
  for (std::size_t k = 0; k < base.keys.size(); ++k) {
    if (std::find(d.removed.begin(), d.removed.end(), k) != d.removed.end()) continue;
    TimedKey key = base.keys[k];
    for (const auto& [index, time] : d.moved)
      if (index == k) key.time = time;
    keys.push_back(key);
  }
  for (const AddedPress& p : d.added)
    for (int i = 0; i < p.repeats; ++i) {
      const double shift = i * p.period;
      keys.push_back({p.down + shift, p.key, KeyDirection::Down});
      if (p.up >= p.down) keys.push_back({p.up + shift, p.key, KeyDirection::Up});
    }
  std::erase_if(keys, [&](const TimedKey& k) { return !(k.time >= 0) || !(k.time < run.duration); });
  std::stable_sort(keys.begin(), keys.end(), [](const TimedKey& a, const TimedKey& b) { return a.time < b.time; });
  run.keys = std::move(keys);
  for (const BallDeparture& b : d.balls) applyBallChange(run.board.balls[b.ball], b);
  run.board.gravity *= d.gravityFactor;
  run.board.mu *= d.muFactor;
  run.board.mu2 *= d.mu2Factor;
  if (d.otherModel) run.model = run.model == MotionModel::Ballistic ? MotionModel::Classic : MotionModel::Ballistic;
  run.maxTick *= d.maxTickFactor;
  return run;
}

std::vector<Departure> departuresCloser(const RunRequest& base, const Departure& d, double shortestRun) {
  std::vector<Departure> out;
  auto with = [&](auto change) {
    Departure c = d;
    change(c);
    out.push_back(std::move(c));
  };
  // Key presses: all gone, each half, then each one; a fast repeat pressed once.
  const std::size_t n = d.added.size();
  if (n > 0) with([](Departure& c) { c.added.clear(); });
  if (n > 2) {
    with([&](Departure& c) { c.added.erase(c.added.begin(), c.added.begin() + std::ptrdiff_t(n / 2)); });
    with([&](Departure& c) { c.added.erase(c.added.begin() + std::ptrdiff_t(n / 2), c.added.end()); });
  }
  for (std::size_t i = 0; n > 1 && i < n; ++i)
    with([&](Departure& c) { c.added.erase(c.added.begin() + std::ptrdiff_t(i)); });
  for (std::size_t i = 0; i < n; ++i)
    if (d.added[i].repeats > 1) with([&](Departure& c) { c.added[i].repeats = 1; });
  for (std::size_t i = 0; i < d.removed.size(); ++i)
    with([&](Departure& c) { c.removed.erase(c.removed.begin() + std::ptrdiff_t(i)); });
  for (std::size_t i = 0; i < d.moved.size(); ++i) {
    with([&](Departure& c) { c.moved.erase(c.moved.begin() + std::ptrdiff_t(i)); });
    const double from = base.keys[d.moved[i].first].time, to = d.moved[i].second;
    if (std::abs(to - from) > 1e-3) with([&](Departure& c) { c.moved[i].second = (from + to) / 2; });
  }
  // Every ball's change undone at once; then each change given back on its own (each ball's,
  // gravity, friction, tick, model); then each halved, while it is not already tiny.
  if (d.balls.size() > 1) with([](Departure& c) { c.balls.clear(); });
  const std::vector<Departure> givenBack = eachChangeGivenBack(d);
  out.insert(out.end(), givenBack.begin(), givenBack.end());
  for (std::size_t i = 0; i < d.balls.size(); ++i) {
    const BallDeparture& b = d.balls[i];
    const bool big = std::abs(b.dx) + std::abs(b.dy) > 1e-4 || std::abs(b.speedFactor - 1) > 1e-4 ||
                     std::abs(b.turn) > 1e-4 || std::abs(b.kickVx) + std::abs(b.kickVy) > 1e-4;
    if (!big) continue;
    with([&](Departure& c) {
      BallDeparture& h = c.balls[i];
      h.dx /= 2, h.dy /= 2, h.speedFactor = (1 + h.speedFactor) / 2, h.turn /= 2, h.kickVx /= 2, h.kickVy /= 2;
    });
  }
  for (double Departure::*f : {&Departure::gravityFactor, &Departure::muFactor, &Departure::mu2Factor})
    if (std::abs(d.*f - 1) > 1e-4) with([&](Departure& c) { c.*f = (1 + c.*f) / 2; });
  // A change given back while one added press moves a little: the press may have found its window
  // only with the change (gravity a hair weaker brought the ball later), and finds it again without
  // the change at another time. Only near the end, with one or two presses left.
  if (!d.added.empty() && d.added.size() <= 2)
    for (const Departure& back : givenBack)
      for (std::size_t i = 0; i < back.added.size(); ++i)
        for (double shift : {-0.01, 0.01, -0.02, 0.02, -0.04, 0.04, -0.08, 0.08, -0.16, 0.16}) {
          Departure c = back;
          AddedPress& p = c.added[i];
          if (p.down + shift < 0) continue;
          p.down += shift;
          if (p.up >= p.down - shift) p.up += shift;
          out.push_back(std::move(c));
        }
  // A shorter run: half, then nine tenths.
  const double duration = effectiveDuration(base, d);
  if (duration / 2 >= shortestRun) with([&](Departure& c) { c.duration = duration / 2; });
  if (duration * 0.9 >= shortestRun) with([&](Departure& c) { c.duration = duration * 0.9; });
  return out;
}

ShrunkDeparture shrinkDeparture(const RunRequest& base, const Departure& failing,
                                const std::function<bool(const RunRequest&, const Departure&)>& fails,
                                std::size_t budget, double shortestRun) {
  ShrunkDeparture s{failing, 0, 0};
  const std::size_t problems = checkBoardSpec(base.board).size();
  for (bool progress = true; progress && s.tries < budget;) {
    progress = false;
    for (Departure& candidate : departuresCloser(base, s.departure, shortestRun)) {
      if (s.tries >= budget) break;
      // Half a move or a kick may land where the whole did not: a ball overlapping a gizmo, or
      // moving inside an absorber. Such a run is not a variation of the board at all.
      const RunRequest run = applyDeparture(base, candidate);
      if (checkBoardSpec(run.board).size() > problems) continue;
      ++s.tries;
      if (fails(run, candidate)) {
        s.departure = std::move(candidate);
        ++s.steps;
        progress = true;
        break;
      }
    }
  }
  return s;
}

std::string describeDeparture(const RunRequest& base, const Departure& d, Precision baseScalar) {
  std::vector<std::string> parts;
  for (const AddedPress& p : d.added) {
    const std::string key = "key " + std::to_string(p.key);
    if (p.repeats > 1)
      parts.push_back(key + " pressed " + std::to_string(p.repeats) + " times from " + seconds(p.down) + ", every " +
                      seconds(p.period) + " (each held " + seconds(p.up - p.down) + ")");
    else if (p.up < p.down) parts.push_back(key + " down at " + seconds(p.down) + " and held");
    else if (p.up == p.down) parts.push_back(key + " down and up at " + seconds(p.down));
    else parts.push_back(key + " down at " + seconds(p.down) + ", up at " + seconds(p.up));
  }
  for (std::size_t k : d.removed)
    parts.push_back("key " + std::to_string(base.keys[k].key) + " " + directionName(base.keys[k].direction) + " at " +
                    seconds(base.keys[k].time) + " left out");
  for (const auto& [k, time] : d.moved)
    parts.push_back("key " + std::to_string(base.keys[k].key) + " " + directionName(base.keys[k].direction) +
                    " moved from " + seconds(base.keys[k].time) + " to " + seconds(time));
  for (const BallDeparture& b : d.balls) {
    const BallSpec& ball = base.board.balls[b.ball];
    std::vector<std::string> says;
    if (b.dx != 0 || b.dy != 0)
      says.push_back("moved " + number(std::hypot(b.dx, b.dy)) + " L to (" + number(ball.x + b.dx) + ", " +
                     number(ball.y + b.dy) + ")");
    if (b.speedFactor != 1)
      says.push_back("launched " + number(std::abs(b.speedFactor - 1) * 100) + " % " +
                     (b.speedFactor > 1 ? "faster" : "slower"));
    if (b.turn != 0)  // y points down the screen: a positive turn is clockwise there
      says.push_back("turned " + number(std::abs(2 * std::atan(b.turn)) * 180 / 3.14159265358979323846) + "° " +
                     (b.turn > 0 ? "clockwise" : "anticlockwise"));
    if (b.kickVx != 0 || b.kickVy != 0)
      says.push_back("given (" + number(b.kickVx) + ", " + number(b.kickVy) + ") L/s from rest");
    std::string all;
    for (const std::string& s : says) all += (all.empty() ? "" : ", ") + s;
    if (!all.empty()) parts.push_back(ball.name + " " + all);
  }
  if (d.gravityFactor != 1)
    parts.push_back("gravity " + number(base.board.gravity * d.gravityFactor) + " L/s² (" + number(base.board.gravity) +
                    " on the board)");
  if (d.muFactor != 1)
    parts.push_back("friction mu " + number(base.board.mu * d.muFactor) + " (" + number(base.board.mu) +
                    " on the board)");
  if (d.mu2Factor != 1)
    parts.push_back("friction mu2 " + number(base.board.mu2 * d.mu2Factor) + " (" + number(base.board.mu2) +
                    " on the board)");
  if (d.otherModel)
    parts.push_back(std::string("the ") + (base.model == MotionModel::Ballistic ? "classic" : "ballistic") +
                    " model (" + std::string(motionModelName(base.model)) + " given)");
  if (d.maxTickFactor != 1)
    parts.push_back("maximum tick " + seconds(base.maxTick * d.maxTickFactor) + " (" + seconds(base.maxTick) +
                    " given)");
  if (d.otherScalar)
    parts.push_back(scalarOf(baseScalar, d) == Precision::LongDouble ? "in long double (double given)"
                                                                     : "in double (long double given)");
  if (d.duration) parts.push_back("the run cut to " + seconds(*d.duration) + " (" + seconds(base.duration) + " given)");
  if (parts.empty()) return "none: the board as given";
  std::string s;
  for (const std::string& p : parts) s += (s.empty() ? "" : "; ") + p;
  return s;
}

}  // namespace gizmo::verify::fuzz
