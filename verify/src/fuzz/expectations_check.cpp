// A run checked against the user's expectations (expectations.hpp): an observer that follows
// every ball between the board's events. Between two events (or tick boundaries) a ball's path is
// the one it had after the first of them, so each interval is checked along that path exactly:
// the instants at which its centre crosses a rectangle's side are the roots of its coordinates'
// quadratics. This is a verifier's measurement, not a decision of the run: it may use libm.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/decimal_text.hpp"
#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/gizmos/sink.hpp"
#include "gizmo/verify/fuzz/expectations.hpp"

namespace gizmo::verify::fuzz {
namespace {

struct Rect {
  double x0, y0, x1, y1;
  bool contains(const Vec2<double>& p) const { return x0 <= p.x && p.x <= x1 && y0 <= p.y && p.y <= y1; }
};

// The roots in (0, T) of c + b τ + ½ a τ², where the coordinate path crosses a line.
void crossings(double c, double b, double a, double T, std::vector<double>& out) {
  auto keep = [&](double tau) {
    if (0 < tau && tau < T) out.push_back(tau);
  };
  const double h = a / 2;
  if (h == 0) {
    if (b != 0) keep(-c / b);
    return;
  }
  const double disc = b * b - 4 * h * c;
  if (disc < 0) return;
  const double q = -(b + std::copysign(std::sqrt(disc), b)) / 2;  // no cancellation
  keep(q / h);
  if (q != 0) keep(c / q);
}

// The first τ in [0, T] at which `inside` holds along the path, if any: `inside` can change only
// where a coordinate crosses one of the rectangle's lines, so it is looked at there and halfway
// between.
template <class Inside>
std::optional<double> firstInstant(const Trajectory<double>& path, double T, const Rect& r, Inside inside) {
  std::vector<double> cuts{0, T};
  for (const double x : {r.x0, r.x1}) crossings(path.p.x - x, path.v.x, path.a.x, T, cuts);
  for (const double y : {r.y0, r.y1}) crossings(path.p.y - y, path.v.y, path.a.y, T, cuts);
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    if (inside(path.positionAt(cuts[i]))) return cuts[i];
    if (i + 1 < cuts.size() && inside(path.positionAt((cuts[i] + cuts[i + 1]) / 2))) return cuts[i];
  }
  return std::nullopt;
}

std::string at(const Vec2<double>& p) {
  std::ostringstream s;
  s << "(" << shortestDecimal(p.x) << ", " << shortestDecimal(p.y) << ")";
  return s.str();
}
std::string seconds(double t) { return shortestDecimal(t) + " s"; }

struct BallWatch {
  std::string name;
  double inPlaySince = 0;                // 0, or the instant a spawner put it on the board
  std::map<GizmoId, double> capturedBy;  // each absorber that captured it, first time
  std::optional<double> outOfPlay;       // taken out by a sink
  std::optional<double> restingSince;
  Trajectory<double> path;  // at the last moment
  bool held = false;        // captured at the last moment
};

class ExpectationChecker final : public BoardObserver<double> {
 public:
  ExpectationChecker(const GameBoard<double>& board, const std::vector<Expectation>& expectations, double end)
      : board_(board),
        expectations_(expectations),
        end_(end),
        decided_(expectations.size(), false),
        hits_(expectations.size(), 0) {
    for (const Expectation& e : expectations) gizmos_.push_back(resolve(e));
    for (GizmoId id : board.ballIds()) watch(id, 0);
  }

  void eventExecuted(const Event<double>& e, const EventOutcome<double>&) override {
    if (e.kind == EventKind::Collision) countHit(e);
    moment(e.time);
  }
  void modelRuleApplied(const double& time, ModelRule rule, GizmoId gizmo, GizmoId other) override {
    if (rule == AbsorberRule::Captured) {
      if (BallWatch* b = find(other)) b->capturedBy.emplace(gizmo, time);
    } else if (rule == SinkRule::Sunk) {
      if (BallWatch* b = find(other)) {
        if (!b->outOfPlay) sunk(other, *b, gizmo, time);
        b->outOfPlay = time;
      }
    }
  }
  void tickBoundary(const double& time) override { moment(time); }

  // Decides what the run's end decides: deadlines that fell within it.
  void finish() {
    for (std::size_t i = 0; i < expectations_.size(); ++i) decideDeadlines(i, end_, true);
  }

  std::vector<ExpectationFailure> failures;

