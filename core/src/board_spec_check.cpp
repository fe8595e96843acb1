// checkBoardSpec: the validity of a plain-data board. See board_spec_check.hpp for the rules.
//
// Geometry is decided exactly. Gizmo shapes come from restShape<double>; their vertices are small
// dyadic numbers (multiples of 0.25 near the board), so they are exact doubles. Ball centres are
// arbitrary doubles. Each predicate first tries a double computation with a generous error margin
// and falls back to exact rational arithmetic (GMP) when the answer is within that margin, so a
// ball that exactly touches a gizmo or another ball is never called overlapping, and one that
// overlaps by the smallest representable amount always is.
#include "gizmo/core/board_spec_check.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "exact_dyadic.hpp"
#include "gizmo/core/decimal_text.hpp"
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmo_kinds.hpp"

namespace gizmo {

// Each word is a literal of kGizmoKinds, so its view ends in a terminating null.
const char* gizmoTypeWord(GizmoType type) { return gizmoKind(type).word.data(); }

namespace {

using Exact = detail::ExactDyadic;

// A number for a message: plain decimal digits unless the magnitude is extreme; never rounded.
std::string number(double v) {
  const double a = std::fabs(v);
  const bool plain = v == 0 || (a >= 1e-4 && a < 1e15);
  return plain ? shortestFixedDecimal(v) : shortestDecimal(v);
}

// A name in quotes, cut short when it is very long.
std::string quoted(const std::string& name) {
  if (name.size() > 64) return "'" + name.substr(0, 61) + "...'";
  return "'" + name + "'";
}

bool earlier(const SourcePos& a, const SourcePos& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

// " from line N" when the statement has a position, else nothing.
std::string fromLine(const SourcePos& p) { return p.line > 0 ? " from line " + std::to_string(p.line) : std::string(); }

// "an absorber", "a square": the kinds' words begin with a letter that is sounded.
std::string withArticle(std::string_view word) {
  const bool vowel = !word.empty() && std::string_view("aeiou").find(word.front()) != std::string_view::npos;
  return (vowel ? "an " : "a ") + std::string(word);
}

std::string describe(const GizmoSpec& g) { return std::string(gizmoTypeWord(g.type)) + " " + quoted(g.name); }
std::string describe(const BallSpec& b) { return "ball " + quoted(b.name); }
std::string at(const BallSpec& b) { return " at (" + number(b.x) + ", " + number(b.y) + ")"; }

// ---------------------------------------------------------------------------------------------
// Exact geometric predicates. All "closer than" tests are strict: touching is not overlapping.

// |p − c| < dist, for dist > 0.
bool pointCloserThan(double px, double py, double cx, double cy, double dist) {
  const double dx = px - cx, dy = py - cy;
  // Rounding is monotone and dist is a double: a rounded |dx| above dist means the exact one is.
  if (!(std::fabs(dx) <= dist) || !(std::fabs(dy) <= dist)) return false;
  const double d2 = dx * dx + dy * dy, t = dist * dist;
  // Here d2 ≤ 2t and its relative error is a few units of 2^-53: 1e-9·t is far beyond it.
  if (d2 < t - 1e-9 * t) return true;
  if (d2 > t + 1e-9 * t) return false;
  const Exact ex = Exact(px) - Exact(cx), ey = Exact(py) - Exact(cy), rd(dist);
  return ex * ex + ey * ey < rd * rd;
}

// Distance from p to the closed segment ab is less than dist (dist > 0). The bounding-box test
// subtracts dist from vertex coordinates, which is exact for the small dyadic vertices of gizmos.
bool segmentCloserThan(double px, double py, const Vec2<double>& a, const Vec2<double>& b, double dist) {
  if (px <= std::min(a.x, b.x) - dist || px >= std::max(a.x, b.x) + dist) return false;
  if (py <= std::min(a.y, b.y) - dist || py >= std::max(a.y, b.y) + dist) return false;
  const Exact ax(a.x), ay(a.y), bx(b.x), by(b.y), qx(px), qy(py), r2 = Exact(dist) * Exact(dist);
  const Exact dx = bx - ax, dy = by - ay, wx = qx - ax, wy = qy - ay;
  const Exact along = dx * wx + dy * wy;
  const Exact len2 = dx * dx + dy * dy;
  if (along <= 0) return wx * wx + wy * wy < r2;
  if (along >= len2) {
    const Exact ex = qx - bx, ey = qy - by;
    return ex * ex + ey * ey < r2;
  }
  const Exact c = dx * wy - dy * wx;  // distance² = c² / len2
  return c * c < r2 * len2;
}

// p inside or on the convex polygon (vertices in order, either direction).
bool insideConvex(double px, double py, const std::vector<Vec2<double>>& poly) {
  if (poly.size() < 3) return false;
  double minX = poly[0].x, maxX = poly[0].x, minY = poly[0].y, maxY = poly[0].y;
  for (const auto& v : poly) {
    minX = std::min(minX, v.x);
    maxX = std::max(maxX, v.x);
    minY = std::min(minY, v.y);
    maxY = std::max(maxY, v.y);
  }
  if (px < minX || px > maxX || py < minY || py > maxY) return false;
  const Exact qx(px), qy(py);
  bool positive = false, negative = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2<double>& a = poly[i];
    const Vec2<double>& b = poly[(i + 1) % poly.size()];
    const Exact c = (Exact(b.x) - Exact(a.x)) * (qy - Exact(a.y)) - (Exact(b.y) - Exact(a.y)) * (qx - Exact(a.x));
    if (c > 0) positive = true;
    if (c < 0) negative = true;
    if (positive && negative) return false;
  }
  return true;
}

// A gizmo's rest shape prepared for the ball test: its features, and the convex regions they
// bound. restShape lists a polygon's edges as a closed chain and a capsule's two sides as
// p+off→q+off, q−off→p−off; in both cases the chain of segment end points, without repeats, is
// a convex region whose inside is part of the solid (the capsule's round ends are its circles).
// A turning kind's cross (a spinner's) is two capsules, so two regions of two sides each; every other
// shape is one.
struct PreparedShape {
  Shape<double> shape;
  std::vector<std::vector<Vec2<double>>> hulls;
};

PreparedShape prepare(const GizmoSpec& g) {
  PreparedShape p;
  p.shape = restShape<double>(g);
  const std::size_t n = p.shape.segments.size();
  const std::size_t perPart = turns(g.type) ? 2 : std::max<std::size_t>(n, 1);
  for (std::size_t first = 0; first < n; first += perPart) {
    std::vector<Vec2<double>> hull;
    for (std::size_t i = first; i < std::min(n, first + perPart); ++i) {
      const SegmentFeature<double>& s = p.shape.segments[i];
      if (hull.empty() || !(hull.back() == s.a)) hull.push_back(s.a);
      if (!(hull.back() == s.b)) hull.push_back(s.b);
    }
    if (hull.size() > 1 && hull.front() == hull.back()) hull.pop_back();
    p.hulls.push_back(std::move(hull));
  }
  return p;
}

// The open disc of radius kBallRadius about p shares area with the solid shape.
bool ballOverlaps(double px, double py, const PreparedShape& p) {
  for (const std::vector<Vec2<double>>& hull : p.hulls)
    if (insideConvex(px, py, hull)) return true;
  for (const auto& s : p.shape.segments)
    if (segmentCloserThan(px, py, s.a, s.b, kBallRadius)) return true;
  for (const auto& c : p.shape.circles)
    if (pointCloserThan(px, py, c.centre.x, c.centre.y, c.radius + kBallRadius)) return true;
  return false;
}

// ---------------------------------------------------------------------------------------------

struct Collector {
  std::vector<SpecProblem> list;
  void add(const SourcePos& where, std::string message) { list.push_back(SpecProblem{where, std::move(message)}); }
};

// Indices of v sorted by source position, ties kept in vector order.
template <class T>
std::vector<std::size_t> bySource(const std::vector<T>& v) {
  std::vector<std::size_t> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return earlier(v[a].where, v[b].where); });
  return order;
}

