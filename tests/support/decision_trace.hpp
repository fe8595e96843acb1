#pragma once
// An observer that keeps every decision a board reports as comparable plain values, and can
// save the board's state at chosen tick boundaries: for tests that a run resumed from a saved
// state (or replayed) decides exactly as the original did.
#include <array>
#include <cstdint>
#include <map>
#include <ostream>
#include <vector>

#include "gizmo/core/board/game_board.hpp"

namespace gizmo::test {

struct Decision {
  int what = 0;  // which observer call
  double time = 0;
  int kind = -1;
  GizmoId a = kNoGizmo, b = kNoGizmo;
  std::int64_t feature = -1;
  std::uint64_t sequence = 0;
  std::array<double, 6> values{};  // an outcome: the first ball's position and velocities

  bool operator==(const Decision&) const = default;
};

inline std::ostream& operator<<(std::ostream& os, const Decision& d) {
  os << "{call " << d.what << " t=" << std::hexfloat << d.time << std::defaultfloat << " kind " << d.kind << " a "
     << d.a << " b " << d.b << " feature " << d.feature << " seq " << d.sequence << "}";
  return os;
}

template <class Real>
class DecisionTrace : public BoardObserver<Real> {
 public:
  std::vector<Decision> decisions;
  std::int64_t ticks = 0;
  // Tick boundary index → the state then, and how many decisions had been made.
  std::map<std::int64_t, std::pair<BoardState<Real>, std::size_t>> saved;

  void watch(const GameBoard<Real>& board, std::vector<std::int64_t> saveAtTicks) {
    board_ = &board;
    saveAt_ = std::move(saveAtTicks);
  }

  void eventScheduled(const Event<Real>& e) override { add(0, e.time, e); }
  void eventRemoved(const Event<Real>& e) override { add(1, e.time, e); }
  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>& o) override {
    Decision& d = add(2, e.time, e);
    if (o.count > 0) {
      const BallChange<Real>& c = o.changes[0];
      d.values = {toDouble(c.position.x),       toDouble(c.position.y),      toDouble(c.velocityBefore.x),
                  toDouble(c.velocityBefore.y), toDouble(c.velocityAfter.x), toDouble(c.velocityAfter.y)};
    }
  }
  void triggerFired(const Real& t, GizmoId s, GizmoId g) override { push({3, toDouble(t), -1, s, g}); }
  void actionPerformed(const Real& t, GizmoId g) override { push({4, toDouble(t), -1, g}); }
  void inputApplied(const Real& t, int key, KeyDirection dir) override {
    push({5, toDouble(t), int(dir), kNoGizmo, kNoGizmo, key});
  }
  void modelRuleApplied(const Real& t, ModelRule r, GizmoId g, GizmoId o) override {
    push({6, toDouble(t), int(r), g, o});
  }
  void tickBoundary(const Real& t) override {
    push({7, toDouble(t)});
    ++ticks;
    for (std::int64_t k : saveAt_)
      if (k == ticks && board_) saved[k] = {board_->saveState(), decisions.size()};
  }

 private:
  Decision& add(int what, const Real& t, const Event<Real>& e) {
    push({what, toDouble(t), int(e.kind), e.a, e.b, e.feature, e.sequence});
    return decisions.back();
  }
  void push(Decision d) { decisions.push_back(d); }

  const GameBoard<Real>* board_ = nullptr;
  std::vector<std::int64_t> saveAt_;
};

}  // namespace gizmo::test
