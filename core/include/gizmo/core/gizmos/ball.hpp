#pragma once
// The ball: the one gizmo that moves. Its path between events is anchored at the time its
// velocity last changed: p(t) = p₀ + v₀ τ + ½ a τ², τ = t − t₀ (a = 0 in the classic model,
// which moves balls in straight lines and applies gravity in tick()).
#include <limits>
#include <optional>
#include <vector>

#include "gizmo/core/geometry/features.hpp"
#include "gizmo/core/geometry/time_of_impact.hpp"
#include "gizmo/core/gizmos/abstract_gizmo.hpp"

namespace gizmo {

// A straight surface the ball slides along (the resting-contact rule, docs/physics.md).
template <class Real>
struct SurfaceContact {
  GizmoId gizmo = kNoGizmo;
  std::int32_t feature = -1;
  SegmentFeature<Real> segment;
  Real coefficient{1};
};

// How a surface responds to a slow hit: a static segment can carry a sliding ball, anything
// round or moving gets the minimum bounce instead.
enum class SurfaceType { StaticSegment, Round };

template <class Real>
class Ball final : public AbstractGizmo<Real> {
 public:
  Ball(std::string name, const Vec2<Real>& position, const Vec2<Real>& velocity)
      : AbstractGizmo<Real>(std::move(name)), p0_(position), v0_(velocity) {}

  static Real radius() { return fromDouble<Real>(kBallRadius); }

  GizmoKind kind() const override { return GizmoKind::Ball; }
  Ball* asBall() override { return this; }
  const Ball* asBall() const override { return this; }
  bool hasTrigger() const override { return false; }

  CollisionAnswer canCollideWith(const AbstractGizmo<Real>& other) const override {
    if (other.asBall()) return CollisionAnswer::CanCollide;
    return CollisionAnswer::Defer;  // every other gizmo knows how to meet a ball
  }

  // --- state --------------------------------------------------------------------------------
  Vec2<Real> positionAt(const Real& t) const {
    if (captured_) return p0_;
    return trajectoryAt(t).p;
  }
  Vec2<Real> velocityAt(const Real& t) const {
    if (captured_) return Vec2<Real>();
    return v0_ + (t - t0_) * a_;
  }
  Trajectory<Real> trajectoryAt(const Real& t) const {
    const Trajectory<Real> anchored{p0_, v0_, a_};
    const Real tau = t - t0_;
    return Trajectory<Real>{anchored.positionAt(tau), anchored.velocityAt(tau), a_};
  }
  const Vec2<Real>& acceleration() const { return a_; }
  const Real& anchorTime() const { return t0_; }

  // Re-anchors the path at time t; the acceleration follows the model and the contact.
  void setState(const Real& t, const Vec2<Real>& p, const Vec2<Real>& v, const PhysicsParams<Real>& params) {
    const bool wasResting = resting();
    t0_ = t;
    p0_ = p;
    v0_ = v;
    a_ = params.model == MotionModel::Ballistic ? effectiveGravity(params) : Vec2<Real>();
    if (wedged_) a_ = Vec2<Real>();
    if (wasResting && !resting()) startedMoving_ = true;
  }

  // Whether the ball left rest since the last call (what rests on it may have to wake: GameBoard's
  // noteBallsThatLeftRest). Only within one event: not part of the state.
  bool takeStartedMoving() {
    const bool started = startedMoving_;
    startedMoving_ = false;
    return started;
  }

  // Gravity less the part a supporting surface takes (none when free or wedged).
  Vec2<Real> effectiveGravity(const PhysicsParams<Real>& params) const {
    if (wedged_) return Vec2<Real>();
    const Vec2<Real> g(Real(0), params.gravity);
    if (!contact_) return g;
    const Vec2<Real>& n = contact_->segment.normal;
    return g - dot(g, n) * n;
  }

  bool captured() const { return captured_; }
  void capture(const Real& t, const Vec2<Real>& holdPosition) {
    captured_ = true;
    contact_.reset();
    wedged_ = false;
    t0_ = t;
    p0_ = holdPosition;
    v0_ = Vec2<Real>();
    a_ = Vec2<Real>();
  }
  void release(const Real& t, const Vec2<Real>& p, const Vec2<Real>& v, const PhysicsParams<Real>& params) {
    captured_ = false;
    setState(t, p, v, params);
    startedMoving_ = false;  // held in an absorber, it held nothing up
  }

