#include "gizmo/verify/fuzz/invariants.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/verify/fuzz/checker_geometry.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"
#include "kinds/verify_registry.hpp"

namespace gizmo::verify::fuzz {

std::string_view invariantName(Invariant i) {
  switch (i) {
    case Invariant::NoTunnelling: return "no-tunnelling";
    case Invariant::Energy: return "energy";
    case Invariant::EventQueue: return "event-queue";
  }
  return "?";
}

namespace {

// What each rule code does to energy: nothing for the board's own rules (the invariants treat
// the minimum bounce themselves), and for a kind's rule what its verify file says.
constexpr std::array<RuleEnergy, kModelRuleCodeCount> ruleEnergies() {
  std::array<RuleEnergy, kModelRuleCodeCount> energies{};
  forEachKind([&]<GizmoType T>(KindTag<T>) {
    for (const KindRule& k : KindCore<T>::rules) energies[static_cast<int>(k.rule)] = KindVerify<T>::ruleEnergy(k.rule);
  });
  return energies;
}
constexpr std::array<RuleEnergy, kModelRuleCodeCount> kRuleEnergies = ruleEnergies();

// Instants looked at between two events, evenly spaced inside the interval.
constexpr int kSamplesBetweenEvents = 3;
// The fastest a flipper's surface can move: 6π rad/s at 1.75 L from the pivot (the tip's far
// side), rounded up; a spinner's: 3.14 rad/s at 0.75 L from its centre, rounded up.
constexpr double kFlipperSurfaceSpeed = 33.0;
constexpr double kSpinnerSurfaceSpeed = 2.5;

template <class Real>
std::string text(const Real& x) {
  return exact(toDouble(x));
}

}  // namespace

// The fixed gizmos as the checker sees them, binned by the 1 L cells that a ball touching them
// can have its centre in.
template <class Real>
struct InvariantChecker<Real>::Geometry {
  struct Piece {
    GizmoId id = kNoGizmo;
    GizmoType type = GizmoType::Square;
    std::vector<Vec2<Real>> polygon;  // squares, triangles, absorbers
    Vec2<Real> centre;                // circles
  };
  std::vector<Piece> pieces;
  std::vector<std::size_t> cells[kBoardSize][kBoardSize];
};

template <class Real>
struct InvariantChecker<Real>::Snapshot {
  Real time{0};
  struct BallPath {
    GizmoId id = kNoGizmo;
    Trajectory<Real> path;  // from `time`
  };
  std::vector<BallPath> balls;  // the free balls
  // The flippers' and spinners' capsules at `time`, and whether they turn.
  struct Turning {
    std::vector<SwingingAxis<Real>> arms;
    bool moving = false;
    double surfaceSpeed = 0;  // the fastest the surface moves while it turns
  };
  std::map<GizmoId, Turning> turning;
};

template <class Real>
InvariantChecker<Real>::InvariantChecker(const GameBoard<Real>& board, std::vector<Invariant> checked)
    : board_(board), checked_(std::move(checked)), lastTime_(board.now()), geometry_(std::make_unique<Geometry>()) {
  for (const Event<Real>& e : board.pendingEvents()) {
    pending_.emplace(e.sequence, e);
    ordered_.insert(e);
  }
  for (std::size_t i = 0; i < board.gizmoCount(); ++i) {
    const AbstractGizmo<Real>& g = board.gizmo(GizmoId(i));
    if (g.asBall() || GizmoId(i) == board.outerWallsId()) continue;
    const GizmoSpec spec = g.spec();
    const Shape<Real> shape = restShape<Real>(spec);
    if (shape.segments.empty() && shape.circles.empty()) continue;  // nothing meets it (a spawner)
    typename Geometry::Piece piece;
    piece.id = GizmoId(i);
    piece.type = spec.type;
    if (isDiscGizmo(spec.type)) piece.centre = shape.circles.front().centre;
    else if (gizmoKind(spec.type).motion == KindMotion::Still)
      for (const CircleFeature<Real>& c : shape.circles) piece.polygon.push_back(c.centre);
    geometry_->pieces.push_back(piece);
    // A ball can touch the gizmo only with its centre within a radius of its box.
    const int x0 = std::max(0, spec.x - 1), y0 = std::max(0, spec.y - 1);
    const int x1 = std::min(kBoardSize - 1, spec.x + spec.width), y1 = std::min(kBoardSize - 1, spec.y + spec.height);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) geometry_->cells[y][x].push_back(geometry_->pieces.size() - 1);
  }
  energyBefore_ = board.energy();
  takeSnapshot();
}

