#pragma once
// A ball's motion over a whole run, rebuilt from a log's decisions for drawing: a list of
// pieces p(t) = p + v τ + ½ a τ², τ = t − t0, each valid after a given event. The log records
// the ball's exact state only where an event changed it, so the pieces are anchored there; the
// acceleration in between is what carries the recorded velocity to the next recorded one
// (gravity in free flight, less in a sliding contact, none when held). The classic model moves
// balls in straight lines that bend at every event, which the log does not record, so the
// builder steps them as the board does (p += v dt, then friction, then gravity).
//
// Pieces a viewer could not tell apart are dropped: a piece whose motion stays within
// `tolerance` of the piece kept before it (extended over the new piece's span) is left out, and
// a ball that stays inside a spot smaller than the tolerance (jittering between two bumpers) is
// held still at the spot's centre. So the drawn position is never more than `tolerance` from the
// rebuilt one; a tolerance of 0 keeps every piece. The events themselves are never dropped.
#include <cstdint>
#include <optional>
#include <vector>

#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo::cli {

struct PathPiece {
  std::int64_t event = -1;  // valid once this many events + 1 have run; −1: from the start
  double t0 = 0;
  Vec2<double> p, v, a;
  bool logged = false;  // p and v are the log's own values (not stepped, interpolated or held still)
};

class BallPathBuilder {
 public:
  BallPathBuilder(MotionModel model, const PhysicsParams<double>& params, double tolerance, const PathPiece& start,
                  bool captured);

  // Classic model: every ball is stepped up to each executed event before the event runs.
  void step(std::int64_t event, double t);
  // The log's ball change at an executed event.
  void logged(std::int64_t event, double t, const Vec2<double>& p, const Vec2<double>& vBefore,
              const Vec2<double>& vAfter);
  // An absorber took the ball (held at p) or fired it (from p with velocity v).
  void captured(std::int64_t event, double t, const Vec2<double>& p);
  void released(std::int64_t event, double t, const Vec2<double>& p, const Vec2<double>& v);
  // The run ends at `endTime`; `endVelocity` (when known) settles the last piece's acceleration.
  std::vector<PathPiece> finish(double endTime, const std::optional<Vec2<double>>& endVelocity);

 private:
  struct Pending {
    PathPiece piece;
    std::optional<Vec2<double>> vBefore;  // the recorded velocity on arrival, when known
    bool captured = false;
  };
  // A state the log gives (or an absorber sets: `held` when it takes the ball) starts a piece.
  void anchor(std::int64_t event, double t, const Vec2<double>& p, const Vec2<double>& v,
              const std::optional<Vec2<double>>& vBefore, bool held);
  void push(const Pending& next);
  // Settles the first `count` pending pieces (each one's acceleration from the next one's arrival).
  void flush(std::size_t count, double endOfLast, const std::optional<Vec2<double>>& finalVBefore);
  Vec2<double> defaultAcceleration(const Pending& p) const;
  void keep(const PathPiece& piece, double end);

  MotionModel model_;
  PhysicsParams<double> params_;
  double tolerance_;
  bool captured_;
  // Pieces since the last recorded state (classic: the steps between two records).
  std::vector<Pending> pending_;
  std::vector<PathPiece> kept_;
  // Where the ball went since the last kept piece began, and whether that piece now holds it still.
  struct Extent {
    Vec2<double> lo, hi;
    void add(const PathPiece& piece, double from, double to);
  } keptExtent_{};
  bool keptStill_ = false;
  Vec2<double> lastAcceleration_;  // inferred values that agree with it are taken as equal
};

// The largest distance between two pieces' positions over [from, to] (bounded per axis, exact
// for each axis since both are quadratics in t).
double pieceDeviation(const PathPiece& a, const PathPiece& b, double from, double to);

// The position of a piece at time t, in the same operations as the simulator's trajectory.
Vec2<double> positionAt(const PathPiece& piece, double t);

}  // namespace gizmo::cli
