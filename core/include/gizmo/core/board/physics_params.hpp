#pragma once
// The numbers a run depends on besides the board: the motion model and the constants of
// docs/physics.md, each recorded in a replay log's header.
#include <cstdint>
#include <string_view>

namespace gizmo {

enum class MotionModel : std::uint8_t { Classic, Ballistic };

inline std::string_view motionModelName(MotionModel m) { return m == MotionModel::Classic ? "classic" : "ballistic"; }

template <class Real>
struct PhysicsParams {
  MotionModel model = MotionModel::Ballistic;
  Real gravity{25};              // L/s², +y
  Real mu{0.025};                // friction per s
  Real mu2{0.025};               // friction per L
  Real maxTick{0.05};            // seed: the maximum tick length; also the prediction horizon
  Real frictionStep{0.01};       // ballistic: friction ticks at k·h
  Real restSpeed{0.01};          // L/s: slower hits on a surface that gravity presses into are contacts
  std::int32_t pinchLimit = 16;  // hits of one ball in one flipper swing before the flipper blocks
  // L: a bounce off a still surface that would lift the ball less than this is no bounce (the
  // settling threshold, docs/physics.md "Piles"). Like pinchLimit, a constant of the model rather
  // than of a run, so it is not in a log's header.
  Real settleRise{0.005};
};

}  // namespace gizmo