  const std::optional<SurfaceContact<Real>>& contact() const { return contact_; }
  bool wedged() const { return wedged_; }
  // At rest for good until something hits it: no friction, no recalculation needed.
  bool resting() const { return captured_ || (v0_ == Vec2<Real>() && a_ == Vec2<Real>()); }

  // Ballistic friction ticks run on the global grid k·h; this is the next k for this ball.
  std::int64_t nextFrictionIndex = 1;

  // --- collisions ----------------------------------------------------------------------------
  std::optional<Contact<Real>> timeUntilCollision(const AbstractGizmo<Real>& other, const Real& now, const Real& limit,
                                                  const PhysicsParams<Real>&) const override {
    const Ball* b = other.asBall();
    if (!b || captured_ || b->captured()) return std::nullopt;
    const bool grazedNow = metWhileJammed(b->id(), now, JamMeeting::Graze);
    const std::optional<Real> tau =
        ballTimeOfImpact(trajectoryAt(now), b->trajectoryAt(now), radius(), limit - now, grazedNow);
    if (!tau) return std::nullopt;
    return Contact<Real>{now + *tau, 0, EventKind::Collision};
  }

  // Equal masses, elastic: the normal components are exchanged (docs/physics.md §5).
  void collide(AbstractGizmo<Real>& other, const Contact<Real>&, BoardAccess<Real>& board) override {
    Ball* b = other.asBall();
    if (!b) return;
    const Real& now = board.now();
    const PhysicsParams<Real>& params = board.params();
    const Vec2<Real> pa = positionAt(now), pb = b->positionAt(now);
    Vec2<Real> va = velocityAt(now), vb = b->velocityAt(now);
    const Vec2<Real> d = pa - pb;
    const Real dist = length(d);
    if (dist == Real(0)) return;  // coincident centres: no normal to push along
    const Vec2<Real> n(d.x / dist, d.y / dist);
    const Real closing = dot(va - vb, n);
    // Touching and barely opening (under restSpeed) while accelerating together counts as a
    // slow hit: a prediction a rounding error ahead of the present lands on it.
    if (!(closing < Real(0)) && !(closing < params.restSpeed && dot(a_ - b->acceleration(), n) < Real(0))) return;
    const bool jammed = board.jammed();
    const Vec2<Real> relativeVelocity = va - vb;
    // The gap's curvature, |Δv|² + d·Δa: a pair that curves into each other (a ball falling
    // onto one that a floor holds) only presses harder, however slowly it closes now.
    const bool curvingTogether =
        Real(lengthSquared(relativeVelocity) + dot(d, Vec2<Real>(a_ - b->acceleration()))) < Real(0);
    if (jammed && !curvingTogether && -closing <= Real(1e-3) * length(relativeVelocity)) {
      // Jammed balls grazing each other (closing at under a thousandth of their relative speed:
      // they slide past, touching): with no room around them, any push would come straight back.
      // They are let through for this instant (overlapping by a rounding error at most) and the
      // pair looks for its next contact after it, which it finds only if the gap opens first:
      // a pair curving together would sink into each other unseen (seed 2024, case 85).
      rememberJamMeeting(b->id(), now, JamMeeting::Graze);
      b->rememberJamMeeting(this->id(), now, JamMeeting::Graze);
      board.reportRule(ModelRule::Jammed, this->id(), b->id());
      return;
    }
    if (jammed) {
      // Struck again at the instant of its last jammed hit: something else pushed one of the
      // two straight back into the other, so they are wedged between other surfaces. Solved
      // pairwise, such a chain (a wall, a ball, a ball, a wall) passes a sliver of velocity
      // back and forth and converges only after ~1/θ² rounds for a line of centres tilted by θ
      // (3.8·10⁻⁵ rad, seven hundred million rounds; campaign seed 20261203, case 4731): both
      // come to rest instead, as jammed balls that gravity presses together do.
      if (metWhileJammed(b->id(), now, JamMeeting::Hit)) {
        comeToRest(board, b->id());
        b->comeToRest(board, this->id());
        return;
      }
      rememberJamMeeting(b->id(), now, JamMeeting::Hit);
      b->rememberJamMeeting(this->id(), now, JamMeeting::Hit);
    }
    if (!jammed && rowWithoutRoom(*b, pa, pb, va, vb, n, closing, board)) {
      // Neither can move along n by more than settleRise: both come to rest, as two jammed
      // balls that gravity presses together do.
      comeToRest(board, b->id());
      b->comeToRest(board, this->id());
      return;
    }
    Real exchange = -closing;  // added to a along n, taken from b
    const Real pressing = -dot(Vec2<Real>(effectiveGravity(params) - b->effectiveGravity(params)), n);
    const bool pressedTogether = Real(0) < pressing;
    if (pressedTogether && (-closing < params.restSpeed || (!jammed && settles(closing, pressing, params)))) {
      if (jammed) {
        // One rests on the other with no room to bounce: both come to rest.
        comeToRest(board, b->id());
        b->comeToRest(board, this->id());
        return;
      }
      // Either may be pressed slowly onto the other at rest (the closing speed is the same
      // seen from either side).
      if (meetsBallAtRest(*b, pa, n, va, closing, board)) return;
      if (b->meetsBallAtRest(*this, pb, -n, vb, closing, board)) return;
      exchange = (params.restSpeed - closing) / Real(2);  // the minimum bounce
      board.reportRule(ModelRule::MinimumBounce, this->id(), b->id());
    } else if (jammed) {
      // Both leave with the mean normal velocity; below restSpeed that is none at all, so a
      // jam settles in a finite number of hits whatever the precision.
      exchange = -closing / Real(2);
      const Real mean = dot(va, n) - closing / Real(2);
      if (absOf(mean) < params.restSpeed) {
        va -= mean * n;
        vb -= mean * n;
      }
      board.reportRule(ModelRule::Jammed, this->id(), b->id());
    }
    va += exchange * n;
    vb -= exchange * n;
    setVelocity(now, pa, va, board);
    b->setVelocity(now, pb, vb, board);
  }