template <class Real>
InvariantChecker<Real>::~InvariantChecker() = default;

template <class Real>
bool InvariantChecker<Real>::checks(Invariant i) const {
  return std::find(checked_.begin(), checked_.end(), i) != checked_.end();
}

template <class Real>
void InvariantChecker<Real>::fail(Invariant i, const std::string& message) {
  for (const Violation& v : violations_)
    if (v.invariant == i) return;  // the first one says it; the rest follow from it
  violations_.push_back(Violation{i, message, toDouble(board_.now())});
}

template <class Real>
void InvariantChecker<Real>::runFailed(const std::string& what) {
  for (Invariant i : checked_) fail(i, "the run stopped at t = " + text(board_.now()) + ": " + what);
}

template <class Real>
void InvariantChecker<Real>::timePasses(const Real& time, const char* what) {
  if (!checks(Invariant::EventQueue)) return;
  if (time < lastTime_)
    fail(Invariant::EventQueue,
         std::string("time went backwards: ") + what + " at t = " + text(time) + " after t = " + text(lastTime_));
  lastTime_ = time;
}

template <class Real>
void InvariantChecker<Real>::takeSnapshot() {
  auto s = std::make_unique<Snapshot>();
  s->time = board_.now();
  for (GizmoId id : board_.ballIds()) {
    const Ball<Real>& b = *board_.gizmo(id).asBall();
    if (!b.captured()) s->balls.push_back({id, b.trajectoryAt(s->time)});
  }
  for (const typename Geometry::Piece& p : geometry_->pieces) {
    if (gizmoKind(p.type).motion == KindMotion::Still) continue;
    typename Snapshot::Turning& t = s->turning[p.id];
    if (const auto* f = dynamic_cast<const Flipper<Real>*>(&board_.gizmo(p.id))) {
      t = {{f->axisAt(s->time)}, f->swinging(), kFlipperSurfaceSpeed};
    } else if (const auto* spinner = dynamic_cast<const Spinner<Real>*>(&board_.gizmo(p.id))) {
      t = {{}, spinner->turning(), kSpinnerSurfaceSpeed};
      for (int k = 0; k < 4; ++k) t.arms.push_back(spinner->armAt(k, s->time));
    }
  }
  snapshot_ = std::move(s);
}

// Every free ball of the snapshot at `time` (inside the interval the snapshot holds for) against
// the walls and every gizmo near it.
template <class Real>
void InvariantChecker<Real>::checkOverlaps(const Real& time, const Snapshot& s, const char* when) {
  const Real r = fromDouble<Real>(kBallRadius), bound = Bounds<Real>::overlap, size(kBoardSize);
  const Real tau = time - s.time;
  for (const typename Snapshot::BallPath& b : s.balls) {
    const Vec2<Real> p = b.path.positionAt(tau);
    auto report = [&](const std::string& what, const Real& depth) {
      std::ostringstream m;
      m << "ball " << board_.gizmo(b.id).name() << " is " << text(depth) << " L " << what << " " << when
        << " t = " << text(time) << ", centre (" << text(p.x) << ", " << text(p.y) << "), bound " << text(bound);
      fail(Invariant::NoTunnelling, m.str());
    };
    const Real wallDepth = r - std::min({p.x, Real(size - p.x), p.y, Real(size - p.y)});
    if (!(wallDepth <= bound)) report("beyond a wall", wallDepth);
    const int cx = int(std::clamp(toDouble(p.x), 0.0, kBoardSize - 1.0)),
              cy = int(std::clamp(toDouble(p.y), 0.0, kBoardSize - 1.0));
    for (std::size_t k : geometry_->cells[cy][cx]) {
      const typename Geometry::Piece& g = geometry_->pieces[k];
      // A gizmo that fired a ball (a rule of effect Fired: an absorber's shot) ignores it until it is out.
      if (fired_.count({g.id, b.id})) continue;
      Real distance;
      if (isDiscGizmo(g.type)) {
        distance = length(Vec2<Real>(p - g.centre)) - fromDouble<Real>(0.5);
      } else if (!g.polygon.empty()) {
        distance = signedDistanceToPolygon(p, g.polygon);
      } else {
        const typename Snapshot::Turning& turning = s.turning.at(g.id);
        const Real along = turning.moving ? tau : Real(0);
        distance = Real(kBoardSize);
        for (const SwingingAxis<Real>& axis : turning.arms) {
          const Vec2<Real> tip = axis.pivot + axis.length * axis.direction(along);
          distance = std::min(distance, Real(distanceToSegment(p, axis.pivot, tip) - axis.radius));
        }
      }
      const Real depth = r - distance;
      if (!(depth <= bound)) report("inside " + board_.gizmo(g.id).name(), depth);
    }
  }
}

