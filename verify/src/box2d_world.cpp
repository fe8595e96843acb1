// Box2D 2.4 as the driver's engine (box2d_engine.hpp), in process: the mapping's bodies in a
// b2World, contacts heard in its callbacks, the Gizmoball rules applied between steps by the
// one driver (box2d_driver.cpp).
#include "gizmo/verify/box2d_world.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "box2d_driver.hpp"
#include "gizmo/verify/box2d_shapes.hpp"

namespace gizmo::verify {
namespace {

// What the engine knows of each Box2D body; a fixture's user data is its index here.
struct BodyInfo {
  bool ball = false;
  bool sensor = false;
  double restitution = 1;
  b2Body* body = nullptr;
};

class Box2d24Engine final : public SteppedEngine, public b2ContactListener {
 public:
  Box2d24Engine(const RunRequest& request, const Box2dOptions& options)
      : options_(options),
        params_(paramsFor<double>(request)),
        gravity_(0, request.board.gravity),
        world_(b2Vec2(0, static_cast<float>(request.board.gravity))) {
    world_.SetAllowSleeping(false);  // a Gizmoball never sleeps
    world_.SetContinuousPhysics(options.continuous);
    world_.SetContactListener(this);
    addBody(box2dOuterWalls());
    for (const GizmoSpec& g : request.board.gizmos) addBody(box2dBodyOf(g));
    firstBall_ = bodies_.size();
    for (const BallSpec& b : request.board.balls) addBall(b);
  }

  // --- the engine ----------------------------------------------------------------------------
  EngineBall ball(std::size_t i) const override {
    const b2Body* body = bodies_[firstBall_ + i].body;
    return EngineBall{fromBox2d(body->GetPosition()), fromBox2d(body->GetLinearVelocity()), !body->IsEnabled()};
  }

  double angle(std::size_t body) const override { return bodies_[body].body->GetAngle(); }

  void turn(std::size_t body, double radians) override {
    rotationCapped_ = rotationCapped_ || std::fabs(radians) > kBox2dMaxRotation * (1 + 1e-5);
    bodies_[body].body->SetAngularVelocity(static_cast<float>(radians / options_.dt));
  }

  void setVelocity(std::size_t i, const Vec2<double>& v) override {
    velocity_[i] = v;
    bodies_[firstBall_ + i].body->SetLinearVelocity(toBox2d(v));
  }

  void hold(std::size_t i, const Vec2<double>& position) override {
    b2Body* body = bodies_[firstBall_ + i].body;
    // Disabling the body ends its contacts at once; those ends are the driver's doing, not the
    // ball leaving anything (else the absorber would take its own capture for a departure).
    muted_ = true;
    body->SetEnabled(false);
    muted_ = false;
    body->SetTransform(toBox2d(position), 0);
  }

  void release(std::size_t i, const Vec2<double>& position, const Vec2<double>& v) override {
    b2Body* body = bodies_[firstBall_ + i].body;
    body->SetEnabled(true);
    body->SetTransform(toBox2d(position), 0);
    body->SetLinearVelocity(toBox2d(v));
    velocity_[i] = v;
  }

  EngineStep step(double t0, double dt) override {
    EngineStep out;
    for (std::size_t i = 0; i < velocity_.size(); ++i) {
      const b2Body* body = bodies_[firstBall_ + i].body;
      if (!body->IsEnabled()) continue;
      // Box2D scales such a velocity down for good (b2Island::Solve); the margin keeps a ball
      // already scaled to the cap, give or take float rounding, from counting again.
      out.speedCapped = out.speedCapped || length(velocity_[i]) * dt > kBox2dMaxTranslation * (1 + 1e-5);
      stepFrom_[i] = fromBox2d(body->GetPosition());
      stepTo_[i] = stepFrom_[i] + dt * (velocity_[i] + dt * gravity_);  // where the integrator takes it, unhindered
    }
    out.rotationCapped = rotationCapped_;
    rotationCapped_ = false;
    stepStart_ = t0;
    ++stepNumber_;
    world_.Step(static_cast<float>(dt), options_.velocityIterations, options_.positionIterations);
    out.contacts.swap(contacts_);
    return out;
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
  void addBody(const Box2dBody& spec) {
    b2BodyDef def;
    def.type = spec.kinematic ? b2_kinematicBody : b2_staticBody;
    def.position = toBox2d(spec.origin);
    def.angle = static_cast<float>(spec.angle);
    BodyInfo info;
    info.sensor = spec.sensor;
    info.restitution = spec.restitution;
    info.body = world_.CreateBody(&def);
    for (const Box2dPart& part : spec.parts) addFixture(info.body, *makeBox2dShape(part), spec.sensor);
    bodies_.push_back(info);
  }

  void addFixture(b2Body* body, const b2Shape& shape, bool sensor) {
    b2FixtureDef def;
    def.shape = &shape;
    def.density = 1;
    def.friction = 0;     // Box2D's Coulomb friction off: the Gizmoball law is applied each step
    def.restitution = 0;  // set per contact in PreSolve
    def.restitutionThreshold = static_cast<float>(options_.restitutionThreshold);
    def.isSensor = sensor;
    def.userData.pointer = bodies_.size();  // the index the body's info gets
    body->CreateFixture(&def);
  }

  void addBall(const BallSpec& spec) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.bullet = options_.bullet;
    def.fixedRotation = true;
    def.position = toBox2d(Vec2<double>(spec.x, spec.y));
    def.linearVelocity = toBox2d(Vec2<double>(spec.vx, spec.vy));
    BodyInfo info;
    info.ball = true;
    info.body = world_.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(kBallRadius);
    addFixture(info.body, circle, false);
    bodies_.push_back(info);
    velocity_.emplace_back(spec.vx, spec.vy);
    stepFrom_.emplace_back();
    stepTo_.emplace_back();
  }