bool validOrientation(int o) { return o == 0 || o == 90 || o == 180 || o == 270; }

void checkNames(const BoardSpec& board, Collector& out) {
  struct Entry {
    SourcePos where;
    bool ball;
    std::size_t index;
  };
  std::vector<Entry> all;
  all.reserve(board.balls.size() + board.gizmos.size());
  for (std::size_t i = 0; i < board.balls.size(); ++i) all.push_back(Entry{board.balls[i].where, true, i});
  for (std::size_t i = 0; i < board.gizmos.size(); ++i) all.push_back(Entry{board.gizmos[i].where, false, i});
  std::stable_sort(all.begin(), all.end(), [](const Entry& a, const Entry& b) { return earlier(a.where, b.where); });

  auto nameOf = [&](const Entry& e) -> const std::string& {
    return e.ball ? board.balls[e.index].name : board.gizmos[e.index].name;
  };
  auto describeEntry = [&](const Entry& e) {
    return e.ball ? describe(board.balls[e.index]) : describe(board.gizmos[e.index]);
  };
  auto kindOf = [&](const Entry& e) -> std::string {
    return e.ball ? "ball" : gizmoTypeWord(board.gizmos[e.index].type);
  };

  std::unordered_map<std::string, std::size_t> first;  // name → index in all
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Entry& e = all[i];
    const std::string& name = nameOf(e);
    if (name == kOuterWallsName) {
      out.add(e.where, "the name 'OuterWalls' is reserved for the outer walls; a " + kindOf(e) + " cannot use it");
      continue;
    }
    auto [it, inserted] = first.emplace(name, i);
    if (!inserted) {
      const Entry& f = all[it->second];
      std::string where = f.where.line > 0 ? " on line " + std::to_string(f.where.line) : std::string();
      out.add(e.where, describeEntry(e) + " has the same name as the " + kindOf(f) + where + "; names must be unique");
    }
  }
}

