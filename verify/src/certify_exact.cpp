// The exact step (certify_exact.hpp): the gap polynomials of the events that stay overlapping,
// rebuilt in rationals from the same doubles the interval kernel reads, and compared through
// their common roots.
#include "gizmo/verify/certify_exact.hpp"

#include <mpfr.h>

#include <cmath>
#include <initializer_list>
#include <limits>

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/verify/certify_qpoly.hpp"

namespace gizmo::verify::detail {

namespace {

struct QVec {
  Rational x, y;
};
QVec exact(const Vec2<double>& v) { return QVec{Rational(v.x), Rational(v.y)}; }
QVec operator-(const QVec& a, const QVec& b) { return QVec{a.x - b.x, a.y - b.y}; }
Rational dotOf(const QVec& a, const QVec& b) { return a.x * b.x + a.y * b.y; }

QPoly poly(std::initializer_list<Rational> c) {
  QPoly p(c);
  trim(p);
  return p;
}

// A ball's path in s = t − now, the same formula as the kernel's motionOf, without rounding.
struct QMotion {
  QVec p, v, h;
};
QMotion motionOf(const BallSnapshot& b, const Rational& now) {
  const Rational delta = now - Rational(b.t0);
  const QVec P = exact(b.p), V = exact(b.v), A = exact(b.a);
  QMotion m;
  m.h = QVec{A.x / 2, A.y / 2};
  m.v = QVec{V.x + delta * A.x, V.y + delta * A.y};
  m.p = QVec{P.x + delta * V.x + delta * delta * m.h.x, P.y + delta * V.y + delta * delta * m.h.y};
  return m;
}

// (p(s) − a)·w
QPoly along(const QMotion& m, const QVec& a, const QVec& w) {
  return poly({dotOf(m.p - a, w), dotOf(m.v, w), dotOf(m.h, w)});
}

// |d + v s + h s²|² − reach²
QPoly roundGap(const QVec& d, const QVec& v, const QVec& h, const Rational& reach) {
  return poly(
      {dotOf(d, d) - reach * reach, 2 * dotOf(d, v), dotOf(v, v) + 2 * dotOf(d, h), 2 * dotOf(v, h), dotOf(h, h)});
}

// √x when it is rational (numerator and denominator perfect squares in lowest terms).
std::optional<Rational> rationalRoot(const Rational& x) {
  const mpq_srcptr q = x.backend().data();
  if (mpq_sgn(q) < 0 || !mpz_perfect_square_p(mpq_numref(q)) || !mpz_perfect_square_p(mpq_denref(q)))
    return std::nullopt;
  Rational root;
  mpz_sqrt(mpq_numref(root.backend().data()), mpq_numref(q));
  mpz_sqrt(mpq_denref(root.backend().data()), mpq_denref(q));
  return root;
}

// An edge's gap (p − a)·n − r with n = (D.y, −D.x)/|D|, times |D|. Where |D| is irrational (the
// 45° edges) the contact also solves ((p − a)·(D.y, −D.x))² = r²|D|², which is rational; its
// other roots (the ball as far behind the line) are told apart by the isolation.
QPoly segmentGap(const QMotion& m, const Vec2<double>& a, const Vec2<double>& b, const Rational& r) {
  const QVec A = exact(a), D = exact(b) - A;
  QPoly height = along(m, A, QVec{D.y, -D.x});
  height.resize(std::max<std::size_t>(height.size(), 1), Rational(0));
  const Rational lengthSquared = dotOf(D, D);
  if (const std::optional<Rational> length = rationalRoot(lengthSquared)) {
    height[0] -= r * *length;
    trim(height);
    return height;
  }
  QPoly squared = product(height, height);
  squared.resize(std::max<std::size_t>(squared.size(), 1), Rational(0));
  squared[0] -= r * r * lengthSquared;
  trim(squared);
  return squared;
}

class Polynomials {
 public:
  Polynomials(const BoardLayout& layout, const BoardSnapshot& snap)
      : layout_(layout), snap_(snap), now_(snap.now), r_(layout.ballRadius) {}

  // The polynomial whose roots include the time (in s) of the event `k`; several crossings (the
  // four sides of a leave, the two ends of a contact) multiply. Nothing for a moving flipper
  // feature or a turning spinner's, whose gaps are not polynomials.
  std::optional<QPoly> of(const EventKey& k) const {
    switch (k.kind) {
      case EventKind::Collision: return collision(k);
      case EventKind::Leave: {
        const QMotion m = motion(k.b);
        const auto& rect = layout_.gizmos[std::size_t(k.a)].rect;
        const Rational x(rect[0]), y(rect[1]), w(rect[2]), h(rect[3]);
        QPoly p = poly({m.p.y - (y - r_), m.v.y, m.h.y});
        p = product(p, poly({y + h + r_ - m.p.y, -m.v.y, -m.h.y}));
        p = product(p, poly({m.p.x - (x - r_), m.v.x, m.h.x}));
        return product(p, poly({x + w + r_ - m.p.x, -m.v.x, -m.h.x}));
      }
      case EventKind::ContactEnd: {
        const BallSnapshot& b = ball(k.a);
        const QMotion m = motion(k.a);
        const QVec A = exact(b.contactA), D = exact(b.contactB) - A;
        const QPoly u = along(m, A, D);  // |D| times the distance along the segment
        QPoly beyond = u;
        beyond.resize(std::max<std::size_t>(beyond.size(), 1), Rational(0));
        for (Rational& c : beyond) c = -c;
        beyond[0] += dotOf(D, D);
        trim(beyond);
        return product(u, beyond);
      }
      default: return std::nullopt;
    }
  }

