#include "gizmo/verify/box2d_world.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/verify/box2d_board_access.hpp"
#include "gizmo/verify/box2d_shapes.hpp"

namespace gizmo::verify {
namespace {

// What the bridge knows of each Box2D body; a fixture's user data is its index here.
struct BodyInfo {
  GizmoId id = kNoGizmo;  // in the shadow board
  std::string name;
  bool ball = false;
  bool sensor = false;
  double restitution = 1;
  b2Body* body = nullptr;
};

// Something a contact callback saw during a step, handled once the step is over (Box2D's world
// is locked inside the callbacks).
struct ContactNote {
  enum class Kind { Hit, Enter, Exit } kind;
  std::size_t ball, other;  // BodyInfo indices
  double time;
  Vec2<double> position;
};

class Box2dBridge final : public b2ContactListener {
 public:
  Box2dBridge(const RunRequest& request, const Box2dOptions& options)
      : request_(request),
        options_(options),
        shadow_(buildBoard<double>(request.board, paramsFor<double>(request))),
        access_(shadow_->params(), [this](GizmoId id) -> Ball<double>& { return shadow_->ballById(id); }),
        world_(b2Vec2(0, static_cast<float>(request.board.gravity))) {
    world_.SetAllowSleeping(false);  // a Gizmoball never sleeps
    world_.SetContinuousPhysics(options.continuous);
    world_.SetContactListener(this);
    addBody(box2dOuterWalls());
    for (const GizmoSpec& g : request.board.gizmos) {
      const std::size_t index = addBody(box2dBodyOf(g));
      if (isFlipper(g.type)) flippers_.push_back(index);
      if (g.type == GizmoType::Spinner) spinners_.push_back(index);
    }
    for (const BallSpec& b : request.board.balls) addBall(b);
    for (const ConnectSpec& c : request.board.connections) triggers_[idOf(c.source)].push_back(idOf(c.target));
    keys_ = request.keys;
    std::stable_sort(keys_.begin(), keys_.end(), [](const TimedKey& a, const TimedKey& b) { return a.time < b.time; });
  }

  RunRecord run() {
    RunRecord record;
    const auto start = std::chrono::steady_clock::now();
    const double dt = options_.dt;
    const std::uint64_t steps = static_cast<std::uint64_t>(std::ceil(request_.duration / dt - 1e-9));
    record.samples.push_back(sample(0));
    std::size_t nextKey = 0;
    for (std::uint64_t k = 0; k < steps; ++k) {
      const double t0 = double(k) * dt, t1 = double(k + 1) * dt;
      // Key input at its own time: the flippers it starts are on schedule again by t1.
      for (; nextKey < keys_.size() && keys_[nextKey].time < t1 && keys_[nextKey].time <= request_.duration; ++nextKey)
        for (const KeyConnectSpec& kc : request_.board.keyConnections)
          if (kc.key == keys_[nextKey].key && kc.direction == keys_[nextKey].direction)
            performAction(idOf(kc.target), keys_[nextKey].time);
      bool rotationCapped = false;
      for (std::size_t f : flippers_) {
        b2Body* body = bodies_[f].body;
        const double turn = flipperAngle(bodies_[f].id, t1) - body->GetAngle();
        rotationCapped = rotationCapped || std::fabs(turn) > kBox2dMaxRotation * (1 + 1e-5);
        body->SetAngularVelocity(static_cast<float>(turn / dt));
      }
      // A spinner turns on the core's schedule too: to where the shadow spinner stands at t1. The
      // cross looks the same a quarter turn on, so the turn is taken the short way round modulo
      // a quarter (a body's angle counts on, the core's restarts every whole turn).
      for (std::size_t sp : spinners_) {
        b2Body* body = bodies_[sp].body;
        const auto& spinner = dynamic_cast<const Spinner<double>&>(shadow_->gizmo(bodies_[sp].id));
        const double quarter = piOf<double>() / 2;
        double turn = spinner.angleAt(t1) - body->GetAngle();
        turn -= quarter * std::round(turn / quarter);
        rotationCapped = rotationCapped || std::fabs(turn) > kBox2dMaxRotation * (1 + 1e-5);
        body->SetAngularVelocity(static_cast<float>(turn / dt));
      }
      bool speedCapped = false;
      const Vec2<double> g(0, request_.board.gravity);
      for (std::size_t i = 0; i < ballBodies_.size(); ++i) {
        b2Body* body = bodies_[ballBodies_[i]].body;
        if (!body->IsEnabled()) continue;
        // The Gizmoball friction law, before Box2D adds gravity (docs/physics.md §4).
        const Vec2<double> v = Ball<double>::frictionApplied(fromBox2d(body->GetLinearVelocity()), dt, shadow_->params());
        body->SetLinearVelocity(toBox2d(v));
        // Box2D scales such a velocity down for good (b2Island::Solve); the margin keeps a ball
        // already scaled to the cap, give or take float rounding, from counting again.
        speedCapped = speedCapped || length(v) * dt > kBox2dMaxTranslation * (1 + 1e-5);
        stepFrom_[i] = fromBox2d(body->GetPosition());
        stepTo_[i] = stepFrom_[i] + dt * (v + dt * g);  // where Box2D's integrator takes it, unhindered
      }
      record.speedCappedSteps += speedCapped;
      record.rotationCappedSteps += rotationCapped;
      stepStart_ = t0;
      stepIndex_ = k;
      world_.Step(static_cast<float>(dt), options_.velocityIterations, options_.positionIterations);
      handleNotes(record);
      record.samples.push_back(sample(t1));
    }
    record.steps = steps;
    record.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::erase_if(record.collisions, [&](const CollisionRecord& c) { return c.time > request_.duration; });
    return record;
  }

