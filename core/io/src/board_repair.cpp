#include "board_repair.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "gizmo/core/board_spec_check.hpp"

namespace gizmo::io::detail {
namespace {

constexpr double kLow = kBallRadius, kHigh = kBoardSize - kBallRadius;

std::string num(double v) { return shortest(v); }

bool finiteBall(const BallSpec& b) {
  return std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.vx) && std::isfinite(b.vy) &&
         std::fabs(b.vx) <= kMaxSpeedComponent && std::fabs(b.vy) <= kMaxSpeedComponent;
}

bool gizmoOnBoard(const GizmoSpec& g) {
  return g.x >= 0 && g.y >= 0 && g.x + g.width <= kBoardSize && g.y + g.height <= kBoardSize;
}

// A ball whose centre lies in an absorber's rectangle (edges included) and that is not already a
// valid captured ball: caught by that absorber, as the programs that allow it do at once.
void captureBallsInAbsorbers(BoardSpec& board, Reporter& rep) {
  std::vector<const GizmoSpec*> absorbers;
  for (const GizmoSpec& g : board.gizmos)
    if (g.type == GizmoType::Absorber && gizmoOnBoard(g)) absorbers.push_back(&g);
  if (absorbers.empty()) return;
  for (BallSpec& b : board.balls) {
    if (!finiteBall(b)) continue;
    for (const GizmoSpec* a : absorbers) {
      const GizmoSpec& g = *a;
      const double x0 = g.x, y0 = g.y, x1 = g.x + g.width, y1 = g.y + g.height;
      if (b.x < x0 || b.x > x1 || b.y < y0 || b.y > y1) continue;
      const bool wholly = b.x - kBallRadius >= x0 && b.x + kBallRadius <= x1 && b.y - kBallRadius >= y0 &&
                          b.y + kBallRadius <= y1;
      if (wholly && b.vx == 0 && b.vy == 0) break;  // captured already
      const double x = std::clamp(b.x, x0 + kBallRadius, x1 - kBallRadius);
      const double y = std::clamp(b.y, y0 + kBallRadius, y1 - kBallRadius);
      rep.lenient("ball-in-absorber", b.where,
                  "ball " + quote(b.name) + " at (" + num(b.x) + ", " + num(b.y) + ") with velocity (" + num(b.vx) +
                      ", " + num(b.vy) + ") lies in absorber " + quote(g.name) +
                      "; it is read as captured there, at rest at (" + num(x) + ", " + num(y) + ")");
      b.x = x;
      b.y = y;
      b.vx = b.vy = 0;
      break;
    }
  }
}

// A ball whose centre is on the board but whose circle sticks out: moved inside, touching the wall.
void moveBallsInside(BoardSpec& board, Reporter& rep) {
  for (BallSpec& b : board.balls) {
    if (!finiteBall(b) || b.x < 0 || b.x > kBoardSize || b.y < 0 || b.y > kBoardSize) continue;
    const double x = std::clamp(b.x, kLow, kHigh), y = std::clamp(b.y, kLow, kHigh);
    if (x == b.x && y == b.y) continue;
    rep.lenient("ball-on-wall", b.where,
                "ball " + quote(b.name) + " at (" + num(b.x) + ", " + num(b.y) +
                    ") sticks out of the board; it is moved inside to (" + num(x) + ", " + num(y) +
                    "), touching the wall");
    b.x = x;
    b.y = y;
  }
}

using Pos = std::pair<int, int>;
Pos key(const SourcePos& p) { return {p.line, p.column}; }

}  // namespace

void repairPlacements(BoardSpec& board, Reporter& rep) {
  if (board.balls.size() > kMaxBalls || board.gizmos.size() > kMaxGizmos) return;
  captureBallsInAbsorbers(board, rep);
  moveBallsInside(board, rep);
  // Each problem is reported at one statement; a statement places one ball or gizmo. Overlaps are
  // reported at the later of the two, so leaving that one out keeps the earlier. Removing only
  // shrinks the board, so this ends.
  for (int round = 0; round < 64; ++round) {
    std::map<Pos, std::size_t> ballAt, gizmoAt;
    for (std::size_t i = 0; i < board.balls.size(); ++i)
      if (finiteBall(board.balls[i]) && board.balls[i].where.line > 0) ballAt[key(board.balls[i].where)] = i;
    for (std::size_t i = 0; i < board.gizmos.size(); ++i)
      if (gizmoOnBoard(board.gizmos[i]) && board.gizmos[i].where.line > 0) gizmoAt[key(board.gizmos[i].where)] = i;
    std::set<std::size_t> dropBalls, dropGizmos;
    for (const SpecProblem& p : checkBoardSpec(board)) {
      const bool overlap = p.message.find(" overlaps ") != std::string::npos;
      if (!overlap) continue;
      if (const auto it = ballAt.find(key(p.where)); it != ballAt.end() && dropBalls.insert(it->second).second)
        rep.lenient("overlap-left-out", p.where, p.message + "; the ball is left out");
      else if (const auto jt = gizmoAt.find(key(p.where)); jt != gizmoAt.end() && dropGizmos.insert(jt->second).second)
        rep.lenient("overlap-left-out", p.where, p.message + "; the " + gizmoTypeWord(board.gizmos[jt->second].type) +
                                                     " is left out");
    }
    if (dropBalls.empty() && dropGizmos.empty()) return;
    std::set<std::string> gone;
    for (const std::size_t i : dropGizmos) gone.insert(board.gizmos[i].name);
    std::vector<BallSpec> balls;
    for (std::size_t i = 0; i < board.balls.size(); ++i)
      if (!dropBalls.count(i)) balls.push_back(std::move(board.balls[i]));
    board.balls = std::move(balls);
    std::vector<GizmoSpec> gizmos;
    for (std::size_t i = 0; i < board.gizmos.size(); ++i)
      if (!dropGizmos.count(i)) gizmos.push_back(std::move(board.gizmos[i]));
    board.gizmos = std::move(gizmos);
    std::erase_if(board.connections, [&](const ConnectSpec& c) {
      const bool drop = gone.count(c.source) || gone.count(c.target);
      if (drop)
        rep.lenient("connection-to-left-out", c.where,
                    "this connection names " + quote(gone.count(c.source) ? c.source : c.target) +
                        ", which is left out; the connection is ignored");
      return drop;
    });
    std::erase_if(board.keyConnections, [&](const KeyConnectSpec& k) {
      const bool drop = gone.count(k.target) > 0;
      if (drop)
        rep.lenient("connection-to-left-out", k.where,
                    "this connection names " + quote(k.target) + ", which is left out; the connection is ignored");
      return drop;
    });
  }
}

}  // namespace gizmo::io::detail