 private:
  // The gizmo an expectation names (the absorber of `reaches`, the gizmo of `hit`), looked up
  // once; kNoGizmo for the other kinds.
  GizmoId resolve(const Expectation& e) {
    auto named = [&](const std::string& name, const char* what) {
      const std::optional<GizmoId> id = board_.find(name);
      if (!id) throw ExpectationError(e.source + ": the board has no " + what + " named '" + name + "'");
      return *id;
    };
    if (!e.ball.empty() && !board_.gizmo(named(e.ball, "ball")).asBall())
      throw ExpectationError(e.source + ": '" + e.ball + "' is not a ball");
    if (e.kind == ExpectationKind::Reaches) {
      const GizmoId absorber = named(e.gizmo, "absorber");
      if (board_.gizmo(absorber).kind() != GizmoKind::Absorber)
        throw ExpectationError(e.source + ": '" + e.gizmo + "' is not an absorber");
      return absorber;
    }
    return e.kind == ExpectationKind::Hit ? named(e.gizmo, "gizmo") : kNoGizmo;
  }

  void watch(GizmoId id, double since) {
    const Ball<double>& ball = *board_.gizmo(id).asBall();
    BallWatch w;
    w.name = ball.name();
    w.inPlaySince = since;
    w.path = ball.trajectoryAt(since);
    w.held = ball.captured();
    balls_.emplace(id, std::move(w));
  }
  BallWatch* find(GizmoId id) {
    const auto it = balls_.find(id);
    return it == balls_.end() ? nullptr : &it->second;
  }
  bool about(const Expectation& e, const BallWatch& b) const { return e.ball.empty() || e.ball == b.name; }

  void fail(std::size_t i, double time, const std::string& what) {
    if (decided_[i]) return;
    decided_[i] = true;
    failures.push_back(ExpectationFailure{i, time, expectations_[i].source + ": " + what});
  }

  void countHit(const Event<double>& e) {
    const bool ballInvolved = board_.gizmo(e.a).asBall() || board_.gizmo(e.b).asBall();
    for (std::size_t i = 0; i < expectations_.size(); ++i) {
      const Expectation& x = expectations_[i];
      if (x.kind != ExpectationKind::Hit || !ballInvolved || e.time > x.seconds) continue;
      if (e.a == gizmos_[i] || e.b == gizmos_[i]) ++hits_[i];
    }
  }

  void sunk(GizmoId id, const BallWatch& b, GizmoId sink, double time) {
    for (std::size_t i = 0; i < expectations_.size(); ++i) {
      const Expectation& e = expectations_[i];
      if (e.kind != ExpectationKind::StaysOnBoard || !about(e, b)) continue;
      fail(i, time,
           "ball " + b.name + " was taken out of play by " + board_.gizmo(sink).name() + " at t = " + seconds(time) +
               ", at " + at(board_.gizmo(id).asBall()->positionAt(time)));
    }
  }

  // The interval since the last moment, along the paths the balls had then; then the deadlines
  // that passed, and the paths and rests from now on.
  void moment(double now) {
    for (GizmoId id : board_.ballIds())
      if (!balls_.count(id)) watch(id, now);
    for (const auto& entry : balls_)
      if (!entry.second.held && !entry.second.outOfPlay) along(entry.second, now);
    for (std::size_t i = 0; i < expectations_.size(); ++i) decideDeadlines(i, now, false);
    for (auto& [id, b] : balls_) {
      const Ball<double>& ball = *board_.gizmo(id).asBall();
      b.path = ball.trajectoryAt(now);
      b.held = ball.captured();
      rest(ball, b, now);
    }
    last_ = now;
  }

  void along(const BallWatch& b, double now) {
    const double T = now - last_;
    for (std::size_t i = 0; i < expectations_.size(); ++i) {
      const Expectation& e = expectations_[i];
      if (decided_[i] || !about(e, b)) continue;
      std::optional<double> tau;
      std::string what;
      if (e.kind == ExpectationKind::Avoids) {
        const Rect r{e.x0, e.y0, e.x1, e.y1};
        tau = firstInstant(b.path, T, r, [&](const Vec2<double>& p) { return r.contains(p); });
        what = "entered the rectangle " + at({e.x0, e.y0}) + " to " + at({e.x1, e.y1});
      } else if (e.kind == ExpectationKind::StaysOnBoard) {
        const Rect board{0, 0, kBoardSize, kBoardSize};
        tau = firstInstant(b.path, T, board, [&](const Vec2<double>& p) { return !board.contains(p); });
        what = "left the board";
      }
      if (tau)
        fail(
            i, last_ + *tau,
            "ball " + b.name + " " + what + " at t = " + seconds(last_ + *tau) + ", at " + at(b.path.positionAt(*tau)));
    }
  }