  // --- Box2D's callbacks ------------------------------------------------------------------------
  void BeginContact(b2Contact* contact) override { note(contact, +1); }
  void EndContact(b2Contact* contact) override { note(contact, -1); }

  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    const BodyInfo& a = infoOf(contact->GetFixtureA());
    const BodyInfo& b = infoOf(contact->GetFixtureB());
    // Two balls: elastic; a ball and a gizmo: the gizmo's coefficient.
    contact->SetRestitution(static_cast<float>(a.ball && b.ball ? 1.0 : a.ball ? b.restitution : a.restitution));
    contact->SetRestitutionThreshold(static_cast<float>(options_.restitutionThreshold));
  }

 private:
  GizmoId idOf(const std::string& name) const {
    const std::optional<GizmoId> id = shadow_->find(name);
    if (!id) throw std::invalid_argument("board names an unknown gizmo '" + name + "'");
    return *id;
  }

  std::size_t addBody(const Box2dBody& spec) {
    b2BodyDef def;
    def.type = spec.kinematic ? b2_kinematicBody : b2_staticBody;
    def.position = toBox2d(spec.origin);
    def.angle = static_cast<float>(spec.angle);
    BodyInfo info;
    info.id = idOf(spec.name);
    info.name = spec.name;
    info.sensor = spec.sensor;
    info.restitution = spec.restitution;
    info.body = world_.CreateBody(&def);
    for (const Box2dPart& part : spec.parts) addFixture(info.body, *makeBox2dShape(part), spec.sensor);
    bodies_.push_back(info);
    return bodies_.size() - 1;
  }

  void addFixture(b2Body* body, const b2Shape& shape, bool sensor) {
    b2FixtureDef def;
    def.shape = &shape;
    def.density = 1;
    def.friction = 0;  // Box2D's Coulomb friction off: the Gizmoball law is applied each step
    def.restitution = 0;  // set per contact in PreSolve
    def.restitutionThreshold = static_cast<float>(options_.restitutionThreshold);
    def.isSensor = sensor;
    def.userData.pointer = bodies_.size();  // the index the body's info gets
    body->CreateFixture(&def);
  }

  void addBall(const BallSpec& spec) {
    const GizmoId id = idOf(spec.name);
    const Ball<double>& shadowBall = shadow_->ballById(id);
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.bullet = options_.bullet;
    def.fixedRotation = true;
    def.position = toBox2d(shadowBall.positionAt(0));  // a ball held from time 0 sits at the hold position
    def.linearVelocity = toBox2d(shadowBall.velocityAt(0));
    def.enabled = !shadowBall.captured();
    BodyInfo info;
    info.id = id;
    info.name = spec.name;
    info.ball = true;
    info.body = world_.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(kBallRadius);
    addFixture(info.body, circle, false);
    bodies_.push_back(info);
    ballBodies_.push_back(bodies_.size() - 1);
    stepFrom_.emplace_back();
    stepTo_.emplace_back();
  }

  const BodyInfo& infoOf(b2Fixture* f) const { return bodies_.at(f->GetUserData().pointer); }

