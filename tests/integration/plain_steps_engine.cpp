// A deliberately naive engine, for the tests of `gizmo crosscheck --trace` (docs/verification.md,
// "Any engine's run"): it moves every ball in plain fixed steps (x += v·dt, then v += g·dt) and
// looks for contacts only where a step ends, against the outer walls and the board's squares (it
// knows no other gizmo). A ball that crosses a square within one step passes through it; the
// cross-check must say so. It writes its run as a trace (JSON lines) on standard output.
//   plain_steps_engine BOARD DT SECONDS
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "gizmo/io/board_file.hpp"

namespace {

struct Body {
  std::string name;
  double x, y, vx, vy;
};

struct Contact {
  double t;
  std::string ball, other;
  double x, y;
};

constexpr double kRadius = 0.25, kSize = 20;

// Pushes the ball out of the walls, reflecting its velocity; one contact per wall met.
void walls(Body& b, double t, std::vector<Contact>& contacts) {
  bool hit = false;
  if (b.x < kRadius) b.x = 2 * kRadius - b.x, b.vx = -b.vx, hit = true;
  if (b.x > kSize - kRadius) b.x = 2 * (kSize - kRadius) - b.x, b.vx = -b.vx, hit = true;
  if (b.y < kRadius) b.y = 2 * kRadius - b.y, b.vy = -b.vy, hit = true;
  if (b.y > kSize - kRadius) b.y = 2 * (kSize - kRadius) - b.y, b.vy = -b.vy, hit = true;
  if (hit) contacts.push_back({t, b.name, "OuterWalls", b.x, b.y});
}

// A ball overlapping the unit square at (sx, sy) is mirrored out along the axis of least overlap
// (as the walls mirror it), that component of its velocity reversed.
void square(Body& b, const std::string& name, double sx, double sy, double t, std::vector<Contact>& contacts) {
  const double cx = std::clamp(b.x, sx, sx + 1), cy = std::clamp(b.y, sy, sy + 1);
  if ((b.x - cx) * (b.x - cx) + (b.y - cy) * (b.y - cy) >= kRadius * kRadius) return;
  contacts.push_back({t, b.name, name, b.x, b.y});
  const double left = b.x + kRadius - sx, right = sx + 1 + kRadius - b.x;
  const double top = b.y + kRadius - sy, bottom = sy + 1 + kRadius - b.y;
  const double least = std::min({left, right, top, bottom});
  if (least == left) b.x -= 2 * left, b.vx = -std::fabs(b.vx);
  else if (least == right) b.x += 2 * right, b.vx = std::fabs(b.vx);
  else if (least == top) b.y -= 2 * top, b.vy = -std::fabs(b.vy);
  else b.y += 2 * bottom, b.vy = std::fabs(b.vy);
}

void printStep(double t, const std::vector<Body>& balls, const std::vector<Contact>& contacts) {
  std::printf("{\"t\":%.17g,\"balls\":{", t);
  for (std::size_t i = 0; i < balls.size(); ++i)
    std::printf("%s\"%s\":{\"x\":%.17g,\"y\":%.17g,\"vx\":%.17g,\"vy\":%.17g}", i ? "," : "", balls[i].name.c_str(),
                balls[i].x, balls[i].y, balls[i].vx, balls[i].vy);
  std::printf("},\"contacts\":[");
  for (std::size_t i = 0; i < contacts.size(); ++i)
    std::printf("%s{\"t\":%.17g,\"ball\":\"%s\",\"other\":\"%s\",\"x\":%.17g,\"y\":%.17g}", i ? "," : "", contacts[i].t,
                contacts[i].ball.c_str(), contacts[i].other.c_str(), contacts[i].x, contacts[i].y);
  std::printf("]}\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: plain_steps_engine BOARD DT SECONDS\n");
    return 2;
  }
  gizmo::BoardSpec board;
  try {
    board = gizmo::io::readBoardFile(argv[1]).board;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plain_steps_engine: %s\n", e.what());
    return 2;
  }
  const double dt = std::atof(argv[2]), seconds = std::atof(argv[3]);
  if (!(dt > 0) || !(seconds > 0)) {
    std::fprintf(stderr, "plain_steps_engine: DT and SECONDS must be positive\n");
    return 2;
  }
  std::vector<Body> balls;
  for (const gizmo::BallSpec& b : board.balls) balls.push_back({b.name, b.x, b.y, b.vx, b.vy});
  std::printf("{\"format\":\"gizmo-trace\",\"version\":1,\"engine\":\"plain steps of %g s\",\"contacts\":true}\n", dt);
  printStep(0, balls, {});
  const long steps = std::lround(std::ceil(seconds / dt));
  for (long k = 1; k <= steps; ++k) {
    const double t = double(k) * dt;
    std::vector<Contact> contacts;
    for (Body& b : balls) {
      b.x += b.vx * dt;
      b.y += b.vy * dt;
      b.vy += board.gravity * dt;
      walls(b, t, contacts);
      for (const gizmo::GizmoSpec& g : board.gizmos)
        if (g.type == gizmo::GizmoType::Square) square(b, g.name, g.x, g.y, t, contacts);
    }
    printStep(t, balls, contacts);
  }
  return 0;
}
