#include "gizmo/verify/box2d_time_of_impact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/outer_walls.hpp"
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"
#include "gizmo/core/math/trig.hpp"
#include "gizmo/verify/box2d_board_access.hpp"
#include "gizmo/verify/box2d_shapes.hpp"

namespace gizmo::verify {
namespace {

constexpr double kR = kBallRadius;
constexpr double kTwoPi = 6.283185307179586;

// Unit vector at angle a (from +x towards +y), with the core's deterministic sine and cosine so
// that a seed gives the same sweeps on every machine.
Vec2<double> direction(double a) {
  double s, c;
  math::sinCos(a, s, c);
  return Vec2<double>(c, s);
}
Vec2<double> turned(const Vec2<double>& d, double a) {
  const Vec2<double> u = direction(a);
  return Vec2<double>(u.x * d.x - u.y * d.y, u.y * d.x + u.x * d.y);
}
Vec2<double> unit(const Vec2<double>& d) { return (1 / length(d)) * d; }

double distanceToSegment(const Vec2<double>& p, const Vec2<double>& a, const Vec2<double>& b) {
  const Vec2<double> ab = b - a;
  double u = dot(p - a, ab) / lengthSquared(ab);
  u = std::clamp(u, 0.0, 1.0);
  return length(p - (a + u * ab));
}

// Distance from p to a shape's surface (negative inside a circle feature; edges count from
// both sides, which is what a clearance check and a depth need).
double distanceToShape(const Shape<double>& shape, const Vec2<double>& p) {
  double best = 1e300;
  for (const SegmentFeature<double>& s : shape.segments) best = std::min(best, distanceToSegment(p, s.a, s.b));
  for (const CircleFeature<double>& c : shape.circles) best = std::min(best, length(p - c.centre) - c.radius);
  return best;
}

GizmoSpec gizmoAt(GizmoType type, int orientation) {
  GizmoSpec g;
  g.type = type;
  g.name = "G";
  g.x = 8;
  g.y = 8;
  g.orientation = orientation;
  g.width = g.height = ownSide(type);
  return g;
}

int quarterFrom(double u) { return std::min(3, static_cast<int>(u * 4)) * 90; }

// Our shape of the obstacle at rest (a flipper's capsule at its rest angle).
Shape<double> obstacleShape(const StraightSweep& s) {
  return s.walls ? outerWallsShape<double>() : restShape<double>(s.gizmo);
}

// The ball placed so that its centre reaches the contact centre c (normal nrm) after
// travelling `travel` along d at `speed`; the sweep lasts a little longer than that. A start
// that is not clear of the obstacle (an oblique path that passes through it first) becomes a
// head-on approach along the normal.
void aim(StraightSweep& s, const Vec2<double>& c, const Vec2<double>& nrm, Vec2<double> d, double speed, double travel,
         double stretch) {
  const Vec2<double> start = c - travel * d;
  const double lo = kR + 0.02, hi = kBoardSize - lo;
  const bool inBoard = start.x >= lo && start.x <= hi && start.y >= lo && start.y <= hi;
  if (distanceToShape(obstacleShape(s), start) < lo || (s.walls && !inBoard)) d = -nrm;
  s.v = speed * d;
  s.p = c - travel * d;
  s.duration = (travel / speed) / (0.1 + 0.8 * stretch);
}

bool flipperSwings(const StraightSweep& s) {
  return s.kind == SweepKind::FlipperSwinging || s.kind == SweepKind::FlipperQuarterTurn;
}

// The core's flipper of the sweep; a swinging one was triggered at rest swingStart seconds
// before time 0, so that at time 0 it is that far into its forward swing.
std::unique_ptr<Flipper<double>> flipperOf(const StraightSweep& s) {
  auto flipper = std::make_unique<Flipper<double>>(s.gizmo);
  if (flipperSwings(s)) {
    PhysicsParams<double> params;
    DrivenBoardAccess access(
        params, [](GizmoId) -> Ball<double>& { throw std::logic_error("a flipper's trigger needs no ball"); });
    access.setNow(-s.swingStart);
    flipper->fireTrigger(access);
  }
  return flipper;
}

}  // namespace

std::string_view sweepKindName(SweepKind kind) {
  switch (kind) {
    case SweepKind::Edge: return "edge";
    case SweepKind::Vertex: return "vertex";
    case SweepKind::Circle: return "circle";
    case SweepKind::Ball: return "ball";
    case SweepKind::FlipperAtRest: return "flipper-at-rest";
    case SweepKind::FlipperSwinging: return "flipper-swinging";
    case SweepKind::FlipperQuarterTurn: return "flipper-quarter-turn";
  }
  return "?";
}

// u[0] the obstacle, u[1] where on it, u[2] the approach angle, u[3] how long the sweep runs on
// after the contact, u[4] the speed, u[5] the distance travelled to the contact, u[6] and u[7]
// what else the kind needs.
StraightSweep makeSweep(SweepKind kind, const std::array<double, kSweepRandoms>& u) {
  StraightSweep s;
  s.kind = kind;
  const double speed = 0.5 + 59.5 * u[4] * u[4];  // slow ones as often as fast ones
  const double travel = 0.05 + 4 * u[5];
  const double approach = (u[2] - 0.5) * 2.4;  // up to ±69° off head-on
  switch (kind) {
    case SweepKind::Edge: {
      if (u[0] < 0.2) s.walls = true;
      else
        s.gizmo =
            u[0] < 0.6 ? gizmoAt(GizmoType::Square, 0) : gizmoAt(GizmoType::Triangle, quarterFrom((u[0] - 0.6) / 0.4));
      const Shape<double> shape = obstacleShape(s);
      const SegmentFeature<double>& e =
          shape.segments.at(std::min(shape.segments.size() - 1, std::size_t(u[6] * shape.segments.size())));
      const Vec2<double> at = e.a + ((0.05 + 0.9 * u[1]) * e.length) * e.direction;
      aim(s, at + kR * e.normal, e.normal, turned(-e.normal, approach), speed, travel, u[3]);
      break;
    }
    case SweepKind::Vertex: {
      s.gizmo =
          u[0] < 0.4 ? gizmoAt(GizmoType::Square, 0) : gizmoAt(GizmoType::Triangle, quarterFrom((u[0] - 0.4) / 0.6));
      const Shape<double> shape = restShape<double>(s.gizmo);
      const std::size_t n = shape.segments.size(), i = std::min(n - 1, std::size_t(u[6] * n));
      // The contact normal lies between the normals of the two edges that meet at vertex i.
      const Vec2<double> nrm =
          unit((1 - u[1]) * shape.segments[(i + n - 1) % n].normal + u[1] * shape.segments[i].normal);
      aim(s, shape.segments[i].a + kR * nrm, nrm, turned(-nrm, 0.8 * approach), speed, travel, u[3]);
      break;
    }
    case SweepKind::Circle: {
      s.gizmo = gizmoAt(GizmoType::Circle, 0);
      const CircleFeature<double> c = restShape<double>(s.gizmo).circles.at(0);
      const Vec2<double> nrm = direction(kTwoPi * u[1]);
      aim(s, c.centre + (c.radius + kR) * nrm, nrm, turned(-nrm, approach), speed, travel, u[3]);
      break;
    }
    case SweepKind::Ball: {
      // The other ball meets ours at (10, 10); both move, the relative motion aims at contact.
      const Vec2<double> q(10, 10), nrm = direction(kTwoPi * u[1]);
      s.otherV = (20 * u[6]) * direction(kTwoPi * u[0]);
      const Vec2<double> relative = speed * turned(-nrm, approach);
      s.v = s.otherV + relative;
      const double hit = travel / speed;
      s.p = q + (2 * kR) * nrm - hit * s.v;
      s.otherP = q - hit * s.otherV;
      s.duration = hit / (0.1 + 0.8 * u[3]);
      break;
    }
    case SweepKind::FlipperAtRest: {
      s.gizmo =
          gizmoAt(u[0] < 0.5 ? GizmoType::LeftFlipper : GizmoType::RightFlipper, quarterFrom(std::fmod(2 * u[0], 1.0)));
      const Shape<double> capsule = restShape<double>(s.gizmo);  // sides 0 and 1, ends 2 (pivot) and 3 (tip)
      Vec2<double> c, nrm;
      if (u[1] < 0.6) {
        const SegmentFeature<double>& side = capsule.segments.at(u[1] < 0.3 ? 0 : 1);
        const double along = (u[1] < 0.3 ? u[1] : u[1] - 0.3) / 0.3;
        nrm = side.normal;
        c = side.a + (along * side.length) * side.direction + kR * nrm;
      } else {
        const CircleFeature<double>& end = capsule.circles.at(u[1] < 0.8 ? 0 : 1);
        const CircleFeature<double>& other = capsule.circles.at(u[1] < 0.8 ? 1 : 0);
        // Within the half-circle that faces away from the other end.
        nrm = turned(unit(end.centre - other.centre), (u[7] - 0.5) * 3.0);
        c = end.centre + (end.radius + kR) * nrm;
      }
      aim(s, c, nrm, turned(-nrm, approach), speed, travel, u[3]);
      break;
    }
    case SweepKind::FlipperSwinging:
    case SweepKind::FlipperQuarterTurn: {
      s.gizmo =
          gizmoAt(u[0] < 0.5 ? GizmoType::LeftFlipper : GizmoType::RightFlipper, quarterFrom(std::fmod(2 * u[0], 1.0)));
      // One Box2D step of a swing (1/480 to 1/60 s, from anywhere in it), or the whole quarter turn.
      const double swing = 1.0 / 12;
      if (kind == SweepKind::FlipperSwinging) {
        s.swingStart = 0.8 * swing * u[7];
        s.duration = std::min(swing - s.swingStart, 1.0 / 480 + (1.0 / 60 - 1.0 / 480) * u[3]);
      } else {
        s.duration = swing;
      }
      const SwingingAxis<double> axis = flipperOf(s)->axisAt(0);
      const Vec2<double> along = axis.direction(0);
      // The side the bar turns towards: ω > 0 turns +x towards +y, i.e. towards perpendicular(along).
      const Vec2<double> ahead = axis.omega > 0 ? perpendicular(along) : -perpendicular(along);
      // Beside the bar, a little ahead of it, moving anywhere at up to 30 L/s.
      const double gap = kind == SweepKind::FlipperSwinging ? 0.02 + 0.4 * u[6] : 0.02 + 1.5 * u[6];
      s.p = axis.pivot + (axis.length * u[1]) * along + (axis.radius + kR + gap) * ahead;
      s.v = (30 * u[4] * u[4]) * direction(kTwoPi * u[2]);
      break;
    }
  }
  return s;
}

namespace {

// --- our side: the core's own gizmos answer -------------------------------------------------------

struct OurHit {
  std::optional<double> tau;
  std::string feature;
};

PhysicsParams<double> straightLines() {
  PhysicsParams<double> p;
  p.model = MotionModel::Classic;  // a = 0: the ball moves in a straight line
  return p;
}

OurHit ourTime(const StraightSweep& s) {
  const PhysicsParams<double> params = straightLines();
  Ball<double> ball("B", s.p, s.v);
  ball.setId(1);
  ball.setState(0, s.p, s.v, params);
  auto featureOf = [](const Shape<double>& shape, std::int32_t f) -> std::string {
    const std::size_t i = static_cast<std::size_t>(f);
    if (i < shape.segments.size()) return "edge";
    return shape.circles.at(i - shape.segments.size()).radius == 0 ? "vertex" : "circle";
  };
  if (s.kind == SweepKind::Ball) {
    Ball<double> other("C", s.otherP, s.otherV);
    other.setId(2);
    other.setState(0, s.otherP, s.otherV, params);
    const auto c = ball.timeUntilCollision(other, 0, s.duration, params);
    return OurHit{c ? std::optional<double>(c->time) : std::nullopt, "ball"};
  }
  if (s.walls) {
    OuterWalls<double> walls;
    const auto c = walls.timeUntilCollision(ball, 0, s.duration, params);
    return OurHit{c ? std::optional<double>(c->time) : std::nullopt, "edge"};
  }
  if (swings(s.gizmo.type)) {
    const auto c = flipperOf(s)->timeUntilCollision(ball, 0, s.duration, params);
    if (!c) return OurHit{};
    return OurHit{c->time, c->feature < 2 ? "flipper-side" : "flipper-end"};
  }
  GridBumper<double> bumper(s.gizmo);
  const auto c = bumper.timeUntilCollision(ball, 0, s.duration, params);
  if (!c) return OurHit{};
  return OurHit{c->time, featureOf(bumper.shape(), c->feature)};
}

// Our gap (distance between surfaces) at time t, for the depth of Box2D's stop.
double ourGapAt(const StraightSweep& s, double t) {
  const Vec2<double> p = s.p + t * s.v;
  if (s.kind == SweepKind::Ball) return length(p - (s.otherP + t * s.otherV)) - 2 * kR;
  if (flipperSwings(s)) {
    const SwingingAxis<double> axis = flipperOf(s)->axisAt(0);
    return distanceToSegment(p, axis.pivot, axis.pivot + axis.length * axis.direction(t)) - axis.radius - kR;
  }
  return distanceToShape(obstacleShape(s), p) - kR;
}

// --- Box2D's side -----------------------------------------------------------------------------

b2Sweep makeSweepB2(const Vec2<double>& c0, const Vec2<double>& c1, double a0, double a1) {
  b2Sweep w;  // no constructor: every field, alpha0 too
  w.localCenter.SetZero();
  w.c0 = toBox2d(c0);
  w.c = toBox2d(c1);
  w.a0 = static_cast<float>(a0);
  w.a = static_cast<float>(a1);
  w.alpha0 = 0;
  return w;
}

struct Box2dHit {
  std::string state = "separated";
  std::optional<double> t;
};

Box2dHit box2dTime(const StraightSweep& s) {
  b2CircleShape ballShape;
  ballShape.m_radius = static_cast<float>(kR);
  const b2Sweep ballSweep = makeSweepB2(s.p, s.p + s.duration * s.v, 0, 0);
  Box2dHit result;
  auto run = [&](const b2Shape& shape, const b2Sweep& sweep) {
    b2TOIInput in;
    in.proxyA.Set(&ballShape, 0);
    in.proxyB.Set(&shape, 0);
    in.sweepA = ballSweep;
    in.sweepB = sweep;
    in.tMax = 1;
    b2TOIOutput out;
    b2TimeOfImpact(&out, &in);
    if (out.state == b2TOIOutput::e_overlapped) result.state = "overlapped";
    else if (out.state == b2TOIOutput::e_failed && result.state != "overlapped") result.state = "failed";
    else if (out.state == b2TOIOutput::e_touching) {
      const double t = double(out.t) * s.duration;
      if (!result.t || t < *result.t) result.t = t;
      if (result.state == "separated") result.state = "touching";
    }
  };
  if (s.kind == SweepKind::Ball) {
    b2CircleShape other;
    other.m_radius = static_cast<float>(kR);
    run(other, makeSweepB2(s.otherP, s.otherP + s.duration * s.otherV, 0, 0));
    return result;
  }
  const Box2dBody body = s.walls ? box2dOuterWalls() : box2dBodyOf(s.gizmo);
  double a0 = body.angle, turn = 0;
  if (flipperSwings(s)) {
    // The angle on the forward swing, swingStart into it, and the turn over the sweep.
    const double omega = flipperLayout(s.gizmo.type, s.gizmo.orientation).forwardSign * 6 * piOf<double>();
    a0 += omega * s.swingStart;
    turn = omega * s.duration;
  }
  const b2Sweep still = makeSweepB2(body.origin, body.origin, a0, a0 + turn);
  for (const Box2dPart& part : body.parts) run(*makeBox2dShape(part), still);
  return result;
}

// --- what Box2D should answer ---------------------------------------------------------------------

// Our first time at which the ball's centre comes within Box2D's stop distance of Box2D's cores,
// the stop distance moved by `shift` (positive: further out, so earlier).
std::optional<double> box2dStop(const StraightSweep& s, double shift) {
  const Trajectory<double> path{s.p, s.v, Vec2<double>()};
  if (s.kind == SweepKind::Ball) {
    const Trajectory<double> other{s.otherP, s.otherV, Vec2<double>()};
    return ballTimeOfImpact(path, other, (box2dToiTarget(2 * kR) + shift) / 2, s.duration);
  }
  if (flipperSwings(s)) {
    // The three turning parts stop the ball exactly where a capsule of the flipper's radius
    // stops a ball of radius target − radius (box2d_mapping.cpp: their union is the capsule).
    const SwingingAxis<double> axis = flipperOf(s)->axisAt(0);
    const double r = box2dToiTarget(kR + axis.radius) + shift - axis.radius;
    std::optional<double> best =
        circleTimeOfImpact(path, r, CircleFeature<double>{axis.pivot, axis.radius}, s.duration);
    if (const auto hit = swingingCapsuleTimeOfImpact(path, r, axis, best ? *best : s.duration))
      if (!best || hit->tau < *best) best = hit->tau;
    return best;
  }
  const Box2dBody body = s.walls ? box2dOuterWalls() : box2dBodyOf(s.gizmo);
  const int quarter =
      swings(s.gizmo.type) && !s.walls ? flipperLayout(s.gizmo.type, s.gizmo.orientation).restQuarter : 0;
  std::optional<FeatureHit<double>> best;
  for (const Box2dPart& part : body.parts) {
    const Box2dPart placed = placePart(part, body.origin, quarter);
    const auto hit = shapeTimeOfImpact(coreShape(placed), path, box2dToiTarget(kR + placed.radius) + shift,
                                       best ? best->tau : s.duration, -1);
    if (hit && (!best || hit->tau < best->tau)) best = hit;
  }
  return best ? std::optional<double>(best->tau) : std::nullopt;
}

// Box2D works in float: its inputs round to 24 bits (a few ulps of the largest coordinate in
// distance) and its answer is a float fraction of the sweep.
double floatSlackDistance(const StraightSweep& s) {
  const Vec2<double> end = s.p + s.duration * s.v;
  const double m = std::max({std::fabs(s.p.x), std::fabs(s.p.y), std::fabs(end.x), std::fabs(end.y), 22.0});
  return 16 * std::ldexp(m, -24);
}

std::string formatTime(const std::optional<double>& t) {
  if (!t) return "none";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", *t);
  return buf;
}

}  // namespace

SweepVerdict compareSweep(const StraightSweep& s) {
  SweepVerdict v;
  const OurHit ours = ourTime(s);
  v.ours = ours.tau;
  v.oursFeature = ours.feature;
  const Box2dHit b2 = box2dTime(s);
  v.box2dState = b2.state;
  v.box2d = b2.t;
  const double slack = kBox2dToiTolerance + floatSlackDistance(s);
  v.earliest = box2dStop(s, +slack);
  v.latest = box2dStop(s, -slack);
  const double timeSlack = 4 * std::ldexp(s.duration, -24);
  if (b2.state == "overlapped" || b2.state == "failed") {
    v.why = "b2TimeOfImpact " + b2.state;
  } else if (b2.t) {
    v.depth = -ourGapAt(s, *b2.t);
    if (!v.earliest) v.why = "Box2D touches where its cores cannot come within target + tolerance";
    else if (*b2.t < *v.earliest - timeSlack) v.why = "Box2D touches before its target + tolerance";
    else if (v.latest && *v.latest + timeSlack < *b2.t) v.why = "Box2D touches after its target − tolerance";
  } else if (v.latest) {
    v.why = "Box2D reports no contact where its cores come within target − tolerance";
  }
  if (!v.why.empty()) {
    v.why += " (ours " + formatTime(v.ours) + ", Box2D " + formatTime(v.box2d) + ", window " + formatTime(v.earliest) +
             " .. " + formatTime(v.latest) + ")";
  }
  v.explained = v.why.empty();
  return v;
}

std::string describeSweep(const StraightSweep& s) {
  char buf[512];
  const char* obstacle = s.kind == SweepKind::Ball ? "another ball"
                         : s.walls                 ? "OuterWalls"
                                                   : gizmoKind(s.gizmo.type).textCommand.data();
  std::snprintf(buf, sizeof buf, "kind %s, obstacle %s at (%d, %d) orientation %d, ball p (%a, %a) v (%a, %a)",
                std::string(sweepKindName(s.kind)).c_str(), obstacle, s.gizmo.x, s.gizmo.y, s.gizmo.orientation, s.p.x,
                s.p.y, s.v.x, s.v.y);
  std::string out = buf;
  if (s.kind == SweepKind::Ball) {
    std::snprintf(buf, sizeof buf, ", other p (%a, %a) v (%a, %a)", s.otherP.x, s.otherP.y, s.otherV.x, s.otherV.y);
    out += buf;
  }
  if (flipperSwings(s)) {
    std::snprintf(buf, sizeof buf, ", swing start %a", s.swingStart);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, ", duration %a", s.duration);
  return out + buf;
}

std::vector<SweepKindSurvey> surveySweeps(std::uint64_t seed, int perKind) {
  std::mt19937_64 random(seed);
  std::vector<SweepKindSurvey> out;
  for (SweepKind kind : kSweepKinds) {
    SweepKindSurvey k;
    k.kind = kind;
    bool anyDepth = false;
    for (int i = 0; i < perKind; ++i) {
      std::array<double, kSweepRandoms> u;
      for (double& x : u) x = std::ldexp(double(random() >> 11), -53);  // 53 random bits in [0, 1)
      const StraightSweep sweep = makeSweep(kind, u);
      const SweepVerdict v = compareSweep(sweep);
      ++k.sweeps;
      if (v.ours) ++k.oursHits;
      if (v.box2d) ++k.box2dHits;
      if (v.ours && v.box2d) {
        k.maxDifference = std::max(k.maxDifference, std::fabs(*v.box2d - *v.ours));
        k.minDepth = anyDepth ? std::min(k.minDepth, v.depth) : v.depth;
        k.maxDepth = anyDepth ? std::max(k.maxDepth, v.depth) : v.depth;
        anyDepth = true;
      }
      if (!v.explained) {
        ++k.findingCount;
        if (k.findings.size() < 20) k.findings.push_back(v.why + "; " + describeSweep(sweep));
      }
    }
    out.push_back(std::move(k));
  }
  return out;
}

}  // namespace gizmo::verify
