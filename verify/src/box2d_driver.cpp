#include "box2d_driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/verify/box2d_board_access.hpp"
#include "gizmo/verify/box2d_mapping.hpp"

namespace gizmo::verify {
namespace {

class Driver {
 public:
  Driver(const RunRequest& request, double dt, SteppedEngine& engine)
      : request_(request),
        dt_(dt),
        engine_(engine),
        shadow_(buildBoard<double>(request.board, paramsFor<double>(request))),
        access_(shadow_->params(), [this](GizmoId id) -> Ball<double>& { return shadow_->ballById(id); }) {
    bodies_.push_back(idOf(kOuterWallsName));
    for (const GizmoSpec& g : request.board.gizmos) {
      bodies_.push_back(idOf(g.name));
      if (swings(g.type)) flippers_.push_back(bodies_.size() - 1);
      if (turns(g.type)) spinners_.push_back(bodies_.size() - 1);
    }
    for (const BallSpec& b : request.board.balls) {
      balls_.push_back(idOf(b.name));
      // A ball an absorber holds from the start sits at its hold position, out of the world.
      const Ball<double>& ball = shadow_->ballById(balls_.back());
      if (ball.captured()) engine_.hold(balls_.size() - 1, ball.positionAt(0));
    }
    for (const ConnectSpec& c : request.board.connections) triggers_[idOf(c.source)].push_back(idOf(c.target));
    keys_ = request.keys;
    std::stable_sort(keys_.begin(), keys_.end(), [](const TimedKey& a, const TimedKey& b) { return a.time < b.time; });
  }

  RunRecord run() {
    RunRecord record;
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t steps = static_cast<std::uint64_t>(std::ceil(request_.duration / dt_ - 1e-9));
    record.samples.push_back(sample(0));
    std::size_t nextKey = 0;
    for (std::uint64_t k = 0; k < steps; ++k) {
      const double t0 = double(k) * dt_, t1 = double(k + 1) * dt_;
      // Key input at its own time: the flippers it starts are on schedule again by t1.
      for (; nextKey < keys_.size() && keys_[nextKey].time < t1 && keys_[nextKey].time <= request_.duration; ++nextKey)
        for (const KeyConnectSpec& kc : request_.board.keyConnections)
          if (kc.key == keys_[nextKey].key && kc.direction == keys_[nextKey].direction)
            performAction(idOf(kc.target), keys_[nextKey].time);
      const double pi = piOf<double>();
      // Every flipper turns at the rate that brings it to the schedule's angle at t1 (never a
      // half turn in a step: the difference is taken the short way round).
      for (std::size_t f : flippers_)
        engine_.turn(f, std::remainder(flipperAngle(bodies_[f], t1) - engine_.angle(f), 2 * pi));
      // A spinner turns on the core's schedule too: to where the shadow spinner stands at t1. The
      // cross looks the same a quarter turn on, so the turn is taken the short way round modulo
      // a quarter (a body's angle counts on, the core's restarts every whole turn).
      for (std::size_t sp : spinners_) {
        const auto& spinner = dynamic_cast<const Spinner<double>&>(shadow_->gizmo(bodies_[sp]));
        const double quarter = pi / 2;
        double turn = spinner.angleAt(t1) - engine_.angle(sp);
        turn -= quarter * std::round(turn / quarter);
        engine_.turn(sp, turn);
      }
      // The Gizmoball friction law, before Box2D adds gravity (docs/physics.md §4).
      for (std::size_t i = 0; i < balls_.size(); ++i) {
        const EngineBall b = engine_.ball(i);
        if (!b.held) engine_.setVelocity(i, Ball<double>::frictionApplied(b.velocity, dt_, shadow_->params()));
      }
      const EngineStep step = engine_.step(t0, dt_);
      record.speedCappedSteps += step.speedCapped;
      record.rotationCappedSteps += step.rotationCapped;
      for (const EngineContact& c : step.contacts) handle(c, record);
      record.samples.push_back(sample(t1));
    }
    record.steps = steps;
    record.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::erase_if(record.collisions, [&](const CollisionRecord& c) { return c.time > request_.duration; });
    std::stable_sort(record.collisions.begin(), record.collisions.end(),
                     [](const CollisionRecord& a, const CollisionRecord& b) { return a.time < b.time; });
    return record;
  }

 private:
  GizmoId idOf(const std::string& name) const {
    const std::optional<GizmoId> id = shadow_->find(name);
    if (!id) throw std::invalid_argument("board names an unknown gizmo '" + name + "'");
    return *id;
  }

  const std::string& ballName(std::size_t i) const { return request_.board.balls[i].name; }

