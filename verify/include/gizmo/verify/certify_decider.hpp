#pragma once
// One decision at one rung: the executed event against every event that could have come
// first, with the kernel's gap searches (certify_kernel.hpp, and certify_swing.hpp for swinging
// flippers and turning spinners). A template over the interval type, like the kernel; only
// certify_rungs.cpp instantiates it (built with -frounding-math, and with sin, cos and π for the
// interval type in scope).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gizmo/verify/certify_kernel.hpp"
#include "gizmo/verify/certify_swing.hpp"

namespace gizmo::verify::detail {

// How far past the window's end the searches look (seconds).
inline constexpr double kPastWindow = 0x1p-32;

template <class I>
class Decider {
 public:
  Decider(const BoardLayout& layout, const SearchLimits& limits)
      : layout_(layout), limits_(limits), r_(layout.ballRadius) {
    fixed_.resize(layout.gizmos.size());
    for (const LayoutGizmo& g : layout.gizmos)
      if (g.kind == LayoutKind::FixedShape || g.kind == LayoutKind::Absorber)
        fixed_[std::size_t(g.id)] = geometryOf(g.shape);
  }

  RungOutcome decide(const BoardSnapshot& snap, const DecisionInput& in) {
    snap_ = &snap;
    in_ = &in;
    const Event<double>& e = in.executed;
    executed_ = keyOf(e);
    root_ = isRootKind(e.kind);
    const double windowTime = root_ && in.hasNextScheduled ? in.nextScheduled.time : e.time;
    windowEnd_ = I(windowTime) - I(snap.now);
    const I window = hull(I(0.0), upperEnd(windowEnd_));
    // The searches reach a little past the window's end, so that a contact exactly at it has
    // an enclosure (g is 0 there, not below) and can be proven tied with it, or later.
    const I end = upperEnd(upperEnd(windowEnd_) + I(kPastWindow));

    motions_.clear();
    boxes_.clear();
    for (const BallSnapshot& b : snap.balls) {
      motions_.push_back(motionOf<I>(b, snap.now));
      boxes_.push_back(sweptBoxOf(motions_.back(), window, r_));
    }
    // Built before any gap points into it. The window never runs past a swing's end: the
    // flipper's stop is a scheduled event, so it bounds the window. A spinner turns on until an
    // event stops it, so its arms turn at one rate throughout the window too.
    axes_.clear();
    for (const FlipperSnapshot& f : snap.flippers)
      if (f.swinging) axes_.push_back(swingAxisOf<I>(layout_.gizmos[std::size_t(f.id)], f, snap.now));
    for (const SpinnerSnapshot& sp : snap.spinners) {
      if (!sp.turning) continue;
      const LayoutGizmo& spinner = layout_.gizmos[std::size_t(sp.id)];
      for (int arm = 0; arm < 4; ++arm) axes_.push_back(spinnerArmAxisOf<I>(spinner, sp, arm, snap.now));
    }

    best_ = RungOutcome{};
    best_.verdict = Verdict::Certified;
    if (root_) {
      RungOutcome out;
      if (!claimedEntry(end, out)) return out;
      competitorEnd_ = hi_;
      best_.ownLo = lowerDouble(lo_);
      best_.ownHi = upperDouble(hi_);
      best_.ownPolynomial = ownSwing_.empty();
      if (!certainlyNotAfter(hi_, windowEnd_)) {
        // The next scheduled event may come first: it overlaps the entry.
        best_.verdict = Verdict::Undecided;
        best_.other = keyOf(in.nextScheduled);
        best_.otherIsScheduled = true;
        best_.window = widthUpper(hull(hull(lo_, hi_), windowEnd_));
        best_.overlaps.push_back(
            Overlap{best_.other, true, true, true, lowerDouble(windowEnd_), upperDouble(windowEnd_)});
      }
    } else {
      competitorEnd_ = end;
      best_.ownLo = lowerDouble(windowEnd_);
      best_.ownHi = upperDouble(windowEnd_);
    }
    forEachRival([&](const auto& gap) { judge(gap); });
    return best_;
  }

