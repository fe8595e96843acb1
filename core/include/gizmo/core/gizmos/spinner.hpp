#pragma once
// The spinner (docs/physics.md, "Gizmos other programs added"), NiklavsM/Gizmoball's addition: a
// cross of two capsules 1.5 L long and 0.5 L wide about the centre of its 2×2 box. It stands still
// at load; each hit and each trigger starts it turning at 3.14 rad/s (clockwise on screen), or
// stops it where it stands (Spinner.java: the action negates the speed, and only a positive speed
// turns). Turning, it is four arms that swing about the centre, each a capsule from the centre
// like a flipper's from its pivot, so its times of impact are the flipper's certified search.
#include <cstdint>

#include "gizmo/core/geometry/flipper_time_of_impact.hpp"
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmos/grid_properties.hpp"
#include "gizmo/core/gizmos/pinch_count.hpp"
#include "gizmo/core/gizmos/shape_collisions.hpp"

namespace gizmo {

// The spinner's rule (model_rule.hpp): its code is in logs.
struct SpinnerRule {
  static constexpr ModelRule Blocked{12};  // a spinner pinching a ball stops where it stands
};

template <class Real>
class Spinner final : public GridPlaced<AbstractGizmo<Real>> {
 public:
  explicit Spinner(const GizmoSpec& spec) : GridPlaced<AbstractGizmo<Real>>(spec, spec.name) { layOut(); }

  static Real turnRate() { return fromDouble<Real>(kSpinnerTurnRate); }
  static Real coefficient() { return fromDouble<Real>(0.9); }
  static Real halfPi() { return piOf<Real>() / Real(2); }

  GizmoKind kind() const override { return GizmoKind::Spinner; }

  CollisionAnswer canCollideWith(const AbstractGizmo<Real>& other) const override {
    return other.asBall() ? CollisionAnswer::CanCollide : CollisionAnswer::NeverCollides;
  }

  // --- turning state ---------------------------------------------------------------------------
  // The cross's angle at t0_ is quarter_ quarter turns plus phase_ ∈ [0, π/2); it grows at
  // turnRate() while it turns. At a time t it is split again into whole quarters past quarter_
  // and a phase in [0, π/2), so that the swing searches and the project's sine (|x| ≤ 2) only
  // ever see a phase: the cross looks the same a quarter turn on.
  struct Turn {
    std::int64_t quarters;  // whole quarters past quarter_
    Real phase;             // in [0, π/2)
  };
  Turn turnAt(const Real& t) const {
    if (!turning_) return Turn{0, phase_};
    const Real angle = phase_ + turnRate() * (t - t0_), q = halfPi();
    // A first guess in double, then settled by exact comparisons (as the friction ticks' index).
    std::int64_t k = static_cast<std::int64_t>(toDouble(Real(angle / q)));
    while (k > 0 && angle < Real(Real(k) * q)) --k;
    while (!(angle < Real(Real(k + 1) * q))) ++k;
    return Turn{k, Real(angle - Real(k) * q)};
  }

  bool turning() const { return turning_; }
  bool movesForEver() const override { return turning_; }

  // Arm k ∈ {0, 1, 2, 3} at time t: a capsule from the centre, turning from there.
  SwingingAxis<Real> armAt(int k, const Real& t) const {
    const Turn turn = turnAt(t);
    return arm(static_cast<int>((quarter_ + turn.quarters + k) % 4), turn.phase);
  }

  // The angle of arm 0 at time t, from +x toward +y: for pictures.
  Real angleAt(const Real& t) const {
    const Turn turn = turnAt(t);
    return Real(quarter_ + static_cast<int>(turn.quarters % 4)) * halfPi() + turn.phase;
  }

  void fireTrigger(BoardAccess<Real>& board) override {
    // Stopped by the pinch rule at this very instant: it stays so until time moves on (a spinner
    // connected to itself is triggered again by the hit that stopped it).
    if (blocked_ && t0_ == board.now()) return;
    toggle(board);
  }

