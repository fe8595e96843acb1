// models-agree's comparison on decisions built by hand (docs/fuzzing.md, "When the models may
// part"): what rounding may decide passes, a different decision while the states agree does not.
#include <gtest/gtest.h>

#include <vector>

#include "gizmo/verify/fuzz/properties.hpp"

namespace gizmo::verify::fuzz {
namespace {

PhysicalDecision hit(const char* what, double time, double vx, bool negligible = false) {
  return PhysicalDecision{what, 1, time, {5.0, 5.0, vx, 0.0}, negligible};
}

TEST(ModelsAgreeComparison, TheSameDecisionsAgree) {
  const std::vector<PhysicalDecision> run{hit("collision a=1 b=9", 0.5, -2), hit("collision a=2 b=9", 0.75, 2)};
  EXPECT_TRUE(compareModelDecisions(run, run).holds);
}

TEST(ModelsAgreeComparison, IndependentHitsAFewUlpsApartMayComeInEitherOrder) {
  const std::vector<PhysicalDecision> classic{
      hit("collision a=1 b=9", 0.5, -2), hit("collision a=3 b=8", 0.5 + 1e-14, 3), hit("collision a=2 b=9", 0.75, 2)};
  const std::vector<PhysicalDecision> ballistic{classic[1], classic[0], classic[2]};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
}

TEST(ModelsAgreeComparison, ADifferentDecisionWhileTheStatesAgreeFails) {
  const std::vector<PhysicalDecision> classic{hit("collision a=1 b=9", 0.5, -2), hit("collision a=2 b=9", 0.75, 2)};
  const std::vector<PhysicalDecision> ballistic{hit("collision a=1 b=9", 0.5, -2), hit("collision a=4 b=9", 0.8, 2)};
  const PropertyResult r = compareModelDecisions(classic, ballistic);
  EXPECT_FALSE(r.holds);
  EXPECT_NE(r.message.find("decision 1 differs"), std::string::npos) << r.message;
}

TEST(ModelsAgreeComparison, AnExtraHitCountsUnlessItChangedNothing) {
  const std::vector<PhysicalDecision> classic{hit("collision a=1 b=9", 0.5, -2), hit("collision a=2 b=9", 0.75, 2)};
  std::vector<PhysicalDecision> ballistic{classic[0], hit("collision a=5 b=9", 0.6, 1e-13, true), classic[1]};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
  ballistic[1].negligible = false;  // the same extra hit, but one that changed a velocity
  EXPECT_FALSE(compareModelDecisions(classic, ballistic).holds);
  // An extra hit at the end of one run only.
  std::vector<PhysicalDecision> longer = classic;
  longer.push_back(hit("collision a=6 b=9", 0.9, 4));
  EXPECT_FALSE(compareModelDecisions(classic, longer).holds);
}

TEST(ModelsAgreeComparison, AnExtraHitThatChangedNothingButFiredATriggerPartsTheRuns) {
  // A ball at rest to within rounding touches a flipper (gizmo 2) in one model, firing its
  // trigger, and another surface in the other; the trigger's consequences come after.
  const std::vector<PhysicalDecision> classic{
      hit("collision a=1 b=9", 0.5, -2), hit("collision a=6 b=9", 0.5, 1e-13, true), hit("collision a=3 b=8", 0.6, 3)};
  // (The trigger and its action are reported while the hit runs, before it.)
  const PhysicalDecision trigger = consequenceAt("trigger 2 -> 7", 0.5), action = consequenceAt("action 7", 0.5);
  const std::vector<PhysicalDecision> ballistic{hit("collision a=1 b=9", 0.5, -2), trigger, action,
                                                hit("collision a=2 b=9", 0.5, 1e-13, true),
                                                hit("collision a=3 b=8", 0.61, 3)};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
  EXPECT_TRUE(compareModelDecisions(ballistic, classic).holds);
  // A trigger fired at another time is not that hit's: the extra trigger is a different decision.
  std::vector<PhysicalDecision> later = ballistic;
  later[1].time = 0.45;
  later[2].time = 0.45;
  EXPECT_FALSE(compareModelDecisions(classic, later).holds);
  // Nor does a hit that changed a velocity count as rounding's.
  std::vector<PhysicalDecision> real = ballistic;
  real[3].negligible = false;
  EXPECT_FALSE(compareModelDecisions(classic, real).holds);
}

TEST(ModelsAgreeComparison, AnExtraHitThatChangedNothingButCapturedABallPartsTheRuns) {
  // A ball stopped dead beside an absorber, tangent to it, is left moving into it at 8e-11 L/s
  // by one model's rounding, which captures it; the other's leaves it outside, and the ball it
  // stopped goes on to hit a wall (campaign seed 314159265, case 4834).
  const PhysicalDecision captured = consequenceAt("captured 1 4", 0.5);
  const std::vector<PhysicalDecision> classic{hit("collision a=3 b=4", 0.5, 0), hit("collision a=0 b=5", 0.6, -3)};
  const std::vector<PhysicalDecision> ballistic{hit("collision a=3 b=4", 0.5, 0), captured,
                                                hit("collision a=1 b=4", 0.5, 0, true),
                                                hit("collision a=0 b=5", 0.6, -3)};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
  EXPECT_TRUE(compareModelDecisions(ballistic, classic).holds);
  // A capture by a hit that changed a velocity is a decision of its own: the other model must take it.
  std::vector<PhysicalDecision> real = ballistic;
  real[2].negligible = false;
  EXPECT_FALSE(compareModelDecisions(classic, real).holds);
}

TEST(ModelsAgreeComparison, AHitClosingWithinTheTolerancesInOneRunOnlyPartsTheRuns) {
  // A ball sliding along an absorber's top at 55 L/s, moving into it at 2e-13 L/s in one model
  // and 0 in the other, is captured in the first: the capture stops it, a change far beyond the
  // tolerance, but whether the hit happens at all was rounding's (seed 271828182, case 1283).
  PhysicalDecision capturingHit = hit("collision a=1 b=4", 0.5, 0);
  capturingHit.grazing = true;
  const std::vector<PhysicalDecision> classic{hit("collision a=3 b=4", 0.5, 55), hit("collision a=0 b=5", 0.6, -3)};
  const std::vector<PhysicalDecision> ballistic{classic[0], consequenceAt("captured 1 4", 0.5), capturingHit,
                                                classic[1]};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
  EXPECT_TRUE(compareModelDecisions(ballistic, classic).holds);
  // A ball passing over another at a tangent strikes it in one model only, 1e-10 L lower there
  // (seed 271828182, case 1802): no consequences, but velocities changed beyond the tolerance.
  PhysicalDecision passingHit = hit("collision a=7 b=11", 0.55, 0.001);
  passingHit.grazing = true;
  const std::vector<PhysicalDecision> struck{classic[0], passingHit, classic[1]};
  EXPECT_TRUE(compareModelDecisions(struck, classic).holds);
  EXPECT_TRUE(compareModelDecisions(classic, struck).holds);
  // A hit that closed faster than that is one the other model must have too.
  PhysicalDecision firmHit = passingHit;
  firmHit.grazing = false;
  EXPECT_FALSE(compareModelDecisions(classic, std::vector<PhysicalDecision>{classic[0], firmHit, classic[1]}).holds);
}

TEST(ModelsAgreeComparison, ExclusiveDecisionsWithinTheTimeToleranceAreANearTie) {
  const std::vector<PhysicalDecision> classic{hit("captured 5 9", 0.5, 0)};
  const std::vector<PhysicalDecision> ballistic{hit("collision a=3 b=9", 0.5 + 1e-16, -1)};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
  const std::vector<PhysicalDecision> apart{hit("collision a=3 b=9", 0.5 + 1e-6, -1)};
  EXPECT_FALSE(compareModelDecisions(classic, apart).holds);
}

// Campaign seed 20261121, case 140: a ball reaches an absorber's underside and a flipper's side at
// one instant. Classic strikes it off the flipper and then captures it 8e-16 s later; ballistic
// captures it at once, so the flipper hit never happens (the two models do the same at mpfr:256:
// the instant is a tie that every precision breaks by rounding).
TEST(ModelsAgreeComparison, AHitThatAReorderedNearTieRulesOutIsANearTie) {
  const std::vector<PhysicalDecision> classic{hit("collision a=2 b=5", 0.5, 1.9),
                                              hit("collision a=1 b=5", 0.5 + 8e-16, 0)};
  const std::vector<PhysicalDecision> ballistic{hit("collision a=1 b=5", 0.5 + 2e-16, 0)};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
  EXPECT_TRUE(compareModelDecisions(ballistic, classic).holds);
  // The same extra hit, but not where the two runs' order parted: a disagreement.
  const std::vector<PhysicalDecision> inOrder{hit("collision a=1 b=5", 0.5, 0),
                                              hit("collision a=2 b=5", 0.5 + 8e-16, 1.9)};
  EXPECT_FALSE(compareModelDecisions(inOrder, ballistic).holds);
  // And a hit missing long after a reordered pair still counts.
  std::vector<PhysicalDecision> later = classic;
  later.push_back(hit("collision a=3 b=5", 0.9, 2));
  std::vector<PhysicalDecision> laterBallistic = ballistic;
  EXPECT_TRUE(compareModelDecisions(later, laterBallistic).holds);  // parted at the near-tie first
  std::vector<PhysicalDecision> swapped{hit("collision a=4 b=6", 0.3 + 1e-14, 1), hit("collision a=7 b=8", 0.3, 1),
                                        hit("collision a=3 b=5", 0.9, 2)};
  const std::vector<PhysicalDecision> swappedShort{swapped[1], swapped[0]};
  EXPECT_FALSE(compareModelDecisions(swapped, swappedShort).holds);
}

TEST(ModelsAgreeComparison, TheSameEventPartedInTimeIsRoundingAmplified) {
  const std::vector<PhysicalDecision> classic{hit("collision a=1 b=9", 0.5, -2)};
  const std::vector<PhysicalDecision> ballistic{hit("collision a=1 b=9", 0.5 + 3e-9, -2)};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
}

}  // namespace
}  // namespace gizmo::verify::fuzz