  // Reflects off a surface of gizmo `by` with normal n (towards the ball), coefficient c and
  // surface velocity u, applying the slow-contact rules. Returns false when the ball was not
  // approaching. surfaceBend: how the surface's own motion bends the gap (a swinging flipper
  // turning into the ball presses it even without gravity); 0 for surfaces that do not move.
  bool reflect(const Vec2<Real>& n, const Real& c, const Vec2<Real>& u, SurfaceType type, GizmoId by,
               const SurfaceContact<Real>* surface, BoardAccess<Real>& board, const Real& surfaceBend = Real(0)) {
    const Real& now = board.now();
    const PhysicsParams<Real>& params = board.params();
    const Vec2<Real> p = positionAt(now);
    Vec2<Real> v = velocityAt(now);
    const Real closing = dot(v - u, n);
    // Touching and barely opening (under restSpeed) while accelerating into the surface counts
    // as a slow hit: that is how a ball at rest on a floor comes to lie on it, and how a
    // prediction a rounding error ahead of the present (a time that rounds to now) lands.
    if (!(closing < Real(0)) && !(closing < params.restSpeed && Real(dot(a_, n) + surfaceBend) < Real(0))) return false;
    // Pressed by what actually accelerates the ball: gravity, less what a surface it slides on
    // takes (sliding down an incline presses it into whatever stands at the bottom). A ball let
    // in above while not approaching at all is pressed by definition: only the gap's curvature
    // closes it. (In the classic model the path has no acceleration, so that curvature is a
    // flipper turning into the ball, which gravity may pull the other way. Reflected, such a
    // still or opening ball would keep its normal speed or be turned into the flipper: nothing
    // would part them, and a flipper triggered by its own hit restarted its swing against the
    // ball at one instant for ever; campaign seed 20261203, case 1495.)
    const Real pressing = -Real(dot(effectiveGravity(params), n) + surfaceBend);
    const bool pressed = !(closing < Real(0)) || Real(0) < pressing;
    const bool still = surfaceBend == Real(0) && u == Vec2<Real>();
    const bool jammed = board.jammed();
    // The settling threshold is for a scene with room to settle: within a jam its own rules
    // decide (a jammed hit that settled came to rest at once, and a turning spinner that struck
    // it again a nanosecond later made the pair rest and wake for ever: campaign seed
    // 2718281829, case 5745, gravity 1000).
    if (pressed && (-closing < params.restSpeed || (still && !jammed && settles(closing, pressing, params)))) {
      if (type == SurfaceType::StaticSegment && surface) {
        if (contact_ && !(contact_->gizmo == surface->gizmo && contact_->feature == surface->feature)) {
          // Pressed onto a second surface while sliding on one: it rests in the corner.
          comeToRest(board, surface->gizmo);
          return true;
        }
        contact_ = *surface;
        board.reportRule(ModelRule::ContactBegin, this->id(), surface->gizmo);
        setState(now, p, v - dot(v, n) * n, params);
        return true;
      }
      if (still && balancedOn(n, v, params)) {
        // Exactly on top of something round and still, with nothing to roll it off: it rests
        // there, where the minimum bounce would rattle for ever (~1250 hits a second).
        comeToRest(board, kNoGizmo);
        return true;
      }
      if (still && board.cradled(this->id(), p, n, by)) {
        // In a V of two still surfaces that hold it against gravity (two circle bumpers): the
        // minimum bounce would rattle it between them for as long as the run lasts, giving back
        // most of what friction takes, where friction alone brings it to rest in the V.
        comeToRest(board, by);
        return true;
      }
      if (jammed) {
        // Pressed slowly onto something round with no room to bounce: it rests there.
        comeToRest(board, by);
        return true;
      }
      v += (params.restSpeed - closing) * n;
      board.reportRule(ModelRule::MinimumBounce, this->id(), kNoGizmo);
    } else if (jammed) {
      // Struck again by the same gizmo at the instant of its last jammed hit from it: the
      // surfaces around it turn each hit's leftover velocity into the next, so it is wedged.
      // Without gravity nothing presses it, and the leftovers only shrink geometrically, by
      // cos² of the angle between the surfaces per round, to denormals and never to zero: a
      // ball pinned by a blocked flipper against the floor was hit a million times at one
      // instant (campaign seed 271828182, case 1309). It rests, as a pair of jammed balls does.
      if (metWhileJammed(by, now, JamMeeting::Hit)) {
        comeToRest(board, by);
        return true;
      }
      rememberJamMeeting(by, now, JamMeeting::Hit);
      v -= closing * n;  // no rebound: the normal part of the relative velocity is gone
      board.reportRule(ModelRule::Jammed, this->id(), by);
    } else {
      v -= ((Real(1) + c) * closing) * n;
    }
    setVelocity(now, p, v, board);
    return true;
  }

