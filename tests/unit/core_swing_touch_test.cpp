// A still ball that touches a swinging arm (a flipper, a spinner's arm) to within rounding, and
// that the arm turns into or gravity presses into it, is met at once: placed a few ulps either way
// of touching, beyond the tip, beside it and along the side the arm turns towards, it is struck now
// or found entering within the nanoseconds its gap takes to close. The arm's present contact test
// (pressedIntoSwing) and its entry search compute the gap in different ways; where the first put a
// ball an ulp or two off and the second at zero, neither met it, and a ball released at rest
// against a spinner's tip as the spinner started fell into the arm (campaign seed 1796527371, case
// 704: 8.5·10⁻⁹ L inside, then a stall). docs/physics.md, "A moving flipper pressing a touching
// ball". Without that slack the spinner's test finds two such balls; the flipper's finds none
// either way (its arm turns six times as fast, and closes on or curves away from a ball where the
// spinner's lies still beside it), and guards the same property.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "support/board_builder.hpp"
#include "support/stub_board.hpp"

namespace gizmo {
namespace {

using namespace test;

constexpr double kUlpAt10 = 0x1p-49;  // the spacing of doubles in [8, 16), where these balls lie

// Where a ball touches `axis` on the side it turns towards: on the tip's circle, straight beyond
// the tip and at angles towards that side, and along the leading side; only where the surface
// faces up (y grows downwards), so that gravity presses the ball in. Straight beyond the tip the
// arm neither closes nor opens: only where gravity presses harder than the tip's circle curves
// away (its bend, ωL² + (ωL)²/reach) does the ball stay on it. An arm turning away from a ball
// meets it only once gravity has brought it back, milliseconds later.
std::vector<Vec2<double>> touchesAhead(const SwingingAxis<double>& axis, double gravity) {
  const double reach = Ball<double>::radius() + axis.radius;
  const Vec2<double> u = axis.direction(0);
  const Vec2<double> ahead = axis.omega > 0 ? Vec2<double>(-u.y, u.x) : Vec2<double>(u.y, -u.x);
  const double tipSpeed = axis.length * axis.omega;
  const double tipBend = axis.length * axis.omega * axis.omega + tipSpeed * tipSpeed / reach;
  std::vector<Vec2<double>> touches;
  auto add = [&](const Vec2<double>& surface, const Vec2<double>& n) {
    if (n.y < -0.2) touches.push_back(surface + reach * n);
  };
  if (gravity * -u.y > tipBend) add(axis.pivot + axis.length * u, u);
  for (const double angle : {0.6, 1.2})
    add(axis.pivot + axis.length * u, std::cos(angle) * u + std::sin(angle) * ahead);
  for (const double along : {0.4, 0.7}) add(axis.pivot + along * axis.length * u, ahead);
  return touches;
}

// Each touch of `axis`, moved by up to three ulps in x and in y, met by `gizmo` within 1e-6 s;
// `placed` counts the balls placed.
void expectEachTouchMetAtOnce(const AbstractGizmo<double>& gizmo, const SwingingAxis<double>& axis, StubBoard& board,
                              const std::string& where, int& placed) {
  Ball<double>& ball = board.balls[0];
  int index = 0;
  for (const Vec2<double>& touch : touchesAhead(axis, board.params().gravity))
    for (int dx = -3, touchIndex = index++; dx <= 3; ++dx)
      for (int dy = -3; dy <= 3; ++dy) {
        const Vec2<double> p(touch.x + dx * kUlpAt10, touch.y + dy * kUlpAt10);
        ball.setState(board.now(), p, {0, 0}, board.params());
        const std::optional<Contact<double>> hit =
            gizmo.timeUntilCollision(ball, board.now(), board.now() + 1, board.params());
        std::ostringstream at;
        at.precision(17);
        at << where << ", touch " << touchIndex << ", t " << board.now() << ", ball at " << p.x << ", " << p.y;
        ++placed;
        ASSERT_TRUE(hit.has_value()) << at.str();
        EXPECT_LE(hit->time - board.now(), 1e-6) << at.str();
      }
}

TEST(SwingTouch, ABallPressedIntoATurningSpinnerArmWithinRoundingOfTouchingIsMetAtOnce) {
  StubBoard board({{"K", {0, 0}, {0, 0}}}, 1000);
  Spinner<double> spinner(gizmoAt(GizmoType::Spinner, "S", 9, 9, 0, 2, 2));
  spinner.setId(1);
  spinner.fireTrigger(board);  // at t = 0, from the cross at load
  ASSERT_TRUE(spinner.turning());
  int placed = 0;
  for (int step = 1; step <= 60; ++step) {
    board.setNow(0.0173 * step);  // angles over two turns, none a whole quarter
    for (int k = 0; k < 4; ++k)
      expectEachTouchMetAtOnce(spinner, spinner.armAt(k, board.now()), board, "arm " + std::to_string(k), placed);
  }
  EXPECT_GT(placed, 3000);
}

TEST(SwingTouch, ABallPressedIntoASwingingFlipperWithinRoundingOfTouchingIsMetAtOnce) {
  int placed = 0;
  for (const GizmoType type : {GizmoType::LeftFlipper, GizmoType::RightFlipper})
    for (const int orientation : {0, 90, 180, 270})
      for (const int swing : {1, 2}) {  // forward, then back from the end
        StubBoard board({{"K", {0, 0}, {0, 0}}}, 1000);
        Flipper<double> flipper(gizmoAt(type, "F", 9, 9, orientation, 2, 2));
        flipper.setId(1);
        flipper.fireTrigger(board);
        if (swing == 2) {
          board.setNow(flipper.stopTime());
          Event<double> stop;
          stop.kind = EventKind::FlipperStop;
          flipper.handleOwnEvent(stop, board);
          flipper.fireTrigger(board);
        }
        ASSERT_TRUE(flipper.swinging());
        const double start = board.now(), length = flipper.stopTime() - start;
        for (int step = 1; step <= 9; ++step) {
          board.setNow(start + length * step / 10);
          std::ostringstream where;
          where << (type == GizmoType::LeftFlipper ? "left" : "right") << " flipper at " << orientation << "°, swing "
                << swing;
          expectEachTouchMetAtOnce(flipper, flipper.axisAt(board.now()), board, where.str(), placed);
        }
      }
  EXPECT_GT(placed, 3000);
}

}  // namespace
}  // namespace gizmo
