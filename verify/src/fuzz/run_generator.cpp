#include "gizmo/verify/fuzz/run_generator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/cell_occupancy.hpp"
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/verify/fuzz/seeded_random.hpp"
#include "kinds/verify_registry.hpp"

namespace gizmo::verify::fuzz {
namespace {

// The key codes that key connections and the key script share, so that presses do something.
constexpr std::array<int, 4> kKeys{32, 37, 39, 65};

struct Builder {
  SeededRandom& rng;
  BoardSpec& board;
  CellOccupancy cells{};

  void physics() {
    switch (rng.whole(0, 3)) {
      case 0: board.gravity = 0; break;
      case 1: board.gravity = 25; break;
      case 2: board.gravity = rng.real(0, 100); break;
      default: board.gravity = 1000; break;  // large
    }
    switch (rng.whole(0, 3)) {
      case 0: board.mu = board.mu2 = 0; break;
      case 1: board.mu = board.mu2 = 0.025; break;
      case 2: board.mu = rng.real(0, 0.5), board.mu2 = rng.real(0, 0.5); break;
      default: board.mu = 5, board.mu2 = 5; break;  // large
    }
  }

  void gizmos(int count) {
    for (int i = 0, tries = 0; i < count && tries < 4 * count; ++tries) {
      GizmoSpec g;
      g.type = GizmoType(rng.whole(0, kStandardKindCount - 1));
      g.width = g.height = ownSide(g.type);
      if (sizedByLine(g.type)) {
        // Every size occurs, from 1×1 to the full width; tall ones rarely, so that they leave room.
        g.width = rng.chance(4) ? kBoardSize : rng.whole(1, kBoardSize);
        g.height = rng.chance(5) ? rng.whole(1, kBoardSize) : rng.whole(1, 3);
      }
      g.x = rng.whole(0, kBoardSize - g.width);
      g.y = rng.whole(0, kBoardSize - g.height);
      g.orientation = sizedByLine(g.type) ? 0 : 90 * rng.whole(0, 3);
      if (!cells.place(g)) continue;
      g.name = "G" + std::to_string(i++);
      board.gizmos.push_back(g);
    }
  }

  // The additions of other programs (docs/physics.md, "Gizmos other programs added") take the
  // place of gizmos of the same outline: each kind's verify file says which kind it converts and
  // with what chance (verify/src/kinds/STEM.hpp). The conversions run in the kind list's order,
  // each drawn after the ones before, so that boards without squares, teleporters or flippers keep
  // what came before. The choice is drawn from a stream of its own, so that every other draw, and
  // every board without a triangle, stays what it was before the additions.
  void additions(std::uint64_t seed) {
    SeededRandom own(seed ^ 0x6164646974696f6eULL);  // "addition"
    forEachKind([&]<GizmoType T>(KindTag<T>) {
      using K = KindVerify<T>;
      if constexpr (K::generatedByConversion) {
        for (GizmoSpec& g : board.gizmos)
          if (K::convertsFrom(g.type) && own.chance(K::oneIn)) {
            g.type = T;
            K::converted(g, own);
          }
        K::afterConversions(board, own);
      }
    });
  }

  void connections() {
    if (board.gizmos.empty()) return;
    const int n = int(board.gizmos.size());
    for (const GizmoSpec& g : board.gizmos) {
      if (rng.chance(4)) {
        const int from = rng.whole(-1, n - 1);  // -1: the outer walls
        const std::string source = from < 0 ? kOuterWallsName : board.gizmos[std::size_t(from)].name;
        const bool twice = std::any_of(board.connections.begin(), board.connections.end(),
                                       [&](const ConnectSpec& c) { return c.source == source && c.target == g.name; });
        if (!twice) board.connections.push_back(ConnectSpec{source, g.name, {}});
      }
      const bool keyed = verifyFact(g.type, [](auto k) { return k.alwaysKeyed; });
      if (rng.chance(3) || keyed) keyConnect(g.name, rng.whole(0, 1) ? KeyDirection::Down : KeyDirection::Up);
    }
  }

  void keyConnect(const std::string& target, KeyDirection direction) {
    const int key = kKeys[std::size_t(rng.whole(0, int(kKeys.size()) - 1))];
    for (const KeyConnectSpec& k : board.keyConnections)
      if (k.key == key && k.direction == direction && k.target == target) return;
    board.keyConnections.push_back(KeyConnectSpec{key, direction, target, {}});
  }