  // A new velocity from a hit: a sliding ball keeps, bounces off or leaves its surface; a
  // wedged ball wakes up.
  void setVelocity(const Real& now, const Vec2<Real>& p, Vec2<Real> v, BoardAccess<Real>& board) {
    const PhysicsParams<Real>& params = board.params();
    if (wedged_) {
      wedged_ = false;
      contact_.reset();
    }
    if (contact_) {
      const Vec2<Real>& n = contact_->segment.normal;
      const Real vn = dot(v, n);
      if (vn < -params.restSpeed) {
        v -= ((Real(1) + contact_->coefficient) * vn) * n;
        leaveContact(board);
      } else if (params.restSpeed < vn) {
        leaveContact(board);
      } else {
        v -= vn * n;
      }
    }
    setState(now, p, v, params);
  }

  // A bounce that would lift the ball less than settleRise off what it struck is no bounce: the
  // speed it leaves at, |closing|, against the deceleration that presses it back, `pressing`,
  // rises closing²/(2·pressing). Products only, so that exact scalars decide it too.
  static bool settles(const Real& closing, const Real& pressing, const PhysicsParams<Real>& params) {
    return Real(0) < pressing && Real(closing * closing) < Real(Real(2) * params.settleRise * pressing);
  }

  // A row with no room (docs/physics.md, "Piles"): this ball at pa, moving at va, strikes b (at
  // pb, moving at vb) along n (from b towards this one), both slowly, and a line of balls leads
  // from b to a still surface ahead and from this one to a still surface behind, within
  // settleRise at every link. Elastic, the hit would pass momentum along the line and back,
  // each pass crossing the line's little room, for as long as friction takes to slow the balls
  // below restSpeed: two balls that fill the gap between two gizmos, a row that fills a floor.
  // Slow: a speed that would rise less than settleRise against gravity, the scale of `settles`.
  bool rowWithoutRoom(const Ball& b, const Vec2<Real>& pa, const Vec2<Real>& pb, const Vec2<Real>& va,
                      const Vec2<Real>& vb, const Vec2<Real>& n, const Real& closing,
                      const BoardAccess<Real>& board) const {
    const PhysicsParams<Real>& params = board.params();
    const Real slow2 = Real(2) * params.settleRise * absOf(params.gravity);
    if (!(Real(closing * closing) < slow2) || !(lengthSquared(va) < slow2) || !(lengthSquared(vb) < slow2))
      return false;
    return board.boxedAlong(b.id(), pb, Vec2<Real>(-n), this->id()) && board.boxedAlong(this->id(), pa, n, b.id());
  }

