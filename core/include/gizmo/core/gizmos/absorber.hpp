#pragma once
// The absorber (docs/physics.md §2): a rectangle that captures balls instead of reflecting
// them, holds them at its lower-right corner, and fires the first one it captured when triggered.
#include <algorithm>
#include <array>
#include <deque>

#include "gizmo/core/gizmos/polygonal_gizmo.hpp"

namespace gizmo {

// The absorber's rules (model_rule.hpp): their codes are in logs.
struct AbsorberRule {
  static constexpr ModelRule Captured{6};  // it captured a ball
  static constexpr ModelRule Released{7};  // it fired a ball
};

template <class Real>
class Absorber final : public GridBumper<Real> {
 public:
  explicit Absorber(const GizmoSpec& spec) : GridBumper<Real>(spec) {}

  GizmoKind kind() const override { return GizmoKind::Absorber; }
  // It does more than reflect (it captures): no ball rests against it.
  const Shape<Real>* restingShape() const override { return nullptr; }

  Vec2<Real> holdPosition() const {
    const GizmoSpec s = this->spec();
    const Real r = Ball<Real>::radius();
    return Vec2<Real>(Real(s.x + s.width) - r, Real(s.y + s.height) - r);
  }
  std::optional<Vec2<Real>> heldBallPosition() const override { return holdPosition(); }
  bool makesEventKind(EventKind k) const override { return k == EventKind::Leave; }
  static Vec2<Real> fireVelocity() { return Vec2<Real>(Real(0), Real(-50)); }

  const std::deque<GizmoId>& held() const { return held_; }
  const std::vector<GizmoId>& firedStillInside() const { return firedInside_; }

  // A ball placed at rest inside the absorber by a board file is held from time 0.
  void holdAtStart(Ball<Real>& ball, const Real& now) {
    ball.capture(now, holdPosition());
    held_.push_back(ball.id());
  }

  std::optional<Contact<Real>> timeUntilCollision(const AbstractGizmo<Real>& other, const Real& now, const Real& limit,
                                                  const PhysicsParams<Real>& params) const override {
    const Ball<Real>* ball = other.asBall();
    if (!ball || ball->captured()) return std::nullopt;
    if (firedAndInside(*ball, now)) return leaveTime(*ball, now, limit);
    return GridBumper<Real>::timeUntilCollision(other, now, limit, params);
  }

  void collide(AbstractGizmo<Real>& other, const Contact<Real>& contact, BoardAccess<Real>& board) override {
    std::erase(firedInside_, other.id());  // left, or came back from outside (below)
    if (contact.kind == EventKind::Leave) return;
    GridBumper<Real>::collide(other, contact, board);
  }

  // Seed: fireTrigger. Fires the first held ball unless one it fired is still inside.
  void fireTrigger(BoardAccess<Real>& board) override {
    if (held_.empty()) return;
    for (const GizmoId fired : firedInside_)
      if (firedAndInside(board.ballById(fired), board.now())) return;
    firedInside_.clear();
    const GizmoId id = held_.front();
    held_.pop_front();
    Ball<Real>& ball = board.ballById(id);
    ball.release(board.now(), holdPosition(), fireVelocity(), board.params());
    firedInside_.push_back(id);
    board.reportRule(AbsorberRule::Released, this->id(), id);
    board.markForRecompute(id);
    board.markForRecompute(this->id());
  }

  void saveState(GizmoState<Real>& out) const override {
    out.ints.push_back(std::int64_t(held_.size()));
    out.ints.insert(out.ints.end(), held_.begin(), held_.end());
    out.ints.push_back(std::int64_t(firedInside_.size()));
    out.ints.insert(out.ints.end(), firedInside_.begin(), firedInside_.end());
  }

  void restoreState(GizmoStateReader<Real>& in, const GizmoIdCheck& ids) override {
    auto readBalls = [&](auto& into) {
      into.clear();
      const std::int64_t n = in.integer(0, 1 << 20);
      for (std::int64_t k = 0; k < n; ++k) {
        const std::int64_t ball = in.integer();
        if (!ids.isBall(ball)) throw StateError("absorber: holds something that is not a ball");
        into.push_back(static_cast<GizmoId>(ball));
      }
    };
    readBalls(held_);
    readBalls(firedInside_);
  }

