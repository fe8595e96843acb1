// Runs that campaigns on fresh seeds found failing, shrunk, each kept as a test: the property
// that failed must hold on it (docs/fuzzing.md, "What the properties found"). Every board here
// failed before its fix.
#include <gtest/gtest.h>

#include <string>

#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/fuzz/invariants.hpp"
#include "gizmo/verify/fuzz/properties.hpp"
#include "gizmo/verify/fuzz/run_generator.hpp"
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

// Every invariant on the run, in both models.
void expectInvariantsInBothModels(RunRequest run) {
  for (const MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    run.model = model;
    const InvariantRun result = checkInvariants<double>(run, {std::begin(kAllInvariants), std::end(kAllInvariants)});
    EXPECT_TRUE(result.violations.empty()) << motionModelName(model) << ": " << firstViolation(result);
  }
}

// models-agree on a run, which the shrunk board failed before the comparison learnt what rounding decides.
void expectModelsAgree(const RunRequest& run) {
  const Property* modelsAgree = findProperty("models-agree");
  ASSERT_NE(modelsAgree, nullptr);
  const PropertyResult r = modelsAgree->check(run, Precision::Double);
  EXPECT_TRUE(r.holds) << r.message;
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
  const InvariantRun run =
      checkInvariants<double>(ballisticRun(board, 0.05, 0.1), {std::begin(kAllInvariants), std::end(kAllInvariants)});
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
  for (int i = 0; i < 10; ++i)
    board.balls.push_back(ballAt(names[i], balls[i][0], balls[i][1], balls[i][2], balls[i][3]));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G0", 0, 10, 0, 20, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G2", 5, 12, 180));
  board.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "G2", {}});
  RunRequest run = ballisticRun(board, 0.05, 0.1400470246749601);
  run.model = MotionModel::Classic;
  const Property* modelsAgree = findProperty("models-agree");
  ASSERT_NE(modelsAgree, nullptr);
  const PropertyResult r = modelsAgree->check(run, Precision::Double);
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
  const InvariantRun run =
      checkInvariants<double>(ballisticRun(board, 0.05, 0.5), {std::begin(kAllInvariants), std::end(kAllInvariants)});
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
  RunRequest run = ballisticRun(board, 0.05, 0.3);
  run.keys.push_back(TimedKey{0.176122196769977, 32, KeyDirection::Up});
  expectInvariantsInBothModels(run);
}

// Campaign seed 271828182, case 1309, shrunk: without gravity a ball lies on the floor between a
// left flipper and a right flipper's resting side. A key swings the right flipper down onto it:
// the ball has no room, the pinch rule blocks the flipper, and the jammed ball is struck by the
// floor and the still flipper in turn at one instant. Each jammed hit only took the normal part
// of its velocity away, leaving cos² of the angle between the two surfaces per round: 207 L/s
// fell to denormals and never to zero, a million hits at one instant.
TEST(FuzzRegressions, ABallPinnedByABlockedFlipperAgainstTheFloorWithoutGravityRests) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B51", 3.75, 19.75));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G3", 2, 18, 180));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G15", 4, 18));
  board.keyConnections.push_back(KeyConnectSpec{39, KeyDirection::Up, "G3", {}});
  RunRequest run = ballisticRun(board, 0.05, 0.8997685654791533);
  run.keys.push_back(TimedKey{0.8309829893005635, 39, KeyDirection::Up});
  expectInvariantsInBothModels(run);
}

// Campaign seed 271828182, case 184, shrunk: the same jam in a triangle's corner, a ball without
// gravity between a triangle's edge and two flippers, one of which a key swings into it.
TEST(FuzzRegressions, ABallPinnedByAFlipperInATrianglesCornerWithoutGravityRests) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B11", 4.25, 3.75));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G6", 4, 2, 270));
  board.gizmos.push_back(gizmoAt(GizmoType::Triangle, "G28", 3, 3, 180));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G29", 4, 4, 90));
  board.keyConnections.push_back(KeyConnectSpec{37, KeyDirection::Down, "G6", {}});
  RunRequest run = ballisticRun(board, 0.05, 0.9375278396718305);
  run.keys.push_back(TimedKey{0.6111364184208937, 37, KeyDirection::Down});
  expectInvariantsInBothModels(run);
}

