#pragma once
// The gaps between a ball and a swinging flipper or a turning spinner's arm, for the certification
// kernel. The flipper's axis (and each arm) turns at a constant rate, so its gaps hold sin and cos
// of a linear angle and are not polynomials; they are enclosed with the interval sine and cosine
// (interval_trig.hpp for the double intervals, MPFI's own for MpfiInterval) and searched by the
// kernel's subdivision.
//
// The model (docs/verification.md, "Swinging flippers"): between two events a swinging flipper's
// progress is s0 + d (t − t0) with the run's doubles t0, s0 and direction d taken as exact, and its
// axis points at the quarter turn it swings from turned by σ·6π times the progress beyond it (σ:
// the forward swing's sense), with the exact π; a flipper that starts back from its end position
// starts from that exact quarter turn, as the core's own snap to it says. The pivot end does not
// move: it is an ordinary circle gap. The two long sides and the tip are these gaps:
//   side:  h = σk (q·n) − reach, n = (u.y, −u.x),   h' = σk (q'·n + ω q·u),  contact q·u ∈ [0, L]
//   tip:   g = |q − L u|² − reach²,                  g' = 2 (q − L u)·(q' − L ω u⊥)
// with q the ball's centre less the pivot and σk = +1 for side 0, −1 for side 1 (as the core's
// flipper_time_of_impact.hpp). Same includes and -frounding-math rule as certify_kernel.hpp.
#include <cmath>

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/verify/certify_kernel.hpp"

namespace gizmo::verify::detail {

// Where a swinging flipper's axis, or a turning spinner's arm, points over the decision's window:
// the quarter turn `quarter` applied to (cos φ, sin φ), φ(s) = phase + omega·s.
template <class I>
struct SwingAxis {
  GizmoId id = kNoGizmo;
  int arm = 0;  // a spinner's arm (features 4·arm + 0, 1, 3); a flipper's is 0
  Vec2<I> pivot;
  int quarter = 0;
  I phase, omega;
  I length, radius;
};

template <class I>
SwingAxis<I> swingAxisOf(const LayoutGizmo& layout, const FlipperSnapshot& f, double now) {
  SwingAxis<I> axis;
  axis.id = f.id;
  axis.pivot = vecOf<I>(layout.pivot);
  axis.quarter = f.quarter;
  const I sixPi = I(6.0) * I::pi();
  axis.omega = I(double(f.turn)) * sixPi;
  axis.phase = I(double(layout.forwardSign)) * sixPi * I(f.offset) + axis.omega * (I(now) - I(f.t0));
  axis.length = I(kFlipperLength);
  axis.radius = I(kFlipperRadius);
  return axis;
}

// A turning spinner's arm `arm` (docs/verification.md, "Turning spinners"): the snapshot's phase
// and t0 taken as exact, the arm at the exact quarter turn quarter + arm. The core counts the
// quarters the cross has turned with π rounded to the scalar and turns the phase left over; this
// model turns the whole angle with the exact π, as the flipper's model does.
template <class I>
SwingAxis<I> spinnerArmAxisOf(const LayoutGizmo& layout, const SpinnerSnapshot& s, int arm, double now) {
  SwingAxis<I> axis;
  axis.id = s.id;
  axis.arm = arm;
  axis.pivot = vecOf<I>(layout.pivot);
  axis.quarter = (s.quarter + arm) % 4;
  axis.omega = I(kSpinnerTurnRate);
  axis.phase = I(s.phase) + axis.omega * (I(now) - I(s.t0));
  axis.length = I(kSpinnerArmLength);
  axis.radius = I(kSpinnerArmRadius);
  return axis;
}

// One moving feature (0, 1: the sides; 3: the tip) against one ball.
template <class I>
struct SwingGap {
  EventKey key;
  const SwingAxis<I>* axis = nullptr;
  Vec2<I> q0, v, h;  // the ball's centre less the pivot: q(s) = q0 + v s + h s²
  I reach;
  int feature = 0;
  bool side() const { return feature == 0 || feature == 1; }
};

template <class I>
SwingGap<I> swingGapOf(const Motion<I>& m, const SwingAxis<I>& axis, const I& r, const EventKey& key) {
  SwingGap<I> gap;
  gap.key = key;
  gap.axis = &axis;
  gap.q0 = m.p - axis.pivot;
  gap.v = m.v;
  gap.h = m.h;
  gap.reach = r + axis.radius;
  gap.feature = key.feature % 4;  // a spinner's arm k numbers its features 4k + 0, 1, 3
  return gap;
}

template <class I>
struct SwingValues {
  I g, dg;   // the gap and its derivative
  I along;   // sides: q·u, the contact point's distance from the pivot along the axis
  I across;  // sides: σk (q·n), the centre's height over the axis on this side
};

// The gap over S (a piece, or a point), by plain interval evaluation; the slope only on request.
// The axis's direction u at the times S.
template <class I>
Vec2<I> axisDirection(const SwingAxis<I>& axis, const I& S) {
  I sine, cosine;
  sinCos(I(axis.phase + axis.omega * S), sine, cosine);
  Vec2<I> u(cosine, sine);
  for (int i = 0; i < ((axis.quarter % 4) + 4) % 4; ++i) u = Vec2<I>(-u.y, u.x);
  return u;
}

// The ball's centre less the pivot, q(S), and its rate q'(S).
template <class I>
Vec2<I> offsetAt(const SwingGap<I>& gap, const I& S) {
  return Vec2<I>(gap.q0.x + S * (gap.v.x + S * gap.h.x), gap.q0.y + S * (gap.v.y + S * gap.h.y));
}
template <class I>
Vec2<I> offsetRate(const SwingGap<I>& gap, const I& S) {
  const I two(2.0);
  return Vec2<I>(gap.v.x + two * S * gap.h.x, gap.v.y + two * S * gap.h.y);
}

// The path relative to the tip's centre and its rate: e = q − L u, e' = q' − Lω u⊥.
template <class I>
Vec2<I> tipOffset(const SwingAxis<I>& axis, const Vec2<I>& q, const Vec2<I>& u) {
  return Vec2<I>(q.x - axis.length * u.x, q.y - axis.length * u.y);
}
template <class I>
Vec2<I> tipOffsetRate(const SwingAxis<I>& axis, const Vec2<I>& dq, const Vec2<I>& u) {
  const I turn = axis.length * axis.omega;
  return Vec2<I>(dq.x + turn * u.y, dq.y - turn * u.x);
}

template <class I>
SwingValues<I> swingValues(const SwingGap<I>& gap, const I& S, bool withSlope) {
  const SwingAxis<I>& axis = *gap.axis;
  const Vec2<I> u = axisDirection(axis, S);
  const Vec2<I> q = offsetAt(gap, S);
  SwingValues<I> out;
  if (gap.side()) {
    const I sigma(gap.feature == 0 ? 1.0 : -1.0);
    const Vec2<I> n(sigma * u.y, -(sigma * u.x));
    out.across = dot(q, n);
    out.along = dot(q, u);
    out.g = out.across - gap.reach;
    if (withSlope) out.dg = dot(offsetRate(gap, S), n) + sigma * axis.omega * out.along;
  } else {
    const Vec2<I> e = tipOffset(axis, q, u);
    out.g = dot(e, e) - square(gap.reach);
    if (withSlope) out.dg = I(2.0) * dot(e, tipOffsetRate(axis, offsetRate(gap, S), u));
  }
  return out;
}

// The graze rule at the round tip over the times S, on the path relative to the tip's centre
// (the core's tip search), whose acceleration is q'' + Lω² u.
template <class I>
Tri tipGrazes(const SwingGap<I>& gap, const I& S) {
  const SwingAxis<I>& axis = *gap.axis;
  const Vec2<I> u = axisDirection(axis, S);
  const I two(2.0), spin = axis.length * axis.omega * axis.omega;
  const Vec2<I> dde(two * gap.h.x + spin * u.x, two * gap.h.y + spin * u.y);
  return grazes(tipOffset(axis, offsetAt(gap, S), u), tipOffsetRate(axis, offsetRate(gap, S), u), dde);
}

// The kernel's search interface (subdivide in certify_kernel.hpp) for a moving feature.
template <class I>
struct SwingModel {
  const SwingGap<I>& gap;

