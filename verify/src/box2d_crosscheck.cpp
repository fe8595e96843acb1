#include "gizmo/verify/box2d_crosscheck.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "gizmo/verify/box2d_mapping.hpp"
#include "trace.hpp"

namespace gizmo::verify {
namespace {

// Our run's collisions and samples, seen through the board's one observer seam.
class OurRecorder final : public BoardObserver<double> {
 public:
  OurRecorder(const GameBoard<double>& board, const BoardSpec& spec, RunRecord& record)
      : board_(board), record_(record) {
    for (const BallSpec& b : spec.balls) balls_.push_back(*board.find(b.name));
    tickBoundary(0);
  }

  void eventExecuted(const Event<double>& e, const EventOutcome<double>& outcome) override {
    if (e.kind != EventKind::Collision) return;
    const AbstractGizmo<double>& a = board_.gizmo(e.a);
    const AbstractGizmo<double>& b = board_.gizmo(e.b);
    const AbstractGizmo<double>& ball = a.asBall() ? a : b;
    const AbstractGizmo<double>& other = a.asBall() ? b : a;
    CollisionRecord hit = collisionRecord(e.time, ball.name(), other.name(), other.asBall() != nullptr);
    hit.position = board_.gizmo(*board_.find(hit.ball)).asBall()->positionAt(e.time);
    for (const BallChange<double>& c : outcome.balls())
      if (board_.gizmo(c.ball).name() == hit.ball) hit.position = c.position;
    record_.collisions.push_back(std::move(hit));
  }

  void tickBoundary(const double& time) override {
    TrajectorySample s;
    s.time = time;
    for (GizmoId id : balls_) s.positions.push_back(board_.gizmo(id).asBall()->positionAt(time));
    s.energy = board_.energy();
    record_.samples.push_back(s);
  }

