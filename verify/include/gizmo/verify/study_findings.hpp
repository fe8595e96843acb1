#pragma once
// What the study's numbers say, computed once for the tables, the charts and the page: the
// Pareto front per scene, our ballistic double run against Box2D at equal error and at equal
// cost, and where each method fails on the stress scenes.
#include <optional>
#include <string>
#include <vector>

#include "gizmo/verify/study.hpp"

namespace gizmo::verify {

// The point a method makes on a scene's chart: cost (median wall seconds per board second)
// against error (largest ball position error at the sampling instants).
struct ChartPoint {
  std::size_t result = 0;  // index into SceneReport::results
  double cost = 0;
  double error = 0;
};
// Every method but the reference (its error is 0 by definition) and runs that stopped early.
std::vector<ChartPoint> chartPoints(const SceneReport& scene);
// The points no other point beats in both cost and error (ties do not beat), by cost.
std::vector<ChartPoint> paretoFront(const std::vector<ChartPoint>& points);

// Our ballistic double run against Box2D (with and without bullets) on one scene.
struct Box2dComparison {
  std::string scene;
  double oursCost = 0, oursError = 0;
  // Box2D's cheapest cost at our error or better, over ours. When no step size reaches our
  // error, the dearest Box2D run's cost over ours: a lower bound (`speedupIsBound`).
  double speedupAtEqualError = 0;
  bool speedupIsBound = false;
  // Box2D's smallest error at our cost or less, over ours. When every Box2D run costs more, the
  // cheapest one's error over ours: a lower bound, since a cheaper step is a longer one.
  double accuracyGainAtEqualCost = 0;
  bool accuracyGainIsBound = false;
};
std::optional<Box2dComparison> compareBallisticDoubleWithBox2d(const SceneReport& scene);

// Where a family of methods fails on a stress scene, its parameter from coarse to fine (tick,
// step size) or from few bits to many (precision).
struct StabilityCell {
  std::string method;  // the label
  int status = 0;      // 0 agrees with the reference, 1 fails (error or a wrong decision), 2 stopped
};
struct StabilityRow {
  std::string scene;
  std::vector<StabilityCell> cells;  // in stabilityColumns order
};
// The methods of the map: the ballistic model at each precision, the classic model in double at
// each tick, Box2D at each step size with and without bullets.
std::vector<StudyMethod> stabilityColumns(const StudyPlan& plan);
std::vector<StabilityRow> stabilityMap(const StudyReport& report);

// "fails for h >= 0.01", "fails at every step size", "never fails", or the failing parameters
// listed where failure is not monotone; for one family on one stress scene.
std::string failsFrom(const SceneReport& scene, MethodFamily family);

}  // namespace gizmo::verify