 protected:
  void respond(Ball<Real>& ball, const Contact<Real>&, BoardAccess<Real>& board) override {
    ball.capture(board.now(), holdPosition());
    held_.push_back(ball.id());
    board.reportRule(AbsorberRule::Captured, this->id(), ball.id());
  }

 private:
  // Whether a ball is one it fired that has not left: in its list, free, and with its centre
  // within the rectangle grown by the ball's radius (leaveTime's) and kFiredSlack, unless it lies
  // within kFiredSlack of a side's line moving in across it. A fired ball can go without crossing
  // a side: a teleporter at the absorber's edge moves it elsewhere, a sink or another absorber
  // takes it. It is then out, and meets this absorber as any ball does: it is captured if it comes
  // back. Counted inside, it would stop the absorber firing for as long as it stayed away, and its
  // "leave" would be found where its path crosses a side's line far from the rectangle, by
  // whichever prediction happened to look that far. The slack: rounding may put a ball on a side's
  // line an ulp either side of it, and one motion model's run not the other's. On the line, a
  // ball moving out is leaving (its Leave comes at once), and one moving in is coming in: one that
  // a hit turns back at the instant it would have left, or one that went without crossing a side
  // and comes back. Counted inside, the second passed into the absorber uncaptured when a
  // prediction met it 1.6e-14 L above the top (campaign seed 1796537443, case 806).
  bool firedAndInside(const Ball<Real>& ball, const Real& now) const {
    if (ball.captured() || std::find(firedInside_.begin(), firedInside_.end(), ball.id()) == firedInside_.end())
      return false;
    const GizmoSpec s = this->spec();
    const Real r = Ball<Real>::radius(), slack = fromDouble<Real>(kFiredSlack);
    const Trajectory<Real> t = ball.trajectoryAt(now);
    // Each grown side: how far the centre lies inside its line, and its speed inwards across it.
    const std::array<std::array<Real, 2>, 4> sides{{
        {t.p.x - (Real(s.x) - r), t.v.x},
        {Real(s.x + s.width) + r - t.p.x, -t.v.x},
        {t.p.y - (Real(s.y) - r), t.v.y},
        {Real(s.y + s.height) + r - t.p.y, -t.v.y},
    }};
    for (const auto& [inside, inwards] : sides)
      if (inside < -slack || (!(slack < inside) && Real(0) < inwards)) return false;
    return true;
  }

  // When a ball it fired stops overlapping the rectangle. The rectangle grown by the ball's
  // radius stands in for the exact rounded one: the ball counts as gone a little later at
  // the corners, never earlier.
  std::optional<Contact<Real>> leaveTime(const Ball<Real>& ball, const Real& now, const Real& limit) const {
    const GizmoSpec s = this->spec();
    const Real r = Ball<Real>::radius();
    const Trajectory<Real> t = ball.trajectoryAt(now);
    const Real half = Real(1) / Real(2);
    // Each gap reaches zero as the centre crosses one grown side outwards.
    const std::array<std::array<Real, 5>, 4> gaps{{
        {t.p.y - (Real(s.y) - r), t.v.y, half * t.a.y, Real(0), Real(0)},
        {Real(s.y + s.height) + r - t.p.y, -t.v.y, -half * t.a.y, Real(0), Real(0)},
        {t.p.x - (Real(s.x) - r), t.v.x, half * t.a.x, Real(0), Real(0)},
        {Real(s.x + s.width) + r - t.p.x, -t.v.x, -half * t.a.x, Real(0), Real(0)},
    }};
    std::optional<Real> best;
    for (const auto& c : gaps) {
      const std::optional<Real> tau = math::firstEntry(c, Real(0), limit - now, [](const Real&) { return true; });
      if (tau && (!best || *tau < *best)) best = tau;
    }
    if (!best) return std::nullopt;
    return Contact<Real>{now + *best, 0, EventKind::Leave};
  }

  static constexpr double kFiredSlack = 1e-6;  // L; far above rounding, far below any path a ball takes

  std::deque<GizmoId> held_;
  std::vector<GizmoId> firedInside_;
};

}  // namespace gizmo
