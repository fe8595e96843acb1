#pragma once
// A whole run in Box2D: the board of a RunRequest built as Box2D bodies (box2d_mapping.hpp),
// stepped at a fixed step size, with the Gizmoball rules that Box2D does not have performed by
// the core's own gizmos (flipper swings, absorber captures and fires, triggers, key input,
// the friction law) through the driver that steps Box2D v3 too (verify/src/box2d_driver.hpp). What it leaves behind is the same record our run leaves, so that
// box2d_crosscheck.hpp compares like with like.
#include <cstdint>
#include <string>
#include <vector>

#include "gizmo/core/run/run.hpp"

namespace gizmo::verify {

// One hit of a ball on a gizmo or on another ball (an absorber's capture counts).
struct CollisionRecord {
  double time = 0;
  std::string ball;       // for two balls: the name that sorts first
  std::string other;      // the gizmo (OuterWalls for the walls), or the other ball
  Vec2<double> position;  // the ball's centre at the hit
};

// A hit of `ball` on `other` at `time`: two balls are named in the order of their names, so that
// both sides of a comparison name a pair alike. The position is the caller's to set.
CollisionRecord collisionRecord(double time, std::string ball, std::string other, bool otherIsBall);

// The balls' centres (in the board file's order) and the mechanical energy at one instant.
struct TrajectorySample {
  double time = 0;
  std::vector<Vec2<double>> positions;
  double energy = 0;
};

struct RunRecord {
  std::vector<CollisionRecord> collisions;  // in time order
  std::vector<TrajectorySample> samples;    // from time 0, in time order
  double wallSeconds = 0;
  std::uint64_t steps = 0;                // Box2D steps (0 for our run)
  std::uint64_t speedCappedSteps = 0;     // steps where a ball would move beyond b2_maxTranslation
  std::uint64_t rotationCappedSteps = 0;  // steps where a flipper would turn beyond b2_maxRotation
};

struct Box2dOptions {
  double dt = 1.0 / 60;
  bool bullet = true;               // the balls are bullets (continuous collision with each other)
  bool continuous = true;           // continuous collision against static and kinematic bodies
  double restitutionThreshold = 0;  // Box2D's default is 1 m/s: slower hits do not bounce
  int velocityIterations = 8;       // Box2D's recommended values
  int positionIterations = 3;
};

// The linked Box2D's own version string (2.4.1's library reports 2.4.0).
std::string box2dVersion();

// Runs request.board in Box2D for request.duration seconds (key input from request.keys).
RunRecord runBox2d(const RunRequest& request, const Box2dOptions& options);

}  // namespace gizmo::verify
