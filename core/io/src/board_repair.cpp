#include "board_repair.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <vector>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/gizmo_kinds.hpp"

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

// A ball whose centre lies in the rectangle of an absorber (a kind that holds the balls placed in it,
// kinds/STEM.hpp: holdsPlacedBalls), edges included, and that is not already a valid captured ball:
// caught by it, as the programs that allow it do at once.
void captureBallsInAbsorbers(BoardSpec& board, Reporter& rep) {
  std::vector<const GizmoSpec*> absorbers;
  for (const GizmoSpec& g : board.gizmos)
    if (gizmoKind(g.type).holdsPlacedBalls && gizmoOnBoard(g)) absorbers.push_back(&g);
  if (absorbers.empty()) return;
  for (BallSpec& b : board.balls) {
    if (!finiteBall(b)) continue;
    for (const GizmoSpec* a : absorbers) {
      const GizmoSpec& g = *a;
      const double x0 = g.x, y0 = g.y, x1 = g.x + g.width, y1 = g.y + g.height;
      if (b.x < x0 || b.x > x1 || b.y < y0 || b.y > y1) continue;
      const bool wholly =
          b.x - kBallRadius >= x0 && b.x + kBallRadius <= x1 && b.y - kBallRadius >= y0 && b.y + kBallRadius <= y1;
      if (wholly && b.vx == 0 && b.vy == 0) break;  // captured already
      const double x = std::clamp(b.x, x0 + kBallRadius, x1 - kBallRadius);
      const double y = std::clamp(b.y, y0 + kBallRadius, y1 - kBallRadius);
      rep.lenient("ball-in-absorber", b.where,
                  "ball " + quote(b.name) + " at (" + num(b.x) + ", " + num(b.y) + ") with velocity (" + num(b.vx) +
                      ", " + num(b.vy) + ") lies in " + gizmoTypeWord(g.type) + " " + quote(g.name) +
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

bool centreOnBoard(const BallSpec& b) { return b.x >= 0 && b.x <= kBoardSize && b.y >= 0 && b.y <= kBoardSize; }

// The sizes of L, in pixels, that Gizmoball programs draw at: MIT 6.170's 20 (a 400-pixel board),
// 25 (500 pixels), and the larger ones some programs chose.
constexpr double kPixelsPerL[] = {20, 25, 30, 40, 50};

// Whether a coordinate, divided by `scale`, falls on the quarter-L grid that programs place balls
// on (cell corners, centres and the quarters between).
bool onQuarterGrid(double v, double scale) {
  const double q = v / scale * 4;
  return std::floor(q) == q;
}

// A file whose gizmos are placed in pixels: some gizmo lies beyond twice the board's size, and at
// one of the pixel sizes of L every gizmo's corner is a whole cell whose gizmo then lies on the
// board, and every ball's centre lies on it. The smallest such size is taken, and every gizmo and
// ball of the file is divided by it (an absorber covers the cells its far corner reaches into; a
// ball's velocity is in pixels per second too). docs/board-files.md §2.
void convertPixelFile(BoardSpec& board, Reporter& rep) {
  const GizmoSpec* far = nullptr;
  for (const GizmoSpec& g : board.gizmos)
    if (!far && (g.x >= 2 * kBoardSize || g.y >= 2 * kBoardSize)) far = &g;
  if (!far) return;
  auto cells = [](long long v, long long s) { return (v + s - 1) / s; };  // v ≥ 0: the cells v reaches into
  long long chosen = 0;
  for (const double size : kPixelsPerL) {
    const long long s = static_cast<long long>(size);
    bool fits = true;
    for (const GizmoSpec& g : board.gizmos) {
      if (g.x < 0 || g.y < 0 || g.x % s != 0 || g.y % s != 0) {
        fits = false;
        break;
      }
      const long long x = g.x / s, y = g.y / s;
      const bool sized = sizedByLine(g.type);
      const long long w = sized ? cells(g.width, s) : g.width;
      const long long h = sized ? cells(g.height, s) : g.height;
      fits = x + w <= kBoardSize && y + h <= kBoardSize &&
             (!gizmoKind(g.type).exitCell || (g.exitX % s == 0 && g.exitY % s == 0));
      if (!fits) break;
    }
    for (const BallSpec& b : board.balls)
      fits = fits && finiteBall(b) && b.x / size >= 0 && b.x / size <= kBoardSize && b.y / size >= 0 &&
             b.y / size <= kBoardSize;
    if (fits) {
      chosen = s;
      break;
    }
  }
  if (chosen == 0) return;
  const std::string was = "(" + std::to_string(far->x) + ", " + std::to_string(far->y) + ")";
  for (GizmoSpec& g : board.gizmos) {
    g.x = static_cast<int>(g.x / chosen);
    g.y = static_cast<int>(g.y / chosen);
    if (sizedByLine(g.type)) {
      g.width = static_cast<int>(cells(g.width, chosen));
      g.height = static_cast<int>(cells(g.height, chosen));
    }
    if (gizmoKind(g.type).exitCell) {
      g.exitX = static_cast<int>(g.exitX / chosen);
      g.exitY = static_cast<int>(g.exitY / chosen);
    }
  }
  const double size = static_cast<double>(chosen);
  for (BallSpec& b : board.balls) {
    b.x /= size;
    b.y /= size;
    b.vx /= size;
    b.vy /= size;
  }
  rep.lenient("file-in-pixels", far->where,
              std::string(gizmoTypeWord(far->type)) + " " + quote(far->name) + " at " + was +
                  " lies beyond the board, and the file places every gizmo at a whole cell of " + num(size) +
                  " pixels: the file is read as written in pixels at " + num(size) +
                  " per L (the smallest of 20, 25, 30, 40 and 50 at which every gizmo and ball is then on the "
                  "board), every gizmo's corner and every ball's position and velocity divided by it");
}

// A ball whose centre lies off the board, among gizmos placed in L, is taken as written in pixels
// when one of the pixel sizes of L puts every such ball of the file on the board with both of its
// coordinates on the quarter-L grid (the smallest such size); its velocity is divided too (pixels
// per second). Without that evidence, as for a ball a little past a wall, the ball is off the
// board (leaveOutWhatIsOffTheBoard). docs/board-files.md §2.
void convertPixelBalls(BoardSpec& board, Reporter& rep) {
  std::vector<BallSpec*> off;
  for (BallSpec& b : board.balls)
    if (finiteBall(b) && !centreOnBoard(b)) off.push_back(&b);
  if (off.empty()) return;
  double chosen = 0;
  for (const double scale : kPixelsPerL) {
    bool fits = true;
    for (const BallSpec* b : off) {
      const double x = b->x / scale, y = b->y / scale;
      fits = fits && x >= kLow && x <= kHigh && y >= kLow && y <= kHigh && onQuarterGrid(b->x, scale) &&
             onQuarterGrid(b->y, scale);
    }
    if (fits) {
      chosen = scale;
      break;
    }
  }
  if (chosen == 0) return;
  for (BallSpec* b : off) {
    const BallSpec was = *b;
    b->x /= chosen;
    b->y /= chosen;
    b->vx /= chosen;
    b->vy /= chosen;
    rep.lenient("ball-in-pixels", b->where,
                "ball " + quote(b->name) + " at (" + num(was.x) + ", " + num(was.y) +
                    ") lies off the 20 L board, among gizmos placed in L; it is read as written in pixels at " +
                    num(chosen) +
                    " per L (the smallest of 20, 25, 30, 40 and 50 that puts every such ball of the "
                    "file on the board, at a quarter of L): at (" +
                    num(b->x) + ", " + num(b->y) + ") with velocity (" + num(b->vx) + ", " + num(b->vy) + ")");
  }
}

// The ball a gizmo's overlap message names ("square 'S' overlaps ball 'K' from line 3 …").
std::optional<std::string> overlappedBall(const std::string& message) {
  const std::string mark = " overlaps ball '";
  const std::size_t from = message.find(mark);
  if (from == std::string::npos) return std::nullopt;
  const std::size_t start = from + mark.size(), end = message.find('\'', start);
  if (end == std::string::npos) return std::nullopt;
  return message.substr(start, end - start);
}

using Pos = std::pair<int, int>;
Pos key(const SourcePos& p) { return {p.line, p.column}; }

// Leaves out the balls and gizmos named by index, and every connection of a gizmo left out.
void leaveOut(BoardSpec& board, const std::set<std::size_t>& dropBalls, const std::set<std::size_t>& dropGizmos,
              Reporter& rep) {
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
  dropConnectionsTo(board, gone, rep);
}

// What lies off the board after the pixel rule, a ball whose centre is off it or a gizmo not
// wholly on it, is left out: the board has no place for it (docs/board-files.md §2).
void leaveOutWhatIsOffTheBoard(BoardSpec& board, Reporter& rep) {
  std::set<std::size_t> dropBalls, dropGizmos;
  for (std::size_t i = 0; i < board.balls.size(); ++i) {
    const BallSpec& b = board.balls[i];
    if (!finiteBall(b) || centreOnBoard(b)) continue;
    dropBalls.insert(i);
    rep.lenient("off-board-ball", b.where,
                "ball " + quote(b.name) + " at (" + num(b.x) + ", " + num(b.y) +
                    ") is not on the board, which spans 0..20 L in both directions; the ball is left out");
  }
  for (std::size_t i = 0; i < board.gizmos.size(); ++i) {
    const GizmoSpec& g = board.gizmos[i];
    if (gizmoKind(g.type).exitCell && (g.exitX < 0 || g.exitY < 0 || g.exitX >= kBoardSize || g.exitY >= kBoardSize)) {
      const std::string word = gizmoTypeWord(g.type);
      dropGizmos.insert(i);
      rep.lenient("off-board-exit", g.where,
                  word + " " + quote(g.name) + " has its exit at cell " + std::to_string(g.exitX) + "," +
                      std::to_string(g.exitY) + ", which is not on the board (cells 0..19 in both); the " + word +
                      " is left out");
      continue;
    }
    if (gizmoOnBoard(g) || g.width <= 0 || g.height <= 0) continue;
    dropGizmos.insert(i);
    rep.lenient("off-board-gizmo", g.where,
                std::string(gizmoTypeWord(g.type)) + " " + quote(g.name) + " covers x " + std::to_string(g.x) + ".." +
                    std::to_string(g.x + g.width) + ", y " + std::to_string(g.y) + ".." +
                    std::to_string(g.y + g.height) + ", not wholly on the board (0..20 in both); the " +
                    gizmoTypeWord(g.type) + " is left out");
  }
  if (!dropBalls.empty() || !dropGizmos.empty()) leaveOut(board, dropBalls, dropGizmos, rep);
}

}  // namespace

void dropConnectionsTo(BoardSpec& board, const std::set<std::string>& gone, Reporter& rep) {
  if (gone.empty()) return;
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

void repairPlacements(BoardSpec& board, Reporter& rep) {
  if (board.balls.size() > kMaxBalls || board.gizmos.size() > kMaxGizmos) return;
  convertPixelFile(board, rep);
  convertPixelBalls(board, rep);
  leaveOutWhatIsOffTheBoard(board, rep);
  captureBallsInAbsorbers(board, rep);
  moveBallsInside(board, rep);
  // Each problem is reported at one statement; a statement places one ball or gizmo. Overlaps are
  // reported at the later of the two, and leaving that one out keeps the earlier, except that of a
  // ball and a gizmo the ball goes, whichever the file places first (an XML file places its balls
  // before its gizmos): the gizmos are the board, a ball inside one has no place to start from.
  // Removing only shrinks the board, so this ends.
  for (int round = 0; round < 64; ++round) {
    std::map<Pos, std::size_t> ballAt, gizmoAt;
    std::map<std::string, std::size_t> ballNamed;
    for (std::size_t i = 0; i < board.balls.size(); ++i) {
      if (finiteBall(board.balls[i]) && board.balls[i].where.line > 0) ballAt[key(board.balls[i].where)] = i;
      ballNamed.emplace(board.balls[i].name, i);
    }
    for (std::size_t i = 0; i < board.gizmos.size(); ++i)
      if (gizmoOnBoard(board.gizmos[i]) && board.gizmos[i].where.line > 0) gizmoAt[key(board.gizmos[i].where)] = i;
    std::set<std::size_t> dropBalls, dropGizmos;
    for (const SpecProblem& p : checkBoardSpec(board)) {
      const bool overlap = p.message.find(" overlaps ") != std::string::npos;
      if (!overlap) continue;
      const auto it = ballAt.find(key(p.where));
      const auto jt = gizmoAt.find(key(p.where));
      if (it == ballAt.end() && jt != gizmoAt.end()) {
        if (const std::optional<std::string> ball = overlappedBall(p.message)) {
          if (const auto b = ballNamed.find(*ball); b != ballNamed.end()) {
            if (dropBalls.insert(b->second).second)
              rep.lenient("overlap-left-out", p.where, p.message + "; the ball is left out");
            continue;
          }
        }
      }
      if (it != ballAt.end() && dropBalls.insert(it->second).second)
        rep.lenient("overlap-left-out", p.where, p.message + "; the ball is left out");
      else if (jt != gizmoAt.end() && dropGizmos.insert(jt->second).second)
        rep.lenient("overlap-left-out", p.where,
                    p.message + "; the " + gizmoTypeWord(board.gizmos[jt->second].type) + " is left out");
    }
    if (dropBalls.empty() && dropGizmos.empty()) return;
    leaveOut(board, dropBalls, dropGizmos, rep);
  }
}

}  // namespace gizmo::io::detail