 private:
  std::optional<QPoly> collision(const EventKey& k) const {
    if (layout_.ballIndex[std::size_t(k.a)] >= 0) {
      const QMotion x = motion(k.a), y = motion(k.b);
      return roundGap(x.p - y.p, x.v - y.v, x.h - y.h, 2 * r_);
    }
    const QMotion m = motion(k.b);
    const LayoutGizmo& g = layout_.gizmos[std::size_t(k.a)];
    const Shape<double>* shape = &g.shape;
    if (g.kind == LayoutKind::Flipper) {
      const FlipperSnapshot* f = flipper(k.a);
      if (!f) return std::nullopt;
      if (f->swinging) {
        if (k.feature != 2) return std::nullopt;  // the sides and the tip turn
        return roundGap(m.p - exact(g.pivot), m.v, m.h, r_ + Rational(kFlipperRadius));
      }
      shape = &f->still;
    } else if (g.kind == LayoutKind::Spinner) {
      const SpinnerSnapshot* s = spinner(k.a);
      if (!s || s->turning) return std::nullopt;  // every feature of a turning cross moves
      shape = &s->still;
    }
    const std::size_t feature = std::size_t(k.feature);
    if (feature < shape->segments.size())
      return segmentGap(m, shape->segments[feature].a, shape->segments[feature].b, r_);
    const std::size_t c = feature - shape->segments.size();
    if (c >= shape->circles.size()) return std::nullopt;
    const CircleFeature<double>& circle = shape->circles[c];
    return roundGap(m.p - exact(circle.centre), m.v, m.h, r_ + Rational(circle.radius));
  }

  const BallSnapshot& ball(GizmoId id) const { return snap_.balls[std::size_t(layout_.ballIndex[std::size_t(id)])]; }
  QMotion motion(GizmoId id) const { return motionOf(ball(id), now_); }
  const FlipperSnapshot* flipper(GizmoId id) const {
    for (const FlipperSnapshot& f : snap_.flippers)
      if (f.id == id) return &f;
    return nullptr;
  }
  const SpinnerSnapshot* spinner(GizmoId id) const {
    for (const SpinnerSnapshot& s : snap_.spinners)
      if (s.id == id) return &s;
    return nullptr;
  }

