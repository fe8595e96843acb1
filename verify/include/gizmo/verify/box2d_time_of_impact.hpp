#pragma once
// Our times of impact against Box2D's b2TimeOfImpact, one contact at a time, for a ball swept
// in a straight line (docs/verification.md, "Cross-checking against Box2D"). Box2D does not aim
// at the contact: it stops when the cores come within box2dToiTarget ± kBox2dToiTolerance. So
// the expected Box2D time is computed with our own functions against Box2D's cores at those
// distances, which gives a window; a Box2D time outside the window (widened only by float
// rounding of Box2D's inputs) is a finding, printed with the exact inputs.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/vec2.hpp"

namespace gizmo::verify {

// What a sweep is aimed at. Our function may report another feature first (a ball aimed at a
// vertex can meet an edge); the comparison holds whatever it reports. A swinging flipper turns
// for one Box2D step (1/480 to 1/60 s) from somewhere in its swing; FlipperQuarterTurn sweeps the
// whole swing in one call, more than Box2D ever turns a body in one step (b2_maxRotation), where
// b2TimeOfImpact is known to miss contacts (docs/verification.md).
enum class SweepKind { Edge, Vertex, Circle, Ball, FlipperAtRest, FlipperSwinging, FlipperQuarterTurn };
inline constexpr std::array<SweepKind, 7> kSweepKinds{SweepKind::Edge,
                                                      SweepKind::Vertex,
                                                      SweepKind::Circle,
                                                      SweepKind::Ball,
                                                      SweepKind::FlipperAtRest,
                                                      SweepKind::FlipperSwinging,
                                                      SweepKind::FlipperQuarterTurn};
std::string_view sweepKindName(SweepKind kind);

struct StraightSweep {
  SweepKind kind = SweepKind::Edge;
  bool walls = false;  // the obstacle is the outer walls (else `gizmo`, unless kind is Ball)
  GizmoSpec gizmo;
  Vec2<double> p, v;            // the ball: centre at time 0 and its constant velocity
  Vec2<double> otherP, otherV;  // Ball: the other ball
  double swingStart = 0;        // a swinging flipper: how far into its forward swing it is at time 0, s
  double duration = 1;          // the sweep covers [0, duration]
};

// A sweep of the given kind from numbers in [0, 1): the same mapping serves the rapidcheck
// property and the seeded survey. It always starts the ball clear of the obstacle.
inline constexpr std::size_t kSweepRandoms = 8;
StraightSweep makeSweep(SweepKind kind, const std::array<double, kSweepRandoms>& u);

struct SweepVerdict {
  std::optional<double> ours;   // our time of impact
  std::string oursFeature;      // edge, vertex, circle, ball, flipper-side, flipper-end
  std::string box2dState;       // touching, separated, overlapped, failed
  std::optional<double> box2d;  // b2TimeOfImpact's time (touching only)
  // Box2D's window: the earliest time the cores can come within target + tolerance, and the
  // latest by which they must come within target − tolerance (none: no contact required).
  std::optional<double> earliest, latest;
  bool explained = false;
  std::string why;   // what is not explained (empty when explained)
  double depth = 0;  // our gap at Box2D's time, negated (touching only)
};
SweepVerdict compareSweep(const StraightSweep& sweep);

// The sweep's inputs exactly (hex floats), for a finding.
std::string describeSweep(const StraightSweep& sweep);

// Seeded random sweeps of every kind: per kind, how often each side finds a contact, the
// differences, and every finding.
struct SweepKindSurvey {
  SweepKind kind = SweepKind::Edge;
  int sweeps = 0;
  int oursHits = 0;
  int box2dHits = 0;
  double maxDifference = 0;  // max |box2d − ours| over sweeps where both hit, seconds
  // How deep past our contact Box2D's time puts the ball (our gap at that time, negated), over
  // the same sweeps: 3 linear slops ± the tolerance on faces and round features.
  double minDepth = 0, maxDepth = 0;
  int findingCount = 0;
  std::vector<std::string> findings;  // the first 20, each with its exact inputs
};
std::vector<SweepKindSurvey> surveySweeps(std::uint64_t seed, int perKind);

}  // namespace gizmo::verify
