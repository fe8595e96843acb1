#pragma once
// A whole run in Box2D v3 (docs/verification.md, "Box2D v3"): the board of a RunRequest exported
// as a scene (JSON: the bodies and shapes of the one mapping, box2d_mapping.hpp, the balls and
// the run's settings), built by the project's node program verify/box2d3/run_scene.mjs in the
// box2d3-wasm package and stepped by the same driver as Box2D 2.4's run, which applies the
// core's rules between steps (flippers, spinners, absorbers, triggers, keys, friction) and asks
// the program for one step at a time over a pipe. scripts/setup.sh installs the package
// (scripts/setup-box2d3.sh).
#include <optional>
#include <string>

#include "gizmo/verify/engine_trace.hpp"

namespace gizmo::verify {

inline constexpr int kBox2d3SubSteps = 4;  // Box2D v3's recommended sub-steps per step
// Box2D v3's limits (its constants.h and b2DefaultWorldDef), counted as the run's speed-capped
// and rotation-capped steps: a ball's speed, and a body's turn in one step (B2_MAX_ROTATION).
inline constexpr double kBox2d3MaxSpeed = 400.0;
inline constexpr double kBox2d3MaxRotation = 0.7853981633974483;  // π/4

// Why the v3 program cannot run the board, or nothing: what Box2D 2.4's bridge cannot model (a
// spawner), since both run under the one driver.
std::optional<std::string> box2d3CannotModel(const BoardSpec& board);

// The scene the node program builds: request.board run at options.dt with options.bullet and
// options.continuous; with a `traceOut` file, the program also writes its run there as a trace.
std::string box2d3Scene(const RunRequest& request, const Box2dOptions& options, const std::string& traceOut = {});

// Why the node program cannot run here (no node on the PATH, or the package not installed), or
// nothing. The program's folder is the GIZMO_BOX2D3_DIR environment variable when set, else the
// source tree's verify/box2d3.
std::optional<std::string> box2d3Unavailable();

// The run of the request for request.duration seconds: its engine's name and its record (its
// wall_seconds the steps' cost, the round trips to node included, node's start-up not);
// std::runtime_error when the program fails or says something that does not read. With a
// `traceOut` file the program also writes the run there, in the trace format of
// engine_trace.hpp, whole when this returns and not at all when it throws.
EngineTrace runBox2d3(const RunRequest& request, const Box2dOptions& options, const std::string& traceOut = {});

}  // namespace gizmo::verify