// Campaign seed 314159265, case 4834, shrunk: B44 bounces back off a triangle along the top of an
// absorber, exactly tangent to it, and stops dead striking B61 head-on. One model's rounding left
// it 8e-15 L low, so the hit's normal gave it 8e-11 L/s into the absorber, which captured it; the
// other's left it outside. Whether a tangent ball is captured is rounding's: the runs part there.
TEST(FuzzRegressions, ABallStoppedDeadTangentToAnAbsorberIsCapturedOnlyByRounding) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B41", 13.25, 19.5, -4482.943635057003, 2214.320745714563));
  board.balls.push_back(ballAt("B44", 14.5, 3.75, 5000, 0));
  board.balls.push_back(ballAt("B61", 17.481808591616527, 3.75));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G11", 16, 4, 0, 2, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::Triangle, "G12", 3, 3, 270));
  RunRequest run = ballisticRun(board, 0.05, 0.008833736262427245);
  expectModelsAgree(run);
}

// Campaign seed 271828182, case 1283, shrunk: a flipper strikes B49 along an absorber's top, where
// it strikes B27 head-on; B27 leaves at 55 L/s, tangent to the absorber, and 2e-13 L/s into it in
// one model, which captures it. At mpfr:256 the models part the same way (4.8e-76 L/s into it in
// the ballistic run, captured; exactly 0 in the classic run).
TEST(FuzzRegressions, ABallStruckAlongAnAbsorbersTopIsCapturedOnlyByRounding) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B27", 12.75, 12.75));
  board.balls.push_back(ballAt("B49", 10.25, 12.75));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G3", 7, 13, 0, 7, 6));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G7", 8, 11, 0));
  board.keyConnections.push_back(KeyConnectSpec{39, KeyDirection::Down, "G7", {}});
  RunRequest run = ballisticRun(board, 0.01, 0.7980590197062623);
  run.keys.push_back(TimedKey{0.4369092349583373, 39, KeyDirection::Down});
  run.keys.push_back(TimedKey{0.5353307956713221, 39, KeyDirection::Down});
  expectModelsAgree(run);
}

// Campaign seed 314159265, case 3098, shrunk: B11 runs up past a teleporter, tangent to it; 1.3e-10
// L to the side in one model, it meets the disc closing at 8e-4 L/s (above the core's graze bound)
// and is teleported; the other passes it.
TEST(FuzzRegressions, ABallPassingATeleporterAtATangentIsTeleportedOnlyByRounding) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B9", 14.430170898304299, 6.348699934906831, -620.1370820305395, 2045.2823007346847));
  board.balls.push_back(ballAt("B10", 19.25, 6.75));
  board.balls.push_back(ballAt("B11", 7.75, 17.25));
  board.balls.push_back(ballAt("B13", 13.911862322041792, 7.800746251045482, -53.424129452487634, 192.73261891087313));
  board.balls.push_back(ballAt("B17", 19.5, 0.5, 2.748743537656706, 39.02314596083127));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G2", 6, 15, 270));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G6", 7, 9, 0, 13, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::Triangle, "G11", 17, 8, 180));
  board.gizmos.push_back(gizmoAt(GizmoType::Triangle, "G12", 13, 8, 270));
  board.gizmos.push_back(gizmoAt(GizmoType::Teleporter, "G19", 8, 18, 90));
  board.connections.push_back(ConnectSpec{"G19", "G19", {}});
  board.connections.push_back(ConnectSpec{"G11", "G2", {}});
  RunRequest run = ballisticRun(board, 0.05, 1.2501615405439694);
  expectModelsAgree(run);
}