  const BoardLayout& layout_;
  const BoardSnapshot& snap_;
  Rational now_, r_;
};

// The only root of p in [lo, hi], where p(lo) ≠ 0 ≠ p(hi), or (lo == hi) a known exact time.
struct IsolatedRoot {
  QPoly p;
  Rational lo, hi;
  bool point() const { return lo == hi; }
};

IsolatedRoot pointRoot(const Rational& x) { return IsolatedRoot{poly({-x, Rational(1)}), x, x}; }

// An enclosure from the intervals (doubles rounded outwards) made into an isolating one: widened
// by an ulp while p vanishes at an end (the enclosure only grows), then the Sturm count must be 1.
std::optional<IsolatedRoot> isolate(const QPoly& p, double lo, double hi) {
  if (p.size() < 2 || !(lo <= hi)) return std::nullopt;
  const double inf = std::numeric_limits<double>::infinity();
  for (int k = 0; valueAt(p, Rational(lo)) == 0; ++k) {
    if (k == 8) return std::nullopt;
    lo = std::nextafter(lo, -inf);
  }
  for (int k = 0; lo == hi || valueAt(p, Rational(hi)) == 0; ++k) {
    if (k == 8) return std::nullopt;
    hi = std::nextafter(hi, inf);
  }
  IsolatedRoot r{p, Rational(lo), Rational(hi)};
  if (SturmChain(p).rootsIn(r.lo, r.hi) != 1) return std::nullopt;
  return r;
}

// Halves the enclosure, keeping the root.
void narrow(IsolatedRoot& r, const SturmChain& chain) {
  const Rational m = (r.lo + r.hi) / 2;
  if (valueAt(r.p, m) == 0) {
    r.lo = r.hi = m;
  } else if (chain.rootsIn(r.lo, m) == 1) {
    r.hi = m;
  } else {
    r.lo = m;
  }
}

enum class Order : std::uint8_t { Equal, FirstBefore, SecondBefore, Distinct };

bool sameRoot(const IsolatedRoot& a, const IsolatedRoot& b) {
  if (a.point() && b.point()) return a.lo == b.lo;
  if (a.point()) return b.lo < a.lo && a.lo < b.hi && valueAt(b.p, a.lo) == 0;
  if (b.point()) return sameRoot(b, a);
  // Both roots are the only ones of their polynomials in their enclosures, so a common root of
  // the two in the overlap is both of them. The overlap's ends are ends of a or b, where a's or
  // b's polynomial, and so the gcd dividing it, is not 0: the Sturm count applies.
  const Rational lo = a.lo < b.lo ? b.lo : a.lo, hi = a.hi < b.hi ? a.hi : b.hi;
  if (!(lo < hi)) return false;
  const QPoly common = gcdOf(a.p, b.p);
  return common.size() >= 2 && SturmChain(common).rootsIn(lo, hi) >= 1;
}

// Two different roots, ordered by bisecting their enclosures until they part (their distance is
// not 0, so they do; the cap only bounds the work on absurdly close ones).
Order order(IsolatedRoot& a, IsolatedRoot& b) {
  const SturmChain ca(a.p), cb(b.p);
  for (int step = 0; step < 4096; ++step) {
    // Parted strictly, so that the distance has a positive lower bound.
    if (a.hi < b.lo) return Order::FirstBefore;
    if (b.hi < a.lo) return Order::SecondBefore;
    const Rational wa = a.hi - a.lo, wb = b.hi - b.lo;
    if (wb < wa) narrow(a, ca);
    else narrow(b, cb);
  }
  return Order::Distinct;
}

// a and b come back narrowed when they were ordered (their enclosures then part).
Order compare(IsolatedRoot& a, IsolatedRoot& b, bool orderDistinct) {
  if (sameRoot(a, b)) return Order::Equal;
  return orderDistinct ? order(a, b) : Order::Distinct;
}

double roundedDown(const Rational& x) {
  mpfr_t v;
  mpfr_init2(v, 53);
  mpfr_set_q(v, x.backend().data(), MPFR_RNDD);
  const double d = mpfr_get_d(v, MPFR_RNDD);
  mpfr_clear(v);
  return d;
}
double roundedUp(const Rational& x) { return -roundedDown(-x); }

}  // namespace

std::optional<RungOutcome> settleExactly(const BoardLayout& layout, const BoardSnapshot& snapshot,
                                         const DecisionInput& input, const RungOutcome& undecided, bool orderDistinct) {
  if (undecided.overlaps.empty()) return std::nullopt;
  const Polynomials polynomials(layout, snapshot);
  const Rational now(snapshot.now);
  // A proven entry's time: exact when its enclosure is a single point (an entry from contact at
  // s = 0, which is no root of the gap), else the isolated root of its polynomial.
  auto entryTime = [&](const EventKey& key, bool polynomial, double lo, double hi) -> std::optional<IsolatedRoot> {
    if (lo == hi) return pointRoot(Rational(lo));
    if (!polynomial) return std::nullopt;
    const std::optional<QPoly> p = polynomials.of(key);
    if (!p) return std::nullopt;
    return isolate(*p, lo, hi);
  };
  const std::optional<IsolatedRoot> own =
      isRootKind(input.executed.kind)
          ? entryTime(keyOf(input.executed), undecided.ownPolynomial, undecided.ownLo, undecided.ownHi)
          : pointRoot(Rational(input.executed.time) - now);
  if (!own) return std::nullopt;

  RungOutcome out;
  out.verdict = Verdict::Certified;
  std::optional<Rational> firstBefore;  // the latest bound on the earliest event proven to come before ours
  for (const Overlap& o : undecided.overlaps) {
    std::optional<IsolatedRoot> other;
    if (o.scheduled) {
      if (!input.hasNextScheduled) return std::nullopt;
      other = pointRoot(Rational(input.nextScheduled.time) - now);
    } else {
      if (!o.entry) return std::nullopt;
      other = entryTime(o.key, o.polynomial, o.lo, o.hi);
    }
    if (!other) return std::nullopt;
    IsolatedRoot mine = *own;
    switch (compare(mine, *other, orderDistinct)) {
      case Order::Equal: {
        bool listed = false;
        for (const EventKey& k : out.tiedWith) listed = listed || sameEvent(k, o.key);
        if (!listed) out.tiedWith.push_back(o.key);
        break;
      }
      case Order::FirstBefore: break;
      case Order::SecondBefore:
        if (!firstBefore || other->hi < *firstBefore) {
          firstBefore = other->hi;
          out.other = o.key;
          out.otherIsScheduled = o.scheduled;
          out.byLo = std::max(0.0, roundedDown(mine.lo - other->hi));
          out.byHi = roundedUp(mine.hi - other->lo);
        }
        break;
      case Order::Distinct: return std::nullopt;
    }
  }
  if (firstBefore) {
    out.verdict = Verdict::Wrong;
    out.tiedWith.clear();
    out.explanation =
        "another event comes first, proven in exact rational arithmetic (closer than any interval rung could separate)";
  } else if (!out.tiedWith.empty()) {
    out.verdict = Verdict::Tie;
  }
  return out;
}

}  // namespace gizmo::verify::detail