template <class Real>
void InvariantChecker<Real>::eventScheduled(const Event<Real>& e) {
  if (!checks(Invariant::EventQueue)) return;
  timePasses(board_.now(), "a scheduling");
  if (e.time < board_.now())
    fail(Invariant::EventQueue, "event " + describeEvent(e) + " scheduled in the past, at t = " + text(board_.now()));
  if (!pending_.emplace(e.sequence, e).second)
    fail(Invariant::EventQueue, "event sequence number " + std::to_string(e.sequence) + " scheduled twice");
  ordered_.insert(e);
}

template <class Real>
void InvariantChecker<Real>::eventRemoved(const Event<Real>& e) {
  if (!checks(Invariant::EventQueue)) return;
  timePasses(board_.now(), "a removal");
  const auto it = pending_.find(e.sequence);
  if (it == pending_.end() || !(it->second.time == e.time) || it->second.kind != e.kind || it->second.a != e.a ||
      it->second.b != e.b || it->second.feature != e.feature) {
    fail(Invariant::EventQueue, "removed event " + describeEvent(e) + " was not pending");
    return;
  }
  ordered_.erase(it->second);
  pending_.erase(it);
}

template <class Real>
void InvariantChecker<Real>::eventExecuted(const Event<Real>& e, const EventOutcome<Real>& outcome) {
  ++executed_;
  const Real& now = board_.now();
  if (checks(Invariant::EventQueue)) {
    timePasses(e.time, "an executed event");
    if (!(e.time == now)) fail(Invariant::EventQueue, "event " + describeEvent(e) + " executed at t = " + text(now));
    const auto it = pending_.find(e.sequence);
    if (it == pending_.end()) {
      fail(Invariant::EventQueue, "executed event " + describeEvent(e) + " was not pending");
    } else {
      if (ordered_.begin()->sequence != e.sequence)
        fail(Invariant::EventQueue,
             "executed event " + describeEvent(e) + " while " + describeEvent(*ordered_.begin()) + " was due first");
      ordered_.erase(it->second);
      pending_.erase(it);
    }
  }
  if (checks(Invariant::NoTunnelling)) {
    // Between the last event and this one everything moved as the snapshot says.
    if (snapshot_->time < now)
      for (int k = 1; k <= kSamplesBetweenEvents; ++k)
        checkOverlaps(Real(snapshot_->time + (now - snapshot_->time) * Real(k) / Real(kSamplesBetweenEvents + 1)),
                      *snapshot_, "between events, at");
  }
  if (e.kind == EventKind::Leave) fired_.erase({e.a, e.b});
  if (checks(Invariant::Energy)) checkEnergy(e, outcome);
  allowance_ = Real(0);
  released_.clear();
  teleported_.clear();
  takeSnapshot();
  if (checks(Invariant::NoTunnelling))
    checkOverlaps(now, *snapshot_, std::string("after " + describeEvent(e) + " at").c_str());
}

