// Runs that campaigns on fresh seeds found failing, shrunk, each kept as a test: the property
// that failed must hold on it (docs/fuzzing.md, "What the properties found"). Every board here
// failed before its fix.
#include <gtest/gtest.h>

#include <string>

#include "gizmo/verify/fuzz/invariants.hpp"
#include "gizmo/verify/fuzz/properties.hpp"
#include "support/board_builder.hpp"

namespace gizmo::verify::fuzz {
namespace {

using test::ballAt;
using test::gizmoAt;

RunRequest ballisticRun(BoardSpec board, double maxTick, double duration) {
  RunRequest r;
  r.board = std::move(board);
  r.model = MotionModel::Ballistic;
  r.maxTick = maxTick;
  r.duration = duration;
  return r;
}

std::string firstViolation(const InvariantRun& run) {
  return run.violations.empty() ? std::string() : run.violations.front().message;
}

// Seed 20261201, case 359: a ball thrown up past a flipper's pivot comes down onto the flipper's
// top side from beside it. Its centre started behind that side's line, where the edge was never
// looked at, and it sank 0.049 L into the flipper before the next recalculation found it there.
TEST(FuzzRegressions, ABallArcingOntoAFlippersTopSideFromBesideItLandsOnIt) {
  BoardSpec board = test::emptyBoard(1000);
  board.balls.push_back(ballAt("B21", 12.522527032318791, 18.02436634557278, -105.3627631957021, -72.25506501591016));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G2", 1, 16, 90));
  for (double maxTick : {0.05, 0.1, 0.2}) {
    const InvariantRun run = checkInvariants<double>(ballisticRun(board, maxTick, 0.2), {Invariant::NoTunnelling});
    EXPECT_TRUE(run.violations.empty()) << "max tick " << maxTick << ": " << firstViolation(run);
  }
}

// Seed 20261201, case 499: the same over a square bumper, a ball beside it below its top edge's
// line flying up and over onto it.
TEST(FuzzRegressions, ABallArcingOntoASquaresTopFromBesideItLandsOnIt) {
  BoardSpec board = test::emptyBoard(1000);
  board.balls.push_back(ballAt("B44", 3.0113470283839713, 16.00693381082062, 55.226450573617034, -24.47813122063693));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "G20", 4, 16));
  const InvariantRun run = checkInvariants<double>(ballisticRun(board, 0.05, 0.1),
                                                   {std::begin(kAllInvariants), std::end(kAllInvariants)});
  EXPECT_TRUE(run.violations.empty()) << firstViolation(run);
}

// Seed 20261121, case 140 (shrunk): ball B13 reaches the absorber's underside and the flipper's
// side at one instant. Classic strikes it off the flipper and captures it 8e-16 s later, ballistic
// captures it at once (so do the two models at mpfr:256): a near-tie, not a disagreement.
TEST(FuzzRegressions, ABallReachingAnAbsorberAndAFlipperAtOneInstantIsANearTie) {
  BoardSpec board = test::emptyBoard(0);
  const double balls[][4] = {{11.5, 18, 0, -66},
                             {11.5, 16, -0.0, 66},
                             {9.5, 14.5, 200, 200},
                             {13.5, 18.5, -200, -200},
                             {15.977976403919827, 9.75, -0.009720199659991562, 0},
                             {14.5, 19.75, 0, 0},
                             {1.5, 16.25, 5000, 0},
                             {2.6272011978828687, 17.51756049960031, -1811.9388627115627, 4660.137075000641},
                             {13.5, 7.04135623606914, 28.985608412204616, 9.934329998109174},
                             {7.25, 13.75, 0, 0}};
  const char* names[] = {"B5", "B6", "B13", "B14", "B16", "B17", "B18", "B19", "B20", "B21"};
  for (int i = 0; i < 10; ++i) board.balls.push_back(ballAt(names[i], balls[i][0], balls[i][1], balls[i][2], balls[i][3]));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G0", 0, 10, 0, 20, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G2", 5, 12, 180));
  board.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "G2", {}});
  RunRequest run = ballisticRun(board, 0.05, 0.1400470246749601);
  run.model = MotionModel::Classic;
  const Property* modelsAgree = findProperty("models-agree");
  ASSERT_NE(modelsAgree, nullptr);
  const PropertyResult r = modelsAgree->check(run);
  EXPECT_TRUE(r.holds) << r.message;
}