struct Cell {
  int x, y;
};

void checkGeometry(const BoardSpec& board, Collector& out) {
  constexpr int N = kBoardSize;
  constexpr std::size_t kPerCell = 4;  // gizmos kept per cell for ball tests (more means overlaps anyway)
  const std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> owner(N * N, none);             // first gizmo (order position) per cell
  std::vector<std::vector<std::size_t>> occupants(N * N);  // gizmo indices, at most kPerCell
  std::vector<std::optional<PreparedShape>> shapes(board.gizmos.size());
  std::vector<std::array<long long, 4>> boxes(board.gizmos.size());  // clipped x0, y0, x1, y1

  const std::vector<std::size_t> gizmoOrder = bySource(board.gizmos);
  for (std::size_t k = 0; k < gizmoOrder.size(); ++k) {
    const std::size_t gi = gizmoOrder[k];
    const GizmoSpec& g = board.gizmos[gi];
    bool placeable = true;
    if (!validOrientation(g.orientation)) {
      out.add(g.where,
              describe(g) + " has orientation " + std::to_string(g.orientation) + "; it must be 0, 90, 180 or 270");
      placeable = false;
    } else if (sizedByLine(g.type) && g.orientation != 0) {
      out.add(g.where, describe(g) + " has orientation " + std::to_string(g.orientation) + ", but " +
                           withArticle(gizmoTypeWord(g.type)) + " cannot be rotated");
    }
    const int ownW = ownSide(g.type), ownH = ownW;  // a kind sized by its line: any size of at least 1×1
    if (sizedByLine(g.type)) {
      if (g.width < 1 || g.height < 1) {
        out.add(g.where, describe(g) + " is " + std::to_string(g.width) + " x " + std::to_string(g.height) +
                             " L; its width and height must each be at least 1");
        placeable = false;
      }
    } else if (g.width != ownW || g.height != ownH) {
      out.add(g.where, describe(g) + " is " + std::to_string(g.width) + " x " + std::to_string(g.height) +
                           " L, but every " + gizmoTypeWord(g.type) + " is " + std::to_string(ownW) + " x " +
                           std::to_string(ownH) + " L");
      placeable = false;
    }
    if (!placeable) continue;

    if (gizmoKind(g.type).exitCell && (g.exitX < 0 || g.exitY < 0 || g.exitX >= N || g.exitY >= N)) {
      out.add(g.where, describe(g) + " has its exit at cell " + std::to_string(g.exitX) + "," +
                           std::to_string(g.exitY) + ", which is not on the board (cells 0..19 in both)");
    }
    const long long x0 = g.x, y0 = g.y, x1 = x0 + g.width, y1 = y0 + g.height;
    if (x0 < 0 || y0 < 0 || x1 > N || y1 > N) {
      out.add(g.where, describe(g) + " is not inside the board: it covers x " + std::to_string(x0) + ".." +
                           std::to_string(x1) + ", y " + std::to_string(y0) + ".." + std::to_string(y1) +
                           ", and the board spans 0..20 in both");
    }
    const long long cx0 = std::max(x0, 0LL), cy0 = std::max(y0, 0LL);
    const long long cx1 = std::min(x1, static_cast<long long>(N)), cy1 = std::min(y1, static_cast<long long>(N));
    boxes[gi] = {cx0, cy0, cx1, cy1};
    shapes[gi] = prepare(g);
    if (cx0 >= cx1 || cy0 >= cy1) continue;  // wholly off the board: nothing to overlap on it

    std::size_t firstOther = none;
    for (long long y = cy0; y < cy1; ++y)
      for (long long x = cx0; x < cx1; ++x) {
        const std::size_t o = owner[static_cast<std::size_t>(y * N + x)];
        if (o != none && (firstOther == none || o < firstOther)) firstOther = o;
      }
    if (firstOther != none) {
      const std::size_t oi = gizmoOrder[firstOther];
      const GizmoSpec& other = board.gizmos[oi];
      const long long sx = std::max(cx0, boxes[oi][0]), sy = std::max(cy0, boxes[oi][1]);
      out.add(g.where, describe(g) + " overlaps " + describe(other) + fromLine(other.where) + " (both occupy cell " +
                           std::to_string(sx) + "," + std::to_string(sy) + ")");
    }
    for (long long y = cy0; y < cy1; ++y)
      for (long long x = cx0; x < cx1; ++x) {
        const std::size_t c = static_cast<std::size_t>(y * N + x);
        if (owner[c] == none) owner[c] = k;
        if (occupants[c].size() < kPerCell) occupants[c].push_back(gi);
      }
  }

  // Balls.
  const std::vector<std::size_t> ballOrder = bySource(board.balls);
  std::vector<char> captured(board.balls.size(), 0);
  std::vector<char> usable(board.balls.size(), 0);
  for (const std::size_t bi : ballOrder) {
    const BallSpec& b = board.balls[bi];
    if (!std::isfinite(b.x) || !std::isfinite(b.y)) {
      out.add(b.where, describe(b) + " has a position that is not a finite number");
      continue;
    }
    if (!std::isfinite(b.vx) || !std::isfinite(b.vy)) {
      out.add(b.where, describe(b) + " has a velocity that is not a finite number");
    } else if (std::fabs(b.vx) > kMaxSpeedComponent || std::fabs(b.vy) > kMaxSpeedComponent) {
      out.add(b.where, describe(b) + " is too fast: its velocity (" + number(b.vx) + ", " + number(b.vy) +
                           ") L/s exceeds " + number(kMaxSpeedComponent) + " L/s in x or y");
    }
    usable[bi] = 1;
    const double lo = kBallRadius, hi = kBoardSize - kBallRadius;
    if (!(b.x >= lo && b.x <= hi && b.y >= lo && b.y <= hi)) {
      out.add(b.where,
              describe(b) + at(b) + " is not inside the board: its centre must be at least 0.25 L from every wall");
    }
    // Candidate gizmos: those in the cells the ball's disc can reach (with margin).
    const double fx0 = std::max(0.0, std::floor(b.x - 0.5)), fx1 = std::min(N - 1.0, std::floor(b.x + 0.5));
    const double fy0 = std::max(0.0, std::floor(b.y - 0.5)), fy1 = std::min(N - 1.0, std::floor(b.y + 0.5));
    std::vector<std::size_t> candidates;
    for (double y = fy0; y <= fy1; ++y)
      for (double x = fx0; x <= fx1; ++x)
        for (const std::size_t gi : occupants[static_cast<std::size_t>(y) * N + static_cast<std::size_t>(x)])
          candidates.push_back(gi);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    // Report in the gizmos' source order.
    std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t c) {
      return earlier(board.gizmos[a].where, board.gizmos[c].where);
    });
    const bool atRest = b.vx == 0 && b.vy == 0;
    for (const std::size_t gi : candidates) {
      const GizmoSpec& g = board.gizmos[gi];
      if (gizmoKind(g.type).holdsPlacedBalls) {
        const double ax0 = g.x + kBallRadius, ax1 = static_cast<double>(g.x) + g.width - kBallRadius;
        const double ay0 = g.y + kBallRadius, ay1 = static_cast<double>(g.y) + g.height - kBallRadius;
        if (b.x >= ax0 && b.x <= ax1 && b.y >= ay0 && b.y <= ay1) {
          if (atRest) {
            captured[bi] = 1;
          } else {
            out.add(b.where, describe(b) + at(b) + " is inside " + describe(g) +
                                 " but moving; a ball may start inside " + withArticle(gizmoTypeWord(g.type)) +
                                 " only at rest (it is then captured)");
          }
          continue;
        }
      }
      if (!ballOverlaps(b.x, b.y, *shapes[gi])) continue;
      if (earlier(b.where, g.where)) {
        out.add(g.where, describe(g) + " overlaps " + describe(b) + fromLine(b.where) + at(b));
      } else {
        out.add(b.where, describe(b) + at(b) + " overlaps " + describe(g) + fromLine(g.where));
      }
    }
  }

  // Ball against ball: buckets of one cell, clamped to −1..20 so that far-off balls still meet
  // their neighbours; each ball is compared with the balls before it in source order.
  constexpr int B = N + 2;
  auto bucketOf = [](double v) {
    const double f = std::floor(v);
    return static_cast<int>(std::clamp(f, -1.0, static_cast<double>(N))) + 1;  // 0..B−1
  };
  std::vector<std::vector<std::size_t>> buckets(B * B);  // positions in ballOrder
  for (std::size_t k = 0; k < ballOrder.size(); ++k) {
    const std::size_t bi = ballOrder[k];
    if (!usable[bi] || captured[bi]) continue;
    const BallSpec& b = board.balls[bi];
    const int ux = bucketOf(b.x), uy = bucketOf(b.y);
    std::size_t firstOther = static_cast<std::size_t>(-1);
    for (int y = std::max(0, uy - 1); y <= std::min(B - 1, uy + 1); ++y)
      for (int x = std::max(0, ux - 1); x <= std::min(B - 1, ux + 1); ++x)
        for (const std::size_t o : buckets[static_cast<std::size_t>(y * B + x)]) {
          if (o >= firstOther) break;  // buckets hold increasing positions
          const BallSpec& c = board.balls[ballOrder[o]];
          if (pointCloserThan(b.x, b.y, c.x, c.y, 2 * kBallRadius)) {
            firstOther = o;
            break;
          }
        }
    if (firstOther != static_cast<std::size_t>(-1)) {
      const BallSpec& c = board.balls[ballOrder[firstOther]];
      out.add(b.where, describe(b) + at(b) + " overlaps " + describe(c) + fromLine(c.where) + at(c) +
                           ": their centres are closer than 0.5 L");
    }
    buckets[static_cast<std::size_t>(uy * B + ux)].push_back(k);
  }
}