  Piece examine(const I& S) const {
    const SwingValues<I> over = swingValues(gap, S, true);
    Piece piece;
    piece.side = Side::Inside;
    if (gap.side()) {
      if (certainlyNegative(over.along) || certainlyBefore(gap.axis->length, over.along)) {
        piece.side = Side::Outside;
        return piece;
      }
      if (!(certainlyNotAfter(I(0.0), over.along) && certainlyNotAfter(over.along, gap.axis->length)))
        piece.side = Side::Unknown;
    }
    // The mean-value form around the midpoint narrows the plain enclosure of g.
    const I m = midpoint(S);
    const I G = intersect(over.g, swingValues(gap, m, false).g + over.dg * (S - m));
    piece.free = certainlyPositive(G) || certainlyNegative(G) || certainlyPositive(over.dg);
    return piece;
  }
  I at(const I& s) const { return swingValues(gap, s, false).g; }
};

// The first entry of a moving feature's gap in s ∈ [0, end] (as firstEntry for polynomials).
// Already touching at s = 0 counts when the gap is closing there and, for a side, the ball's
// centre is on that side of the axis and the contact point on the side.
template <class I>
SearchResult<I> firstSwingEntry(const SwingGap<I>& gap, const I& end, const SearchLimits& limits,
                                std::vector<std::pair<I, I>>& stack) {
  const I zero(0.0);
  const SwingValues<I> start = swingValues(gap, zero, true);
  Tri closing = Tri::Unknown;
  if (certainlyPositive(start.g) || certainlyPositive(start.dg)) closing = Tri::No;
  else if (gap.side() && certainlyNegative(start.across)) closing = Tri::No;  // the other side's ball
  else if (certainlyNotAfter(start.g, zero) && certainlyNegative(start.dg)) closing = Tri::Yes;
  Side sideAtStart = Side::Inside;
  if (gap.side()) {
    const bool on = certainlyNotAfter(zero, start.along) && certainlyNotAfter(start.along, gap.axis->length) &&
                    certainlyNotAfter(zero, start.across);
    const bool off = certainlyNegative(start.along) || certainlyBefore(gap.axis->length, start.along);
    sideAtStart = on ? Side::Inside : off ? Side::Outside : Side::Unknown;
  }
  return searchPassingGrazes(SwingModel<I>{gap}, decidedAtStart(closing, sideAtStart, end), end, limits, stack,
                             [&](const I& S) { return gap.side() ? Tri::No : tipGrazes(gap, S); });
}

}  // namespace gizmo::verify::detail