 private:
  const GameBoard<double>& board_;
  RunRecord& record_;
  std::vector<GizmoId> balls_;
};

}  // namespace

TrajectorySample interpolate(const std::vector<TrajectorySample>& samples, double t) {
  const auto after = std::upper_bound(samples.begin(), samples.end(), t,
                                      [](double time, const TrajectorySample& s) { return time < s.time; });
  if (after == samples.end()) return samples.back();
  if (after == samples.begin()) return samples.front();
  const TrajectorySample& a = *(after - 1);
  const TrajectorySample& b = *after;
  const double f = std::clamp((t - a.time) / (b.time - a.time), 0.0, 1.0);
  TrajectorySample s;
  s.time = t;
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    s.positions.push_back(a.positions[i] + f * (b.positions[i] - a.positions[i]));
  s.energy = a.energy + f * (b.energy - a.energy);
  return s;
}

namespace {

void compareCollisions(const RunRecord& ours, const RunRecord& theirs, StepComparison& out) {
  const auto pairs = matchCollisions(ours.collisions, theirs.collisions, out.matchWindow);
  std::vector<bool> oursMatched(ours.collisions.size()), theirsMatched(theirs.collisions.size());
  double sum = 0;
  // The ball's centre stops up to target + tolerance past contact in Box2D (3.25 linear slops):
  // another engine's positions are held to the same depth.
  const double toiDepth = 3 * kBox2dLinearSlop + kBox2dToiTolerance;
  std::size_t counted = 0;
  for (const auto& [i, j] : pairs) {
    oursMatched[i] = theirsMatched[j] = true;
    if (std::min(ours.collisions[i].time, theirs.collisions[j].time) > out.end) continue;
    ++counted;
    const double dtErr = std::fabs(theirs.collisions[j].time - ours.collisions[i].time);
    const double dp = length(theirs.collisions[j].position - ours.collisions[i].position);
    out.maxTimeError = std::max(out.maxTimeError, dtErr);
    out.maxPositionError = std::max(out.maxPositionError, dp);
    out.matchedWithinToi += dp <= toiDepth;
    sum += dtErr;
  }
  out.matched = counted;
  out.meanTimeError = counted == 0 ? 0 : sum / double(counted);
  // Both runs went on past the end by the match window, so that a collision near the end can
  // find its partner just after it; collisions after the end count only as partners.
  const double end = out.end;
  auto missed = [&](const std::vector<CollisionRecord>& list, const std::vector<bool>& matched, std::size_t k) {
    return !matched[k] && list[k].time <= end;
  };
  out.theirCollisions = std::count_if(theirs.collisions.begin(), theirs.collisions.end(),
                                      [&](const CollisionRecord& r) { return r.time <= end; });
  out.missedByThem = out.missedByUs = 0;
  for (std::size_t k = 0; k < oursMatched.size(); ++k) out.missedByThem += missed(ours.collisions, oursMatched, k);
  for (std::size_t k = 0; k < theirsMatched.size(); ++k) out.missedByUs += missed(theirs.collisions, theirsMatched, k);
  std::size_t i = 0, j = 0;
  while (i < oursMatched.size() && !missed(ours.collisions, oursMatched, i)) ++i;
  while (j < theirsMatched.size() && !missed(theirs.collisions, theirsMatched, j)) ++j;
  const bool ourFirst =
      i < oursMatched.size() && (j == theirsMatched.size() || ours.collisions[i].time <= theirs.collisions[j].time);
  if (ourFirst) out.firstUnmatched = UnmatchedCollision{"ours", ours.collisions[i]};
  else if (j < theirsMatched.size()) out.firstUnmatched = UnmatchedCollision{"theirs", theirs.collisions[j]};
}

void compareTrajectories(const RunRecord& ours, const RunRecord& theirs, StepComparison& out) {
  std::size_t n = 0;
  while (n < ours.samples.size() && ours.samples[n].time <= out.end) ++n;
  const std::size_t every = std::max<std::size_t>(1, (n + 49) / 50);
  for (std::size_t k = 0; k < n; ++k) {
    const TrajectorySample& a = ours.samples[k];
    const TrajectorySample b = interpolate(theirs.samples, a.time);
    double d = 0;
    for (std::size_t i = 0; i < a.positions.size(); ++i) d = std::max(d, length(b.positions[i] - a.positions[i]));
    out.maxDivergence = std::max(out.maxDivergence, d);
    for (std::size_t l = 0; l < kDivergenceLevels.size(); ++l)
      if (!out.divergenceFrom[l] && d > kDivergenceLevels[l]) out.divergenceFrom[l] = a.time;
    if (!out.parting && d > kPartingLevel) out.parting = PartingCheck{a.time, a.positions, b.positions, {}, 0, 0, ""};
    if (k % every == 0 || k + 1 == n) out.divergence.emplace_back(a.time, d);
    // Relative to the larger of our energy now and at the start: a capture takes a ball's energy
    // to 0 on one side first, which would otherwise divide by nothing.
    const double scale = std::max(std::fabs(a.energy), std::fabs(ours.samples.front().energy));
    if (scale > 0) out.maxEnergyDifference = std::max(out.maxEnergyDifference, std::fabs(b.energy - a.energy) / scale);
  }
  out.energyEnd = interpolate(theirs.samples, out.end).energy;
}

// Every engine run: the collisions (when the engine gave them) and the paths.
StepComparison compareRun(const RunRecord& ours, const RunRecord& theirs, double dt, double end, bool withCollisions) {
  StepComparison c;
  c.dt = dt;
  c.end = end;
  c.matchWindow = matchWindow(dt);
  c.collisionsCompared = withCollisions;
  if (withCollisions) compareCollisions(ours, theirs, c);
  compareTrajectories(ours, theirs, c);
  c.wallSeconds = theirs.wallSeconds;
  return c;
}

// Our run of the request on past its end by `window`, and the report's figures of our side.
RunRecord runOurSide(const RunRequest& request, double window, CrosscheckReport& report) {
  const double end = request.duration;
  RunRequest longer = request;
  longer.duration = end + window;
  std::uint64_t eventsLonger = 0;
  RunRecord ours = runOurs(longer, eventsLonger);
  report.ourCollisions = std::count_if(ours.collisions.begin(), ours.collisions.end(),
                                       [&](const CollisionRecord& c) { return c.time <= end; });
  report.energyStart = ours.samples.front().energy;
  for (const TrajectorySample& s : ours.samples)
    if (s.time <= end) report.ourEnergyEnd = s.energy;
  const auto start = std::chrono::steady_clock::now();
  report.ourEvents = simulate<double>(request).total;
  report.ourWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return ours;
}

double largestDistance(const std::vector<Vec2<double>>& a, const std::vector<Vec2<double>>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, length(a[i] - b[i]));
  return d;
}

// Where the paths part, the balls of a run of the same request at mpfr:256: one run for every
// parting (each is one of our tick boundaries, where that run can be sampled).
void checkPartings(const RunRequest& request, std::vector<StepComparison>& steps) {
  TraceExtras extras;
  for (const StepComparison& s : steps)
    if (s.parting) extras.sampleAt.push_back(s.parting->time);
  if (extras.sampleAt.empty()) return;
  std::sort(extras.sampleAt.begin(), extras.sampleAt.end());
  extras.sampleAt.erase(std::unique(extras.sampleAt.begin(), extras.sampleAt.end()), extras.sampleAt.end());
  std::vector<TraceSample> samples;
  extras.samples = &samples;
  extras.stopAtDifference = false;
  traceAt(PrecisionChoice{Precision::Mpfr, 256}, request, nullptr, nullptr, std::numeric_limits<std::size_t>::max(),
          extras);
  for (StepComparison& s : steps) {
    if (!s.parting) continue;
    PartingCheck& p = *s.parting;
    const auto at =
        std::find_if(samples.begin(), samples.end(), [&](const TraceSample& r) { return r.time == p.time; });
    if (at == samples.end()) throw std::logic_error("the mpfr:256 run was not sampled where the paths part");
    for (std::size_t i = 0; i < at->x.size(); ++i) p.reference.emplace_back(at->x[i].toDouble(), at->y[i].toDouble());
    p.oursOff = largestDistance(p.ours, p.reference);
    p.theirsOff = largestDistance(p.theirs, p.reference);
    p.agreesWith = p.oursOff <= p.theirsOff ? "ours" : "theirs";
  }
}

}  // namespace