  // A speed from one of the tiers the simulator must handle: 0, crawling below 0.01, exactly 0.01,
  // ordinary, exactly 200, fast, and exactly 5000 L/s.
  double speed() {
    switch (rng.whole(0, 9)) {
      case 0: return 0;
      case 1: return rng.real(0, 0.01);
      case 2: return 0.01;
      case 3: return 200;
      case 4: return rng.real(200, 5000);
      case 5: return 5000;
      default: return rng.real(0.01, 50);
    }
  }
  // A direction from integer components, scaled by sqrt (correctly rounded): no libm.
  void velocity(BallSpec& b, double s) {
    int dx = 0, dy = 0;
    while (dx == 0 && dy == 0) dx = rng.whole(-1000, 1000), dy = rng.whole(-1000, 1000);
    const double n = std::sqrt(double(dx) * dx + double(dy) * dy);
    b.vx = s * (dx / n);
    b.vy = s * (dy / n);
  }

  const GizmoSpec* pickGizmo(bool (*wanted)(const GizmoSpec&)) {
    std::vector<const GizmoSpec*> found;
    for (const GizmoSpec& g : board.gizmos)
      if (wanted(g)) found.push_back(&g);
    if (found.empty()) return nullptr;
    return found[std::size_t(rng.whole(0, int(found.size()) - 1))];
  }

  // Proposes one ball (or two, for a meeting) at the end of board.balls; returns how many.
  int proposeBalls(int index) {
    BallSpec b;
    b.name = "B" + std::to_string(index);
    switch (rng.whole(0, 9)) {
      case 0: {  // aimed exactly at a corner of a square, triangle or absorber
        const GizmoSpec* g =
            pickGizmo([](const GizmoSpec& s) { return verifyFact(s.type, [](auto k) { return k.aimedAtCorner; }); });
        if (!g) break;
        const double cx = g->x + (rng.whole(0, 1) ? g->width : 0), cy = g->y + (rng.whole(0, 1) ? g->height : 0);
        const int dx = rng.whole(-2, 2), dy = rng.whole(-2, 2);
        if (dx == 0 && dy == 0) break;
        const double k = rng.whole(1, 6) * 0.5;
        const double s = rng.whole(1, 40);
        b.x = cx + k * dx, b.y = cy + k * dy, b.vx = -s * dx, b.vy = -s * dy;
        board.balls.push_back(b);
        return 1;
      }
      case 1: {  // grazing a horizontal edge of a gizmo's cell: centre exactly one radius off it
        const GizmoSpec* g =
            pickGizmo([](const GizmoSpec& s) { return verifyFact(s.type, [](auto k) { return k.grazedAlongEdge; }); });
        if (!g) break;
        const bool above = rng.whole(0, 1);
        b.y = above ? g->y - kBallRadius : g->y + g->height + kBallRadius;
        b.x = rng.whole(0, 1) ? g->x - 1.5 : g->x + g->width + 1.5;
        b.vx = (b.x < g->x ? 1 : -1) * speed();
        board.balls.push_back(b);
        return 1;
      }
      case 2: {  // two balls meeting head-on at the same instant, mirrored about a point
        const double mx = rng.whole(2, 18) + 0.5 * rng.whole(0, 1), my = rng.whole(2, 18) + 0.5 * rng.whole(0, 1);
        const int dx = rng.whole(-2, 2), dy = rng.whole(-2, 2);
        if (dx == 0 && dy == 0) break;
        const double k = rng.whole(1, 3) * 0.5, s = rng.whole(1, 100);
        BallSpec c = b;
        c.name = "B" + std::to_string(index + 1);
        b.x = mx - k * dx, b.y = my - k * dy, b.vx = s * dx, b.vy = s * dy;
        c.x = mx + k * dx, c.y = my + k * dy, c.vx = -s * dx, c.vy = -s * dy;
        board.balls.push_back(b);
        board.balls.push_back(c);
        return 2;
      }
      case 3: {  // resting on a top surface: the floor, or the top of a square or an absorber
        const GizmoSpec* g =
            pickGizmo([](const GizmoSpec& s) { return verifyFact(s.type, [](auto k) { return k.restedOnTop; }); });
        if (!g || rng.chance(3)) {
          b.x = rng.whole(1, 19) + 0.5 * rng.whole(0, 1), b.y = kBoardSize - kBallRadius;
        } else {
          b.x = g->x + rng.real(0, g->width), b.y = g->y - kBallRadius;
        }
        if (rng.chance(2)) b.vx = rng.real(-0.02, 0.02);
        board.balls.push_back(b);
        return 1;
      }
      case 4: {  // touching a flipper at rest, beside its pivot or its tip
        const GizmoSpec* g = pickGizmo(
            [](const GizmoSpec& s) { return verifyFact(s.type, [](auto k) { return k.touchedBesideCapsule; }); });
        if (!g) break;
        // The rest capsule runs from the pivot centre 1.5 L along its rest direction; a ball beside
        // it, its centre 0.5 from the axis, touches it exactly.
        const Shape<double> s = restShape<double>(*g);
        const CircleFeature<double>& end = s.circles[std::size_t(rng.whole(0, 1))];
        const SegmentFeature<double>& side = s.segments[std::size_t(rng.whole(0, 1))];
        b.x = end.centre.x + 2 * kBallRadius * side.normal.x;
        b.y = end.centre.y + 2 * kBallRadius * side.normal.y;
        board.balls.push_back(b);
        return 1;
      }
      default: break;
    }
    // Anywhere, at any speed; a third of them on a cell's top edge, where they start in contact.
    b.x = rng.chance(2) ? rng.whole(1, 19) + 0.5 : rng.real(kBallRadius, kBoardSize - kBallRadius);
    b.y = rng.chance(3) ? rng.whole(1, 20) - kBallRadius : rng.real(kBallRadius, kBoardSize - kBallRadius);
    velocity(b, speed());
    board.balls.push_back(b);
    return 1;
  }

