#pragma once
// The certification kernel: ONE template over the interval type (Interval over double with
// upward rounding, MpfiInterval at 128…1024 bits). Given the state the double run had after an
// event and the event it executed next, it proves that event was the earliest, or proves which
// one should have come first, or says it cannot tell at this precision.
//
// Times are s = t − now (now: the board time of the state, an exact double), so that the gap
// polynomials have no cancellation between large absolute times. Each gap g(s) is a polynomial
// of degree ≤ 4 with interval coefficients; an *entry* is what geometry/time_of_impact.hpp calls
// one: g going from > 0 to ≤ 0 (or already ≤ 0 at s = 0 and closing), with the contact point on
// the segment for edges. Include only from translation units built with -frounding-math when I is
// Interval (interval.hpp says why).
#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "gizmo/core/geometry/time_of_impact.hpp"
#include "gizmo/verify/certify_state.hpp"

namespace gizmo::verify::detail {

// How much work one rung may spend per gap.
struct SearchLimits {
  int pieces = 48;          // subdivisions of the window per gap
  int narrowingSteps = 64;  // bisections that tighten a proven entry
};

template <class I>
struct Poly {
  std::array<I, 5> c;
  int degree = 0;  // the highest coefficient that is not exactly 0

  void settle() {
    degree = 0;
    for (int i = 4; i > 0; --i)
      if (!isExactZero(c[i])) {
        degree = i;
        break;
      }
  }
  I at(const I& s) const {
    I r = c[degree];
    for (int i = degree - 1; i >= 0; --i) r = r * s + c[i];
    return r;
  }
  Poly derivative() const {
    Poly d;
    for (int i = 1; i <= degree; ++i) d.c[i - 1] = c[i] * I(double(i));
    d.settle();
    return d;
  }
};

// Holds the range of p over S: Horner over S, narrowed by the mean-value form p(m) + p'(S)(S − m).
template <class I>
I rangeOver(const Poly<I>& p, const Poly<I>& dp, const I& S) {
  const I m = midpoint(S);
  return intersect(p.at(S), p.at(m) + dp.at(S) * (S - m));
}

// A ball's path in s: p(s) = p + v s + h s² (h = a / 2).
template <class I>
struct Motion {
  Vec2<I> p, v, h;
};

// One (ball, feature) gap, or a leave / contact-end crossing, named as the queue would name it.
template <class I>
struct Gap {
  EventKey key;
  Poly<I> g;
  bool bounded = false;  // edges: the contact parameter u(s) must lie in [0, length]
  Poly<I> u;
  I length;
  I resolution;  // edges: the position resolution at the ball's centre at s = 0 (the end rule)
  // Round features and ball pairs: the path relative to the centre, for the graze rule.
  std::optional<Motion<I>> round;
  // An edge whose line has the ball's centre behind it: only an entry from a positive gap, after
  // gravity bends the path back over the line, counts; never a contact at the start
  // (segmentTimeOfImpact).
  bool fromBehind = false;
};

template <class I>
Vec2<I> vecOf(const Vec2<double>& d) {
  return Vec2<I>(I(d.x), I(d.y));
}

template <class I>
Motion<I> motionOf(const BallSnapshot& b, double now) {
  const I delta = I(now) - I(b.t0);  // the anchor may lie before now (ballistic)
  const Vec2<I> P = vecOf<I>(b.p), V = vecOf<I>(b.v), A = vecOf<I>(b.a);
  const I half(0.5);
  Motion<I> m;
  m.h = Vec2<I>(half * A.x, half * A.y);
  m.v = V + delta * A;
  m.p = P + delta * V + (delta * delta) * m.h;
  return m;
}

// The box that holds the ball (centre ± r) for every s in S.
template <class I>
Box<double> sweptBoxOf(const Motion<I>& m, const I& S, double r) {
  const I sx = m.p.x + S * (m.v.x + S * m.h.x), sy = m.p.y + S * (m.v.y + S * m.h.y);
  const I R(r);
  const I lox = lowerEnd(sx) - R, hix = upperEnd(sx) + R, loy = lowerEnd(sy) - R, hiy = upperEnd(sy) + R;
  return Box<double>{Vec2<double>(lowerDouble(lox), lowerDouble(loy)),
                     Vec2<double>(upperDouble(hix), upperDouble(hiy))};
}

// Exact geometry: end points are exact doubles; the unit direction and normal are enclosed.
template <class I>
struct SegmentI {
  Vec2<I> a, dir, normal;
  I length;
};
template <class I>
SegmentI<I> segmentOf(const Vec2<double>& a, const Vec2<double>& b) {
  SegmentI<I> s;
  s.a = vecOf<I>(a);
  const Vec2<I> d = vecOf<I>(b) - s.a;
  s.length = sqrt(square(d.x) + square(d.y));
  s.dir = Vec2<I>(d.x / s.length, d.y / s.length);
  s.normal = Vec2<I>(s.dir.y, -s.dir.x);  // makeSegment's side: left of the direction on screen
  return s;
}

template <class I>
Poly<I> quadratic(const I& c0, const I& c1, const I& c2) {
  Poly<I> p;
  p.c[0] = c0;
  p.c[1] = c1;
  p.c[2] = c2;
  p.settle();
  return p;
}

// |x| enclosed.
template <class I>
I magnitude(const I& x) {
  if (certainlyNotAfter(I(0.0), x)) return x;
  if (certainlyNotAfter(x, I(0.0))) return -x;
  return hull(-x, x);
}

template <class I>
Gap<I> segmentGap(const Motion<I>& m, const SegmentI<I>& s, const I& r, const EventKey& key) {
  Gap<I> gap;
  gap.key = key;
  const Vec2<I> d = m.p - s.a;
  gap.g = quadratic(I(dot(d, s.normal) - r), dot(m.v, s.normal), dot(m.h, s.normal));
  gap.bounded = true;
  gap.u = quadratic(dot(d, s.dir), dot(m.v, s.dir), dot(m.h, s.dir));
  gap.length = s.length;
  gap.resolution = I(4.0) * I(std::numeric_limits<double>::epsilon()) * (magnitude(m.p.x) + magnitude(m.p.y));
  return gap;
}

// |d(s)|² − reach², d(s) = d + v s + h s².
template <class I>
Gap<I> roundGap(const Vec2<I>& d, const Vec2<I>& v, const Vec2<I>& h, const I& reach, const EventKey& key) {
  Gap<I> gap;
  gap.key = key;
  const I two(2.0);
  gap.g.c[0] = dot(d, d) - square(reach);
  gap.g.c[1] = two * dot(d, v);
  gap.g.c[2] = dot(v, v) + two * dot(d, h);
  gap.g.c[3] = two * dot(v, h);
  gap.g.c[4] = dot(h, h);
  gap.g.settle();
  gap.round = Motion<I>{d, v, h};
  return gap;
}

enum class Tri : std::uint8_t { No, Yes, Unknown };

// Already touching or overlapping at s = 0 and closing: the first derivative that is not
// exactly zero is negative (closingFromContact in time_of_impact.hpp).
template <class I>
Tri closingAtStart(const Poly<I>& g) {
  if (certainlyPositive(g.c[0])) return Tri::No;
  const bool touching = certainlyNotAfter(g.c[0], I(0.0));
  // Opening at a rounding-level speed but pressed back before the gap is ever positive:
  // c1 > 0, c2 < 0 and 4|c2| c0 + c1² <= 0 (the second case of closingFromContact).
  if (certainlyPositive(g.c[1]) && !certainlyNotAfter(I(0.0), g.c[2])) {
    if (!certainlyNegative(g.c[2])) return Tri::Unknown;
    const I top = I(4.0) * -g.c[2] * g.c[0] + square(g.c[1]);
    if (certainlyPositive(top)) return Tri::No;
    return touching && certainlyNotAfter(top, I(0.0)) ? Tri::Yes : Tri::Unknown;
  }
  for (int i = 1; i <= 4; ++i) {
    if (isExactZero(g.c[i])) continue;
    if (certainlyPositive(g.c[i])) return Tri::No;
    if (!certainlyNegative(g.c[i])) return Tri::Unknown;
    return touching ? Tri::Yes : Tri::Unknown;
  }
  return Tri::No;  // a constant gap never closes
}

enum class Side : std::uint8_t { Inside, Outside, Unknown };

template <class I>
Side contactSide(const Gap<I>& gap, const I& S) {
  if (!gap.bounded) return Side::Inside;
  const I u = gap.u.at(S);
  if (certainlyNegative(u) || certainlyBefore(gap.length, u)) return Side::Outside;
  if (certainlyNotAfter(I(0.0), u) && certainlyNotAfter(u, gap.length)) return Side::Inside;
  return Side::Unknown;
}

// The core's end rule at s = 0 (leavingOverEnd in geometry/time_of_impact.hpp): a ball within the
// position resolution of an end of the edge and moving out over it meets that end's vertex, not
// the edge. A ball placed exactly at a corner, or whose sliding contact has just ended at one,
// touches the edge there with the gap closing under gravity; without the rule the edge would
// claim it at once. Inside where the rule certainly does not apply, Unknown where it may.
template <class I>
Side contactSideAtStart(const Gap<I>& gap) {
  const I zero(0.0);
  const Side side = contactSide(gap, zero);
  if (!gap.bounded || side == Side::Outside) return side;
  const I& u = gap.u.c[0];
  const I& du = gap.u.c[1];
  const I& ddu = gap.u.c[2];  // half the acceleration along: the same sign
  // Moving out over the end: the rate towards it negative, or exactly zero and the acceleration
  // negative (movingOut in leavingOverEnd).
  auto movingOut = [](const I& rate, const I& accel) -> Tri {
    if (certainlyNegative(rate)) return Tri::Yes;
    if (!isExactZero(rate)) return certainlyPositive(rate) ? Tri::No : Tri::Unknown;
    if (certainlyNegative(accel)) return Tri::Yes;
    return certainlyNotAfter(I(0.0), accel) ? Tri::No : Tri::Unknown;
  };
  auto leaving = [&](const I& distance, const I& rate, const I& accel) -> Tri {
    if (certainlyBefore(gap.resolution, distance)) return Tri::No;  // not at the end
    const Tri out = movingOut(rate, accel);
    if (out == Tri::No) return Tri::No;
    return out == Tri::Yes && certainlyNotAfter(distance, gap.resolution) ? Tri::Yes : Tri::Unknown;
  };
  const Tri atA = leaving(u, du, ddu), atB = leaving(I(gap.length - u), I(-du), I(-ddu));
  if (atA == Tri::Yes || atB == Tri::Yes) return Side::Outside;
  if (atA == Tri::Unknown || atB == Tri::Unknown) return Side::Unknown;
  return side;
}

enum class Found : std::uint8_t { None, Entry, Undecided };
// Entry: the first entry lies in [lo, hi] and none before lo. Undecided: none before lo; one may
// lie anywhere in [lo, end]; [lo, hi] is the piece that could not be settled.
template <class I>
struct SearchResult {
  Found found = Found::None;
  I lo, hi;
};

// What a search learns about one piece S of the window: where the contact point lies, and
// whether the piece is free of entries in its interior and right end (the gap certainly positive
// on it, certainly negative: nothing to cross from, or certainly not falling: it cannot go from
// > 0 to ≤ 0). `free` is only looked at when the contact is not certainly off the segment.
struct Piece {
  Side side = Side::Unknown;
  bool free = false;
};

// The leftmost-first subdivision of s ∈ [from, end], shared by the polynomial gaps and the swinging
// flipper's (certify_swing.hpp). A model gives examine(S) → Piece and at(s) → the gap at a point.
// A piece with g(u) > 0 > g(v) and the contact certainly on the segment holds the first entry,
// which bisection then narrows. `stack` is scratch space, passed in so that a search allocates
// nothing once it has grown.
template <class I, class Model>
SearchResult<I> subdivide(const Model& model, const I& from, const I& end, const SearchLimits& limits,
                          std::vector<std::pair<I, I>>& stack) {
  SearchResult<I> result;
  stack.clear();
  stack.emplace_back(from, end);
  int budget = limits.pieces;
  while (!stack.empty()) {
    const I u = stack.back().first, v = stack.back().second;
    stack.pop_back();
    const I S = hull(u, v);
    const Piece piece = model.examine(S);
    if (piece.side == Side::Outside || piece.free) continue;
    if (piece.side == Side::Inside) {
      const I gu = model.at(u), gv = model.at(v);
      if (certainlyPositive(gu) && certainlyNegative(gv)) {
        I a = u, b = v;
        for (int k = 0; k < limits.narrowingSteps; ++k) {
          const I m = midpoint(hull(a, b));
          if (!(certainlyBefore(a, m) && certainlyBefore(m, b))) break;
          const I gm = model.at(m);
          if (certainlyPositive(gm)) a = m;
          else if (certainlyNegative(gm)) b = m;
          else break;
        }
        result.found = Found::Entry;
        result.lo = a;
        result.hi = b;
        return result;
      }
    }
    const I m = midpoint(S);
    if (--budget <= 0 || !(certainlyBefore(u, m) && certainlyBefore(m, v))) {
      result.found = Found::Undecided;
      result.lo = u;
      result.hi = v;
      return result;
    }
    stack.emplace_back(m, v);
    stack.emplace_back(u, m);
  }
  return result;
}

// The search interface for a polynomial gap.
template <class I>
struct PolyModel {
  const Gap<I>& gap;
  const Poly<I>& dg;  // the gap's derivative