  // This ball, at p moving at v, in a slow hit (closing along n, from the support towards it) on
  // a ball at rest that gravity presses it onto: that ball is a still surface to it
  // (docs/physics.md, "Piles"). It rests there when it is held (balanced on its top, or in a V
  // with a second support at rest), and otherwise alone takes the minimum bounce: a slow hit from
  // above does not stir a pile. Returns false when the support is not at rest or not below.
  bool meetsBallAtRest(const Ball& support, const Vec2<Real>& p, const Vec2<Real>& n, const Vec2<Real>& v,
                       const Real& closing, BoardAccess<Real>& board) {
    const PhysicsParams<Real>& params = board.params();
    if (!support.resting() || support.captured() || !(dot(effectiveGravity(params), n) < Real(0))) return false;
    if (balancedOn(n, v, params) || board.cradled(this->id(), p, n, support.id())) {
      comeToRest(board, support.id());
      return true;
    }
    board.reportRule(ModelRule::MinimumBounce, this->id(), support.id());
    setVelocity(board.now(), p, Vec2<Real>(v + (params.restSpeed - closing) * n), board);
    return true;
  }

  // Balanced on a round surface: gravity and the velocity both lie exactly along the normal,
  // so the contact point is the top of the surface and nothing moves the ball along it.
  bool balancedOn(const Vec2<Real>& n, const Vec2<Real>& v, const PhysicsParams<Real>& params) const {
    const Vec2<Real> g = effectiveGravity(params);
    return Vec2<Real>(g - dot(g, n) * n) == Vec2<Real>() && Vec2<Real>(v - dot(v, n) * n) == Vec2<Real>();
  }

  // Wedged: at rest, without gravity, until something hits it.
  void comeToRest(BoardAccess<Real>& board, GizmoId against) {
    wedged_ = true;
    board.reportRule(ModelRule::Wedged, this->id(), against);
    setState(board.now(), positionAt(board.now()), Vec2<Real>(), board.params());
  }

  // At rest beside a gizmo that starts to move: it moves under gravity again, sliding on its
  // contact if it has one (reported as the end of its rest against that gizmo).
  void wake(BoardAccess<Real>& board, GizmoId by) {
    if (!wedged_) return;
    wedged_ = false;
    board.reportRule(ModelRule::ContactEnd, this->id(), by);
    setState(board.now(), positionAt(board.now()), velocityAt(board.now()), board.params());
  }

  void leaveContact(BoardAccess<Real>& board) {
    if (!contact_) return;
    board.reportRule(ModelRule::ContactEnd, this->id(), contact_->gizmo);
    contact_.reset();
    wedged_ = false;
  }

  // When the sliding contact runs off the end of its segment, as an absolute time.
  std::optional<Real> contactEndTime(const Real& now, const Real& limit) const {
    if (!contact_ || wedged_) return std::nullopt;
    const Trajectory<Real> t = trajectoryAt(now);
    const SegmentFeature<Real>& s = contact_->segment;
    const Real half = Real(1) / Real(2);
    const Real u0 = dot(t.p - s.a, s.direction), du = dot(t.v, s.direction), ddu = half * dot(t.a, s.direction);
    if (leavingOverEnd(s, u0, du, ddu, positionResolution(t.p))) return now;
    // Leaving past a (u falls through 0) or past b (u rises through length): both are entries
    // of a quadratic gap, which the root finder handles.
    const std::array<Real, 5> pastA{u0, du, ddu, Real(0), Real(0)};
    const std::array<Real, 5> pastB{s.length - u0, -du, -ddu, Real(0), Real(0)};
    std::optional<Real> best;
    for (const auto& c : {pastA, pastB}) {
      const std::optional<Real> tau = firstPolynomialEntry(c, Real(limit - now), [](const Real&) { return true; });
      if (tau && (!best || *tau < *best)) best = tau;
    }
    if (!best) return std::nullopt;
    return now + *best;
  }

