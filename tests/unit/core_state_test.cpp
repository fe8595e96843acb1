// Saved states: a run resumed from a state saved at a tick boundary makes exactly the decisions
// the original made from there on, and restoring refuses states that cannot fit the board.
#include <gtest/gtest.h>

#include "gizmo/core/run/run.hpp"
#include "support/decision_trace.hpp"
#include "support/random_board.hpp"

namespace gizmo {
namespace {

RunRequest requestFor(std::uint64_t seed, MotionModel model) {
  RunRequest r;
  r.board = test::randomBoard(seed);
  r.model = model;
  r.duration = 8;
  for (int k = 0; k < 16; ++k)
    r.keys.push_back(TimedKey{k * 0.5 + 0.013, 32, k % 2 ? KeyDirection::Up : KeyDirection::Down});
  return r;
}

template <class Real>
void resumesIdentically(std::uint64_t seed, MotionModel model) {
  const RunRequest request = requestFor(seed, model);
  const std::vector<std::int64_t> saveAt{1, 7, 51, 120, 159};
  test::DecisionTrace<Real> original;
  {
    auto board = prepareRun<Real>(request);
    original.watch(*board, saveAt);
    board->setObserver(&original);
    continueRun(*board, request, 0);
  }
  ASSERT_EQ(original.saved.size(), saveAt.size()) << "seed " << seed;
  for (const auto& [tick, saved] : original.saved) {
    const auto& [state, decisionsBefore] = saved;
    auto board = prepareRun<Real>(request);
    board->restoreState(state);
    test::DecisionTrace<Real> resumed;
    board->setObserver(&resumed);
    continueRun(*board, request, tick);
    const std::vector<test::Decision> expected(original.decisions.begin() + std::ptrdiff_t(decisionsBefore),
                                               original.decisions.end());
    ASSERT_EQ(resumed.decisions.size(), expected.size()) << "seed " << seed << " resumed at tick " << tick;
    for (std::size_t i = 0; i < expected.size(); ++i)
      ASSERT_EQ(resumed.decisions[i], expected[i])
          << "seed " << seed << " resumed at tick " << tick << ", decision " << i;
  }
}

TEST(SavedState, ResumedRunsDecideAsTheOriginalBallistic) {
  for (std::uint64_t seed = 0; seed < 30; ++seed) resumesIdentically<double>(seed, MotionModel::Ballistic);
}
TEST(SavedState, ResumedRunsDecideAsTheOriginalClassic) {
  for (std::uint64_t seed = 0; seed < 30; ++seed) resumesIdentically<double>(seed, MotionModel::Classic);
}
TEST(SavedState, ResumedRunsDecideAsTheOriginalLongDouble) {
  for (std::uint64_t seed = 0; seed < 10; ++seed) resumesIdentically<long double>(seed, MotionModel::Ballistic);
}

TEST(SavedState, RunLimitStopsBeforeTheFirstLaterEvent) {
  const RunRequest request = requestFor(3, MotionModel::Ballistic);
  auto board = prepareRun<double>(request);
  test::DecisionTrace<double> trace;
  board->setObserver(&trace);
  board->setRunLimit({.events = 1000000, .time = 2.5});
  continueRun(*board, request, 0);
  EXPECT_TRUE(board->stopped());
  EXPECT_LE(board->now(), 2.5);
  for (const Event<double>& e : board->pendingEvents()) EXPECT_GT(e.time, 2.5);

  auto counted = prepareRun<double>(request);
  counted->setRunLimit({.events = 77, .time = std::nullopt});
  continueRun(*counted, request, 0);
  EXPECT_TRUE(counted->stopped());
  EXPECT_EQ(counted->executedTotal(), 77u);
}

// A run cut at the end of the tick that holds a time decides, up to there, exactly as the whole
// run does (a fuzz failure's log is such a cut).
TEST(SavedState, ARunCutAtATicksEndIsAPrefixOfTheWholeRun) {
  for (MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    const RunRequest whole = requestFor(4, model);
    test::DecisionTrace<double> all;
    simulate<double>(whole, &all);
    for (double t : {0.0, 0.05, 3.3, 3.3000000000000003, 7.9}) {
      const RunRequest cut = runThroughTickAt(whole, t);
      EXPECT_GE(cut.duration, t);
      if (t > 0) EXPECT_LT(cut.duration - whole.maxTick, t) << "not the tick that holds " << t;
      else EXPECT_EQ(cut.duration, whole.maxTick) << "the first tick holds the events at 0";
      test::DecisionTrace<double> part;
      simulate<double>(cut, &part);
      ASSERT_LT(part.decisions.size(), all.decisions.size()) << "t = " << t;
      for (std::size_t i = 0; i < part.decisions.size(); ++i)
        ASSERT_EQ(part.decisions[i], all.decisions[i]) << "t = " << t << ", decision " << i;
    }
    EXPECT_EQ(runThroughTickAt(whole, whole.duration).duration, whole.duration);
    EXPECT_EQ(runThroughTickAt(whole, 9).duration, whole.duration);
  }
}

// Each broken state names what is wrong with it.
TEST(SavedState, RestoringRefusesStatesThatDoNotFit) {
  const RunRequest request = requestFor(5, MotionModel::Ballistic);
  test::DecisionTrace<double> trace;
  auto board = prepareRun<double>(request);
  trace.watch(*board, {20});
  board->setObserver(&trace);
  continueRun(*board, request, 0);
  const BoardState<double> good = trace.saved.at(20).first;
  ASSERT_FALSE(good.events.empty());

  auto refuses = [&](auto breakIt, const char* what) {
    BoardState<double> bad = good;
    breakIt(bad);
    auto fresh = prepareRun<double>(request);
    try {
      fresh->restoreState(bad);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const StateError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refuses([](auto& s) { s.gizmos.pop_back(); }, "gizmos");
  refuses([](auto& s) { s.executedTotal += 1; }, "add up");
  refuses([](auto& s) { s.nextInput = 1000; }, "inputs");
  refuses([](auto& s) { s.events.front().a = 100000; }, "queued event");
  refuses([](auto& s) { s.events.front().time = -1; }, "earlier than the present");
  refuses([](auto& s) { s.events.back().sequence = s.nextSequence; }, "sequence");
  refuses([&](auto& s) { s.gizmos[std::size_t(board->ballIds().front())].ints.push_back(0); }, "extra values");
  refuses([&](auto& s) { s.gizmos[std::size_t(board->ballIds().front())].ints.at(0) = 7; }, "outside");

  auto fresh = prepareRun<double>(request);
  fresh->restoreState(good);
  const BoardState<double> again = fresh->saveState();
  EXPECT_EQ(again.gizmos, good.gizmos);
  EXPECT_EQ(again.events.size(), good.events.size());
  EXPECT_EQ(again.nextSequence, good.nextSequence);
}

}  // namespace
}  // namespace gizmo
