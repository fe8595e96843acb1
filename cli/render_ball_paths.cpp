// Rebuilding a ball's motion from its recorded states (see render_ball_paths.hpp).
#include "render_ball_paths.hpp"

#include <algorithm>
#include <cmath>

#include "gizmo/core/gizmos/ball.hpp"

namespace gizmo::cli {
namespace {

double norm(const Vec2<double>& v) { return std::hypot(v.x, v.y); }

// Two accelerations are taken as the same when they agree to this relative error: an inferred
// one carries the rounding of a velocity difference divided by a short time.
bool nearlyEqual(const Vec2<double>& a, const Vec2<double>& b) { return norm(a - b) <= 1e-7 * (1 + norm(b)); }

// The largest |c0 + c1 s + c2 s²| over s in [0, length].
double largestOnSpan(double c0, double c1, double c2, double length) {
  double m = std::max(std::abs(c0), std::abs(c0 + c1 * length + c2 * length * length));
  if (c2 != 0) {
    const double s = -c1 / (2 * c2);
    if (s > 0 && s < length) m = std::max(m, std::abs(c0 + c1 * s + c2 * s * s));
  }
  return m;
}

}  // namespace

Vec2<double> positionAt(const PathPiece& piece, double t) {
  // The simulator's Trajectory::positionAt, operation for operation, so that a double run's
  // positions come out bit for bit.
  const double tau = t - piece.t0;
  const double half = 0.5;
  return piece.p + tau * piece.v + (half * tau * tau) * piece.a;
}

double pieceDeviation(const PathPiece& a, const PathPiece& b, double from, double to) {
  const Vec2<double> c0 = positionAt(a, from) - positionAt(b, from);
  const Vec2<double> c1 = (a.v + (from - a.t0) * a.a) - (b.v + (from - b.t0) * b.a);
  const Vec2<double> c2 = 0.5 * (a.a - b.a);
  const double length = std::max(0.0, to - from);
  return std::hypot(largestOnSpan(c0.x, c1.x, c2.x, length), largestOnSpan(c0.y, c1.y, c2.y, length));
}

BallPathBuilder::BallPathBuilder(MotionModel model, const PhysicsParams<double>& params, double tolerance,
                                 const PathPiece& start, bool captured)
    : model_(model), params_(params), tolerance_(tolerance), captured_(captured), lastAcceleration_(start.a) {
  pending_.push_back(Pending{start, std::nullopt, captured});
}

void BallPathBuilder::step(std::int64_t event, double t) {
  if (captured_ || model_ != MotionModel::Classic) return;
  const PathPiece& last = pending_.back().piece;
  const double dt = t - last.t0;
  if (!(dt > 0)) return;
  // Ball::tick for a free ball: the position moves on the old velocity, then friction, then gravity.
  PathPiece next;
  next.event = event;
  next.t0 = t;
  next.p = last.p + dt * last.v;
  next.v = Ball<double>::frictionApplied(last.v, dt, params_) + dt * Vec2<double>(0, params_.gravity);
  pending_.push_back(Pending{next, std::nullopt, false});
}

void BallPathBuilder::logged(std::int64_t event, double t, const Vec2<double>& p, const Vec2<double>& vBefore,
                             const Vec2<double>& vAfter) {
  if (model_ == MotionModel::Classic && pending_.size() > 1) {
    // Steps that do not arrive where the log says the ball is met something the decisions do not
    // describe (a sliding contact's reduced gravity, a wedge): the ball went in a straight line
    // along the surface, so spread the recorded displacement evenly over the steps instead.
    const Vec2<double> predicted = positionAt(pending_.back().piece, t);
    if (norm(predicted - p) > 1e-9 * (1 + norm(p))) {
      const PathPiece& from = pending_.front().piece;
      const double span = t - from.t0;
      const Vec2<double> velocity = span > 0 ? (1 / span) * (p - from.p) : Vec2<double>();
      for (std::size_t i = 1; i < pending_.size(); ++i) {
        PathPiece& s = pending_[i].piece;
        s.p = from.p + (s.t0 - from.t0) * velocity;
        s.v = velocity;
      }
      pending_.front().piece.v = velocity;
    }
  }
  anchor(event, t, p, vAfter, vBefore, false);
}

void BallPathBuilder::captured(std::int64_t event, double t, const Vec2<double>& p) {
  captured_ = true;
  anchor(event, t, p, Vec2<double>(), std::nullopt, true);
}

void BallPathBuilder::released(std::int64_t event, double t, const Vec2<double>& p, const Vec2<double>& v) {
  captured_ = false;
  anchor(event, t, p, v, std::nullopt, false);
}

void BallPathBuilder::anchor(std::int64_t event, double t, const Vec2<double>& p, const Vec2<double>& v,
                             const std::optional<Vec2<double>>& vBefore, bool held) {
  push(Pending{PathPiece{.event = event, .t0 = t, .p = p, .v = v, .a = {}, .logged = true}, vBefore, held});
}

void BallPathBuilder::push(const Pending& next) {
  // Several states at one event (a capture right after the hit that caused it): the last holds.
  if (pending_.back().piece.event == next.piece.event) pending_.pop_back();
  pending_.push_back(next);
  flush(pending_.size() - 1, next.piece.t0, std::nullopt);
}

Vec2<double> BallPathBuilder::defaultAcceleration(const Pending& p) const {
  if (p.captured || model_ == MotionModel::Classic) return Vec2<double>();
  return Vec2<double>(0, params_.gravity);
}

void BallPathBuilder::flush(std::size_t count, double endOfLast, const std::optional<Vec2<double>>& finalVBefore) {
  for (std::size_t i = 0; i < count; ++i) {
    PathPiece piece = pending_[i].piece;
    const bool hasNext = i + 1 < pending_.size();
    const double end = hasNext ? pending_[i + 1].piece.t0 : endOfLast;
    const std::optional<Vec2<double>> arrival = hasNext ? pending_[i + 1].vBefore : finalVBefore;
    piece.a = defaultAcceleration(pending_[i]);
    if (model_ == MotionModel::Ballistic && !pending_[i].captured && arrival && end - piece.t0 > 1e-9) {
      const Vec2<double> inferred = (1 / (end - piece.t0)) * (*arrival - piece.v);
      const Vec2<double> gravity(0, params_.gravity);
      if (nearlyEqual(inferred, gravity)) piece.a = gravity;
      else if (norm(inferred) <= 1e-7) piece.a = Vec2<double>();
      else if (nearlyEqual(inferred, lastAcceleration_)) piece.a = lastAcceleration_;
      else piece.a = inferred;
    }
    lastAcceleration_ = piece.a;
    keep(piece, end);
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(count));
}

void BallPathBuilder::Extent::add(const PathPiece& piece, double from, double to) {
  // Each axis of a piece is a quadratic in t: its extremes are at the ends or where v + a τ = 0.
  auto include = [&](double t) {
    const Vec2<double> p = positionAt(piece, t);
    lo = Vec2<double>(std::min(lo.x, p.x), std::min(lo.y, p.y));
    hi = Vec2<double>(std::max(hi.x, p.x), std::max(hi.y, p.y));
  };
  include(from);
  include(to);
  for (const auto& [v, a] : {std::pair(piece.v.x, piece.a.x), std::pair(piece.v.y, piece.a.y)}) {
    if (a == 0) continue;
    const double t = piece.t0 - v / a;
    if (t > from && t < to) include(t);
  }
}

void BallPathBuilder::keep(const PathPiece& piece, double end) {
  if (tolerance_ > 0 && !kept_.empty()) {
    PathPiece& kept = kept_.back();
    Extent grown = keptExtent_;
    grown.add(piece, piece.t0, end);
    if (!keptStill_ && pieceDeviation(kept, piece, piece.t0, end) <= tolerance_) {
      keptExtent_ = grown;
      return;
    }
    const Vec2<double> size = grown.hi - grown.lo;
    if (0.5 * norm(size) <= tolerance_) {
      // Every point since the kept piece began is within the tolerance of the spot's centre.
      kept.p = 0.5 * (grown.lo + grown.hi);
      kept.v = kept.a = Vec2<double>();
      kept.logged = false;
      keptStill_ = true;
      keptExtent_ = grown;
      return;
    }
  }
  kept_.push_back(piece);
  keptStill_ = false;
  keptExtent_ = Extent{piece.p, piece.p};
  keptExtent_.add(piece, piece.t0, end);
}

std::vector<PathPiece> BallPathBuilder::finish(double endTime, const std::optional<Vec2<double>>& endVelocity) {
  flush(pending_.size(), std::max(endTime, pending_.back().piece.t0), endVelocity);
  return std::move(kept_);
}

}  // namespace gizmo::cli