  // --- the classic model's step ----------------------------------------------------------------
  // Seed: simulate for dt. p += v dt, then friction and gravity update v (docs/physics.md §6).
  bool tick(const Real& dt, BoardAccess<Real>& board) override {
    if (captured_ || board.params().model != MotionModel::Classic) return false;
    const PhysicsParams<Real>& params = board.params();
    const Vec2<Real> p = p0_ + dt * v0_;
    Vec2<Real> v = frictionApplied(v0_, dt, params) + dt * effectiveGravity(params);
    if (!(v == Vec2<Real>()) && settlesOnLevel(v, params)) {
      v = Vec2<Real>();
      board.reportRule(ModelRule::Settled, this->id(), contact_->gizmo);
    }
    const bool changed = !(v == v0_);
    t0_ = t0_ + dt;
    p0_ = p;
    v0_ = v;
    return changed;
  }

  // Friction on a level surface (one that leaves the ball no part of gravity) stops a ball
  // slower than restSpeed: nothing would ever move it again, and the law below only shrinks
  // its speed geometrically, a friction tick every frictionStep for as long as the run lasts.
  // Returns whether it stopped it (reported as Settled).
  bool settlesOnLevel(const Vec2<Real>& v, const PhysicsParams<Real>& params) const {
    return contact_ && !wedged_ && effectiveGravity(params) == Vec2<Real>() &&
           lengthSquared(v) < Real(params.restSpeed * params.restSpeed);
  }

  // The friction law v ← v (1 − μ Δt − μ₂ |v| Δt). The factor is kept at 0 or above: beyond
  // 1/(μ₂ Δt) the per-step law would reverse the ball, which no friction does.
  static Vec2<Real> frictionApplied(const Vec2<Real>& v, const Real& dt, const PhysicsParams<Real>& params) {
    if (params.mu == Real(0) && params.mu2 == Real(0)) return v;
    Real factor = Real(1) - params.mu * dt;
    // Without μ₂ the speed is not needed, and an exact run must not take its square root.
    if (params.mu2 != Real(0)) factor = factor - params.mu2 * length(v) * dt;
    if (factor < Real(0)) factor = Real(0);
    return factor * v;
  }

  // --- board plumbing --------------------------------------------------------------------------
  Box<Real> bounds() const override {
    const Real r = radius();
    return Box<Real>::around(p0_, r);
  }

  GizmoSpec spec() const override { return GizmoSpec{}; }  // balls are BallSpec: see ballSpec()
  BallSpec ballSpec(const Real& now) const {
    const Vec2<Real> p = positionAt(now), v = velocityAt(now);
    return BallSpec{this->name(), toDouble(p.x), toDouble(p.y), toDouble(v.x), toDouble(v.y), SourcePos{}};
  }

  std::vector<std::string> propertyNames() const override {
    return {property::kName, property::kX, property::kY, property::kVx, property::kVy};
  }
  std::optional<PropertyValue> property(std::string_view name) const override {
    if (name == property::kName) return PropertyValue(this->name());
    if (name == property::kX) return PropertyValue(toDouble(p0_.x));
    if (name == property::kY) return PropertyValue(toDouble(p0_.y));
    if (name == property::kVx) return PropertyValue(toDouble(v0_.x));
    if (name == property::kVy) return PropertyValue(toDouble(v0_.y));
    return std::nullopt;
  }
  bool setPropertyUnchecked(std::string_view name, const PropertyValue& value) override {
    if (name == property::kName) {
      if (!std::holds_alternative<std::string>(value)) return false;
      this->rename(std::get<std::string>(value));
      return true;
    }
    const double* d = std::get_if<double>(&value);
    if (!d) return false;
    if (name == property::kX) p0_.x = fromDouble<Real>(*d);
    else if (name == property::kY) p0_.y = fromDouble<Real>(*d);
    else if (name == property::kVx) v0_.x = fromDouble<Real>(*d);
    else if (name == property::kVy) v0_.y = fromDouble<Real>(*d);
    else return false;
    return true;
  }