void checkConnections(const BoardSpec& board, Collector& out) {
  std::unordered_map<std::string, GizmoType> gizmos;
  std::unordered_map<std::string, char> balls;
  for (const auto& g : board.gizmos) gizmos.emplace(g.name, g.type);
  for (const auto& b : board.balls) balls.emplace(b.name, 0);
  auto hint = [](const std::string& name) {
    std::string lower;
    for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower == "outerwalls" && name != kOuterWallsName ? std::string(" (the outer walls are named OuterWalls)")
                                                            : std::string();
  };
  auto checkTarget = [&](const SourcePos& where, const std::string& what, const std::string& target) {
    if (gizmos.count(target)) return;
    if (target == kOuterWallsName) out.add(where, what + " cannot be the outer walls: they have no action");
    else if (balls.count(target)) out.add(where, what + " " + quoted(target) + " is a ball; a ball has no action");
    else out.add(where, what + " " + quoted(target) + " is not a gizmo on this board" + hint(target));
  };

  std::map<std::pair<std::string, std::string>, SourcePos> seen;
  for (const std::size_t i : bySource(board.connections)) {
    const ConnectSpec& c = board.connections[i];
    if (c.source != kOuterWallsName && !gizmos.count(c.source)) {
      if (balls.count(c.source))
        out.add(c.where, "connection source " + quoted(c.source) + " is a ball; a ball triggers nothing");
      else out.add(c.where, "connection source " + quoted(c.source) + " is not a gizmo on this board" + hint(c.source));
    }
    checkTarget(c.where, "connection target", c.target);
    auto [it, inserted] = seen.emplace(std::make_pair(c.source, c.target), c.where);
    if (!inserted) {
      const std::string where = it->second.line > 0 ? " (first on line " + std::to_string(it->second.line) + ")" : "";
      out.add(c.where,
              "the connection from " + quoted(c.source) + " to " + quoted(c.target) + " is listed twice" + where);
    }
  }
  std::map<std::tuple<int, int, std::string>, SourcePos> seenKeys;
  for (const std::size_t i : bySource(board.keyConnections)) {
    const KeyConnectSpec& k = board.keyConnections[i];
    const std::string problem = keyCodeProblem(k.key);
    if (!problem.empty()) out.add(k.where, problem);
    checkTarget(k.where, "key connection target", k.target);
    const char* dir = k.direction == KeyDirection::Down ? "down" : "up";
    auto [it, inserted] = seenKeys.emplace(std::make_tuple(k.key, static_cast<int>(k.direction), k.target), k.where);
    if (!inserted) {
      const std::string where = it->second.line > 0 ? " (first on line " + std::to_string(it->second.line) + ")" : "";
      out.add(k.where, "the key connection from key " + std::to_string(k.key) + " " + dir + " to " + quoted(k.target) +
                           " is listed twice" + where);
    }
  }
}

}  // namespace