  // --- collisions ----------------------------------------------------------------------------
  // Still: the features of stillShape_. Turning: 4k + f for arm k's side 0 or 1 (f) or tip (3).
  std::optional<Contact<Real>> timeUntilCollision(const AbstractGizmo<Real>& other, const Real& now, const Real& limit,
                                                  const PhysicsParams<Real>& params) const override {
    const Ball<Real>* ball = other.asBall();
    if (!ball || ball->captured()) return std::nullopt;
    const Trajectory<Real> t = ball->trajectoryAt(now);
    const Real r = Ball<Real>::radius();
    if (!turning_) {
      const std::int32_t skip =
          ball->contact() && ball->contact()->gizmo == this->id() ? ball->contact()->feature : std::int32_t{-1};
      const std::optional<FeatureHit<Real>> hit = shapeTimeOfImpact(stillShape_, t, r, limit - now, skip);
      if (!hit) return std::nullopt;
      return Contact<Real>{now + hit->tau, hit->feature, EventKind::Collision};
    }
    const Turn turn = turnAt(now);
    const Real quarterTime = halfPi() / turnRate();
    // Searched in pieces of one quarter each (the phase's range), over the rest of this quarter and
    // at most one whole quarter more: the cross sweeps in a quarter turn every place it ever will,
    // so a ball at rest that it misses that long it never meets (a moving ball's limit is nearer).
    Real pieceEnd = (halfPi() - turn.phase) / turnRate();
    const Real span = minOf(Real(limit - now), Real(pieceEnd + quarterTime));
    {
      const Real travel = length(t.v) * span + length(t.a) * span * span / Real(2);
      const Real armsReach = fromDouble<Real>(kSpinnerArmLength + kSpinnerArmRadius) + r;
      const Real reach = armsReach + travel;
      if (reach * reach < lengthSquared(Vec2<Real>(t.p - centre_))) return std::nullopt;
      if (!pathMayComeWithin(t, span, centre_, armsReach)) return std::nullopt;
    }
    // A ball touching an arm now and pressed into it is hit now (as at a swinging flipper), to
    // within its position resolution (pressedIntoSwing).
    const Real touching = positionResolution(t.p);
    for (int k = 0; k < 4; ++k) {
      const SwingingAxis<Real> axis = arm(static_cast<int>((quarter_ + turn.quarters + k) % 4), turn.phase);
      const std::optional<int> pressed = touchedSwingFeature(t, r, axis, [&](const SwingTouch<Real>& touch) {
        return pressedIntoSwing(t, touch, touching, params.restSpeed);
      });
      if (pressed) return Contact<Real>{now, 4 * k + *pressed, EventKind::Collision};
    }
    std::optional<Contact<Real>> best;
    Real pieceStart(0);
    for (std::int64_t piece = 0; pieceStart < span && !best; ++piece) {
      const Real end = minOf(pieceEnd, span);
      const Trajectory<Real> from = ball->trajectoryAt(Real(now + pieceStart));
      for (int k = 0; k < 4; ++k) {
        const SwingingAxis<Real> axis =
            arm(static_cast<int>((quarter_ + turn.quarters + piece + k) % 4), piece == 0 ? turn.phase : Real(0));
        const Real searchEnd = best ? Real(best->time - (now + pieceStart)) : Real(end - pieceStart);
        if (const auto hit = swingingCapsuleTimeOfImpact(from, r, axis, searchEnd)) {
          const Real time = now + pieceStart + hit->tau;
          if (!best || time < best->time) best = Contact<Real>{time, 4 * k + hit->feature, EventKind::Collision};
        }
      }
      pieceStart = pieceEnd;
      pieceEnd = pieceEnd + quarterTime;
    }
    return best;
  }

  void collide(AbstractGizmo<Real>& other, const Contact<Real>& contact, BoardAccess<Real>& board) override {
    Ball<Real>* ball = other.asBall();
    if (!ball) return;
    if (!turning_) {
      bounceOffShape(stillShape_, this->id(), coefficient(), *ball, contact.feature, board);
    } else {
      const std::optional<SwingTouch<Real>> touch =
          swingTouchNow(ball->trajectoryAt(board.now()), Ball<Real>::radius(), armAt(contact.feature / 4, board.now()),
                        contact.feature % 4);
      if (!touch) return;
      ball->reflect(touch->normal, coefficient(), touch->surfaceVelocity, SurfaceType::Round, this->id(), nullptr,
                    board, touch->bend);
      if (countHit(ball->id(), board)) return;
    }
    board.performAction(this->id());  // NiklavsM's spinner acts on its own hits
  }

