#pragma once
// The seed's AbstractGizmo: every piece on the board, the ball included. A gizmo says which
// other gizmos it has collision handlers for (canCollideWith), computes the time until it
// collides with them, resolves the collision, and performs its action when triggered.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/board/board_state.hpp"
#include "gizmo/core/board/event.hpp"
#include "gizmo/core/board/model_rule.hpp"
#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/features.hpp"
#include "gizmo/core/geometry/trajectory.hpp"
#include "gizmo/core/gizmos/property.hpp"

namespace gizmo {

enum class CollisionAnswer { CanCollide, Defer, NeverCollides };

#define GIZMO_KIND_ENUMERATOR(Name, stem) Name,
enum class GizmoKind { Ball, OuterWalls, GIZMO_KINDS(GIZMO_KIND_ENUMERATOR) };
#undef GIZMO_KIND_ENUMERATOR

// The GizmoKind of a gizmo on the grid: both enums follow the kind list, GizmoKind after its two
// kinds of its own.
constexpr GizmoKind gizmoKindOf(GizmoType t) { return GizmoKind(static_cast<int>(t) + 2); }

template <class Real>
class Ball;

// A predicted collision: when, and through which of the collider's features.
template <class Real>
struct Contact {
  Real time{0};  // absolute board time
  std::int32_t feature = -1;
  EventKind kind = EventKind::Collision;
};

// What a gizmo may ask of the board while it handles an event or performs its action.
template <class Real>
class BoardAccess {
 public:
  virtual ~BoardAccess() = default;
  virtual const Real& now() const = 0;
  virtual const PhysicsParams<Real>& params() const = 0;
  virtual Ball<Real>& ballById(GizmoId id) = 0;
  virtual void markForRecompute(GizmoId id) = 0;
  virtual void schedule(EventKind kind, const Real& time, GizmoId a, GizmoId b, std::int32_t feature) = 0;
  virtual void reportRule(ModelRule rule, GizmoId gizmo, GizmoId other) = 0;
  // Many hits at this one instant: balls are jammed between surfaces with no room to move, and
  // hits now leave no rebound along their normal.
  virtual bool jammed() const = 0;
  // Gizmo g starts to move now. Once the event's actions are done, if g is still in motion
  // (inMotionAt), every ball sliding on it leaves that contact and every ball at rest (wedged)
  // beside it wakes, since what g held up it may hold no more. One that was stopped again at
  // this instant never moved, and what rests on it stays: a spinner connected to itself starts
  // and stops at each of its own hits, and a ball wedged on it was woken by every hit and struck
  // again by gravity a nanosecond later, for ever (campaign seed 2536957963, case 65).
  virtual void releaseContactsOn(GizmoId g) = 0;
  // Whether ball `ball` could be put with its centre at p now: inside the walls, clear of every
  // free ball and of the box of every gizmo but `ignore` (boxes, not shapes: a cautious answer).
  virtual bool roomForBall(const Vec2<Real>& p, GizmoId ball, GizmoId ignore) const = 0;
  // Whether a ball centred at p, struck slowly by gizmo `by` along `normal`, lies in a V: `by`
  // and another gizmo are still surfaces it can rest against, the other within a minimum
  // bounce's rise of it (settleRise when both are balls at rest), and gravity is held between
  // the two (geometry/cradle.hpp).
  virtual bool cradled(GizmoId ball, const Vec2<Real>& p, const Vec2<Real>& normal, GizmoId by) const = 0;
  // Whether a ball centred at p has no room along the unit direction m: a line of slow balls
  // ahead of it, each within settleRise of the one before and within 30° of straight ahead along
  // m, ends within settleRise of a still surface (docs/physics.md, "Piles": a row with no room).
  // `behind` is not part of the line (the ball on the other side of the hit).
  virtual bool boxedAlong(GizmoId ball, const Vec2<Real>& p, const Vec2<Real>& m, GizmoId behind) const = 0;
  // Gizmo `target` performs its action now, as a trigger would make it, and the log records it
  // as an action (a gizmo that acts on its own hits, like the spinner).
  virtual void performAction(GizmoId target) = 0;
  // A ball put at rest with its centre at p now, for a spawner: one that a gizmo took
  // out of play for good comes back (handBackRetiredBall below, asked in id order); else a new
  // ball joins the board, unless spawners have added kMaxSpawnedBalls already. Its id, or kNoGizmo when no ball
  // could be had. The caller has checked that p has room.
  virtual GizmoId spawnBall(const Vec2<Real>& p) = 0;
};

template <class Real>
class AbstractGizmo {
 public:
  explicit AbstractGizmo(std::string name) : name_(std::move(name)) {}
  virtual ~AbstractGizmo() = default;
  AbstractGizmo(const AbstractGizmo&) = delete;
  AbstractGizmo& operator=(const AbstractGizmo&) = delete;

