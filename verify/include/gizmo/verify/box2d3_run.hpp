#pragma once
// A whole run in Box2D v3 (docs/verification.md, "Box2D v3"): the board of a RunRequest exported
// as a scene (JSON: the bodies and shapes of the one mapping, box2d_mapping.hpp, the balls and
// the run's settings), run by the project's node program verify/box2d3/run_scene.mjs in the
// box2d3-wasm package, and its run read back as a trace (engine_trace.hpp). scripts/setup.sh
// installs the package (scripts/setup-box2d3.sh).
#include <optional>
#include <string>

#include "gizmo/verify/engine_trace.hpp"

namespace gizmo::verify {

inline constexpr int kBox2d3SubSteps = 4;  // Box2D v3's recommended sub-steps per step

// Why the v3 program cannot run the board, or nothing. It builds static bodies and balls only: a
// flipper or a spinner would need the core's schedule each step, an absorber the core's capture,
// and it mixes coefficients of restitution by their maximum, so every gizmo's must be 1.
std::optional<std::string> box2d3CannotModel(const BoardSpec& board);

// The scene the node program builds: request.board run for request.duration seconds at options.dt
// with options.bullet and options.continuous.
std::string box2d3Scene(const RunRequest& request, const Box2dOptions& options);

// Why the node program cannot run here (no node on the PATH, or the package not installed), or
// nothing. The program's folder is the GIZMO_BOX2D3_DIR environment variable when set, else the
// source tree's verify/box2d3.
std::optional<std::string> box2d3Unavailable();

// The program's run of the request (its wall_seconds the program's own figure, without node's
// start-up), which must reach board time `end`; std::runtime_error when the program fails or
// writes a trace that does not read.
EngineTrace runBox2d3(const RunRequest& request, const Box2dOptions& options, double end);

}  // namespace gizmo::verify
