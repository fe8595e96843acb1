#pragma once
// The shape of each kind of gizmo, from its plain-data description. One function serves the
// simulator (every scalar) and the board checker (double), so that both see the same geometry.
#include <array>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/geometry/features.hpp"

namespace gizmo {

// Rotates p by k quarter turns clockwise on screen about c: (dx, dy) → (−dy, dx) per turn.
// Exact in every scalar.
template <class Real>
Vec2<Real> rotateQuarterTurns(const Vec2<Real>& p, const Vec2<Real>& c, int k) {
  Vec2<Real> d = p - c;
  for (int i = 0; i < ((k % 4) + 4) % 4; ++i) d = Vec2<Real>(-d.y, d.x);
  return c + d;
}

// A closed convex polygon, vertices listed clockwise on screen: one segment per edge with the
// outward normal, and each vertex as a circle of radius 0.
template <class Real>
void addPolygon(Shape<Real>& shape, const std::vector<Vec2<Real>>& clockwise) {
  const std::size_t n = clockwise.size();
  for (std::size_t i = 0; i < n; ++i) shape.segments.push_back(makeSegment(clockwise[i], clockwise[(i + 1) % n]));
  for (const Vec2<Real>& v : clockwise) shape.circles.push_back(CircleFeature<Real>{v, Real(0)});
}

// A capsule: the set of points within `radius` of the axis from p to q.
template <class Real>
void addCapsule(Shape<Real>& shape, const Vec2<Real>& p, const Vec2<Real>& q, const Real& radius) {
  SegmentFeature<Real> axis = makeSegment(p, q);
  Vec2<Real> off = radius * axis.normal;
  shape.segments.push_back(makeSegment(p + off, q + off));  // normal = axis.normal
  shape.segments.push_back(makeSegment(q - off, p - off));  // normal = −axis.normal
  shape.circles.push_back(CircleFeature<Real>{p, radius});
  shape.circles.push_back(CircleFeature<Real>{q, radius});
}

// Flipper geometry of docs/physics.md §2, in whole quarter turns so that it is exact.
struct FlipperLayout {
  Vec2<double> pivot;  // pivot centre, relative to the box's upper-left corner
  int restQuarter;     // rest angle θ = restQuarter · π/2 (θ from +x toward +y)
  int endQuarter;      // end angle of the forward swing
  int forwardSign;     // sign of ω during the forward swing
};
inline constexpr double kFlipperLength = 1.5;  // pivot centre to tip centre
inline constexpr double kFlipperRadius = 0.25;

inline FlipperLayout flipperLayout(GizmoType type, int orientationDegrees) {
  const int k = orientationDegrees / 90;
  const bool left = type == GizmoType::LeftFlipper;
  FlipperLayout f;
  f.pivot = rotateQuarterTurns(left ? Vec2<double>(0.25, 0.25) : Vec2<double>(1.75, 0.25), Vec2<double>(1, 1), k);
  f.restQuarter = 1 + k;
  f.endQuarter = (left ? 0 : 2) + k;
  f.forwardSign = left ? -1 : +1;
  return f;
}

// The spinner (NiklavsM/Gizmoball's Spinner.java): a cross of two capsules through the centre of
// its 2×2 box, each arm a capsule from the centre `kSpinnerArmLength` long (its tip's centre) and
// `kSpinnerArmRadius` wide; it turns at kSpinnerTurnRate rad/s (clockwise on screen).
inline constexpr double kSpinnerArmLength = 0.5;
inline constexpr double kSpinnerArmRadius = 0.25;
inline constexpr double kSpinnerTurnRate = 3.14;

// The cross about `centre` with one arm along the unit vector u.
template <class Real>
void addSpinnerCross(Shape<Real>& shape, const Vec2<Real>& centre, const Vec2<Real>& u) {
  const Vec2<Real> w(-u.y, u.x);
  const Real half = fromDouble<Real>(kSpinnerArmLength), radius = fromDouble<Real>(kSpinnerArmRadius);
  addCapsule(shape, Vec2<Real>(centre - half * u), Vec2<Real>(centre + half * u), radius);
  addCapsule(shape, Vec2<Real>(centre - half * w), Vec2<Real>(centre + half * w), radius);
}

// Unit vector at angle q·π/2: exact.
template <class Real>
Vec2<Real> quarterDirection(int q) {
  switch (((q % 4) + 4) % 4) {
    case 0: return Vec2<Real>(Real(1), Real(0));
    case 1: return Vec2<Real>(Real(0), Real(1));
    case 2: return Vec2<Real>(Real(-1), Real(0));
    default: return Vec2<Real>(Real(0), Real(-1));
  }
}

// The shape of a gizmo at rest (flippers in their rest position), in board coordinates: each
// kind's file says its own (kinds/STEM.hpp, addRestShape). Defined in core/src/kind_outline_impl.hpp
// and compiled once per scalar with the core (core/src/instantiate.hpp), where every kind's file
// is included: a kind's file includes its gizmo's class, which needs this declaration.
template <class Real>
Shape<Real> restShape(const GizmoSpec& g);

// The gizmos that are a disc of radius 0.5 in their cell (each kind's `disc`). Defined in
// core/src/kind_registry.cpp.
bool isDiscGizmo(GizmoType t);

// The outer walls: four segments whose normals point into the board; their corners cannot be
// reached from inside, so they carry no vertex circles.
template <class Real>
Shape<Real> outerWallsShape() {
  Shape<Real> s;
  const Real n(kBoardSize);
  const Vec2<Real> tl(Real(0), Real(0)), tr(n, Real(0)), br(n, n), bl(Real(0), n);
  // Counter-clockwise on screen puts each normal inside.
  s.segments.push_back(makeSegment(tl, bl));
  s.segments.push_back(makeSegment(bl, br));
  s.segments.push_back(makeSegment(br, tr));
  s.segments.push_back(makeSegment(tr, tl));
  return s;
}

}  // namespace gizmo