  GizmoId id() const { return id_; }
  void setId(GizmoId id) { id_ = id; }  // by the board, when the gizmo joins it
  const std::string& name() const { return name_; }
  void rename(std::string name) { name_ = std::move(name); }

  virtual GizmoKind kind() const = 0;
  virtual Ball<Real>* asBall() { return nullptr; }
  virtual const Ball<Real>* asBall() const { return nullptr; }

  // Seed: can collide (it has a handler for other), defer (other must handle it), or never.
  virtual CollisionAnswer canCollideWith(const AbstractGizmo& other) const = 0;

  // The collider's prediction: the first contact with other in [now, limit], if any.
  virtual std::optional<Contact<Real>> timeUntilCollision(const AbstractGizmo& /*other*/, const Real& /*now*/,
                                                          const Real& /*limit*/,
                                                          const PhysicsParams<Real>& /*params*/) const {
    return std::nullopt;
  }
  // The collider's handler, run at the contact's time.
  virtual void collide(AbstractGizmo& /*other*/, const Contact<Real>& /*contact*/, BoardAccess<Real>& /*board*/) {}

  // Simulates the gizmo for dt; true when its velocity changed (seed: schedule a recomputation).
  virtual bool tick(const Real& /*dt*/, BoardAccess<Real>& /*board*/) { return false; }

  // Whether hits on this gizmo produce a trigger (docs/physics.md §3: all but the ball).
  virtual bool hasTrigger() const { return true; }
  // Seed: the action performed when a trigger connected to this gizmo fires.
  virtual void fireTrigger(BoardAccess<Real>& /*board*/) {}

  // Events of the gizmo's own (a flipper's stop); scheduled whenever it is recomputed.
  virtual void scheduleOwnEvents(BoardAccess<Real>& /*board*/) {}
  virtual void handleOwnEvent(const Event<Real>& /*event*/, BoardAccess<Real>& /*board*/) {}
  // Whether it makes events of kind k that only some kinds make (a flipper's stop, an absorber's
  // leave): what a restored state's queued events are checked against.
  virtual bool makesEventKind(EventKind /*k*/) const { return false; }

  // Until when predictions made now against this gizmo hold (a swinging flipper: until it
  // stops); nullopt for a gizmo that stays as it is.
  virtual std::optional<Real> predictionHorizon() const { return std::nullopt; }
  // Whether it moves with no end in sight (a turning spinner): its predictions hold for ever,
  // yet a ball at rest beside it may still be struck, so the board predicts those pairs too and
  // the gizmo bounds its own search.
  virtual bool movesForEver() const { return false; }
  // Whether it is moving at `now` (a flipper between its stops, a turning spinner): what decides
  // whether its start releases what rests on it (BoardAccess::releaseContactsOn).
  virtual bool inMotionAt(const Real& /*now*/) const { return movesForEver(); }

  // What changes as the board runs (board_state.hpp); gizmos that never change keep nothing.
  // restoreState reads back what saveState wrote and checks the ids it finds.
  virtual void saveState(GizmoState<Real>& /*out*/) const {}
  virtual void restoreState(GizmoStateReader<Real>& /*in*/, const GizmoIdCheck& /*ids*/) {}

  // The surface a ball can lie against now, for the rules that bring a ball to rest in a V: a
  // still shape that only reflects. None for a gizmo that moves, captures, boosts or sends the
  // ball elsewhere, and for a ball.
  virtual const Shape<Real>* restingShape() const { return nullptr; }

  // Where a ball it captured lies (an absorber's lower right corner, a sink's centre), for the
  // pictures; nullopt for a gizmo that captures none.
  virtual std::optional<Vec2<Real>> heldBallPosition() const { return std::nullopt; }
  // Where the balls it spawns appear (a spawner's centre); nullopt for a gizmo that spawns none.
  virtual std::optional<Vec2<Real>> spawnPosition() const { return std::nullopt; }

  // A ball this gizmo took out of play for good (a sink's), the one it took first, handed back to
  // the board to be spawned again: kNoGizmo when it holds none. The gizmo forgets it.
  virtual GizmoId handBackRetiredBall() { return kNoGizmo; }

  // Everything the gizmo can ever touch, for the broad phase.
  virtual Box<Real> bounds() const = 0;

  // The gizmo as plain data (for writing boards and for the property system's checks).
  virtual GizmoSpec spec() const = 0;

  // The property system: typed values readable and writable by name.
  virtual std::vector<std::string> propertyNames() const = 0;
  virtual std::optional<PropertyValue> property(std::string_view name) const = 0;
  // Applies a value without checking it against the rest of the board (GameBoard does that).
  virtual bool setPropertyUnchecked(std::string_view name, const PropertyValue& value) = 0;

 private:
  std::string name_;
  GizmoId id_ = kNoGizmo;
};

}  // namespace gizmo