  const BodyInfo& infoOf(b2Fixture* f) const { return bodies_.at(f->GetUserData().pointer); }

  // The time of a contact seen during the current step: Box2D moves a ball in a straight line
  // over a step, and its time of impact stops it part way, so the fraction of the way it got
  // is the fraction of the step (0 for contacts found at the start of the step).
  double contactTime(std::size_t ball, const Vec2<double>& p) const {
    const Vec2<double> path = stepTo_[ball] - stepFrom_[ball];
    const double l2 = lengthSquared(path);
    const double alpha = l2 > 0 ? std::clamp(dot(p - stepFrom_[ball], path) / l2, 0.0, 1.0) : 0.0;
    return stepStart_ + alpha * options_.dt;
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
    const std::size_t ball = a - firstBall_;
    const bool otherIsBall = bodies_[b].ball;
    const std::size_t other = otherIsBall ? b - firstBall_ : b;
    if (bodies_[b].sensor) {
      int& count = touching_[{a, b}];
      count += change;
      if (muted_ || !((change > 0 && count == 1) || (change < 0 && count == 0))) return;
      const auto kind = change > 0 ? EngineContact::Kind::Enter : EngineContact::Kind::Exit;
      contacts_.push_back(EngineContact{kind, ball, false, other, contactTime(ball, p), p});
      return;
    }
    if (change < 0 || muted_ || !approaching(contact, a, b)) return;
    std::uint64_t& last = lastHitStep_[{a, b}];
    if (last == stepNumber_) return;
    last = stepNumber_;
    contacts_.push_back(EngineContact{EngineContact::Kind::Hit, ball, otherIsBall, other, contactTime(ball, p), p});
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
    return dot(relative, n) < -params_.restSpeed;
  }

  Box2dOptions options_;
  PhysicsParams<double> params_;
  Vec2<double> gravity_;
  b2World world_;
  std::vector<BodyInfo> bodies_;  // the walls, the gizmos, the balls
  std::size_t firstBall_ = 0;
  std::vector<Vec2<double>> velocity_;  // per ball: the velocity last set
  std::map<std::pair<std::size_t, std::size_t>, int> touching_;
  std::vector<EngineContact> contacts_;
  std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> lastHitStep_;  // the step number of the pair's last hit
  bool muted_ = false;
  bool rotationCapped_ = false;
  std::uint64_t stepNumber_ = 0;  // steps begun, so the first is 1
  double stepStart_ = 0;
  std::vector<Vec2<double>> stepFrom_, stepTo_;  // per ball, over the current step
};

}  // namespace

CollisionRecord collisionRecord(double time, std::string ball, std::string other, bool otherIsBall) {
  if (otherIsBall && other < ball) std::swap(ball, other);
  return CollisionRecord{time, std::move(ball), std::move(other), Vec2<double>()};
}

std::string box2dVersion() {
  return std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
         std::to_string(b2_version.revision);
}

RunRecord runBox2d(const RunRequest& request, const Box2dOptions& options) {
  Box2d24Engine engine(request, options);
  return driveBox2dRun(request, options.dt, engine);
}

}  // namespace gizmo::verify
