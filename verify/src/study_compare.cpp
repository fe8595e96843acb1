#include "study_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gizmo/verify/box2d_crosscheck.hpp"
#include "gizmo/verify/study.hpp"

namespace gizmo::verify {
namespace {

// The largest distance over the balls at one instant.
double sampleDistance(const TraceSample& a, const TraceSample& b) {
  double d = 0;
  for (std::size_t i = 0; i < std::min(a.x.size(), b.x.size()); ++i)
    d = std::max(d, distance(a.x[i], a.y[i], b.x[i], b.y[i]));
  return d;
}

std::string describe(const char* side, const CollisionRecord& c) {
  char text[200];
  std::snprintf(text, sizeof text, "%s collision of %s with %s at %.6f s, (%.4f, %.4f)", side, c.ball.c_str(),
                c.other.c_str(), c.time, c.position.x, c.position.y);
  return text;
}

}  // namespace

StudyRun studyRunOf(const Trace& trace, std::vector<TraceSample> samples, const BoardSpec& board) {
  // The ids of a board built from the spec are the same in every scalar: name them once.
  const std::unique_ptr<GameBoard<double>> names = buildBoard<double>(board, PhysicsParams<double>());
  StudyRun run;
  for (const TracePoint& p : trace) {
    if (p.kind != EventKind::Collision) continue;
    const AbstractGizmo<double>& a = names->gizmo(p.a);
    const AbstractGizmo<double>& b = names->gizmo(p.b);
    const AbstractGizmo<double>& ball = a.asBall() ? a : b;
    const AbstractGizmo<double>& other = a.asBall() ? b : a;
    const double time = p.time.toDouble();
    CollisionRecord hit = collisionRecord(time, ball.name(), other.name(), other.asBall() != nullptr);
    for (std::uint8_t i = 0; i < p.ballCount; ++i)
      if (names->gizmo(p.ball[i]).name() == hit.ball) hit.position = Vec2<double>(p.x[i].toDouble(), p.y[i].toDouble());
    run.collisions.push_back(std::move(hit));
    run.collisionTimes.push_back(p.time);
  }
  run.samples = std::move(samples);
  return run;
}

StudyRun studyRunOf(const RunRecord& record, const std::vector<double>& instants, std::size_t balls) {
  StudyRun run;
  run.collisions = record.collisions;
  for (const CollisionRecord& c : record.collisions) run.collisionTimes.push_back(WideValue::of(c.time));
  for (double t : instants) {
    const TrajectorySample s = interpolate(record.samples, t);
    TraceSample sample;
    sample.time = t;
    for (std::size_t i = 0; i < balls; ++i) {
      sample.x.push_back(WideValue::of(s.positions[i].x));
      sample.y.push_back(WideValue::of(s.positions[i].y));
    }
    sample.energy = WideValue::of(s.energy);
    run.samples.push_back(std::move(sample));
  }
  return run;
}

double largestPositionDistance(const std::vector<TraceSample>& a, const std::vector<TraceSample>& b) {
  double d = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) d = std::max(d, sampleDistance(a[k], b[k]));
  return d;
}

RunErrors compareWithReference(const StudyRun& reference, const StudyRun& run, double end, double window) {
  RunErrors e;
  // Positions and energy at the instants both runs reached.
  std::vector<double> perInstant;
  const double energyStart = reference.samples.empty() ? 0 : std::fabs(reference.samples.front().energy.toDouble());
  for (std::size_t k = 0; k < std::min(reference.samples.size(), run.samples.size()); ++k) {
    const double d = sampleDistance(reference.samples[k], run.samples[k]);
    perInstant.push_back(d);
    if (!e.divergedAt && d > kFailDistance) e.divergedAt = reference.samples[k].time;
    // Relative to the larger of the reference's energy now and at the start: a capture takes a
    // ball's energy to 0, which would otherwise divide by nothing.
    const double scale = std::max(std::fabs(reference.samples[k].energy.toDouble()), energyStart);
    const double drift = distance(run.samples[k].energy, reference.samples[k].energy);
    e.energyDrift = std::max(e.energyDrift, scale > 0 ? drift / scale : drift);
  }
  if (!perInstant.empty()) {
    e.positionError = *std::max_element(perInstant.begin(), perInstant.end());
    std::nth_element(perInstant.begin(), perInstant.begin() + std::ptrdiff_t(perInstant.size() / 2), perInstant.end());
    e.positionErrorMedian = perInstant[perInstant.size() / 2];
  }

  // Collisions: the first one either side made without a partner is the first wrong decision;
  // event times are compared over the pairs before it.
  const auto pairs = matchCollisions(reference.collisions, run.collisions, window);
  std::vector<bool> refMatched(reference.collisions.size()), runMatched(run.collisions.size());
  for (const auto& [i, j] : pairs) refMatched[i] = runMatched[j] = true;
  const double countedUntil = end - window;
  auto firstUnmatched = [&](const std::vector<CollisionRecord>& list,
                            const std::vector<bool>& matched) -> std::optional<std::size_t> {
    for (std::size_t k = 0; k < list.size(); ++k)
      if (!matched[k] && list[k].time <= countedUntil) return k;
    return std::nullopt;
  };
  const std::optional<std::size_t> missed = firstUnmatched(reference.collisions, refMatched);
  const std::optional<std::size_t> extra = firstUnmatched(run.collisions, runMatched);
  if (missed && (!extra || reference.collisions[*missed].time <= run.collisions[*extra].time)) {
    e.firstWrongTime = reference.collisions[*missed].time;
    e.firstWrong = describe("missed the reference's", reference.collisions[*missed]);
  } else if (extra) {
    e.firstWrongTime = run.collisions[*extra].time;
    e.firstWrong = describe("made a", run.collisions[*extra]) + " that the reference does not";
  }
  double sum = 0;
  for (const auto& [i, j] : pairs) {
    if (e.firstWrongTime && reference.collisions[i].time >= *e.firstWrongTime) continue;
    if (reference.collisions[i].time > end) continue;
    const double dt = distance(reference.collisionTimes[i], run.collisionTimes[j]);
    e.eventTimeError = std::max(e.eventTimeError, dt);
    sum += dt;
    ++e.matched;
  }
  e.meanEventTimeError = e.matched == 0 ? 0 : sum / double(e.matched);
  return e;
}

}  // namespace gizmo::verify
