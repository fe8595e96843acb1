#pragma once
// The boards the benchmarks run: the specification's example and a crowded generated board.
#include "gizmo/core/board_spec.hpp"

namespace gizmo::bench {

BoardSpec specExample();
// ~210 bumpers of every kind and 100 moving balls: the broad phase's test.
BoardSpec crowdedBoard();

}  // namespace gizmo::bench