  void saveState(GizmoState<Real>& out) const override {
    auto& r = out.reals;
    auto& i = out.ints;
    r.insert(r.end(), {t0_, p0_.x, p0_.y, v0_.x, v0_.y, a_.x, a_.y});
    i.insert(i.end(), {captured_, wedged_, nextFrictionIndex, contact_.has_value(), std::int64_t(jamMeetings_.size())});
    if (contact_) {
      const SegmentFeature<Real>& g = contact_->segment;
      i.insert(i.end(), {contact_->gizmo, contact_->feature});
      r.insert(r.end(), {g.a.x, g.a.y, g.b.x, g.b.y, g.normal.x, g.normal.y, g.direction.x, g.direction.y, g.length,
                         contact_->coefficient});
    }
    // A graze is written as the other ball's id, a hit as -1 - id: a state without hits has
    // the bytes it had before hits were remembered.
    for (const JamMeeting& m : jamMeetings_) {
      i.push_back(m.kind == JamMeeting::Graze ? std::int64_t(m.other) : -1 - std::int64_t(m.other));
      r.push_back(m.time);
    }
  }

  void restoreState(GizmoStateReader<Real>& in, const GizmoIdCheck& ids) override {
    auto vec = [&] {
      const Real x = in.real();
      return Vec2<Real>(x, in.real());
    };
    t0_ = in.real();
    p0_ = vec();
    v0_ = vec();
    a_ = vec();
    captured_ = in.flag();
    wedged_ = in.flag();
    nextFrictionIndex = in.integer(0, std::numeric_limits<std::int64_t>::max());
    const bool hasContact = in.flag();
    // Each meeting is one integer and one real, so a count larger than the state holds fails
    // on reading them rather than allocating for it.
    const std::int64_t meetingCount = in.integer(0, std::numeric_limits<std::int32_t>::max());
    contact_.reset();
    if (hasContact) {
      SurfaceContact<Real> c;
      c.gizmo = static_cast<GizmoId>(in.integer(0, std::numeric_limits<GizmoId>::max()));
      if (!ids.isGizmo(c.gizmo) || ids.isBall(c.gizmo)) throw StateError("ball contact: not a surface");
      c.feature = static_cast<std::int32_t>(in.integer(0, std::numeric_limits<std::int32_t>::max()));
      SegmentFeature<Real>& g = c.segment;
      g.a = vec();
      g.b = vec();
      g.normal = vec();
      g.direction = vec();
      g.length = in.real();
      c.coefficient = in.real();
      contact_ = c;
    }
    jamMeetings_.clear();
    for (std::int64_t k = 0; k < meetingCount; ++k) {
      constexpr std::int64_t most = std::numeric_limits<GizmoId>::max();
      const std::int64_t written = in.integer(-1 - most, most);
      const bool graze = written >= 0;
      const GizmoId other = static_cast<GizmoId>(graze ? written : -1 - written);
      if (!ids.isBall(other)) throw StateError("ball jam meeting: not a ball");
      jamMeetings_.push_back(JamMeeting{other, in.real(), graze ? JamMeeting::Graze : JamMeeting::Hit});
    }
  }

 private:
  Real t0_{0};
  Vec2<Real> p0_, v0_, a_;
  bool captured_ = false;
  bool wedged_ = false;
  bool startedMoving_ = false;
  std::optional<SurfaceContact<Real>> contact_;
  // The jammed meetings of the latest instant that had any, one per other gizmo: grazes let
  // through (see collide), whose pair must skip its contact at that instant, and hits by balls
  // and surfaces (a second hit by the same one at that instant wedges the ball). In a pile
  // a ball can graze several balls at one instant; with one remembered graze, the second
  // overwrote the first, whose pair then predicted its contact at that instant again, grazed
  // again and overwrote the other in turn, a million times (campaign seed 20261203, case 4731).
  struct JamMeeting {
    enum Kind : std::uint8_t { Graze, Hit };
    GizmoId other;
    Real time;
    Kind kind;
  };
  std::vector<JamMeeting> jamMeetings_;

  bool metWhileJammed(GizmoId other, const Real& t, typename JamMeeting::Kind kind) const {
    for (const JamMeeting& m : jamMeetings_)
      if (m.other == other && m.time == t && m.kind == kind) return true;
    return false;
  }
  void rememberJamMeeting(GizmoId other, const Real& t, typename JamMeeting::Kind kind) {
    if (!jamMeetings_.empty() && !(jamMeetings_.front().time == t)) jamMeetings_.clear();  // an earlier instant's
    if (!metWhileJammed(other, t, kind)) jamMeetings_.push_back(JamMeeting{other, t, kind});
  }
};

}  // namespace gizmo