template <class Real>
void InvariantChecker<Real>::modelRuleApplied(const Real& time, ModelRule rule, GizmoId gizmo, GizmoId other) {
  timePasses(time, "a model rule");
  const PhysicsParams<Real>& params = board_.params();
  // The documented minimum bounce: at most ½·restSpeed² per slow hit on something round.
  if (rule == ModelRule::MinimumBounce) allowance_ += params.restSpeed * params.restSpeed / Real(2);
  // A kind's rule: what its verify file says the rule does to the ball it names.
  const RuleEnergy energy = kRuleEnergies[static_cast<int>(rule)];
  switch (energy.effect) {
    case RuleEffect::Kept: break;
    case RuleEffect::Fired: fired_.insert({gizmo, other}); [[fallthrough]];
    case RuleEffect::Brought: released_.push_back(other); break;
    // Settled after the event (checkEnergy), from the height before.
    case RuleEffect::Lifted: teleported_.emplace_back(other, board_.gizmo(other).asBall()->positionAt(time).y); break;
    case RuleEffect::SpeedScaled: {
      const Vec2<Real> v = board_.gizmo(other).asBall()->velocityAt(time);
      const int k = energy.speedFactor;
      allowance_ += Real(k * k - 1) * lengthSquared(v) / Real(2);
      break;
    }
  }
}

template <class Real>
void InvariantChecker<Real>::checkEnergy(const Event<Real>& e, const EventOutcome<Real>& outcome) {
  const PhysicsParams<Real>& params = board_.params();
  const Real half = Real(1) / Real(2), g = params.gravity < Real(0) ? Real(-params.gravity) : params.gravity;
  const Real after = board_.energy();
  Real allowance = allowance_, scale = Real(1);
  // An absorber shot or a spawn supplies the released ball's whole energy (a captured ball has none).
  for (GizmoId id : released_) {
    const Ball<Real>& b = *board_.gizmo(id).asBall();
    const Vec2<Real> v = b.velocityAt(board_.now()), p = b.positionAt(board_.now());
    allowance += half * lengthSquared(v) + params.gravity * (Real(kBoardSize) - p.y);
  }
  // A teleport lifts a ball from height 20 − y to 20 − y′: g·(y − y′) of potential energy.
  for (const auto& [id, y] : teleported_) {
    const Real lift = params.gravity * Real(y - board_.gizmo(id).asBall()->positionAt(board_.now()).y);
    if (Real(0) < lift) allowance += lift;
  }
  // A turning flipper's or spinner's surface moves at up to its surfaceSpeed u: a ball leaves it
  // at most that much faster than it came relative to it, so |v'| ≤ |v| + 2u.
  const auto turning = snapshot_->turning.find(e.a);
  if (e.kind == EventKind::Collision && turning != snapshot_->turning.end() && turning->second.moving) {
    const Real u(turning->second.surfaceSpeed);
    for (const BallChange<Real>& c : outcome.balls()) {
      const Real speed = length(c.velocityBefore);
      allowance += Real(2) * u * speed + Real(2) * u * u;
    }
  }
  // The classic model's explicit step, p += v·dt then v += g·dt (friction first), gains up to
  // ½g²dt² per ball, and friction taken off an upward velocity can add g·dt·(friction's share).
  if (params.model == MotionModel::Classic) {
    const Real dt = board_.now() - snapshot_->time;
    for (const typename Snapshot::BallPath& b : snapshot_->balls) {
      const Real speed = length(b.path.v);
      const Real share = std::min(Real(1), Real((params.mu + params.mu2 * speed) * dt));
      allowance += half * g * g * dt * dt + g * dt * speed * share;
    }
  }
  for (const typename Snapshot::BallPath& b : snapshot_->balls)
    scale += half * lengthSquared(b.path.v) + g * Real(kBoardSize);
  scale += after < Real(0) ? Real(-after) : after;
  const Real rise = after - energyBefore_;
  if (!(rise <= allowance + Bounds<Real>::energy * scale)) {
    std::ostringstream m;
    m << "energy rose by " << text(rise) << " from " << text(energyBefore_) << " to " << text(after) << " at "
      << describeEvent(e) << "; what it could supply: " << text(allowance) << ", rounding allowance "
      << text(Real(Bounds<Real>::energy * scale));
    fail(Invariant::Energy, m.str());
  }
  // Friction: a friction tick never speeds a ball up, and slows a moving one.
  if (e.kind == EventKind::FrictionTick) {
    for (const BallChange<Real>& c : outcome.balls()) {
      const Real before = lengthSquared(c.velocityBefore), now = lengthSquared(c.velocityAfter);
      const bool mustFall = before > Real(0) && params.mu * params.frictionStep >= fromDouble<Real>(1e-9);
      if (now > before || (mustFall && !(now < before)))
        fail(Invariant::Energy, "friction tick at t = " + text(e.time) + " took ball " + board_.gizmo(c.ball).name() +
                                    "'s speed² from " + text(before) + " to " + text(now));
    }
  }
  energyBefore_ = after;
}