  void balls(int count) {
    int index = 0;
    for (int tries = 0; int(board.balls.size()) < count && tries < 8 * count; ++tries) {
      const std::size_t before = board.balls.size();
      index += proposeBalls(index);
      if (!checkBoardSpec(board).empty()) board.balls.resize(before);  // it does not fit: drop it
    }
  }
};

std::vector<TimedKey> keyScript(SeededRandom& rng, const BoardSpec& board, double duration, int count) {
  std::vector<TimedKey> keys;
  for (int i = 0; i < count; ++i) {
    TimedKey k;
    // Some presses land exactly on a tick boundary (multiples of 0.05 s) or at time 0.
    k.time = rng.chance(4) ? 0.05 * rng.whole(0, int(duration / 0.05)) : rng.real(0, duration);
    if (!board.keyConnections.empty() && !rng.chance(5)) {
      const KeyConnectSpec& c = board.keyConnections[std::size_t(rng.whole(0, int(board.keyConnections.size()) - 1))];
      k.key = c.key, k.direction = c.direction;
    } else {
      k.key = kKeys[std::size_t(rng.whole(0, int(kKeys.size()) - 1))];
      k.direction = rng.whole(0, 1) ? KeyDirection::Down : KeyDirection::Up;
    }
    keys.push_back(k);
  }
  std::stable_sort(keys.begin(), keys.end(), [](const TimedKey& a, const TimedKey& b) { return a.time < b.time; });
  return keys;
}

}  // namespace

RunRequest generateRun(std::uint64_t seed, int size) {
  size = std::clamp(size, 0, kMaxSize);
  SeededRandom rng(seed);
  RunRequest r;
  Builder b{rng, r.board};
  b.physics();
  r.model = rng.whole(0, 1) ? MotionModel::Ballistic : MotionModel::Classic;
  r.maxTick = rng.chance(4) ? (rng.whole(0, 1) ? 0.01 : 0.1) : 0.05;
  b.gizmos(rng.whole(0, 1 + size * 3 / 5));
  b.additions(seed);
  b.connections();
  // One to a hundred balls; many only on large sizes.
  b.balls(rng.whole(1, 1 + size * 99 / kMaxSize));
  if (r.board.balls.empty()) b.balls(1);
  r.duration = rng.real(0.05, 0.25 + size * 0.02);
  r.keys = keyScript(rng, r.board, r.duration, rng.whole(0, 1 + size / 4));
  return r;
}

}  // namespace gizmo::verify::fuzz