  Box<Real> bounds() const override {
    const Vec2<Real> o(Real(this->placement().x), Real(this->placement().y));
    return Box<Real>{o, o + Vec2<Real>(Real(2), Real(2))};
  }

  const Shape<Real>& stillShape() const { return stillShape_; }
  const Shape<Real>* restingShape() const override { return turning_ ? nullptr : &stillShape_; }

  void saveState(GizmoState<Real>& out) const override {
    out.reals.insert(out.reals.end(), {t0_, phase_});
    out.ints.insert(out.ints.end(), {quarter_, turning_, blocked_});
    pinch_.save(out);
  }

  void restoreState(GizmoStateReader<Real>& in, const GizmoIdCheck& ids) override {
    t0_ = in.real();
    phase_ = in.real();
    quarter_ = static_cast<int>(in.integer(0, 3));
    turning_ = in.flag();
    blocked_ = in.flag();
    pinch_.restore(in, ids, "spinner");
    if (!turning_) stillShape_ = shapeAt(phase_);
  }

 protected:
  void placed() override { layOut(); }

 private:
  void layOut() {
    const GizmoSpec& s = this->placement();
    centre_ = Vec2<Real>(Real(s.x + 1), Real(s.y + 1));
    anchor(t0_, 0, Real(0), false);
  }

  // The arm along quarter q plus `phase`, turning at the spinner's rate from there if it turns.
  SwingingAxis<Real> arm(int q, const Real& phase) const {
    SwingingAxis<Real> axis;
    axis.pivot = centre_;
    axis.baseQuarter = q;
    axis.phi0 = phase;
    axis.omega = turning_ ? turnRate() : Real(0);
    axis.length = fromDouble<Real>(kSpinnerArmLength);
    axis.radius = fromDouble<Real>(kSpinnerArmRadius);
    return axis;
  }

  void anchor(const Real& t, int quarter, const Real& phase, bool turning) {
    t0_ = t;
    quarter_ = quarter % 4;
    phase_ = phase;
    turning_ = turning;
    if (!turning_) stillShape_ = shapeAt(phase_);
  }

  // Still → turning from where it stands; turning → still where it stands.
  void toggle(BoardAccess<Real>& board) {
    const Real& now = board.now();
    const Turn turn = turnAt(now);
    // The pinch count is per turning: a spinner that stood still for a while starts afresh, one
    // stopped and started again at one instant (by its own hit and a connection to itself) does not.
    if (!turning_ && !(t0_ == now)) pinch_.clear();
    blocked_ = false;
    // Starting, it may push what lay against it. Stopping, it held nothing up (a turning spinner
    // is no surface to rest or slide on), so nothing wakes: balls woken by every toggle at one
    // instant were struck again at that instant by what they rested on, whose trigger toggled it
    // again, a million times (campaign seed 244948974, case 2066).
    if (!turning_) board.releaseContactsOn(this->id());
    anchor(now, static_cast<int>((quarter_ + turn.quarters) % 4), turn.phase, !turning_);
    board.markForRecompute(this->id());
  }

  // The cross at `phase` past quarter_ quarters: exact at whole quarters.
  Shape<Real> shapeAt(const Real& phase) const {
    Shape<Real> shape;
    addSpinnerCross(shape, centre_,
                    phase == Real(0) ? quarterDirection<Real>(quarter_) : arm(quarter_, phase).direction(Real(0)));
    return shape;
  }

  // A ball struck again and again in one turning is pinched against something: the spinner stops
  // where it stands instead of pushing through it (the flipper's pinch rule, docs/physics.md).
  // True when it stopped.
  bool countHit(GizmoId ball, BoardAccess<Real>& board) {
    if (!pinch_.hit(ball, board.params().pinchLimit)) return false;
    board.reportRule(SpinnerRule::Blocked, this->id(), ball);
    toggle(board);
    blocked_ = true;
    return true;
  }

  Vec2<Real> centre_;
  Real t0_{0}, phase_{0};
  int quarter_ = 0;
  bool turning_ = false;
  bool blocked_ = false;
  PinchCount pinch_;
  Shape<Real> stillShape_;
};

}  // namespace gizmo