// Campaign seed 271828182, case 1802, shrunk: after a flipper's shot and a head-on hit, B51 runs
// along a row, passing over B26 at a tangent. A negligible hit long before left it 1.2e-10 L low
// in the classic run, where it strikes B26 closing at 2e-5 of its speed; the ballistic run
// passes. Both are within the models' tolerances.
TEST(FuzzRegressions, ABallPassingOverABallAtATangentStrikesItOnlyByRounding) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B14", 13.5, 5.5, -17, -17));
  board.balls.push_back(ballAt("B24", 10.529592615409179, 9.557834714169578, -4905.6008472294425, 966.9955158436773));
  board.balls.push_back(ballAt("B26", 2.5, 7.75));
  board.balls.push_back(ballAt("B33", 14.75, 9.75, -188.59806671657788, 66.56402354702749));
  board.balls.push_back(ballAt("B34", 15.5, 11.75, 1521.0280632634397, 0));
  board.balls.push_back(ballAt("B37", 10.75, 7.25));
  board.balls.push_back(ballAt("B51", 9.75, 7.25));
  board.gizmos.push_back(gizmoAt(GizmoType::Triangle, "G15", 13, 4, 270));
  board.gizmos.push_back(gizmoAt(GizmoType::Booster, "G16", 9, 11, 0));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G18", 0, 13, 0, 20, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G19", 10, 7, 180));
  board.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "G19", {}});
  RunRequest run = ballisticRun(board, 0.05, 1.183228986656855);
  run.keys.push_back(TimedKey{0.7090199696951597, 32, KeyDirection::Down});
  expectModelsAgree(run);
}

// Campaign seed 667430151, case 4778, shrunk: B3 and B5 run along y = 15.75, passing a still
// flipper's tip exactly at a tangent. Each head-on hit between them, and B5's turn on the
// triangle, turns a rounding into a vertical speed and amplifies it (to 1.3e-7 L/s in the
// ballistic run, 6.3e-8 L/s in the classic run), so B3 dips 7.5e-11 L into the tip in one run,
// past the graze's 5.8e-11 L, and is struck, and 3.7e-11 L in the other, and passes. At mpfr:256
// the two models part there as well. Both are within the models' tolerances.
TEST(FuzzRegressions, ABallPassingAStillFlippersTipAtATangentStrikesItOnlyByRounding) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B0", 2.5, 7.25, 5000, 0));
  board.balls.push_back(ballAt("B3", 4.5, 15.75, -4214.316169320152, 0));
  board.balls.push_back(ballAt("B5", 5.5, 15.75));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G0", 1, 16, 180));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "G6", 5, 7, 90));
  board.gizmos.push_back(gizmoAt(GizmoType::Triangle, "G14", 14, 15, 90));
  RunRequest run = ballisticRun(board, 0.05, 0.02085358299550017);
  expectModelsAgree(run);
}

// Campaign seed 223606798, case 2158, shrunk: B7 knocks B24 onto right flipper G7's pivot end,
// where it comes to sit on the flipper's side 4.5e-14 L (50 ulps of rounding) from that end in the
// ballistic run, and a hair nearer it in the classic run. The key swings the flipper away from it:
// the side's end leaves the ball at 9.4 L/s, long before the side could press into it by a
// rounding, so in neither run is it struck.
TEST(FuzzRegressions, ASideSwingingAwayFromABallAtItsPivotEndDoesNotStrikeIt) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B7", 10, 3.5, -48, 48));
  board.balls.push_back(ballAt("B24", 7.75, 18.25));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G7", 6, 16, 90));
  board.keyConnections.push_back(KeyConnectSpec{39, KeyDirection::Up, "G7", {}});
  RunRequest run = ballisticRun(board, 0.05, 0.7299756008575122);
  run.keys.push_back(TimedKey{0.45, 39, KeyDirection::Up});
  expectModelsAgree(run);
}