// Seed 2024, case 85 (made small by hand): B82 lies between a circle bumper and B93, which a
// floor holds. It rattles between them until the jam rule calls the pair jammed, and the ball-ball
// response let it through as a graze (closing at under a thousandth of the relative speed) while
// gravity pressed it into B93. The next contact was looked for after that instant, where the gap
// only closes, so none came: B82 sank 1e-4 L into B93 by the next recalculation, and from there
// the same contact was predicted and ignored at one instant a million times.
TEST(FuzzRegressions, ABallJammedOntoABallThatTheFloorHoldsRestsOnIt) {
  BoardSpec board = test::emptyBoard(1.9582674858462767, 0.06482548899468621, 0.4322812153267072);
  board.balls.push_back(ballAt("B82", 16.5, 19.25));
  board.balls.push_back(ballAt("B93", 16.5, 19.75, -0.002872147958525719, 0));
  board.gizmos.push_back(gizmoAt(GizmoType::Circle, "G28", 16, 18));
  const InvariantRun run = checkInvariants<double>(ballisticRun(board, 0.05, 0.5),
                                                   {std::begin(kAllInvariants), std::end(kAllInvariants)});
  EXPECT_TRUE(run.violations.empty()) << firstViolation(run);
}

// Campaign seed 20261203, case 1495 (shrunk): in the classic model a ball at rest hangs under a
// right flipper's side at its pivot. A key starts the swing, and the side, turning into the ball,
// presses it only through the gap's curvature (its first-order closing is zero there) while
// gravity pulls the ball away. The hit reflected a normal speed of zero, so nothing changed; the
// flipper, triggered by its own hit, turned back and then forward again at t = 0, a million times.
TEST(FuzzRegressions, AFlipperTurningIntoABallThatHangsUnderItInTheClassicModelStrikesIt) {
  BoardSpec board = test::emptyBoard(1000);
  board.balls.push_back(ballAt("B22", 1.25, 10.75));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G11", 1, 10, 270));
  board.connections.push_back(ConnectSpec{"G11", "G11", {}});
  board.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Up, "G11", {}});
  RunRequest run = ballisticRun(board, 0.01, 0.007963735698682646);
  run.model = MotionModel::Classic;
  run.keys.push_back(TimedKey{0, 32, KeyDirection::Up});
  const InvariantRun result = checkInvariants<double>(run, {std::begin(kAllInvariants), std::end(kAllInvariants)});
  EXPECT_TRUE(result.violations.empty()) << firstViolation(result);
}

// Found by the fuzz generator's first draw with boosters (docs/fuzzing.md), shrunk: in the
// classic model a ball hangs at rest beside a right flipper's side 1, level with the pivot. The
// key starts the swing as the ball, given a tick's gravity, runs down along that side, which turns
// into it. The pressing test took the Coriolis part of the gap's curvature with side 0's sign, so
// the ball counted as opening, was not hit, and was 6.6e-4 L inside the flipper 0.6 ms later.
TEST(FuzzRegressions, ABallRunningAlongAFlippersTurningSideIsHit) {
  BoardSpec board = test::emptyBoard(1000, 0, 0);
  board.balls.push_back(ballAt("B", 1.25, 18.25));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G", 0, 18));
  board.keyConnections.push_back(KeyConnectSpec{37, KeyDirection::Down, "G", {}});
  RunRequest run = ballisticRun(board, 0.1, 0.2);
  run.model = MotionModel::Classic;
  run.keys.push_back(TimedKey{0.09765929724790692, 37, KeyDirection::Down});
  const InvariantRun result = checkInvariants<double>(run, {std::begin(kAllInvariants), std::end(kAllInvariants)});
  EXPECT_TRUE(result.violations.empty()) << firstViolation(result);
}

// Seed 299792458, case 11204, shrunk: B38 shuttles along a row at 1601 L/s, striking B104 (at
// rest on a left flipper's pivot circle) and taking its speed back again, a Newton's cradle whose
// roundings leave B104 1.9e-13 L behind the end of the flipper's side. The key turns that side
// towards it: the side's gap is never positive there, only zero when the end comes under the
// ball, so no entry was found and B104 was 3e-4 L inside the flipper 1.8 ms later.
TEST(FuzzRegressions, ABallOnAFlippersPivotIsHitWhenTheTurningSidesEndComesUnderIt) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B38", 11.5, 16.75, -1601.831315770533, 0));
  board.balls.push_back(ballAt("B104", 18.75, 16.75));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G3", 17, 16, 90));
  board.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Up, "G3", {}});
  for (const MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    RunRequest run = ballisticRun(board, 0.05, 0.3);
    run.model = model;
    run.keys.push_back(TimedKey{0.176122196769977, 32, KeyDirection::Up});
    const InvariantRun result = checkInvariants<double>(run, {std::begin(kAllInvariants), std::end(kAllInvariants)});
    EXPECT_TRUE(result.violations.empty()) << firstViolation(result);
  }
}

}  // namespace
}  // namespace gizmo::verify::fuzz
