#include "gizmo/verify/study_findings.hpp"

#include <algorithm>
#include <cmath>

namespace gizmo::verify {
namespace {

// The comparison with Box2D is with 2.4, the engine linked in (its cost is Box2D's own, where v3's
// includes WebAssembly and node).
bool isBox2d24(MethodFamily f) { return f == MethodFamily::Box2d || f == MethodFamily::Box2dNoBullet; }

bool isDouble(const PrecisionChoice& p) { return p.kind == Precision::Double; }

// The results of one family on a scene, coarse to fine, for the map and failsFrom.
std::vector<const MethodResult*> familyResults(const SceneReport& scene, MethodFamily family) {
  std::vector<const MethodResult*> out;
  for (const MethodResult& r : scene.results) {
    if (r.method.family != family) continue;
    if (family == MethodFamily::Classic && !isDouble(r.method.precision)) continue;
    out.push_back(&r);
  }
  // Classic ticks and Box2D steps are listed coarse to fine by the plan; precisions few bits first.
  return out;
}

std::string parameterOf(const MethodResult& r) {
  const std::string label = r.method.label();
  if (r.method.family == MethodFamily::Ballistic) return precisionName(r.method.precision);
  const std::size_t eq = label.find('=');
  const std::size_t end = label.find(' ', eq);
  return label.substr(eq + 1, end == std::string::npos ? std::string::npos : end - eq - 1);
}

}  // namespace

std::vector<ChartPoint> chartPoints(const SceneReport& scene) {
  std::vector<ChartPoint> points;
  for (std::size_t i = 0; i < scene.results.size(); ++i) {
    const MethodResult& r = scene.results[i];
    if (r.reference || !r.stopped.empty()) continue;
    points.push_back(ChartPoint{i, r.secondsPerBoardSecond.median, r.positionError});
  }
  return points;
}

std::vector<ChartPoint> paretoFront(const std::vector<ChartPoint>& points) {
  std::vector<ChartPoint> front;
  for (const ChartPoint& p : points) {
    const bool beaten = std::any_of(points.begin(), points.end(), [&](const ChartPoint& q) {
      return q.cost <= p.cost && q.error <= p.error && (q.cost < p.cost || q.error < p.error);
    });
    if (!beaten) front.push_back(p);
  }
  std::sort(front.begin(), front.end(), [](const ChartPoint& a, const ChartPoint& b) {
    return a.cost != b.cost ? a.cost < b.cost : a.result < b.result;
  });
  return front;
}

std::optional<Box2dComparison> compareBallisticDoubleWithBox2d(const SceneReport& scene) {
  const MethodResult* ours = nullptr;
  std::vector<const MethodResult*> box2d;
  for (const MethodResult& r : scene.results) {
    if (!r.stopped.empty()) continue;
    if (r.method.family == MethodFamily::Ballistic && isDouble(r.method.precision)) ours = &r;
    if (isBox2d24(r.method.family)) box2d.push_back(&r);
  }
  if (ours == nullptr || box2d.empty()) return std::nullopt;
  Box2dComparison c;
  c.scene = scene.scene.name;
  c.oursCost = ours->secondsPerBoardSecond.median;
  c.oursError = ours->positionError;
  // An error of exactly 0 (the scene's arithmetic is exact in double) is taken at the smallest
  // distance a 512-bit comparison tells apart from it, so that ratios stay finite.
  const double ourError = std::max(c.oursError, 1e-150);
  double cheapestAtError = INFINITY, dearest = 0, bestAtCost = INFINITY, cheapest = INFINITY, cheapestError = 0;
  for (const MethodResult* b : box2d) {
    const double cost = b->secondsPerBoardSecond.median;
    if (b->positionError <= c.oursError) cheapestAtError = std::min(cheapestAtError, cost);
    dearest = std::max(dearest, cost);
    if (cost <= c.oursCost) bestAtCost = std::min(bestAtCost, b->positionError);
    if (cost < cheapest) {
      cheapest = cost;
      cheapestError = b->positionError;
    }
  }
  c.speedupIsBound = !std::isfinite(cheapestAtError);
  c.speedupAtEqualError = (c.speedupIsBound ? dearest : cheapestAtError) / c.oursCost;
  c.accuracyGainIsBound = !std::isfinite(bestAtCost);
  c.accuracyGainAtEqualCost = (c.accuracyGainIsBound ? cheapestError : bestAtCost) / ourError;
  return c;
}

std::vector<StudyMethod> stabilityColumns(const StudyPlan& plan) {
  std::vector<StudyMethod> columns;
  for (const StudyMethod& m : plan.methods())
    if (m.family != MethodFamily::Classic || isDouble(m.precision)) columns.push_back(m);
  return columns;
}

std::vector<StabilityRow> stabilityMap(const StudyReport& report) {
  const std::vector<StudyMethod> columns = stabilityColumns(report.plan);
  std::vector<StabilityRow> rows;
  for (const SceneReport& s : report.scenes) {
    if (!s.scene.stress) continue;
    StabilityRow row{s.scene.name, {}};
    for (const StudyMethod& m : columns) {
      const std::string label = m.label();
      for (const MethodResult& r : s.results) {
        if (r.method.label() != label) continue;
        row.cells.push_back(StabilityCell{label, !r.stopped.empty() ? 2 : r.failed() ? 1 : 0});
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string failsFrom(const SceneReport& scene, MethodFamily family) {
  const std::vector<const MethodResult*> results = familyResults(scene, family);
  std::vector<std::string> failing;
  std::size_t prefix = 0;  // how many of the coarsest (fewest bits) fail in a row
  for (const MethodResult* r : results) {
    if (!r->failed()) continue;
    if (prefix == failing.size() && results[prefix] == r) ++prefix;
    failing.push_back(parameterOf(*r));
  }
  const char* parameter = family == MethodFamily::Ballistic ? "precision"
                          : family == MethodFamily::Classic ? "tick"
                                                            : "step size";
  if (failing.empty()) return "never fails";
  if (failing.size() == results.size()) return std::string("fails at every ") + parameter;
  if (prefix == failing.size()) {
    if (family == MethodFamily::Ballistic) return "fails up to " + failing.back();
    return std::string("fails for ") + (family == MethodFamily::Classic ? "h" : "dt") + " >= " + failing.back();
  }
  std::string list;
  for (const std::string& f : failing) list += (list.empty() ? "" : ", ") + f;
  return "fails at " + list + " only";
}

}  // namespace gizmo::verify