// Campaign seed 271828182, case 1389, shrunk: a crowded board in which B41, struck by a flipper,
// runs down an absorber's side at a tangent, 2.9e-14 L/s into it in the classic run, which
// captures it, and exactly along it in the ballistic run.
TEST(FuzzRegressions, ABallRunningDownAnAbsorbersSideIsCapturedOnlyByRounding) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B8", 8.29358849622394, 16.75, 22.795624925945997, -11.097870029736868));
  board.balls.push_back(ballAt("B9", 9.5, 18.75, 24.92352738690552, 39.281096916076244));
  board.balls.push_back(ballAt("B26", 9.5, 16.80259459783602, 185.5956920814564, 74.52676754566254));
  board.balls.push_back(ballAt("B27", 0.5511029801830736, 14.93443197397591, -92.56842103469171, 177.28814801656665));
  board.balls.push_back(ballAt("B30", 6.365810807761517, 17.292471870567866, 8.693469504998617, 16.35266771840576));
  board.balls.push_back(ballAt("B36", 12, 8, 98, 196));
  board.balls.push_back(ballAt("B41", 7.25, 9.25));
  board.balls.push_back(ballAt("B50", 14.877929424052466, 10.620310726551073, -86.18942644022192, 180.47543536422228));
  board.balls.push_back(ballAt("B51", 2.5, 18.907878266624877, -5.650092170118662, -2.616811729895253));
  board.balls.push_back(ballAt("B56", 13.5, 10.75));
  board.balls.push_back(ballAt("B61", 8, 17.5, 110, -110));
  board.balls.push_back(ballAt("B62", 10, 15.5, -110, 110));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G4", 10, 16, 0));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G9", 14, 10, 90));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G10", 5, 14, 0, 2, 3));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "G15", 15, 12));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G20", 7, 7, 90));
  board.gizmos.push_back(gizmoAt(GizmoType::Sink, "G28", 8, 18, 180));
  board.gizmos.push_back(gizmoAt(GizmoType::Circle, "G35", 4, 16));
  board.connections.push_back(ConnectSpec{"G15", "G20", {}});
  board.keyConnections.push_back(KeyConnectSpec{37, KeyDirection::Up, "G20", {}});
  RunRequest run = ballisticRun(board, 0.05, 0.5463069356990358);
  run.keys.push_back(TimedKey{0.243509922025828, 37, KeyDirection::Up});
  expectModelsAgree(run);
}

// Campaign seed 141421356, case 3610, shrunk: a key releases the ball an absorber holds, and a
// second release follows 66 ms later. An input's b holds its direction (1 for up), and the queue
// took it for gizmo 1's event: when the absorber (gizmo 1) recomputed as its ball left it, the
// release scheduled for later in that tick was removed. The classic run lost it; the ballistic
// run, whose leave came a rounding earlier, before the release was scheduled, kept it.
TEST(FuzzRegressions, AKeyReleaseSurvivesTheFirstGizmoRecomputing) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B23", 2.5, 15.75, -141.74608826010106, 141.0958768460639));
  board.balls.push_back(ballAt("B25", 1.2059818662261144, 17.050295442034283));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G0", 3, 10, 0, 9, 3));
  board.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Up, "G0", {}});
  RunRequest run = ballisticRun(board, 0.01, 0.42401722438249745);
  run.keys.push_back(TimedKey{0.2, 32, KeyDirection::Up});
  run.keys.push_back(TimedKey{0.2662456921805182, 32, KeyDirection::Up});
  for (const MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    run.model = model;
    EXPECT_EQ(simulate<double>(run).executed[std::size_t(EventKind::Input)], 2u) << motionModelName(model);
  }
  expectModelsAgree(run);
}

