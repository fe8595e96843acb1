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
  const std::vector<PhysicalDecision> classic{hit("collision a=1 b=9", 0.5, -2), hit("collision a=3 b=8", 0.5 + 1e-14, 3),
                                              hit("collision a=2 b=9", 0.75, 2)};
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

TEST(ModelsAgreeComparison, ExclusiveDecisionsWithinTheTimeToleranceAreANearTie) {
  const std::vector<PhysicalDecision> classic{hit("captured 5 9", 0.5, 0)};
  const std::vector<PhysicalDecision> ballistic{hit("collision a=3 b=9", 0.5 + 1e-16, -1)};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
  const std::vector<PhysicalDecision> apart{hit("collision a=3 b=9", 0.5 + 1e-6, -1)};
  EXPECT_FALSE(compareModelDecisions(classic, apart).holds);
}

TEST(ModelsAgreeComparison, TheSameEventPartedInTimeIsRoundingAmplified) {
  const std::vector<PhysicalDecision> classic{hit("collision a=1 b=9", 0.5, -2)};
  const std::vector<PhysicalDecision> ballistic{hit("collision a=1 b=9", 0.5 + 3e-9, -2)};
  EXPECT_TRUE(compareModelDecisions(classic, ballistic).holds);
}

}  // namespace
}  // namespace gizmo::verify::fuzz
