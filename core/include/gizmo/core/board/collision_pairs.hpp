#pragma once
// The seed's collision pairs. Each gizmo answers canCollideWith for every other: it can collide
// (it has the handler), it defers to the other, or the two never collide. A pair forms when
// neither side says never and at least one can; the first in id order that can is the pair's
// collider, whose timeUntilCollision and collide serve the pair. The pairs are formed once per
// board change, never as the board runs.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/gizmos/abstract_gizmo.hpp"

namespace gizmo {

// Which gizmo of a pair holds the collision handler (seed: the collider).
enum class PairRole : std::uint8_t { None, FirstCollides, SecondCollides };

template <class Real>
PairRole formPair(const AbstractGizmo<Real>& a, const AbstractGizmo<Real>& b) {
  const CollisionAnswer x = a.canCollideWith(b), y = b.canCollideWith(a);
  if (x == CollisionAnswer::NeverCollides || y == CollisionAnswer::NeverCollides) return PairRole::None;
  if (x == CollisionAnswer::CanCollide) return PairRole::FirstCollides;
  if (y == CollisionAnswer::CanCollide) return PairRole::SecondCollides;
  return PairRole::None;
}

struct CollisionPair {
  GizmoId collider;
  GizmoId collidee;
};

template <class Real>
using GizmoList = std::vector<std::unique_ptr<AbstractGizmo<Real>>>;

// Every pair of the board, each once, in id order.
template <class Real>
std::vector<CollisionPair> collisionPairsOf(const GizmoList<Real>& gizmos) {
  std::vector<CollisionPair> pairs;
  for (std::size_t a = 0; a < gizmos.size(); ++a)
    for (std::size_t b = a + 1; b < gizmos.size(); ++b) {
      const PairRole r = formPair(*gizmos[a], *gizmos[b]);
      if (r == PairRole::FirstCollides) pairs.push_back({GizmoId(a), GizmoId(b)});
      if (r == PairRole::SecondCollides) pairs.push_back({GizmoId(b), GizmoId(a)});
    }
  return pairs;
}

// The pairs the event loop asks about, every one of them a ball's (gizmos that are not balls
// never meet each other): for each ball and each gizmo, which side is the collider, if any. One
// byte per pair keeps the table of a board of 100 balls and 300 gizmos within the first-level
// cache.
template <class Real>
class ColliderTable {
 public:
  // Forms the table for `balls` (their ids, in row order) against every gizmo. The rows and
  // columns of the gizmos before `known` are kept as they were formed (a spawned ball adds a row
  // and a column to a table `known` wide); known = 0 forms everything.
  void form(const GizmoList<Real>& gizmos, const std::vector<GizmoId>& balls, std::size_t known) {
    const std::size_t n = gizmos.size();
    std::vector<Collider> table(balls.size() * n, Collider::None);
    for (std::size_t i = 0; i < balls.size() && std::size_t(balls[i]) < known; ++i)
      std::copy_n(table_.begin() + std::ptrdiff_t(i * known), known, table.begin() + std::ptrdiff_t(i * n));
    table_.swap(table);
    width_ = n;
    for (std::size_t i = 0; i < balls.size(); ++i)
      for (std::size_t g = 0; g < n; ++g) {
        const std::size_t b = static_cast<std::size_t>(balls[i]);
        if (g == b || (g < known && b < known)) continue;
        const std::size_t lo = std::min(g, b), hi = std::max(g, b);
        const PairRole r = formPair(*gizmos[lo], *gizmos[hi]);
        if (r == PairRole::None) continue;
        table_[i * n + g] = (r == PairRole::FirstCollides ? lo : hi) == b ? Collider::Ball : Collider::Other;
      }
  }

  // The collider of the pair of `ball` (row `row`) and `other`; kNoGizmo when they form none.
  GizmoId colliderOf(std::size_t row, GizmoId ball, GizmoId other) const {
    switch (table_[row * width_ + std::size_t(other)]) {
      case Collider::Ball: return ball;
      case Collider::Other: return other;
      case Collider::None: break;
    }
    return kNoGizmo;
  }

 private:
  enum class Collider : std::uint8_t { None, Ball, Other };
  std::vector<Collider> table_;  // balls × gizmos
  std::size_t width_ = 0;
};

}  // namespace gizmo
