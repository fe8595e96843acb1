// What simulation_fuzz runs (simulation_input.hpp): every input of its seed corpus is a run, read
// as written; inputs outside the envelope or not in the format are refused, so a corpus that the
// target only skipped could not pass for one that ran.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fuzz/simulation_input.hpp"

namespace gizmo::fuzzing::simulation {
namespace {

const std::string kBoard = "Square S 5 5\nBall B 2.0 2.5 3.0 4.0\n";

std::optional<RunRequest> read(const std::string& text) { return readRun(text); }

TEST(SimulationFuzzInput, ReadsTheHeaderTheKeysAndTheBoard) {
  const std::optional<RunRequest> run = read("run classic 0.01 0.75\n# keys\n0.1 down 32\n0.2 up 32\nboard\n" + kBoard);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->model, MotionModel::Classic);
  EXPECT_EQ(run->maxTick, 0.01);
  EXPECT_EQ(run->duration, 0.75);
  ASSERT_EQ(run->keys.size(), 2u);
  EXPECT_EQ(run->keys[1].time, 0.2);
  EXPECT_EQ(run->keys[1].direction, KeyDirection::Up);
  ASSERT_EQ(run->board.balls.size(), 1u);
  EXPECT_EQ(run->board.balls[0].vy, 4.0);
  EXPECT_EQ(run->board.gizmos.size(), 1u);
}

TEST(SimulationFuzzInput, RefusesWhatIsNotARunOfTheEnvelope) {
  for (const char* header :
       {"run fast 0.05 0.5", "run ballistic 0.05", "run ballistic 0.05 0.5 1", "ballistic 0.05 0.5",
        "run ballistic 0.0001 0.5", "run ballistic 0.2 0.5", "run ballistic 0.05 0", "run ballistic 0.05 1.5",
        "run ballistic 0.05 nan", "run  ballistic 0.05 0.5"})
    EXPECT_FALSE(read(std::string(header) + "\nboard\n" + kBoard)) << header;
  EXPECT_FALSE(read("run ballistic 0.05 0.5\n" + kBoard)) << "no line 'board'";
  EXPECT_FALSE(read("run ballistic 0.05 0.5\n0.1 sideways 32\nboard\n" + kBoard)) << "a bad key script";
  // Overlapping gizmos are read as the board reader reads them (docs/board-files.md: the later
  // one is left out, with a warning), so the run is the one `gizmo run` would make.
  const std::optional<RunRequest> overlap = read("run ballistic 0.05 0.5\nboard\nSquare S 5 5\nSquare T 5 5\n");
  ASSERT_TRUE(overlap) << "gizmos overlap";
  ASSERT_EQ(overlap->board.gizmos.size(), 1u);
  EXPECT_EQ(overlap->board.gizmos[0].name, "S");
  EXPECT_FALSE(read("run ballistic 0.05 0.5\nboard\nGravity 1000.5\n" + kBoard)) << "gravity";
  EXPECT_FALSE(read("run ballistic 0.05 0.5\nboard\nFriction 0.025 5.5\n" + kBoard)) << "friction";
  EXPECT_FALSE(read("run ballistic 0.05 0.5\nboard\nBall B 2.0 2.5 4000.0 3001.0\n")) << "a ball faster than 5000 L/s";
  EXPECT_TRUE(read("run ballistic 0.05 0.5\nboard\nBall B 2.0 2.5 3000.0 4000.0\n")) << "a ball at 5000 L/s";

  std::string nine = "run ballistic 0.05 0.5\nboard\n", eight;
  for (int i = 0; i < 9; ++i) {
    if (i == 8) eight = nine;
    nine += "Ball B" + std::to_string(i) + " " + std::to_string(1 + 2 * i) + ".5 10.0 0.0 0.0\n";
  }
  EXPECT_TRUE(read(eight)) << "eight balls";
  EXPECT_FALSE(read(nine)) << "nine balls";
  std::string keys = "run ballistic 0.05 0.5\n";
  for (int i = 0; i < 33; ++i) keys += "0." + std::to_string(10 + i) + " down 32\n";
  EXPECT_FALSE(read(keys + "board\n" + kBoard)) << "33 key inputs";
}

TEST(SimulationFuzzInput, EverySeedInputIsARun) {
  int inputs = 0;
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(GIZMO_SIMULATION_CORPUS_DIR)) {
    std::ifstream in(e.path(), std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::optional<RunRequest> run = read(text);
    ASSERT_TRUE(run) << e.path();
    const bool classic = e.path().stem().string().ends_with("-classic");
    EXPECT_EQ(run->model, classic ? MotionModel::Classic : MotionModel::Ballistic) << e.path();
    EXPECT_FALSE(run->keys.empty()) << e.path();
    EXPECT_FALSE(run->board.balls.empty()) << e.path();
    ++inputs;
  }
  EXPECT_GE(inputs, 40);  // 21 fixture boards today, each in both models
}

}  // namespace
}  // namespace gizmo::fuzzing::simulation
