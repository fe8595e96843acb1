#pragma once
// A board built by hand for the certifier's ladder (verify/certify_state.hpp): the walls (id 0),
// one gizmo that moves (id 1, a flipper or a spinner) with a 2 × 2 box, and one ball (id 2) whose
// state the test sets; no gravity unless the test gives the ball one. Decisions on it are settled
// directly, without a run, so that a test can claim what the core would never have done.
#include <vector>

#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/verify/certify.hpp"
#include "gizmo/verify/certify_ladder.hpp"
#include "support/event_at.hpp"

namespace gizmo::test {

namespace detail = verify::detail;

struct HandBoard {
  detail::BoardLayout layout;
  detail::BoardSnapshot snapshot;

  // `mover` gets id 1 and the box whose low corner is `corner`; the ball lies still at `ball` from
  // time `now` on.
  HandBoard(detail::LayoutGizmo mover, Vec2<double> corner, Vec2<double> ball, double now) {
    layout.model = MotionModel::Ballistic;
    detail::LayoutGizmo walls;
    walls.id = 0;
    walls.name = "OuterWalls";
    walls.shape = outerWallsShape<double>();
    walls.bounds = Box<double>{Vec2<double>(0, 0), Vec2<double>(20, 20)};
    mover.id = 1;
    mover.bounds = Box<double>{corner, corner + Vec2<double>(2, 2)};
    detail::LayoutGizmo b;
    b.id = 2;
    b.name = "B";
    b.kind = detail::LayoutKind::Ball;
    layout.gizmos = {walls, mover, b};
    layout.balls = {2};
    layout.ballIndex = {-1, -1, 0};
    layout.collider = {{0, 1, kNoGizmo}};
    layout.cells.assign(std::size_t(detail::BoardLayout::kCells * detail::BoardLayout::kCells), {});
    for (int y = int(corner.y); y <= int(corner.y) + 2; ++y)
      for (int x = int(corner.x); x <= int(corner.x) + 2; ++x)
        layout.cells[std::size_t(y * detail::BoardLayout::kCells + x)].push_back(1);
    snapshot.now = now;
    detail::BallSnapshot s;
    s.id = 2;
    s.t0 = now;
    s.p = ball;
    snapshot.balls = {s};
  }
};

// The ladder's verdict on running `executed` with `next` the earliest scheduled event left.
inline detail::LadderResult settle(const HandBoard& board, const Event<double>& executed, const Event<double>& next) {
  detail::DecisionInput in;
  in.executed = executed;
  in.hasNextScheduled = true;
  in.nextScheduled = next;
  detail::Ladder ladder(board.layout, verify::CertifyOptions{});
  return ladder.settle(board.snapshot, in);
}

}  // namespace gizmo::test
