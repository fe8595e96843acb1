#pragma once
// What the between-steps driver (box2d_driver.hpp) asks of a Box2D world: step it, read its balls
// and kinematic bodies, turn a kinematic body, set a ball's velocity, hold a ball out of the world
// and release it, and hear what it touched (docs/verification.md, "One driver, two engines").
// Box2D 2.4 answers in process (box2d_world.cpp); Box2D v3 through the node program, spoken to
// over a pipe one request and one reply a step (box2d3_run.cpp). Bodies are numbered as the
// mapping exports them (box2d3_scene.cpp): 0 the outer walls, then the board's gizmos in the
// board's order; balls in the board's order.
#include <cstddef>
#include <vector>

#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo::verify {

// A ball as the engine has it now (after the last step and the requests since).
struct EngineBall {
  Vec2<double> position, velocity;
  bool held = false;  // held out of the world by hold() and not released since
};

// What a step brought: a hit (a contact that began while the ball approached faster than the
// rest speed, the first of its pair in the step), or a ball entering or leaving a sensor (an
// absorber). Its time and the ball's centre then are the engine's estimate within the step.
struct EngineContact {
  enum class Kind { Hit, Enter, Exit };
  Kind kind = Kind::Hit;
  std::size_t ball = 0;
  bool otherIsBall = false;
  std::size_t other = 0;  // a body, or a ball when otherIsBall
  double time = 0;
  Vec2<double> position;
};

struct EngineStep {
  std::vector<EngineContact> contacts;
  bool speedCapped = false;     // a ball would move beyond Box2D 2.4's b2_maxTranslation
  bool rotationCapped = false;  // a body would turn beyond Box2D 2.4's b2_maxRotation
};

class SteppedEngine {
 public:
  virtual ~SteppedEngine() = default;
  virtual EngineBall ball(std::size_t ball) const = 0;
  // A kinematic body's angle now, radians (any turn of it: the driver takes differences).
  virtual double angle(std::size_t body) const = 0;
  // Requests for the next step, applied in the order made.
  // Turn the kinematic body by `radians` over the next step, at a steady rate.
  virtual void turn(std::size_t body, double radians) = 0;
  virtual void setVelocity(std::size_t ball, const Vec2<double>& velocity) = 0;
  // The ball leaves the world (meets nothing, does not move) and stands at `position`.
  virtual void hold(std::size_t ball, const Vec2<double>& position) = 0;
  virtual void release(std::size_t ball, const Vec2<double>& position, const Vec2<double>& velocity) = 0;
  // One step of dt seconds from board time t0.
  virtual EngineStep step(double t0, double dt) = 0;
};

}  // namespace gizmo::verify
