// The state of a log's run at an event or a time, from the nearest keyframe (replay.hpp: seekLog).
#include <type_traits>

#include "gizmo/core/gizmo_kinds.hpp"
#include "run_start.hpp"

namespace gizmo::replay {
namespace {

using namespace detail;

template <class Real>
StateView stateOf(const GameBoard<Real>& board, const Real& at, const std::vector<std::string>& names) {
  StateView s;
  s.time = exact(at);
  s.events = board.executedTotal();
  for (GizmoId id : board.ballIds()) {
    const Ball<Real>& b = *board.gizmo(id).asBall();
    const Vec2<Real> p = b.positionAt(at), v = b.velocityAt(at);
    s.balls.push_back(BallView{id, gizmoName(names, id), exact(p.x), exact(p.y), exact(v.x), exact(v.y), {}, {}});
  }
  for (const Event<Real>& e : board.pendingEvents()) {
    std::string line = exactText(e.time) + " " + std::string(eventKindName(e.kind));
    if (e.a != kNoGizmo) line += " " + gizmoName(names, e.a);
    if (e.b != kNoGizmo && e.kind != EventKind::Input) line += " " + gizmoName(names, e.b);
    if (e.kind == EventKind::Collision) line += " feature " + std::to_string(e.feature);
    if (e.kind == EventKind::Input) line += (e.b ? " up " : " down ") + std::to_string(e.feature);
    s.queue.push_back(line);
  }
  return s;
}

template <class Real>
StateView seekAs(const OpenedLog& log, const SeekTarget& target) {
  SeekStart<Real> start = seekStart<Real>(log, target);
  runToTarget(start, log, target);
  const Real at = target.time ? maxOf(fromDouble<Real>(*target.time), start.board->now()) : start.board->now();
  return stateOf(*start.board, at, log.gizmoNames);
}

}  // namespace

RunStartBoard startBoardInDouble(const OpenedLog& log) {
  if (log.precision.kind != Precision::Double)
    throw FormatError("the log was made with " + log.header.scalar + ", not double", 0);
  return detail::withLogScalar(log, [&]<class Real>() -> RunStartBoard {
    if constexpr (std::is_same_v<Real, double>) {
      const detail::RunStart start = detail::runStartOf(log);
      return RunStartBoard{detail::startBoard<double>(log), start.ticksDone, start.eventsDone};
    } else {
      throw FormatError("the log was made with " + log.header.scalar + ", not double", 0);
    }
  });
}

StartView startView(const OpenedLog& log) {
  return detail::withLogScalar(log, [&]<class Real>() {
    const std::unique_ptr<GameBoard<Real>> board = detail::startBoard<Real>(log);
    board->tickSpan(Real(0), 1, Real(0));  // built, as its run builds it first (a restored board is)
    StartView v;
    v.events = board->executedTotal();
    v.time = toDouble(board->now());
    for (GizmoId id : board->ballIds()) {
      const Ball<Real>& b = *board->gizmo(id).asBall();
      const Vec2<Real> p = b.positionAt(board->now()), u = b.velocityAt(board->now());
      v.balls.push_back(StartView::Ball{id, toDouble(p.x), toDouble(p.y), toDouble(u.x), toDouble(u.y),
                                        toDouble(b.acceleration().x), toDouble(b.acceleration().y), b.captured()});
    }
    for (std::size_t g = 0; g < board->gizmoCount(); ++g) {
      const AbstractGizmo<Real>& gizmo = board->gizmo(GizmoId(g));
      const KindMotion motion = motionOf(gizmo.kind());
      if (motion == KindMotion::Still) continue;
      // A flipper: t0, s0; direction, lastDirection, … A spinner: t0, phase; quarter, turning, …
      // (Flipper and Spinner saveState; docs/replay-format.md, "A gizmo's numbers").
      GizmoState<Real> st;
      gizmo.saveState(st);
      if (motion == KindMotion::Turns)
        v.spinners.push_back(
            StartView::Turn{GizmoId(g), toDouble(st.reals.at(0)), toDouble(st.reals.at(1)), st.ints.at(1) != 0});
      else
        v.flippers.push_back(StartView::Swing{GizmoId(g), toDouble(st.reals.at(0)), toDouble(st.reals.at(1)),
                                              int(st.ints.at(0)), int(st.ints.at(1))});
    }
    return v;
  });
}

StateView seekLog(const OpenedLog& log, const SeekTarget& target) {
  return detail::withLogScalar(log, [&]<class Real>() { return seekAs<Real>(log, target); });
}

}  // namespace gizmo::replay
