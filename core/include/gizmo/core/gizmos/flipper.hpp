#pragma once
// Left and right flippers (docs/physics.md §2): a capsule that swings a quarter turn about its
// pivot in exactly 1/12 s when triggered, reverses at once when triggered mid-swing, and
// adds its surface speed to the balls it strikes.
#include <optional>

#include "gizmo/core/geometry/flipper_time_of_impact.hpp"
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmos/grid_properties.hpp"
#include "gizmo/core/gizmos/pinch_count.hpp"
#include "gizmo/core/gizmos/shape_collisions.hpp"

namespace gizmo {

// The flippers' rule (model_rule.hpp): its code is in logs.
struct FlipperRule {
  static constexpr ModelRule Blocked{5};  // a flipper pinching a ball stops where it is
};

template <class Real>
class Flipper final : public GridPlaced<AbstractGizmo<Real>> {
 public:
  explicit Flipper(const GizmoSpec& spec) : GridPlaced<AbstractGizmo<Real>>(spec, spec.name) { layOut(); }

  static Real swingTime() { return Real(1) / Real(12); }
  static Real coefficient() { return fromDouble<Real>(0.95); }

  GizmoKind kind() const override {
    return this->placement().type == GizmoType::LeftFlipper ? GizmoKind::LeftFlipper : GizmoKind::RightFlipper;
  }

  CollisionAnswer canCollideWith(const AbstractGizmo<Real>& other) const override {
    return other.asBall() ? CollisionAnswer::CanCollide : CollisionAnswer::NeverCollides;
  }

  // --- swing state -----------------------------------------------------------------------------
  // Progress s ∈ [0, 1/12] along the forward swing, anchored at t₀ and moving at `direction`
  // (+1 forward, −1 back, 0 still).
  Real progressAt(const Real& t) const { return s0_ + Real(direction_) * (t - t0_); }
  int direction() const { return direction_; }
  bool swinging() const { return direction_ != 0; }
  bool blocked() const { return blocked_; }
  // Angular velocity while swinging, rad/s (θ from +x toward +y).
  Real omega() const { return Real(layout_.forwardSign * direction_) * Real(6) * piOf<Real>(); }
  // The time the current swing ends (absolute); only while swinging.
  Real stopTime() const { return t0_ + (direction_ > 0 ? swingTime() - s0_ : s0_); }

  SwingingAxis<Real> axisAt(const Real& t) const {
    SwingingAxis<Real> axis;
    axis.pivot = pivot_;
    axis.baseQuarter = layout_.restQuarter;
    axis.phi0 = Real(layout_.forwardSign) * Real(6) * piOf<Real>() * progressAt(t);
    axis.omega = omega();
    axis.length = fromDouble<Real>(kFlipperLength);
    axis.radius = fromDouble<Real>(kFlipperRadius);
    return axis;
  }

  // Seed: fireTrigger. At rest: swing forward; at the end: swing back; mid-swing: reverse.
  void fireTrigger(BoardAccess<Real>& board) override {
    const Real& now = board.now();
    // Blocked by the pinch rule at this very instant: it stays so until time moves on. A
    // flipper connected to itself is triggered by each of its own hits, and a ball on its pivot
    // is pressed by the side turning either way, so each hit reversed the swing into another
    // hit, a million times at one instant (campaign seed 577215664, case 2920).
    if (blocked_ && t0_ == now) return;
    const Real s = progressAt(now);
    int next;
    if (direction_ != 0) next = -direction_;
    else if (s == Real(0)) next = +1;
    else if (s == swingTime()) next = -1;
    else next = -lastDirection_;  // blocked mid-swing: go back the way it came
    board.releaseContactsOn(this->id());
    anchor(now, s, next);
    board.markForRecompute(this->id());
  }

  // A swing reversed at the instant it began ends there, and moved nothing.
  bool inMotionAt(const Real& now) const override { return direction_ != 0 && now < stopTime(); }

  std::optional<Real> predictionHorizon() const override {
    if (direction_ == 0) return std::nullopt;
    return stopTime();
  }

  void scheduleOwnEvents(BoardAccess<Real>& board) override {
    if (direction_ != 0) board.schedule(EventKind::FlipperStop, stopTime(), this->id(), kNoGizmo, -1);
  }

  bool makesEventKind(EventKind k) const override { return k == EventKind::FlipperStop; }

  void handleOwnEvent(const Event<Real>& event, BoardAccess<Real>& board) override {
    if (event.kind != EventKind::FlipperStop || direction_ == 0) return;
    anchor(board.now(), direction_ > 0 ? swingTime() : Real(0), 0);
  }