  // The time of a contact seen during the current step: Box2D moves a ball in a straight line
  // over a step, and its time of impact stops it part way, so the fraction of the way it got
  // is the fraction of the step (0 for contacts found at the start of the step).
  double contactTime(std::size_t ballIndex, const Vec2<double>& p) const {
    const std::size_t i = ballSlot(ballIndex);
    const Vec2<double> path = stepTo_[i] - stepFrom_[i];
    const double l2 = lengthSquared(path);
    const double alpha = l2 > 0 ? std::clamp(dot(p - stepFrom_[i], path) / l2, 0.0, 1.0) : 0.0;
    return stepStart_ + alpha * options_.dt;
  }

  std::size_t ballSlot(std::size_t bodyIndex) const {
    return static_cast<std::size_t>(std::find(ballBodies_.begin(), ballBodies_.end(), bodyIndex) - ballBodies_.begin());
  }

  // A contact that begins is a hit when the ball approaches the other body there faster than
  // the core's rest speed (a ball sliding along a wall touches it again and again in Box2D
  // without ever approaching: docs/physics.md §5 gives no collision for that), and the first of its
  // pair in this step (a flipper's three fixtures, or two wall edges, met at once are one hit).
  // An absorber's sensor counts its touching contacts instead: the ball enters and leaves.
  void note(b2Contact* contact, int change) {
    std::size_t a = contact->GetFixtureA()->GetUserData().pointer, b = contact->GetFixtureB()->GetUserData().pointer;
    if (!bodies_[a].ball) std::swap(a, b);
    if (!bodies_[a].ball) return;
    if (bodies_[b].ball && b < a) std::swap(a, b);
    const Vec2<double> p = fromBox2d(bodies_[a].body->GetPosition());
    if (bodies_[b].sensor) {
      int& count = touching_[{a, b}];
      count += change;
      if (muted_ || !((change > 0 && count == 1) || (change < 0 && count == 0))) return;
      notes_.push_back(ContactNote{change > 0 ? ContactNote::Kind::Enter : ContactNote::Kind::Exit, a, b, contactTime(a, p), p});
      return;
    }
    if (change < 0 || muted_ || !approaching(contact, a, b)) return;
    std::uint64_t& last = lastHitStep_[{a, b}];
    if (last == stepIndex_ + 1) return;
    last = stepIndex_ + 1;
    notes_.push_back(ContactNote{ContactNote::Kind::Hit, a, b, contactTime(a, p), p});
  }

  bool approaching(b2Contact* contact, std::size_t ball, std::size_t other) const {
    if (contact->GetManifold()->pointCount == 0) return false;
    b2WorldManifold m;
    contact->GetWorldManifold(&m);
    // The manifold's normal points from fixture A to fixture B: turn it towards the ball.
    const bool ballIsA = contact->GetFixtureA()->GetUserData().pointer == ball;
    const Vec2<double> n = (ballIsA ? -1.0 : 1.0) * fromBox2d(m.normal);
    const b2Vec2 at = m.points[0];
    const Vec2<double> relative = fromBox2d(bodies_[ball].body->GetLinearVelocityFromWorldPoint(at)) -
                                  fromBox2d(bodies_[other].body->GetLinearVelocityFromWorldPoint(at));
    return dot(relative, n) < -shadow_->params().restSpeed;
  }

  void handleNotes(RunRecord& record) {
    // Handling a note can disable a body, whose contacts then end and add notes: take turns.
    while (!notes_.empty()) {
      std::vector<ContactNote> notes;
      notes.swap(notes_);
      for (const ContactNote& n : notes) handle(n, record);
    }
  }