 private:
  struct Geometry {
    std::vector<SegmentI<I>> segments;
    std::vector<std::pair<Vec2<I>, I>> circles;  // centre, radius
  };
  static Geometry geometryOf(const Shape<double>& shape) {
    Geometry g;
    for (const auto& s : shape.segments) g.segments.push_back(segmentOf<I>(s.a, s.b));
    for (const auto& c : shape.circles) g.circles.emplace_back(vecOf<I>(c.centre), I(c.radius));
    return g;
  }

  // The executed root event's own entry, [lo_, hi_]; false (with `out` filled) when it cannot
  // be shown to happen at all before the next scheduled event, or not with certainty.
  bool claimedEntry(const I& end, RungOutcome& out) {
    own_.clear();
    ownSwing_.clear();
    ownGaps();
    bool certain = false, any = false;
    I lo, hi;
    auto absorb = [&](const SearchResult<I>& r) {
      if (r.found == Found::None) return;
      lo = any ? (certainlyBefore(r.lo, lo) ? lowerEnd(r.lo) : lowerEnd(hull(lo, r.lo))) : lowerEnd(r.lo);
      any = true;
      if (r.found == Found::Entry) {
        hi = certain ? upperEnd(intersectMin(hi, r.hi)) : upperEnd(r.hi);
        certain = true;
      }
    };
    for (const Gap<I>& gap : own_) absorb(firstEntry(gap, end, limits_, stack_));
    for (const SwingGap<I>& gap : ownSwing_) absorb(firstSwingEntry(gap, end, limits_, stack_));
    out.other = keyOf(in_->nextScheduled);
    out.otherIsScheduled = true;
    if (!any) {
      // No entry at all before the next scheduled event: that one should have run first.
      out.verdict = Verdict::Wrong;
      out.byLo = 0;
      out.byHi = std::numeric_limits<double>::infinity();
      out.explanation = "the claimed contact has no entry before the next scheduled event (a miss, or later)";
      return false;
    }
    if (in_->hasNextScheduled && certainlyBefore(windowEnd_, lo)) {
      out.verdict = Verdict::Wrong;
      out.byLo = std::max(0.0, lowerDouble(lo - windowEnd_));
      out.byHi = certain ? upperDouble(hi - windowEnd_) : std::numeric_limits<double>::infinity();
      out.explanation = "the claimed contact comes certainly after the next scheduled event";
      return false;
    }
    if (!certain) {
      out.verdict = Verdict::Undecided;
      out.window = std::numeric_limits<double>::infinity();
      out.other = executed_;
      out.otherIsScheduled = false;
      out.ownPolynomial = ownSwing_.empty();
      return false;
    }
    lo_ = lo;
    hi_ = hi;
    return true;
  }

  // The smaller upper end of two points (for the minimum of several entries).
  static I intersectMin(const I& a, const I& b) { return certainlyBefore(b, a) ? b : a; }

  void ownGaps() {
    const Event<double>& e = in_->executed;
    if (e.kind == EventKind::ContactEnd) {
      const std::size_t i = ballSlot(e.a);
      contactEndGaps(motions_[i], snap_->balls[i], executed_, own_);
      return;
    }
    if (e.kind == EventKind::Leave) {
      leaveGaps(motions_[ballSlot(e.b)], layout_.gizmos[std::size_t(e.a)].rect, I(r_), executed_, own_);
      return;
    }
    // A collision: e.a is the collider (the gizmo, or the lower ball), e.b the ball.
    if (layout_.ballIndex[std::size_t(e.a)] >= 0) {
      own_.push_back(ballPairGap(ballSlot(e.a), ballSlot(e.b)));
      return;
    }
    const std::size_t i = ballSlot(e.b);
    featureGaps(
        e.a, i,
        [&](const auto& gap) {
          if (sameEvent(gap.key, executed_)) keepOwn(gap);
        },
        /*skipOwn=*/false);
  }
  void keepOwn(const Gap<I>& gap) { own_.push_back(gap); }
  void keepOwn(const SwingGap<I>& gap) { ownSwing_.push_back(gap); }