  // --- collisions ----------------------------------------------------------------------------
  // Features: 0 and 1 the long sides, 2 the pivot end, 3 the tip end.
  std::optional<Contact<Real>> timeUntilCollision(const AbstractGizmo<Real>& other, const Real& now, const Real& limit,
                                                  const PhysicsParams<Real>& params) const override {
    const Ball<Real>* ball = other.asBall();
    if (!ball || ball->captured()) return std::nullopt;
    const Trajectory<Real> t = ball->trajectoryAt(now);
    const Real r = Ball<Real>::radius();
    if (direction_ == 0) {
      const std::int32_t skip =
          ball->contact() && ball->contact()->gizmo == this->id() ? ball->contact()->feature : std::int32_t{-1};
      const std::optional<FeatureHit<Real>> hit = shapeTimeOfImpact(stillShape_, t, r, limit - now, skip);
      if (!hit) return std::nullopt;
      return Contact<Real>{now + hit->tau, hit->feature, EventKind::Collision};
    }
    // A ball touching the moving capsule and pressed into it is hit now, to within its position
    // resolution (pressedIntoSwing).
    const SwingingAxis<Real> axis = axisAt(now);
    auto pressedOn = [&params](const Trajectory<Real>& at, const Real& slack) {
      return [&params, &at, slack](const SwingTouch<Real>& touch) {
        return pressedIntoSwing(at, touch, slack, params.restSpeed);
      };
    };
    const std::optional<int> pressed = touchedSwingFeature(t, r, axis, pressedOn(t, positionResolution(t.p)));
    if (pressed) return Contact<Real>{now, *pressed, EventKind::Collision};
    const Real toLimit = limit - now, toStop = stopTime() - now;
    const Real horizon = minOf(toLimit, toStop);
    std::optional<Contact<Real>> best;
    // The pivot end does not move while the flipper turns.
    const CircleFeature<Real> pivotEnd{pivot_, fromDouble<Real>(kFlipperRadius)};
    if (const std::optional<Real> tau = circleTimeOfImpact(t, r, pivotEnd, horizon))
      best = Contact<Real>{now + *tau, 2, EventKind::Collision};
    const Real searchEnd = best ? Real(best->time - now) : horizon;
    if (const auto hit = swingingCapsuleTimeOfImpact(t, r, axis, searchEnd))
      if (!best || now + hit->tau < best->time)
        best = Contact<Real>{now + hit->tau, hit->feature, EventKind::Collision};
    // A ball on the pivot's circle that a side's end comes under (sideEndComesUnder), touching
    // the side then to within its position resolution and pressed into it.
    const Real endSearch = best ? Real(best->time - now) : horizon;
    const auto reached =
        sideEndComesUnder(t, r, axis, endSearch, [&](const Trajectory<Real>& at, const SwingingAxis<Real>& then) {
          return touchedSwingFeature(at, r, then, pressedOn(at, positionResolution(at.p)));
        });
    if (reached && (!best || now + reached->tau < best->time))
      best = Contact<Real>{now + reached->tau, reached->feature, EventKind::Collision};
    if (!best && !(toLimit < toStop)) best = strikeAsTheSwingEnds(*ball, r);
    return best;
  }

  // A ball that the capsule reaches just as the swing ends is struck then, at the stop (a
  // collision runs before the flipper stop of the same instant). The gap closes to zero at the
  // swing's last instant, where the search may round it to a hair above zero: a gap within the
  // ball's position resolution, closing, counts as reached.
  std::optional<Contact<Real>> strikeAsTheSwingEnds(const Ball<Real>& ball, const Real& r) const {
    const Real end = stopTime();
    const Trajectory<Real> t = ball.trajectoryAt(end);
    const SwingingAxis<Real> axis = axisAt(end);
    const Real resolution = positionResolution(t.p);
    // Out of the capsule's reach about the pivot: no feature is near, and no trigonometry is spent.
    const Real reach = axis.length + axis.radius + r + resolution;
    if (reach * reach < lengthSquared(Vec2<Real>(t.p - axis.pivot))) return std::nullopt;
    const std::optional<int> reached = touchedSwingFeature(t, r, axis, [&](const SwingTouch<Real>& touch) {
      return !(resolution < absOf(touch.gap)) && dot(Vec2<Real>(t.v - touch.surfaceVelocity), touch.normal) < Real(0);
    });
    if (!reached) return std::nullopt;
    return Contact<Real>{end, *reached, EventKind::Collision};
  }

