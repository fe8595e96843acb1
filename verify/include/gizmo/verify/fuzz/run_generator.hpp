#pragma once
// Valid runs made up from a seed: a board (gizmos of every kind and orientation without overlap,
// absorbers of every size, connections and key connections, gravity and friction from zero to
// large, one to a hundred balls), a motion model, a duration and a key script. Some balls are
// placed near-degenerately on purpose: aimed exactly at a corner, grazing an edge, two meeting
// head-on at one instant, resting on a surface, touching a flipper.
//
// Deterministic: the same (seed, size) gives the same run on every machine and thread, so that a
// case is named by its seed alone. `size` (0..kMaxSize) bounds how much goes in, as rapidcheck's
// size does; shrinking (run_shrinker.hpp) then takes things out.
#include <cstdint>

#include "gizmo/core/run/run.hpp"

namespace gizmo::verify::fuzz {

inline constexpr int kMaxSize = 100;

RunRequest generateRun(std::uint64_t seed, int size);

}  // namespace gizmo::verify::fuzz