// Campaign seed 577215664, case 2920, shrunk: a right flipper connected to itself is keyed at t = 0
// with a ball resting against its pivot end, on a board whose other balls jam it at that instant.
// The side turning either way presses a ball at the pivot (the gap's curvature has -ω²q·n), so
// each hit, jammed, left the ball at rest, fired the flipper's own trigger and reversed it into
// the next hit; a reversal re-anchored the swing and cleared the pinch count, a million times at
// one instant. The count now runs on through a swing that turns at the instant it began, and a
// flipper blocked at an instant ignores triggers for the rest of it.
TEST(FuzzRegressions, ASelfTriggeredFlipperReversingIntoABallOnItsPivotIsBlocked) {
  BoardSpec board = test::emptyBoard(1000, 0.025, 0.025);
  board.balls.push_back(ballAt("B4", 16.5, 19.75));
  board.balls.push_back(ballAt("B33", 8.5, 19.75, 0.005960481080667188, 0));
  board.balls.push_back(ballAt("B34", 4.5, 12.569107579211147, 2799.476304935194, -850.9421367424158));
  board.balls.push_back(ballAt("B35", 3.75, 3.75));
  board.balls.push_back(ballAt("B36", 2, 9.5, 48, -24));
  board.balls.push_back(ballAt("B37", 8.75, 6.75));
  board.balls.push_back(ballAt("B38", 16.5, 19.25, 0.5733186900687958, 0));
  board.balls.push_back(ballAt("B40", 19.5, 12.802489780420073, 0.002354812455953992, 0.002513787136524726));
  board.balls.push_back(ballAt("B41", 8.5, 10.5, -54, 0));
  board.balls.push_back(ballAt("B42", 5.5, 10.5, 54, -0));
  board.balls.push_back(ballAt("B43", 2.25, 3.75));
  board.balls.push_back(ballAt("B47", 13.968221320307538, 6.75));
  board.balls.push_back(ballAt("B55", 15.041816088061239, 17.594944677942813));
  board.balls.push_back(ballAt("B56", 5.5, 10, -29, -29));
  board.balls.push_back(ballAt("B57", 3.5, 8, 29, 29));
  board.balls.push_back(ballAt("B58", 10.5, 17.5, 70, -35));
  board.balls.push_back(ballAt("B59", 12.5, 16.5, -70, 35));
  board.balls.push_back(ballAt("B64", 2.5, 7.25, 42.52468980246044, 0));
  board.balls.push_back(ballAt("B65", 1.320142392397085, 16.75, 10.687050875997432, -199.714263245202));
  board.balls.push_back(ballAt("B66", 13.25, 3.25));
  board.balls.push_back(ballAt("B67", 17, 9.5, 12, 6));
  board.balls.push_back(ballAt("B68", 19, 10.5, -12, -6));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "G1", 16, 18, 90));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G29", 11, 3, 0));
  board.connections.push_back(ConnectSpec{"G29", "G29", {}});
  board.keyConnections.push_back(KeyConnectSpec{37, KeyDirection::Down, "G29", {}});
  RunRequest run = ballisticRun(board, 0.05, 1.0404441959105033);
  run.keys.push_back(TimedKey{0, 37, KeyDirection::Down});
  expectInvariantsInBothModels(run);
}

// Campaign seed 173205080, case 272, shrunk: without gravity B11 knocks B6 against a right
// flipper's pivot end, where a jam leaves it at -2.3e-13 L/s, still touching. A hit on G15 swings
// G11 away from B6. The classic run kept B6 on the side's end to the last bit and struck it off
// at the minimum bounce; the ballistic run had moved it an ulp away and did not. Neither should:
// the side's end leaves the ball, and the pivot's circle turns in place.
TEST(FuzzRegressions, ABallOnAFlippersPivotIsLeftAloneWhenTheSidesEndTurnsAway) {
  BoardSpec board = test::emptyBoard(0, 0, 0);
  board.balls.push_back(ballAt("B6", 8.75, 8.75));
  board.balls.push_back(ballAt("B11", 6.606399368340863, 5.471082203081327, 1752.670934976514, 2547.6969260998812));
  board.balls.push_back(ballAt("B29", 14.5, 5.5));
  board.balls.push_back(ballAt("B34", 8.325142776152209, 14.75, 3210.8523921761844, -3832.8092720166073));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G4", 7, 9, 90));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G11", 9, 7, 180));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G15", 9, 13, 0));
  board.connections.push_back(ConnectSpec{"G15", "G11", {}});
  expectModelsAgree(ballisticRun(board, 0.05, 0.019603276181580084));
}