  void collide(AbstractGizmo<Real>& other, const Contact<Real>& contact, BoardAccess<Real>& board) override {
    Ball<Real>* ball = other.asBall();
    if (!ball) return;
    if (direction_ == 0) {
      bounceOffShape(stillShape_, this->id(), coefficient(), *ball, contact.feature, board);
      return;
    }
    const Real& now = board.now();
    const SwingingAxis<Real> axis = axisAt(now);
    if (contact.feature == 2) {
      // The pivot end turns in place: its surface moves along itself only.
      const Vec2<Real> d = ball->positionAt(now) - pivot_;
      const Real dist = length(d);
      if (dist == Real(0)) return;
      const Vec2<Real> n(d.x / dist, d.y / dist);
      const Vec2<Real> surfaceVelocity = swingSurfaceVelocity(axis, ball->positionAt(now), Ball<Real>::radius(), n);
      ball->reflect(n, coefficient(), surfaceVelocity, SurfaceType::Round, this->id(), nullptr, board);
    } else {
      const std::optional<SwingTouch<Real>> touch =
          swingTouchNow(ball->trajectoryAt(now), Ball<Real>::radius(), axis, contact.feature);
      if (!touch) return;
      ball->reflect(touch->normal, coefficient(), touch->surfaceVelocity, SurfaceType::Round, this->id(), nullptr,
                    board, touch->bend);
    }
    countHit(ball->id(), board);
  }

  Box<Real> bounds() const override {
    const Vec2<Real> o(Real(this->placement().x), Real(this->placement().y));
    return Box<Real>{o, o + Vec2<Real>(Real(2), Real(2))};
  }

  const Shape<Real>& stillShape() const { return stillShape_; }
  const Shape<Real>* restingShape() const override { return swinging() ? nullptr : &stillShape_; }

  void saveState(GizmoState<Real>& out) const override {
    out.reals.insert(out.reals.end(), {t0_, s0_});
    out.ints.insert(out.ints.end(), {direction_, lastDirection_, blocked_});
    pinch_.save(out);
  }

  void restoreState(GizmoStateReader<Real>& in, const GizmoIdCheck& ids) override {
    t0_ = in.real();
    s0_ = in.real();
    direction_ = static_cast<int>(in.integer(-1, 1));
    lastDirection_ = static_cast<int>(in.integer(-1, 1));
    blocked_ = in.flag();
    pinch_.restore(in, ids, "flipper");
    if (direction_ == 0) stillShape_ = shapeAt(s0_);
  }

 protected:
  void placed() override { layOut(); }

 private:
  void layOut() {
    const GizmoSpec& s = this->placement();
    layout_ = flipperLayout(s.type, s.orientation);
    pivot_ = Vec2<Real>(Real(s.x), Real(s.y)) + toReal<Real>(layout_.pivot);
    anchor(t0_, Real(0), 0);
  }

  void anchor(const Real& t, const Real& s, int direction) {
    // The pinch count is per swing; a swing that turns at the instant it began goes on with it
    // (those hits all happened at that instant), so a flipper reversed by each hit is blocked too.
    if (!(t == t0_)) pinch_.clear();
    t0_ = t;
    s0_ = s;
    if (direction_ != 0) lastDirection_ = direction_;
    direction_ = direction;
    blocked_ = false;
    if (direction_ == 0) stillShape_ = shapeAt(s0_);
  }

  // The capsule at progress s: exact quarter turns at rest and at the end.
  Shape<Real> shapeAt(const Real& s) const {
    Vec2<Real> u;
    if (s == Real(0)) u = quarterDirection<Real>(layout_.restQuarter);
    else if (s == swingTime()) u = quarterDirection<Real>(layout_.endQuarter);
    else {
      SwingingAxis<Real> axis = axisAt(t0_);
      axis.phi0 = Real(layout_.forwardSign) * Real(6) * piOf<Real>() * s;
      u = axis.direction(Real(0));
    }
    Shape<Real> shape;
    addCapsule(shape, pivot_, Vec2<Real>(pivot_ + fromDouble<Real>(kFlipperLength) * u),
               fromDouble<Real>(kFlipperRadius));
    return shape;
  }

  // A ball struck again and again in one swing is pinched against something: the flipper
  // stops where it is instead of pushing through it (docs/physics.md, the pinch rule).
  void countHit(GizmoId ball, BoardAccess<Real>& board) {
    if (!pinch_.hit(ball, board.params().pinchLimit)) return;
    const Real& now = board.now();
    anchor(now, progressAt(now), 0);
    blocked_ = true;
    board.reportRule(FlipperRule::Blocked, this->id(), ball);
    board.markForRecompute(this->id());
  }

  FlipperLayout layout_{};
  Vec2<Real> pivot_;
  Real t0_{0}, s0_{0};
  int direction_ = 0;
  int lastDirection_ = 1;
  bool blocked_ = false;
  PinchCount pinch_;
  Shape<Real> stillShape_;
};

}  // namespace gizmo
