#pragma once
// Whether a BoardSpec describes a board that can be simulated without guessing: everything that
// would make it physically impossible (overlaps, things off the board, absurd numbers) or
// ambiguous (duplicate names, connections to nothing). Pure data in, plain-language problems out:
// no file I/O, so that the readers and the simulator's property system share it.
//
// Naming (which characters a name may use) is not decided here: the readers decide it.
#include <cstddef>
#include <string>
#include <vector>

#include "gizmo/core/board_spec.hpp"

namespace gizmo {

struct SpecProblem {
  SourcePos where;      // position of the statement at fault ({0, 0} for board-wide values)
  std::string message;  // plain words, no file name and no position prefix
};

inline constexpr std::size_t kMaxGizmos = 10000;
inline constexpr int kMaxKeyCode = 65535;
// Limits on numbers that no board needs anywhere near: past them the simulator's arithmetic could
// overflow. Each velocity component, |gravity| and each friction constant must stay within them.
inline constexpr double kMaxSpeedComponent = 1.0e6;  // L/s
inline constexpr double kMaxGravity = 1.0e6;         // L/s²
inline constexpr double kMaxFriction = 1.0e6;        // per s (mu) and per L (mu2)

// Every problem of the board, sorted by source position (problems at the same position keep the
// order in which they were found). Empty when the board is valid.
//
// - More than kMaxBalls balls or kMaxGizmos gizmos: only that is reported.
// - Names: the reserved name OuterWalls, or a name used twice (balls and gizmos share one name
//   space; the later statement is the one reported).
// - Gizmos: orientation not 0/90/180/270; an absorber with orientation other than 0; size other
//   than the type's own (1×1 bumpers, 2×2 flippers) or an absorber smaller than 1×1; a bounding
//   box not inside 0..20; a bounding box sharing area with an earlier gizmo's (each gizmo is
//   reported once, with the earliest gizmo it overlaps).
// - Balls: non-finite numbers; a velocity component beyond kMaxSpeedComponent; a circle (radius
//   kBallRadius) not inside the board; a circle overlapping a gizmo's rest shape (restShape), where
//   touching is allowed and the test is exact; a ball closer than 2·kBallRadius to an earlier ball
//   (each ball reported once). A ball at rest lying wholly inside an absorber's rectangle counts as
//   captured: it may overlap that absorber and other captured balls.
// - Connections: a source that is not a gizmo or OuterWalls, a target that is not a gizmo, a
//   ball named as source or target, a key code outside 0..kMaxKeyCode, the same connection twice.
// - Gravity and friction: non-finite, beyond the limits above, or negative friction.
std::vector<SpecProblem> checkBoardSpec(const BoardSpec& board);

// Single-value checks, also used by readers that know where the value was written. Each returns an
// empty string when the value is fine, else what is wrong.
std::string gravityProblem(double gravity);
std::string frictionProblem(const std::string& which, double value);  // which: "mu" or "mu2"
std::string keyCodeProblem(long long key);

// "square", "circle", "triangle", "left flipper", "right flipper", "absorber".
const char* gizmoTypeWord(GizmoType type);

}  // namespace gizmo