// Campaign seed 667430151, case 701, shrunk: B152 rests on a circle bumper's top, level with the
// top of the square beside it. B89 strikes it at 5000 L/s a hair low, so it leaves along the
// square's top rising at 1.25e-3 L/s, and gravity brings it back to the top's line 9.4e-14 L
// beyond the square's corner. The corner passed it as a graze, and over the square the gap was
// already below zero, so no entry was ever found: it sank 9.4e-8 L into the square in 5e-5 s.
TEST(FuzzRegressions, ABallComingDownOntoASquaresTopOverItsCornerIsHit) {
  BoardSpec board = test::emptyBoard(25, 0, 0);
  board.balls.push_back(ballAt("B89", 19.5, 16.75, -5000, 0));
  board.balls.push_back(ballAt("B152", 18.5, 16.75));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "G7", 17, 17, 0));
  board.gizmos.push_back(gizmoAt(GizmoType::Circle, "G16", 18, 17, 0));
  expectInvariantsInBothModels(ballisticRun(board, 0.05, 0.005046761471183583));
}

// Campaign seed 662607015, case 1669, shrunk: in the classic model B19 strikes a right
// flipper's pivot end at 5000 L/s and friction stops it dead there, 2.7e-14 L inside the pivot's
// circle (twice its position resolution). A key swings the flipper's side round under it; the
// search for the instant the side's end comes under a ball on the pivot's circle looked only at
// balls within a rounding of the circle's rim, from either side, so the side passed 1.6e-4 L
// into the ball.
TEST(FuzzRegressions, ABallAHairInsideAFlippersPivotIsHitWhenTheSidesEndComesUnderIt) {
  BoardSpec board = test::emptyBoard(0, 0.32557735978893937, 0.36190872924522294);
  board.balls.push_back(ballAt("B8", 7.5, 14.699297629849012, 2659.336249560063, -4234.13872136658));
  board.balls.push_back(ballAt("B19", 14.206837008927563, 13.870351218286917, -4993.089146662549, -262.7941656138184));
  board.gizmos.push_back(gizmoAt(GizmoType::Absorber, "G6", 7, 12, 0, 12, 1));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G17", 1, 12, 90));
  board.keyConnections.push_back(KeyConnectSpec{37, KeyDirection::Up, "G17", {}});
  RunRequest run = ballisticRun(board, 0.05, 0.3416020398479544);
  run.keys.push_back(TimedKey{0.3170584042273716, 37, KeyDirection::Up});
  expectInvariantsInBothModels(run);
}

// Campaign seed 662607015, case 1906, shrunk: B38 bounces on a square's top, 0.02 L/s up and
// down, against a flipper's pivot beside it, and drifts into the pivot at 3e-7 L/s: a closing
// speed under the graze fraction of its speed, so each path, started again at the tangency by
// the bounce, passed the pivot as a graze. The dips added up, to 1.04e-9 L in.
TEST(FuzzRegressions, ABallBouncingBesideAFlippersPivotDoesNotGrazeItsWayIn) {
  BoardSpec board = test::emptyBoard(25, 5, 5);
  board.balls.push_back(ballAt("B9", 11.846463841820427, 5.75, 3739.11919445836, 3319.4860520317097));
  board.balls.push_back(ballAt("B19", 12.5, 6.25, 24.652593677325953, 0));
  board.balls.push_back(ballAt("B20", 9.5, 6.159636876116034, 0.004942245444971615, 0.0032427381180446164));
  board.balls.push_back(ballAt("B21", 12.5, 6.75, 0.003450293489973688, -0.0052749019757251814));
  board.balls.push_back(ballAt("B27", 15.164884556690218, 4.4944690777694385, 3749.70539722663, -3307.52315698764));
  board.balls.push_back(ballAt("B34", 16, 3, -34, 34));
  board.balls.push_back(ballAt("B38", 13.365164731948775, 5.75));
  board.balls.push_back(ballAt("B52", 11.25, 3.25));
  board.balls.push_back(ballAt("B53", 13.25, 4.25));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G2", 9, 3, 0));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G3", 2, 0, 90));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G5", 14, 4, 270));
  board.gizmos.push_back(gizmoAt(GizmoType::Square, "G13", 13, 6, 0));
  board.gizmos.push_back(gizmoAt(GizmoType::Teleporter, "G15", 4, 4, 180));
  board.gizmos.push_back(gizmoAt(GizmoType::LeftFlipper, "G17", 11, 4, 180));
  board.connections.push_back(ConnectSpec{"G15", "G15", {}});
  board.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "G17", {}});
  RunRequest run = ballisticRun(board, 0.1, 1.9618098021285861);
  run.keys.push_back(TimedKey{0.35000000000000003, 32, KeyDirection::Down});
  expectInvariantsInBothModels(run);
}

