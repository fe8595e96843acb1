// Random boards (fixed seeds) run for 20 s of board time in both models: none may stall, let a
// ball out of the board, or produce a non-finite number. Each failure names its seed.
#include <gtest/gtest.h>

#include <cmath>

#include "gizmo/core/run/run.hpp"
#include "support/random_board.hpp"

namespace gizmo {
namespace {

constexpr std::uint64_t kBoards = 300;

void soak(MotionModel model) {
  for (std::uint64_t seed = 0; seed < kBoards; ++seed) {
    RunRequest r;
    r.board = test::randomBoard(seed);
    ASSERT_TRUE(checkBoardSpec(r.board).empty()) << "seed " << seed;
    r.model = model;
    r.duration = 20;
    for (int k = 0; k < 40; ++k) r.keys.push_back(TimedKey{k * 0.5, 32, KeyDirection::Down});
    RunSummary s;
    try {
      s = simulate<double>(r);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "seed " << seed << " (" << motionModelName(model) << "): " << e.what();
      continue;
    }
    EXPECT_EQ(s.time, 20.0) << "seed " << seed;
    for (const BallState& b : s.balls) {
      EXPECT_TRUE(std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.vx) && std::isfinite(b.vy))
          << "seed " << seed << " ball " << b.name;
      // Never beyond a wall by more than a rounding error (the ball's radius is 0.25).
      EXPECT_GE(b.x, 0.25 - 1e-9) << "seed " << seed << " ball " << b.name;
      EXPECT_LE(b.x, 19.75 + 1e-9) << "seed " << seed << " ball " << b.name;
      EXPECT_GE(b.y, 0.25 - 1e-9) << "seed " << seed << " ball " << b.name;
      EXPECT_LE(b.y, 19.75 + 1e-9) << "seed " << seed << " ball " << b.name;
    }
  }
}

TEST(Soak, RandomBoardsBallistic) { soak(MotionModel::Ballistic); }
TEST(Soak, RandomBoardsClassic) { soak(MotionModel::Classic); }

}  // namespace
}  // namespace gizmo
