#pragma once
// Small helpers for tests: boards in a few lines, and an observer that keeps what it saw.
#include <memory>
#include <string>
#include <vector>

#include "gizmo/core/board/build_board.hpp"

namespace gizmo::test {

inline GizmoSpec gizmoAt(GizmoType type, std::string name, int x, int y, int orientation = 0, int w = 1, int h = 1) {
  GizmoSpec g;
  g.type = type;
  g.name = std::move(name);
  g.x = x;
  g.y = y;
  g.orientation = orientation;
  g.width = ownSide(type) == 2 ? 2 : w;
  g.height = ownSide(type) == 2 ? 2 : h;
  return g;
}

inline BallSpec ballAt(std::string name, double x, double y, double vx = 0, double vy = 0) {
  return BallSpec{std::move(name), x, y, vx, vy, SourcePos{}};
}

inline BoardSpec emptyBoard(double gravity = 25, double mu = 0, double mu2 = 0) {
  BoardSpec s;
  s.gravity = gravity;
  s.mu = mu;
  s.mu2 = mu2;
  return s;
}

template <class Real = double>
std::unique_ptr<GameBoard<Real>> build(const BoardSpec& spec, MotionModel model = MotionModel::Ballistic,
                                       double maxTick = 0.05) {
  PhysicsParams<Real> p;
  p.model = model;
  p.maxTick = fromDouble<Real>(maxTick);
  return buildBoard<Real>(spec, p);
}

// Keeps every executed event and every model rule.
template <class Real = double>
struct Recorder : BoardObserver<Real> {
  struct Executed {
    Event<Real> event;
    EventOutcome<Real> outcome;
  };
  std::vector<Executed> executed;
  std::vector<Event<Real>> scheduled, removed;
  std::vector<std::pair<ModelRule, GizmoId>> rules;
  std::vector<Real> ruleTimes;
  std::vector<std::pair<GizmoId, GizmoId>> triggers;
  std::vector<GizmoId> actions;

  void eventScheduled(const Event<Real>& e) override { scheduled.push_back(e); }
  void eventRemoved(const Event<Real>& e) override { removed.push_back(e); }
  void eventExecuted(const Event<Real>& e, const EventOutcome<Real>& o) override { executed.push_back({e, o}); }
  void triggerFired(const Real&, GizmoId s, GizmoId t) override { triggers.emplace_back(s, t); }
  void actionPerformed(const Real&, GizmoId t) override { actions.push_back(t); }
  void modelRuleApplied(const Real& t, ModelRule r, GizmoId g, GizmoId) override {
    rules.emplace_back(r, g);
    ruleTimes.push_back(t);
  }

  std::vector<Executed> ofKind(EventKind k) const {
    std::vector<Executed> out;
    for (const auto& e : executed)
      if (e.event.kind == k) out.push_back(e);
    return out;
  }
  int countRule(ModelRule r) const {
    int n = 0;
    for (const auto& x : rules) n += x.first == r;
    return n;
  }
};

}  // namespace gizmo::test