std::string gravityProblem(double gravity) {
  if (!std::isfinite(gravity)) return "gravity is not a finite number";
  if (std::fabs(gravity) > kMaxGravity)
    return "gravity " + number(gravity) + " L/s^2 is beyond the limit of " + number(kMaxGravity) + " L/s^2";
  return {};
}

std::string frictionProblem(const std::string& which, double value) {
  if (!std::isfinite(value)) return "friction " + which + " is not a finite number";
  if (value < 0) return "friction " + which + " is " + number(value) + "; friction constants cannot be negative";
  if (value > kMaxFriction)
    return "friction " + which + " = " + number(value) + " is beyond the limit of " + number(kMaxFriction);
  return {};
}

std::string keyCodeProblem(long long key) {
  if (key < 0 || key > kMaxKeyCode)
    return "key code " + std::to_string(key) + " is outside 0.." + std::to_string(kMaxKeyCode);
  return {};
}

std::vector<SpecProblem> checkBoardSpec(const BoardSpec& board) {
  Collector out;
  // Too many: say only that, since the rest would cost time in proportion.
  if (board.balls.size() > kMaxBalls || board.gizmos.size() > kMaxGizmos) {
    if (board.balls.size() > kMaxBalls)
      out.add(board.balls[bySource(board.balls)[kMaxBalls]].where,
              "the board has " + std::to_string(board.balls.size()) + " balls; at most " + std::to_string(kMaxBalls) +
                  " are allowed");
    if (board.gizmos.size() > kMaxGizmos)
      out.add(board.gizmos[bySource(board.gizmos)[kMaxGizmos]].where,
              "the board has " + std::to_string(board.gizmos.size()) + " gizmos; at most " +
                  std::to_string(kMaxGizmos) + " are allowed");
  } else {
    if (std::string p = gravityProblem(board.gravity); !p.empty()) out.add(SourcePos{}, p);
    if (std::string p = frictionProblem("mu", board.mu); !p.empty()) out.add(SourcePos{}, p);
    if (std::string p = frictionProblem("mu2", board.mu2); !p.empty()) out.add(SourcePos{}, p);
    checkNames(board, out);
    checkGeometry(board, out);
    checkConnections(board, out);
  }
  std::stable_sort(out.list.begin(), out.list.end(),
                   [](const SpecProblem& a, const SpecProblem& b) { return earlier(a.where, b.where); });
  return std::move(out.list);
}

}  // namespace gizmo
