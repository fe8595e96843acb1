// A flipper's swing rebuilt from its actions, stops and blocks (see render_flipper_swings.hpp).
#include "render_flipper_swings.hpp"

#include <algorithm>

#include <cmath>

#include "gizmo/core/gizmos/flipper.hpp"

namespace gizmo::cli {
namespace {
double swingTime() { return Flipper<double>::swingTime(); }

double progress(const SwingAnchor& a, double t) {
  return std::clamp(a.s0 + a.direction * (t - a.t0), 0.0, swingTime());
}

// Where progress stops changing: the ends of the swing, reached at these times.
void addBends(const SwingAnchor& a, double from, double to, std::vector<double>& times) {
  if (a.direction == 0) return;
  for (double end : {0.0, swingTime()}) {
    const double t = a.t0 + (end - a.s0) / a.direction;
    if (t > from && t < to) times.push_back(t);
  }
}
}  // namespace

FlipperSwings::FlipperSwings() { anchors_.push_back(SwingAnchor{-1, 0, 0, 0}); }

FlipperSwings::FlipperSwings(const SwingAnchor& start, int lastDirection) : lastDirection_(lastDirection) {
  anchors_.push_back(start);
}

double FlipperSwings::progressAt(double t) const {
  const SwingAnchor& a = anchors_.back();
  return std::clamp(a.s0 + a.direction * (t - a.t0), 0.0, swingTime());
}

void FlipperSwings::anchor(std::int64_t event, double t, double s, int direction) {
  if (anchors_.back().direction != 0) lastDirection_ = anchors_.back().direction;
  // Several changes at one event (two triggers in one collision): the last one holds.
  if (anchors_.back().event == event && anchors_.size() > 1) anchors_.pop_back();
  anchors_.push_back(SwingAnchor{event, t, s, direction});
}

void FlipperSwings::action(std::int64_t event, double now) {
  const int direction = anchors_.back().direction;
  const double s = progressAt(now);
  int next;
  if (direction != 0) next = -direction;
  else if (s == 0) next = +1;
  else if (s == swingTime()) next = -1;
  else next = -lastDirection_;
  anchor(event, now, s, next);
}

void FlipperSwings::stopped(std::int64_t event, double now) {
  const int direction = anchors_.back().direction;
  if (direction == 0) return;
  anchor(event, now, direction > 0 ? swingTime() : 0.0, 0);
}

std::vector<SwingAnchor> FlipperSwings::visibleAnchors(double tolerance, double endTime) const {
  if (!(tolerance > 0)) return anchors_;
  // A change of progress ds turns the bar by 6π ds; its far edge, length + radius from the
  // pivot, moves by that much more.
  const double reach = (kFlipperLength + kFlipperRadius) * 6 * std::acos(-1.0);
  const double allowed = tolerance / reach;
  std::vector<SwingAnchor> kept{anchors_.front()};
  double lo = 0, hi = 0;  // progress since the kept anchor began
  bool still = false;
  for (std::size_t i = 1; i < anchors_.size(); ++i) {
    const SwingAnchor& a = anchors_[i];
    const double end = i + 1 < anchors_.size() ? anchors_[i + 1].t0 : std::max(endTime, a.t0);
    std::vector<double> times{a.t0, end};
    addBends(a, a.t0, end, times);
    addBends(kept.back(), a.t0, end, times);
    double deviation = 0, nextLo = lo, nextHi = hi;
    for (double t : times) {
      deviation = std::max(deviation, std::abs(progress(kept.back(), t) - progress(a, t)));
      nextLo = std::min(nextLo, progress(a, t));
      nextHi = std::max(nextHi, progress(a, t));
    }
    if (!still && deviation <= allowed) {
      lo = nextLo, hi = nextHi;
      continue;
    }
    if ((nextHi - nextLo) / 2 <= allowed) {
      kept.back().s0 = (nextLo + nextHi) / 2;
      kept.back().direction = 0;
      still = true;
      lo = nextLo, hi = nextHi;
      continue;
    }
    kept.push_back(a);
    still = false;
    lo = hi = progress(a, a.t0);
    for (double t : times) lo = std::min(lo, progress(a, t)), hi = std::max(hi, progress(a, t));
  }
  return kept;
}

void FlipperSwings::blocked(std::int64_t event, double now) { anchor(event, now, progressAt(now), 0); }

}  // namespace gizmo::cli