  std::size_t ballSlot(GizmoId id) const { return std::size_t(layout_.ballIndex[std::size_t(id)]); }

  Gap<I> ballPairGap(std::size_t i, std::size_t j) const {
    const Motion<I>& x = motions_[i];
    const Motion<I>& y = motions_[j];
    const GizmoId a = snap_->balls[i].id, b = snap_->balls[j].id;
    const EventKey key{EventKind::Collision, std::min(a, b), std::max(a, b), 0};
    return roundGap(Vec2<I>(x.p - y.p), Vec2<I>(x.v - y.v), Vec2<I>(x.h - y.h), I(2.0 * r_), key);
  }

  // Every gap between ball slot i and gizmo g that the core would look at.
  template <class F>
  void featureGaps(GizmoId g, std::size_t i, F&& f, bool skipOwn = true) {
    const BallSnapshot& ball = snap_->balls[i];
    const Motion<I>& m = motions_[i];
    const Geometry* geometry = &fixed_[std::size_t(g)];
    Geometry still;
    const I r(r_);
    if (layout_.gizmos[std::size_t(g)].kind == LayoutKind::Flipper) {
      const FlipperSnapshot* fs = flipperState(g);
      if (!fs) return;
      if (fs->swinging) {
        swingingGaps(g, i, f, skipOwn);
        return;
      }
      still = geometryOf(fs->still);
      geometry = &still;
    } else if (layout_.gizmos[std::size_t(g)].kind == LayoutKind::Spinner) {
      const SpinnerSnapshot* ss = spinnerState(g);
      if (!ss) return;
      if (ss->turning) {
        turningArmGaps(g, i, f, skipOwn);
        return;
      }
      still = geometryOf(ss->still);
      geometry = &still;
    }
    std::int32_t feature = 0;
    auto skipped = [&](std::int32_t k) {
      return ball.contactGizmo == g &&
             std::find(ball.skippedFeatures.begin(), ball.skippedFeatures.end(), k) != ball.skippedFeatures.end();
    };
    for (const SegmentI<I>& s : geometry->segments) {
      const EventKey key{EventKind::Collision, g, ball.id, feature};
      const bool own = sameEvent(key, executed_);
      if (!skipped(feature) && !(skipOwn && own)) {
        Gap<I> gap = segmentGap(m, s, r, key);
        // A centre certainly behind the edge's line reaches the edge only if gravity bends its
        // path back over the line (segmentTimeOfImpact): a gap that is concave and rising.
        gap.fromBehind = certainlyNegative(dot(Vec2<I>(m.p - s.a), s.normal));
        const bool bendsBack = !certainlyNotAfter(I(0.0), gap.g.c[2]) && !certainlyNotAfter(gap.g.c[1], I(0.0));
        if (!gap.fromBehind || bendsBack) f(gap);
      }
      ++feature;
    }
    for (const auto& [centre, radius] : geometry->circles) {
      const EventKey key{EventKind::Collision, g, ball.id, feature};
      const bool own = sameEvent(key, executed_);
      if (!skipped(feature) && !(skipOwn && own)) f(roundGap(Vec2<I>(m.p - centre), m.v, m.h, I(r + radius), key));
      ++feature;
    }
  }

  // A swinging flipper's features: the pivot end turns in place (a fixed circle), the sides and
  // the tip move. A ball never slides on a moving flipper (its contact ends when the swing
  // starts), so none is skipped.
  template <class F>
  void swingingGaps(GizmoId g, std::size_t i, F&& f, bool skipOwn) {
    const SwingAxis<I>* axis = nullptr;
    for (const SwingAxis<I>& a : axes_)
      if (a.id == g) axis = &a;
    if (!axis) return;
    const Motion<I>& m = motions_[i];
    const I r(r_);
    for (std::int32_t feature = 0; feature < 4; ++feature) {
      const EventKey key{EventKind::Collision, g, snap_->balls[i].id, feature};
      if (skipOwn && sameEvent(key, executed_)) continue;
      if (feature == 2) f(roundGap(Vec2<I>(m.p - axis->pivot), m.v, m.h, I(r + axis->radius), key));
      else f(swingGapOf(m, *axis, r, key));
    }
  }

