#pragma once
// A flipper's swing over a run, rebuilt from a log's decisions: the log records each action on
// the flipper, each flipper stop and each block, and the swing between them is the fixed motion
// of docs/physics.md §2. Each anchor says: after this event, the progress along the forward
// swing is s0 at t0 and moves at `direction` (+1 forward, −1 back, 0 still), within [0, 1/12 s].
#include <cstdint>
#include <vector>

namespace gizmo::cli {

struct SwingAnchor {
  std::int64_t event = -1;
  double t0 = 0, s0 = 0;
  int direction = 0;
};

class FlipperSwings {
 public:
  FlipperSwings();
  // A flipper as a branch log's first keyframe left it: moving from progress s0 at t0.
  FlipperSwings(const SwingAnchor& start, int lastDirection);
  // The flipper's action (Flipper::fireTrigger): at rest swing forward, at the end swing back,
  // mid-swing reverse, blocked mid-swing go back the way it came.
  void action(std::int64_t event, double now);
  void stopped(std::int64_t event, double now);  // its flipper-stop event ran
  void blocked(std::int64_t event, double now);  // it pinched a ball and stops where it is
  const std::vector<SwingAnchor>& anchors() const { return anchors_; }
  // The anchors a viewer can tell apart: an anchor whose swing keeps the flipper's tip within
  // `tolerance` (L) of the kept anchor before it is left out, and a flipper that trembles within
  // the tolerance (a ball jittering on a bumper that toggles it) is held still at the middle.
  // A tolerance of 0 keeps every anchor.
  std::vector<SwingAnchor> visibleAnchors(double tolerance, double endTime) const;

 private:
  double progressAt(double t) const;
  void anchor(std::int64_t event, double t, double s, int direction);

  std::vector<SwingAnchor> anchors_;
  int lastDirection_ = 1;
};

}  // namespace gizmo::cli