  void handle(const EngineContact& c, RunRecord& record) {
    Ball<double>& shadowBall = shadow_->ballById(balls_[c.ball]);
    if (c.kind == EngineContact::Kind::Hit) {
      if (c.otherIsBall) {
        CollisionRecord hit = collisionRecord(c.time, ballName(c.ball), ballName(c.other), true);
        hit.position = c.position;
        record.collisions.push_back(std::move(hit));
        return;
      }
      const GizmoId other = bodies_[c.other];
      CollisionRecord hit = collisionRecord(c.time, ballName(c.ball), shadow_->gizmo(other).name(), false);
      hit.position = c.position;
      record.collisions.push_back(std::move(hit));
      // NiklavsM's spinner acts on its own hits (Spinner::collide): it starts or stops.
      if (dynamic_cast<const Spinner<double>*>(&shadow_->gizmo(other))) performAction(other, c.time);
      fireTriggersOf(other, c.time);
      return;
    }
    const GizmoId other = bodies_[c.other];
    auto& absorber = dynamic_cast<Absorber<double>&>(shadow_->gizmo(other));
    const auto& fired = absorber.firedStillInside();
    const bool ownShot = std::find(fired.begin(), fired.end(), balls_[c.ball]) != fired.end();
    access_.setNow(c.time);
    if (c.kind == EngineContact::Kind::Exit) {
      // A ball it fired has left its rectangle: from now on it captures that ball again.
      if (ownShot) absorber.collide(shadowBall, Contact<double>{c.time, 0, EventKind::Leave}, access_);
      return;
    }
    const EngineBall now = engine_.ball(c.ball);
    if (ownShot || shadowBall.captured() || now.held) return;
    shadowBall.setState(c.time, c.position, now.velocity, shadow_->params());
    absorber.collide(shadowBall, Contact<double>{c.time, 0, EventKind::Collision}, access_);  // the core captures
    record.collisions.push_back(CollisionRecord{c.time, ballName(c.ball), absorber.name(), c.position});
    engine_.hold(c.ball, shadowBall.positionAt(c.time));
    fireTriggersOf(other, c.time);
  }

  void fireTriggersOf(GizmoId source, double time) {
    const auto it = triggers_.find(source);
    if (it == triggers_.end()) return;
    for (GizmoId target : it->second) performAction(target, time);
  }

  // The target's action, by the core's own gizmo; the engine's bodies then follow it.
  void performAction(GizmoId target, double time) {
    AbstractGizmo<double>& gizmo = shadow_->gizmo(target);
    if (auto* flipper = dynamic_cast<Flipper<double>*>(&gizmo)) {
      settleStop(*flipper, time);
      access_.setNow(time);
      flipper->fireTrigger(access_);
      return;
    }
    std::vector<bool> heldBefore;
    for (GizmoId b : balls_) heldBefore.push_back(shadow_->ballById(b).captured());
    access_.setNow(time);
    gizmo.fireTrigger(access_);
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      const Ball<double>& released = shadow_->ballById(balls_[i]);
      if (heldBefore[i] && !released.captured())
        engine_.release(i, released.positionAt(time), released.velocityAt(time));
    }
  }

  // A swing that ended by `time` stops at its end (the core's flipper-stop event, run late).
  void settleStop(Flipper<double>& flipper, double time) {
    if (!flipper.swinging() || time < flipper.stopTime()) return;
    access_.setNow(flipper.stopTime());
    Event<double> stop;
    stop.kind = EventKind::FlipperStop;
    stop.a = flipper.id();
    flipper.handleOwnEvent(stop, access_);
  }

  // The flipper's angle at `time` on the core's swing schedule.
  double flipperAngle(GizmoId id, double time) {
    auto& flipper = dynamic_cast<Flipper<double>&>(shadow_->gizmo(id));
    settleStop(flipper, time);
    const GizmoSpec s = flipper.spec();
    const FlipperLayout f = flipperLayout(s.type, s.orientation);
    const double progress = std::clamp(flipper.progressAt(time), 0.0, Flipper<double>::swingTime());
    return f.restQuarter * (piOf<double>() / 2) + f.forwardSign * 6 * piOf<double>() * progress;
  }

  TrajectorySample sample(double time) const {
    TrajectorySample s;
    s.time = time;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      const EngineBall b = engine_.ball(i);
      s.positions.push_back(b.position);
      if (!b.held) s.energy += 0.5 * lengthSquared(b.velocity) + request_.board.gravity * (kBoardSize - b.position.y);
    }
    return s;
  }

  const RunRequest& request_;
  double dt_;
  SteppedEngine& engine_;
  std::unique_ptr<GameBoard<double>> shadow_;  // the core's gizmos, never ticked: their rules only
  DrivenBoardAccess access_;
  std::vector<GizmoId> bodies_, balls_;           // the engine's bodies and balls in the shadow board
  std::vector<std::size_t> flippers_, spinners_;  // engine body numbers
  std::map<GizmoId, std::vector<GizmoId>> triggers_;
  std::vector<TimedKey> keys_;
};

}  // namespace

RunRecord driveBox2dRun(const RunRequest& request, double dt, SteppedEngine& engine) {
  Driver driver(request, dt, engine);
  return driver.run();
}

}  // namespace gizmo::verify