  void handle(const ContactNote& n, RunRecord& record) {
    BodyInfo& ball = bodies_[n.ball];
    const BodyInfo& other = bodies_[n.other];
    Ball<double>& shadowBall = shadow_->ballById(ball.id);
    if (n.kind == ContactNote::Kind::Hit) {
      CollisionRecord hit = collisionRecord(n.time, ball.name, other.name, other.ball);
      hit.position = n.position;
      record.collisions.push_back(std::move(hit));
      if (other.ball) return;
      // NiklavsM's spinner acts on its own hits (Spinner::collide): it starts or stops.
      if (dynamic_cast<const Spinner<double>*>(&shadow_->gizmo(other.id))) performAction(other.id, n.time);
      fireTriggersOf(other.id, n.time);
      return;
    }
    auto& absorber = dynamic_cast<Absorber<double>&>(shadow_->gizmo(other.id));
    const auto& fired = absorber.firedStillInside();
    const bool ownShot = std::find(fired.begin(), fired.end(), ball.id) != fired.end();
    access_.setNow(n.time);
    if (n.kind == ContactNote::Kind::Exit) {
      // A ball it fired has left its rectangle: from now on it captures that ball again.
      if (ownShot) absorber.collide(shadowBall, Contact<double>{n.time, 0, EventKind::Leave}, access_);
      return;
    }
    if (ownShot || shadowBall.captured() || !ball.body->IsEnabled()) return;
    shadowBall.setState(n.time, n.position, fromBox2d(ball.body->GetLinearVelocity()), shadow_->params());
    absorber.collide(shadowBall, Contact<double>{n.time, 0, EventKind::Collision}, access_);  // the core captures
    record.collisions.push_back(CollisionRecord{n.time, ball.name, other.name, n.position});
    // Disabling the body ends its contacts at once; those ends are the bridge's doing, not the
    // ball leaving anything (else the absorber would take its own capture for a departure).
    muted_ = true;
    ball.body->SetEnabled(false);
    muted_ = false;
    ball.body->SetTransform(toBox2d(shadowBall.positionAt(n.time)), 0);
    fireTriggersOf(other.id, n.time);
  }

  void fireTriggersOf(GizmoId source, double time) {
    const auto it = triggers_.find(source);
    if (it == triggers_.end()) return;
    for (GizmoId target : it->second) performAction(target, time);
  }

  // The target's action, by the core's own gizmo; the bridge then moves Box2D's bodies to match.
  void performAction(GizmoId target, double time) {
    AbstractGizmo<double>& gizmo = shadow_->gizmo(target);
    if (auto* flipper = dynamic_cast<Flipper<double>*>(&gizmo)) {
      settleStop(*flipper, time);
      access_.setNow(time);
      flipper->fireTrigger(access_);
      return;
    }
    std::vector<bool> heldBefore;
    for (std::size_t b : ballBodies_) heldBefore.push_back(shadow_->ballById(bodies_[b].id).captured());
    access_.setNow(time);
    gizmo.fireTrigger(access_);
    for (std::size_t i = 0; i < ballBodies_.size(); ++i) {
      const Ball<double>& released = shadow_->ballById(bodies_[ballBodies_[i]].id);
      if (!heldBefore[i] || released.captured()) continue;
      b2Body* body = bodies_[ballBodies_[i]].body;
      body->SetEnabled(true);
      body->SetTransform(toBox2d(released.positionAt(time)), 0);
      body->SetLinearVelocity(toBox2d(released.velocityAt(time)));
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
    for (std::size_t b : ballBodies_) {
      const b2Body* body = bodies_[b].body;
      const Vec2<double> p = fromBox2d(body->GetPosition()), v = fromBox2d(body->GetLinearVelocity());
      s.positions.push_back(p);
      if (body->IsEnabled()) s.energy += 0.5 * lengthSquared(v) + request_.board.gravity * (kBoardSize - p.y);
    }
    return s;
  }

  const RunRequest& request_;
  Box2dOptions options_;
  std::unique_ptr<GameBoard<double>> shadow_;  // the core's gizmos, never ticked: their rules only
  DrivenBoardAccess access_;
  b2World world_;
  std::vector<BodyInfo> bodies_;
  std::vector<std::size_t> flippers_, spinners_, ballBodies_;
  std::map<GizmoId, std::vector<GizmoId>> triggers_;
  std::vector<TimedKey> keys_;
  std::map<std::pair<std::size_t, std::size_t>, int> touching_;
  std::vector<ContactNote> notes_;
  std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> lastHitStep_;  // step index + 1 of the pair's last hit
  bool muted_ = false;
  std::uint64_t stepIndex_ = 0;
  double stepStart_ = 0;
  std::vector<Vec2<double>> stepFrom_, stepTo_;  // per ball, over the current step
};

}  // namespace

CollisionRecord collisionRecord(double time, std::string ball, std::string other, bool otherIsBall) {
  if (otherIsBall && other < ball) std::swap(ball, other);
  return CollisionRecord{time, std::move(ball), std::move(other), Vec2<double>()};
}

std::string box2dVersion() {
  return std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." + std::to_string(b2_version.revision);
}

RunRecord runBox2d(const RunRequest& request, const Box2dOptions& options) {
  Box2dBridge bridge(request, options);
  return bridge.run();
}

}  // namespace gizmo::verify