  // A turning spinner's arms: each one's sides and tip move (features 4·arm + 0, 1, 3). The arms
  // meet at the centre, which no ball reaches without meeting an arm first: there is no pivot
  // circle (the core's Spinner::timeUntilCollision). None is skipped, as at a swinging flipper.
  template <class F>
  void turningArmGaps(GizmoId g, std::size_t i, F&& f, bool skipOwn) {
    const Motion<I>& m = motions_[i];
    const I r(r_);
    for (const SwingAxis<I>& axis : axes_) {
      if (axis.id != g) continue;
      for (std::int32_t feature : {0, 1, 3}) {
        const EventKey key{EventKind::Collision, g, snap_->balls[i].id, 4 * axis.arm + feature};
        if (!(skipOwn && sameEvent(key, executed_))) f(swingGapOf(m, axis, r, key));
      }
    }
  }

  const SpinnerSnapshot* spinnerState(GizmoId g) const {
    for (const SpinnerSnapshot& s : snap_->spinners)
      if (s.id == g) return &s;
    return nullptr;
  }

  const FlipperSnapshot* flipperState(GizmoId g) const {
    for (const FlipperSnapshot& f : snap_->flippers)
      if (f.id == g) return &f;
    return nullptr;
  }
  const AbsorberSnapshot* absorberState(GizmoId g) const {
    for (const AbsorberSnapshot& a : snap_->absorbers)
      if (a.id == g) return &a;
    return nullptr;
  }
  bool firedInside(GizmoId absorber, GizmoId ball) const {
    const AbsorberSnapshot* a = absorberState(absorber);
    return a && std::find(a->firedInside.begin(), a->firedInside.end(), ball) != a->firedInside.end();
  }

  // Every event that could come before the executed one: each pair the board forms (the broad
  // phase here is the balls' swept boxes against the gizmos' bounds), each leave of a fired
  // ball, each end of a sliding contact.
  template <class F>
  void forEachRival(F&& f) {
    const std::size_t n = snap_->balls.size();
    for (std::size_t i = 0; i < n; ++i) {
      const BallSnapshot& ball = snap_->balls[i];
      if (ball.captured) continue;
      candidates_.clear();
      candidates_.push_back(0);  // the outer walls
      const Box<double>& box = boxes_[i];
      auto cell = [](double v) { return std::clamp(int(std::floor(v)), 0, BoardLayout::kCells - 1); };
      for (int y = cell(box.lo.y); y <= cell(box.hi.y); ++y)
        for (int x = cell(box.lo.x); x <= cell(box.hi.x); ++x) {
          const auto& list = layout_.cells[std::size_t(y * BoardLayout::kCells + x)];
          candidates_.insert(candidates_.end(), list.begin(), list.end());
        }
      std::sort(candidates_.begin(), candidates_.end());
      candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());
      for (GizmoId g : candidates_) {
        if (layout_.collider[std::size_t(layout_.ballIndex[std::size_t(ball.id)])][std::size_t(g)] == kNoGizmo)
          continue;
        if (!box.overlaps(layout_.gizmos[std::size_t(g)].bounds)) continue;
        if (layout_.gizmos[std::size_t(g)].kind == LayoutKind::Absorber && firedInside(g, ball.id)) {
          const EventKey key{EventKind::Leave, g, ball.id, 0};
          if (sameEvent(key, executed_)) continue;
          rivals_.clear();
          leaveGaps(motions_[i], layout_.gizmos[std::size_t(g)].rect, I(r_), key, rivals_);
          for (const Gap<I>& gap : rivals_) f(gap);
          continue;
        }
        featureGaps(g, i, f);
      }
      for (std::size_t j = i + 1; j < n; ++j) {
        if (snap_->balls[j].captured || !box.overlaps(boxes_[j])) continue;
        const Gap<I> gap = ballPairGap(i, j);
        if (!sameEvent(gap.key, executed_)) f(gap);
      }
      if (ball.contactGizmo != kNoGizmo) {
        const EventKey key{EventKind::ContactEnd, ball.id, kNoGizmo, -1};
        if (sameEvent(key, executed_)) continue;
        rivals_.clear();
        contactEndGaps(motions_[i], ball, key, rivals_);
        for (const Gap<I>& gap : rivals_) f(gap);
      }
    }
  }