// Campaign seed 244948974, case 2066, shrunk: a ball on a swinging flipper's pivot end beside a
// still spinner that the flipper's hits toggle. Each toggle woke the ball resting against the
// spinner, the flipper struck it again at that instant, its trigger toggled the spinner again: a
// million events at t = 0.26404. A spinner that stops holds nothing up, so it wakes nothing.
TEST(FuzzRegressions, ASpinnerToggledByEveryHitNearItDoesNotStall) {
  BoardSpec board = test::emptyBoard(25, 0, 0);
  board.balls.push_back(ballAt("B15", 12.25, 14.75));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G0", 12, 15, 270, 2, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::Spinner, "G2", 10, 15, 0, 2, 2));
  board.connections.push_back(ConnectSpec{"G0", "G2", {}});
  board.keyConnections.push_back(KeyConnectSpec{39, KeyDirection::Down, "G0", {}});
  RunRequest run = ballisticRun(board, 0.05, 2);
  run.keys.push_back(TimedKey{0.25, 39, KeyDirection::Down});
  const InvariantRun checked = checkInvariants<double>(run, {std::begin(kAllInvariants), std::end(kAllInvariants)});
  EXPECT_TRUE(checked.violations.empty()) << firstViolation(checked);
  expectModelsAgree(run);
}

// Campaign seed 27182818, case 174, shrunk: B44 strikes G3, whose trigger swings G19 into B52,
// which rests on G0's top. B52 slides left along it at 55 L/s; its contact ends at the side's
// pivot end, and the wall just there sends it back 3.5·10⁻¹⁸ s later, 8·10⁻¹⁷ L beyond the side's
// end and 3.5·10⁻¹⁵ L/s across its line. Neither the pivot's circle (the ball passes over it)
// nor the side (over it the gap was already falling) found an entry, and gravity 1000 sank the
// ball into the side (1.9·10⁻⁸ L in 6 μs in the unshrunk case, 2.7·10⁻⁴ L here).
TEST(FuzzRegressions, ABallSentBackAlongAFlippersTopByTheWallAtItsEndLandsOnIt) {
  BoardSpec board = test::emptyBoard(1000, 0, 0);
  board.balls.push_back(ballAt("B42", 13.75, 6.75));
  board.balls.push_back(ballAt("B44", 11.5, 5.75, 2492.8194954369837, 1659.3307684350473));
  board.balls.push_back(ballAt("B52", 1.25, 17.75));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G0", 0, 18, 270, 2, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G3", 18, 14, 180, 2, 2));
  board.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "G19", 0, 16, 0, 2, 2));
  board.connections.push_back(ConnectSpec{"G3", "G19", {}});
  expectInvariantsInBothModels(ballisticRun(board, 0.05, 0.04808931757680732));
}

// Campaign seed 2612061514, case 1695 (generated run seed 0x3c4c00558b627f7c, size 79), unshrunk:
// 51 balls without gravity; B49, struck to 5000 L/s, passes the pivot of the swinging flipper G9
// at a tangent, 1.2e-10 L closer to it in the ballistic run, which glances off the pivot's cap
// while the classic run passes it. The cap turns in place: a still circle, whose tangent hits
// are rounding's choice, as at any still circle; the checker judged no hit on a swinging flipper.
TEST(FuzzRegressions, ABallPassingASwingingFlippersPivotAtATangentStrikesItOnlyByRounding) {
  expectModelsAgree(generateRun(0x3c4c00558b627f7cULL, 79));
}

}  // namespace
}  // namespace gizmo::verify::fuzz