template <class Real>
void InvariantChecker<Real>::checkCoverage() {
  const Real& now = board_.now();
  if (!ordered_.empty() && ordered_.begin()->time < now)
    fail(Invariant::EventQueue,
         "pending event " + describeEvent(*ordered_.begin()) + " is earlier than t = " + text(now));
  const std::vector<Event<Real>> queue = board_.pendingEvents();
  bool same = queue.size() == pending_.size();
  for (std::size_t i = 0; same && i < queue.size(); ++i) same = pending_.count(queue[i].sequence) == 1;
  if (!same)
    fail(Invariant::EventQueue, "at t = " + text(now) + " the board's queue holds " + std::to_string(queue.size()) +
                                    " events, but " + std::to_string(pending_.size()) +
                                    " were scheduled and not yet run or removed");
  // Who is looked after: a ball by any pending event that names it, in time.
  const Real horizon = now + board_.params().maxTick;
  std::map<GizmoId, Real> firstEvent;
  for (const Event<Real>& e : queue)
    for (GizmoId id : {e.a, e.b})
      if (id >= 0 && e.kind != EventKind::Input && !firstEvent.count(id)) firstEvent.emplace(id, e.time);
  for (GizmoId id : board_.ballIds()) {
    const Ball<Real>& b = *board_.gizmo(id).asBall();
    if (b.resting()) continue;  // at rest for good until something hits it: the reason for no event
    const auto it = firstEvent.find(id);
    if (it == firstEvent.end() || horizon < it->second)
      fail(Invariant::EventQueue, "moving ball " + b.name() +
                                      " has no pending event within one maximum tick of t = " + text(now) +
                                      (it == firstEvent.end() ? std::string(" (none at all)")
                                                              : " (its first at t = " + text(it->second) + ")"));
  }
  // A swinging flipper must have its stop pending (a spinner turns on without one).
  for (const auto& [id, turning] : snapshot_->turning) {
    if (!turning.moving || motionOf(board_.gizmo(id).kind()) != KindMotion::Swings) continue;
    bool stop = false;
    for (const Event<Real>& e : queue) stop = stop || (e.kind == EventKind::FlipperStop && e.a == id);
    if (!stop)
      fail(Invariant::EventQueue,
           "swinging flipper " + board_.gizmo(id).name() + " has no pending stop at t = " + text(now));
  }
}

template <class Real>
void InvariantChecker<Real>::tickBoundary(const Real& time) {
  timePasses(time, "a tick boundary");
  if (checks(Invariant::EventQueue)) checkCoverage();
}

template <class Real>
void InvariantChecker<Real>::finish() {
  if (checks(Invariant::EventQueue)) checkCoverage();
}

template <class Real>
InvariantRun checkInvariants(const RunRequest& request, const std::vector<Invariant>& checked) {
  std::unique_ptr<GameBoard<Real>> board = prepareRun<Real>(request);
  InvariantChecker<Real> checker(*board, checked);
  board->setObserver(&checker);
  try {
    continueRun(*board, request, 0);
    checker.finish();
  } catch (const std::exception& e) {
    checker.runFailed(e.what());
  }
  board->setObserver(nullptr);
  return InvariantRun{checker.violations(), checker.eventsChecked(), toDouble(board->energy())};
}

template class InvariantChecker<double>;
template InvariantRun checkInvariants<double>(const RunRequest&, const std::vector<Invariant>&);
// A campaign may vary the scalar (docs/fuzzing.md, "Fuzzing your own board").
template class InvariantChecker<long double>;
template InvariantRun checkInvariants<long double>(const RunRequest&, const std::vector<Invariant>&);

}  // namespace gizmo::verify::fuzz