  void judge(const Gap<I>& gap) { judgeSearch(firstEntry(gap, competitorEnd_, limits_, stack_), gap.key, true); }
  void judge(const SwingGap<I>& gap) {
    judgeSearch(firstSwingEntry(gap, competitorEnd_, limits_, stack_), gap.key, false);
  }

  // One rival: certainly later (nothing to do), certainly earlier (a wrong decision; the
  // earliest such is kept), or not separable at this precision (kept for the exact step).
  void judgeSearch(const SearchResult<I>& r, const EventKey& key, bool polynomial) {
    if (r.found == Found::None) return;
    if (r.found == Found::Entry && certainlyBefore(root_ ? hi_ : windowEnd_, r.lo)) return;  // later
    if (r.found == Found::Entry) {
      // Root event: the rival's entry must come before ours. Scheduled event: a contact at or
      // before its time runs first (collisions come first in the tie order).
      const bool earlier = root_ ? certainlyBefore(r.hi, lo_) : certainlyNotAfter(r.hi, windowEnd_);
      if (earlier) {
        const I ref = root_ ? hull(lo_, hi_) : windowEnd_;
        const I by = ref - hull(r.lo, r.hi);
        if (best_.verdict != Verdict::Wrong || lowerDouble(r.hi) < earliestWrong_) {
          earliestWrong_ = upperDouble(r.hi);
          best_.verdict = Verdict::Wrong;
          best_.other = key;
          best_.otherIsScheduled = false;
          best_.byLo = std::max(0.0, lowerDouble(by));
          best_.byHi = upperDouble(by);
          best_.explanation = "an entry of another pair comes certainly earlier";
        }
        return;
      }
    }
    if (best_.verdict == Verdict::Wrong) return;
    // Undecided, or an entry overlapping ours: how wide a window holds both?
    const I mine = root_ ? hull(lo_, hi_) : windowEnd_;
    const I theirs = r.found == Found::Entry ? hull(r.lo, r.hi) : hull(r.lo, competitorEnd_);
    const double width = widthUpper(hull(mine, theirs));
    best_.overlaps.push_back(
        Overlap{key, false, r.found == Found::Entry, polynomial, lowerDouble(theirs), upperDouble(theirs)});
    if (best_.verdict == Verdict::Certified || best_.window < width) {
      best_.verdict = Verdict::Undecided;
      best_.other = key;
      best_.otherIsScheduled = false;
      best_.window = width;
    }
  }

  const BoardLayout& layout_;
  SearchLimits limits_;
  double r_;
  std::vector<Geometry> fixed_;

  const BoardSnapshot* snap_ = nullptr;
  const DecisionInput* in_ = nullptr;
  EventKey executed_;
  bool root_ = false;
  I windowEnd_, competitorEnd_, lo_, hi_;
  std::vector<Motion<I>> motions_;
  std::vector<Box<double>> boxes_;
  std::vector<GizmoId> candidates_;
  std::vector<Gap<I>> own_, rivals_;
  std::vector<SwingGap<I>> ownSwing_;
  std::vector<SwingAxis<I>> axes_;
  std::vector<std::pair<I, I>> stack_;
  RungOutcome best_;
  double earliestWrong_ = 0;
};

}  // namespace gizmo::verify::detail