double matchWindow(double dt) { return std::max(0.05, 3 * dt); }

std::vector<std::pair<std::size_t, std::size_t>> matchCollisions(const std::vector<CollisionRecord>& ours,
                                                                 const std::vector<CollisionRecord>& box2d,
                                                                 double window) {
  // Every candidate pair of the same ball and gizmo within the window in time and within
  // kMatchDistance in space (a hit on the far side of the same gizmo, or on another wall, is
  // another collision), closest in time first (ties by index), taken greedily: deterministic,
  // and no collision is used twice.
  std::map<std::pair<std::string, std::string>, std::vector<std::size_t>> byPair;
  for (std::size_t j = 0; j < box2d.size(); ++j) byPair[{box2d[j].ball, box2d[j].other}].push_back(j);
  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const auto it = byPair.find({ours[i].ball, ours[i].other});
    if (it == byPair.end()) continue;
    for (std::size_t j : it->second) {
      const double d = std::fabs(box2d[j].time - ours[i].time);
      if (d <= window && length(box2d[j].position - ours[i].position) <= kMatchDistance)
        candidates.emplace_back(d, i, j);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> usedOurs(ours.size()), usedTheirs(box2d.size());
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const auto& [d, i, j] : candidates) {
    if (usedOurs[i] || usedTheirs[j]) continue;
    usedOurs[i] = usedTheirs[j] = true;
    out.emplace_back(i, j);
  }
  std::sort(out.begin(), out.end());
  return out;
}

RunRecord runOurs(const RunRequest& request, std::uint64_t& events) {
  RunRecord record;
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(request);
  OurRecorder recorder(*board, request.board, record);
  board->setObserver(&recorder);
  continueRun(*board, request, 0);
  events = board->executedTotal();
  return record;
}

CrosscheckReport crosscheck(const CrosscheckOptions& options) {
  CrosscheckReport report;
  const double end = options.request.duration;
  double longestWindow = 0;
  for (double dt : options.steps) longestWindow = std::max(longestWindow, matchWindow(dt));
  const RunRecord ours = runOurSide(options.request, longestWindow, report);
  RunRequest longer = options.request;
  longer.duration = end + longestWindow;
  for (double dt : options.steps) {
    Box2dOptions b = options.box2d;
    b.dt = dt;
    RunRecord theirs = runBox2d(longer, b);
    StepComparison c = compareRun(ours, theirs, dt, end, true);
    c.steps = static_cast<std::uint64_t>(std::ceil(end / dt - 1e-9));
    c.speedCappedSteps = theirs.speedCappedSteps;
    c.rotationCappedSteps = theirs.rotationCappedSteps;
    if (options.keepBox2dSamples) c.box2dSamples = std::move(theirs.samples);
    report.steps.push_back(std::move(c));
  }
  checkPartings(options.request, report.steps);
  return report;
}

CrosscheckReport crosscheckRuns(const RunRequest& request, const std::vector<EngineRun>& runs) {
  CrosscheckReport report;
  const double end = request.duration;
  double longestWindow = 0;
  for (const EngineRun& r : runs) longestWindow = std::max(longestWindow, matchWindow(r.dt));
  const RunRecord ours = runOurSide(request, longestWindow, report);
  for (const EngineRun& r : runs) {
    StepComparison c = compareRun(ours, r.record, r.dt, end, r.withCollisions);
    // What the engine counted (the driver's runs do; a trace has no field for it: 0).
    c.speedCappedSteps = r.record.speedCappedSteps;
    c.rotationCappedSteps = r.record.rotationCappedSteps;
    c.steps = static_cast<std::uint64_t>(
        std::count_if(r.record.samples.begin(), r.record.samples.end(),
                      [&](const TrajectorySample& s) { return s.time > 0 && s.time <= end; }));
    report.steps.push_back(std::move(c));
  }
  checkPartings(request, report.steps);
  return report;
}

}  // namespace gizmo::verify