  // A ball outside an absorber slower than kRestSpeed now rests since now, or since it was
  // first seen so at an earlier moment.
  void rest(const Ball<double>& ball, BallWatch& b, double now) {
    const bool slow = !b.held && !b.outOfPlay && lengthSquared(b.path.v) <= kRestSpeed * kRestSpeed;
    if (!slow) {
      b.restingSince.reset();
      return;
    }
    if (!b.restingSince) b.restingSince = now;
    for (std::size_t i = 0; i < expectations_.size(); ++i) {
      const Expectation& e = expectations_[i];
      if (e.kind != ExpectationKind::RestsAtMost || !about(e, b) || !(now - *b.restingSince > e.seconds)) continue;
      fail(i, now,
           "ball " + b.name + " has rested at " + at(ball.positionAt(now)) + " outside an absorber since t = " +
               seconds(*b.restingSince) + ", more than " + seconds(e.seconds) + " (seen at t = " + seconds(now) + ")");
    }
  }

  // `reaches` and `hit` are decided once their time has passed (at the end: once it is reached).
  void decideDeadlines(std::size_t i, double now, bool atEnd) {
    const Expectation& e = expectations_[i];
    auto passed = [&](double deadline) { return atEnd ? deadline <= now : deadline < now; };
    if (decided_[i]) return;
    if (e.kind == ExpectationKind::Hit && passed(e.seconds)) {
      if (hits_[i] >= e.count) decided_[i] = true;
      else
        fail(i, e.seconds,
             e.gizmo + " was hit " + std::to_string(hits_[i]) + " times within " + seconds(e.seconds) +
                 ", fewer than " + std::to_string(e.count));
      return;
    }
    if (e.kind != ExpectationKind::Reaches) return;
    for (const auto& entry : balls_) {
      const BallWatch& b = entry.second;
      const double deadline = b.inPlaySince + e.seconds;
      if (!about(e, b) || !passed(deadline)) continue;
      const auto it = b.capturedBy.find(gizmos_[i]);
      if (it != b.capturedBy.end() && it->second <= deadline) continue;
      // Each moment decides the deadlines since the last one, before the paths move on: the
      // path of the last moment holds the ball's place at the deadline.
      const Vec2<double> where = b.path.positionAt(deadline - last_);
      fail(i, deadline,
           "ball " + b.name + " did not reach " + e.gizmo + " within " + seconds(e.seconds) +
               ": at t = " + seconds(deadline) + " it was at " + at(where));
      return;
    }
  }

  const GameBoard<double>& board_;
  const std::vector<Expectation>& expectations_;
  double end_;
  double last_ = 0;
  std::vector<bool> decided_;
  std::vector<long> hits_;
  std::vector<GizmoId> gizmos_;  // resolve()'s answer for each expectation
  std::map<GizmoId, BallWatch> balls_;
};

}  // namespace

std::vector<ExpectationFailure> checkExpectations(RunRequest request, const std::vector<Expectation>& expectations) {
  request.duration = std::max(request.duration, expectationHorizon(expectations));
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(request);
  ExpectationChecker checker(*board, expectations, request.duration);
  board->setObserver(&checker);
  continueRun(*board, request, 0);
  board->setObserver(nullptr);
  checker.finish();
  std::sort(checker.failures.begin(), checker.failures.end(),
            [](const ExpectationFailure& a, const ExpectationFailure& b) { return a.expectation < b.expectation; });
  return checker.failures;
}

void checkExpectationNames(const RunRequest& request, const std::vector<Expectation>& expectations) {
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(request);
  ExpectationChecker checker(*board, expectations, request.duration);  // resolves every name, or throws
}

Property expectationsProperty(std::vector<Expectation> expectations) {
  Property p;
  p.name = kExpectationsPropertyName;
  p.summary = "the expectations of the --expect file hold";
  p.check = [expectations = std::move(expectations)](const RunRequest& run, Precision) {
    std::vector<ExpectationFailure> broken;
    try {
      broken = checkExpectations(run, expectations);
    } catch (const ExpectationError& e) {
      return PropertyResult{false, e.what(), 0};
    }
    if (broken.empty()) return PropertyResult{true, "", 0};
    const auto first = std::min_element(broken.begin(), broken.end(), [](const auto& a, const auto& b) {
      return a.time < b.time || (a.time == b.time && a.expectation < b.expectation);
    });
    std::uint64_t fingerprint = 0xcbf29ce484222325ULL;
    for (const ExpectationFailure& f : broken) fingerprint = (fingerprint ^ f.expectation) * 0x100000001b3ULL;
    std::string message = first->message;
    if (broken.size() > 1) message += " (and " + std::to_string(broken.size() - 1) + " other expectations broken)";
    return PropertyResult{false, message, fingerprint, first->time};
  };
  return p;
}

}  // namespace gizmo::verify::fuzz