  Piece examine(const I& S) const {
    Piece piece;
    piece.side = contactSide(gap, S);
    if (piece.side == Side::Outside) return piece;
    const I G = rangeOver(gap.g, dg, S);
    // Not decreasing anywhere on S (g' ≥ 0, which also covers a gap that starts at zero with a
    // zero slope and rises, as at a corner a ball leaves tangentially): once above zero it stays
    // there, so nothing on S crosses from above zero to zero.
    piece.free = certainlyPositive(G) || certainlyNegative(G) || certainlyNotAfter(I(0.0), dg.at(S));
    return piece;
  }
  I at(const I& s) const { return gap.g.at(s); }
};

// What the start alone decides: an entry at s = 0 (touching and closing, on the feature), or
// nothing certain over the whole window; otherwise the search goes on (nullopt).
template <class I>
std::optional<SearchResult<I>> decidedAtStart(Tri closing, Side sideAtStart, const I& end) {
  const I zero(0.0);
  SearchResult<I> result;
  if (closing == Tri::Yes && sideAtStart == Side::Inside) {
    result.found = Found::Entry;
    result.lo = result.hi = zero;
    return result;
  }
  if (closing == Tri::Unknown || (closing == Tri::Yes && sideAtStart == Side::Unknown)) {
    result.found = Found::Undecided;
    result.lo = zero;
    result.hi = end;
    return result;
  }
  return std::nullopt;
}

// The graze rule of the double run (grazesAt in geometry/time_of_impact.hpp) for a path e
// relative to a round feature's centre, with its rate de and acceleration dde, all enclosed
// over some times: Yes when the path grazes at each of them, No when at none.
template <class I>
Tri grazes(const Vec2<I>& e, const Vec2<I>& de, const Vec2<I>& dde) {
  const I speed2 = dot(de, de);
  const I curve = speed2 + dot(e, dde);  // half the gap's second derivative
  if (certainlyNotAfter(curve, I(0.0))) return Tri::No;
  const I closing = square(dot(e, de)), bound = I(grazeFractionSquared<double>()) * dot(e, e) * speed2;
  if (certainlyBefore(bound, closing)) return Tri::No;
  return certainlyPositive(curve) && certainlyNotAfter(closing, bound) ? Tri::Yes : Tri::Unknown;
}

// The same for a round gap's path d(s) = d + v s + h s² over the times S.
template <class I>
Tri grazesOver(const Motion<I>& path, const I& S) {
  const I two(2.0);
  return grazes(Vec2<I>(path.p + S * Vec2<I>(path.v + S * path.h)), Vec2<I>(path.v + (two * S) * path.h),
                Vec2<I>(two * path.h));
}

// The search after the start, shared by the polynomial gaps and the swinging flipper's: the
// first entry in [0, end], where an entry at which the path grazes a round feature passes, as
// in the core, and the search goes on after it. `decided`: what the start alone settles
// (decidedAtStart); grazesAt(S) → Tri for the times S.
template <class I, class Model, class GrazesAt>
SearchResult<I> searchPassingGrazes(const Model& model, const std::optional<SearchResult<I>>& decided, const I& end,
                                    const SearchLimits& limits, std::vector<std::pair<I, I>>& stack,
                                    GrazesAt&& grazesAt) {
  auto verdict = [&](const SearchResult<I>& r) {
    return r.found == Found::Entry ? grazesAt(hull(r.lo, r.hi)) : Tri::No;
  };
  const I zero(0.0);
  if (decided) {
    const Tri v = verdict(*decided);
    if (v == Tri::No) return *decided;
    if (v == Tri::Unknown) return SearchResult<I>{Found::Undecided, zero, end};
  }
  I from = zero;
  // After a graze the gap must open and close again for another entry: more than a few
  // grazes in one window is not worth telling apart.
  for (int passed = 0; passed < 4; ++passed) {
    const SearchResult<I> r = subdivide(model, from, end, limits, stack);
    switch (verdict(r)) {
      case Tri::No: return r;
      case Tri::Unknown: return SearchResult<I>{Found::Undecided, r.lo, r.hi};
      case Tri::Yes: from = r.hi; break;
    }
  }
  return SearchResult<I>{Found::Undecided, from, end};
}

// The first entry of a gap in s ∈ [0, end]: an entry at s = 0 from contact, else the subdivision.
template <class I>
SearchResult<I> firstEntry(const Gap<I>& gap, const I& end, const SearchLimits& limits,
                           std::vector<std::pair<I, I>>& stack) {
  SearchResult<I> result;
  if (gap.g.degree == 0) return result;  // constant: never crosses
  const I zero(0.0);
  const Tri closing = gap.fromBehind ? Tri::No : closingAtStart(gap.g);
  const Side sideAtStart = contactSideAtStart(gap);
  // An edge's gap is a quadratic: touching and closing at the start, it never comes back from
  // above zero (falling at first, it rises at most once, and then for good), so when the contact
  // at the start is not on the edge (the end rule, or off its ends) the edge has no entry at all.
  if (gap.bounded && closing == Tri::Yes && sideAtStart == Side::Outside && gap.g.degree <= 2) return result;
  const std::optional<SearchResult<I>> decided =
      gap.fromBehind ? std::nullopt : decidedAtStart(closing, sideAtStart, end);
  // A quadratic that opens upwards with no two real roots is never negative, so it has no entry
  // anywhere: that settles exact tangencies (a straight pass at exactly the touching distance,
  // where the discriminant is exactly 0), which no subdivision can.
  if (!decided && gap.g.degree == 2 && certainlyPositive(gap.g.c[2]) &&
      certainlyNotAfter(I(square(gap.g.c[1]) - I(4.0) * gap.g.c[0] * gap.g.c[2]), zero))
    return result;
  const Poly<I> dg = gap.g.derivative();
  return searchPassingGrazes(PolyModel<I>{gap, dg}, decided, end, limits, stack,
                             [&](const I& S) { return gap.round ? grazesOver(*gap.round, S) : Tri::No; });
}

// Leave an absorber: the centre crosses one side of the rectangle grown by r outwards
// (Absorber::leaveTime). No contact condition.
template <class I>
void leaveGaps(const Motion<I>& m, const std::array<double, 4>& rect, const I& r, const EventKey& key,
               std::vector<Gap<I>>& out) {
  const I x(rect[0]), y(rect[1]), w(rect[2]), h(rect[3]);
  auto add = [&](const I& c0, const I& c1, const I& c2) {
    Gap<I> g;
    g.key = key;
    g.g = quadratic(c0, c1, c2);
    out.push_back(g);
  };
  add(m.p.y - (y - r), m.v.y, m.h.y);
  add((y + h) + r - m.p.y, -m.v.y, -m.h.y);
  add(m.p.x - (x - r), m.v.x, m.h.x);
  add((x + w) + r - m.p.x, -m.v.x, -m.h.x);
}

// A sliding ball runs off either end of its segment (Ball::contactEndTime).
template <class I>
void contactEndGaps(const Motion<I>& m, const BallSnapshot& b, const EventKey& key, std::vector<Gap<I>>& out) {
  const SegmentI<I> s = segmentOf<I>(b.contactA, b.contactB);
  const Vec2<I> d = m.p - s.a;
  const I u0 = dot(d, s.dir), u1 = dot(m.v, s.dir), u2 = dot(m.h, s.dir);
  Gap<I> pastA, pastB;
  pastA.key = pastB.key = key;
  pastA.g = quadratic(u0, u1, u2);
  pastB.g = quadratic(I(s.length - u0), -u1, -u2);
  out.push_back(pastA);
  out.push_back(pastB);
}

}  // namespace gizmo::verify::detail
