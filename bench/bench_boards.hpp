#pragma once
// The boards the benchmarks run: the specification's example and the crowded board, both fixtures.
#include <optional>
#include <string>

#include "gizmo/core/board_spec.hpp"

namespace gizmo::bench {

BoardSpec specExample();
// ~210 bumpers of every kind and 100 moving balls: the broad phase's test.
BoardSpec crowdedBoard();

// Boards of other Gizmoball projects, read where they lie (../shared/boards/real beside the
// repository), never copied in. Whole games of these are benchmarked (bench_games.cpp).
inline constexpr const char* kRealManyBalls = "lheckemann__gizmoball__many-balls";  // 55 balls
inline constexpr const char* kRealFlipperCollision =
    "lheckemann__gizmoball__regression-flipper-coll";                                       // 1 ball on a flipper
inline constexpr const char* kRealMultiball = "lheckemann__gizmoball__specDemo-multiball";  // 7 balls
// nullopt when the directory is not there (a clone without shared/ beside it).
std::optional<BoardSpec> realBoard(const std::string& name);

}  // namespace gizmo::bench
