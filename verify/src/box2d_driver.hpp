#pragma once
// The Gizmoball rules a Box2D world does not have, applied between its steps by the core's own
// gizmos, whichever Box2D runs the world (box2d_engine.hpp): key input, triggers, the flippers'
// swings and the spinners' turns on the core's schedules, the absorbers' captures and fires, and
// the friction law (docs/verification.md, "The bridge" and "One driver, two engines").
#include "box2d_engine.hpp"
#include "gizmo/verify/box2d_world.hpp"

namespace gizmo::verify {

// Runs request.board on `engine` (built from the same board: body 0 the walls, then the gizmos,
// then the balls) in steps of dt for request.duration seconds. The record's collisions are in time
// order; its wallSeconds is what the steps cost, the engine's and the rules' together.
RunRecord driveBox2dRun(const RunRequest& request, double dt, SteppedEngine& engine);

}  // namespace gizmo::verify
