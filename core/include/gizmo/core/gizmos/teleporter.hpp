#pragma once
// The teleporter (docs/physics.md, "Gizmos other programs added"), d-g-n/CS308-GizmoBall's
// addition: a disc of radius 0.5 in its cell. `Connect A B` from a teleporter to a teleporter
// makes B the exit of A (the first such connection counts). A ball that comes into A leaves B
// keeping its velocity, at the point opposite the one where it touched A: as if it had passed
// through A's disc and come out of B's. Where that point has no room for the ball (a wall, a
// gizmo's box or another ball in the way), or A has no exit, A is a circle bumper.
// The portal, rgallagher27/308gizmoball's addition (`Portal NAME X Y EXITX EXITY`), is the same
// disc with its exit given by the board file as a cell rather than a gizmo: a ball leaves it as
// it would leave a teleporter standing in that cell.
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"

namespace gizmo {

// The rule of the teleporter and the portal (model_rule.hpp): its code is in logs.
struct TeleporterRule {
  static constexpr ModelRule Teleported{10};  // it moved a ball to its exit
};

template <class Real>
class Teleporter final : public GridBumper<Real> {
 public:
  explicit Teleporter(const GizmoSpec& spec) : GridBumper<Real>(spec) {
    if (spec.type == GizmoType::Portal) {
      const Real half = Real(1) / Real(2);
      exitCentre_ = Vec2<Real>(Real(spec.exitX) + half, Real(spec.exitY) + half);
    }
  }

  // It does more than reflect (it teleports): no ball rests against it.
  const Shape<Real>* restingShape() const override { return nullptr; }

  // Set by the board builder from the connections: the exit and its centre.
  void setExit(GizmoId exit, const Vec2<Real>& centre) {
    exit_ = exit;
    exitCentre_ = centre;
  }
  // The teleporter this one leads to; none for a portal, whose exit is a cell.
  std::optional<GizmoId> exit() const { return exit_; }
  bool hasExit() const { return exitCentre_.has_value(); }

  // Where a ball whose centre is at p, touching this teleporter, comes out of the exit: the
  // point opposite p through the exit's centre. Exact where the scalar holds the sums exactly.
  Vec2<Real> exitPosition(const Vec2<Real>& p) const { return *exitCentre_ - (p - this->centre()); }

 protected:
  void respond(Ball<Real>& ball, const Contact<Real>& contact, BoardAccess<Real>& board) override {
    const Real& now = board.now();
    const Vec2<Real> p = ball.positionAt(now), v = ball.velocityAt(now);
    // Only a ball coming in passes: one that merely touches the disc bounces off it.
    if (exitCentre_ && dot(v, Vec2<Real>(p - this->centre())) < Real(0)) {
      const Vec2<Real> q = exitPosition(p);
      if (board.roomForBall(q, ball.id(), exit_.value_or(kNoGizmo))) {
        board.reportRule(TeleporterRule::Teleported, this->id(), ball.id());
        ball.leaveContact(board);
        ball.setState(now, q, v, board.params());
        return;
      }
    }
    GridBumper<Real>::respond(ball, contact, board);
  }

 private:
  std::optional<GizmoId> exit_;
  std::optional<Vec2<Real>> exitCentre_;
};

}  // namespace gizmo
