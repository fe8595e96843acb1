// Another engine's path over our run (see render_path_overlay.hpp).
#include "render_path_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gizmo::cli {
namespace {

// Where the player draws one of our balls at time t: the piece in force once every event up to
// t has run (the player's ballAt for a moment that is not an event's).
class OurPosition {
 public:
  OurPosition(const RunTrack& run, const BallTrack& ball) : run_(run), ball_(ball) {}

  // Times must not decrease from one call to the next: both searches only move forward.
  Vec2<double> at(double t) {
    while (done_ < run_.eventTime.size() && run_.eventTime[done_] <= t) ++done_;
    const std::int64_t lastEvent = static_cast<std::int64_t>(done_) - 1;
    while (piece_ + 1 < ball_.pieces.size() && ball_.pieces[piece_ + 1].event <= lastEvent) ++piece_;
    return positionAt(ball_.pieces[piece_], t);
  }

 private:
  const RunTrack& run_;
  const BallTrack& ball_;
  std::size_t done_ = 0;
  std::size_t piece_ = 0;
};

}  // namespace

std::vector<std::size_t> thinnedSamples(const std::vector<PathSample>& s, double tolerance) {
  std::vector<std::size_t> kept;
  if (s.empty()) return kept;
  kept.push_back(0);
  if (!(tolerance > 0)) {
    for (std::size_t i = 1; i < s.size(); ++i) kept.push_back(i);
    return kept;
  }
  // A straight piece from the anchor a to a later sample e, travelled at constant speed, passes
  // a skipped sample q at q's own time within the tolerance exactly when the piece's velocity
  // w = (e − a)/(t_e − t_a) lies within tolerance/(t_q − t_a) of (q − a)/(t_q − t_a). Each
  // skipped sample bounds w, so the admissible velocities are kept as one box (per axis
  // tolerance/√2, which bounds the distance by the tolerance; a hair less for rounding): one
  // pass, no sample looked at twice.
  const double half = 0.999 * tolerance / std::sqrt(2.0);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::size_t anchor = 0;
  Vec2<double> lo(-kInf, -kInf), hi(kInf, kInf);
  for (std::size_t j = 1; j < s.size(); ++j) {
    double span = s[j].t - s[anchor].t;
    Vec2<double> w = (1 / span) * (s[j].p - s[anchor].p);
    if (w.x < lo.x || w.x > hi.x || w.y < lo.y || w.y > hi.y) {
      // The piece cannot reach j: it ends at the sample before, which starts the next one.
      anchor = j - 1;
      kept.push_back(anchor);
      lo = Vec2<double>(-kInf, -kInf);
      hi = Vec2<double>(kInf, kInf);
      span = s[j].t - s[anchor].t;
      w = (1 / span) * (s[j].p - s[anchor].p);
    }
    const double reach = half / span;
    lo = Vec2<double>(std::max(lo.x, w.x - reach), std::max(lo.y, w.y - reach));
    hi = Vec2<double>(std::min(hi.x, w.x + reach), std::min(hi.y, w.y + reach));
  }
  if (kept.back() != s.size() - 1) kept.push_back(s.size() - 1);
  return kept;
}

PathOverlay overlayOf(const PathFile& path, const std::string& label, const RunTrack& ours, double tolerance) {
  PathOverlay overlay;
  overlay.label = label;
  overlay.engine = path.engine;
  overlay.dt = path.dt;
  overlay.tolerance = tolerance;
  for (std::size_t b = 0; b < path.balls.size(); ++b) {
    const auto own =
        std::find_if(ours.balls.begin(), ours.balls.end(), [&](const BallTrack& t) { return t.name == path.balls[b]; });
    if (own == ours.balls.end())
      throw std::runtime_error("the path's ball " + path.balls[b] + " is not a ball of the run");
    // The samples up to our run's end, and the one after it, which the player interpolates to.
    const std::vector<PathSample>& all = path.samples[b];
    std::size_t count = 0;
    while (count < all.size() && all[count].t <= ours.endTime) ++count;
    const std::vector<PathSample> shown(all.begin(),
                                        all.begin() + static_cast<std::ptrdiff_t>(std::min(all.size(), count + 1)));

    OurPosition position(ours, *own);
    for (std::size_t k = 0; k < count; ++k) {
      if (own->pieces.empty()) break;
      if (overlay.parting && all[k].t >= overlay.parting->time) break;
      const Vec2<double> here = position.at(all[k].t);
      const double d = std::hypot(all[k].p.x - here.x, all[k].p.y - here.y);
      if (d > kPartingDistance) {
        overlay.parting = PathParting{all[k].t, path.balls[b], d, here, all[k].p};
        break;
      }
    }

    OverlayBall ball;
    ball.name = path.balls[b];
    for (std::size_t i : thinnedSamples(shown, tolerance)) {
      ball.t.push_back(shown[i].t);
      ball.p.push_back(shown[i].p);
    }
    overlay.balls.push_back(std::move(ball));
  }
  return overlay;
}

}  // namespace gizmo::cli
