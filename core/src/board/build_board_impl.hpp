#pragma once
// buildBoard's definition; included by the explicit instantiations in core/src only.
#include <stdexcept>

#include "gizmo/core/board/build_board.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/gizmos/teleporter.hpp"

namespace gizmo {

template <class Real>
std::unique_ptr<GameBoard<Real>> buildBoard(const BoardSpec& spec, PhysicsParams<Real> params) {
  params.gravity = fromDouble<Real>(spec.gravity);
  params.mu = fromDouble<Real>(spec.mu);
  params.mu2 = fromDouble<Real>(spec.mu2);
  auto board = std::make_unique<GameBoard<Real>>(params);
  std::vector<Absorber<Real>*> absorbers;
  for (const GizmoSpec& g : spec.gizmos) {
    // Each kind's file says which gizmo the board builds for it (kinds/STEM.hpp, build).
    std::unique_ptr<AbstractGizmo<Real>> gizmo =
        visitKind(g.type, [&]<GizmoType T>(KindTag<T>) { return KindCore<T>::template build<Real>(g); });
    // A ball at rest inside an absorber is held from the start (below).
    if (auto* absorber = dynamic_cast<Absorber<Real>*>(gizmo.get())) absorbers.push_back(absorber);
    board->add(std::move(gizmo));
  }
  for (const BallSpec& b : spec.balls) {
    auto ball = std::make_unique<Ball<Real>>(b.name, Vec2<Real>(fromDouble<Real>(b.x), fromDouble<Real>(b.y)),
                                             Vec2<Real>(fromDouble<Real>(b.vx), fromDouble<Real>(b.vy)));
    Ball<Real>* raw = ball.get();
    board->add(std::move(ball));
    raw->setState(Real(0), raw->positionAt(Real(0)), raw->velocityAt(Real(0)), params);
    // A ball at rest wholly inside an absorber counts as captured at time 0 (docs/physics.md §2).
    if (b.vx != 0 || b.vy != 0) continue;
    for (Absorber<Real>* a : absorbers) {
      const GizmoSpec s = a->spec();
      const double r = kBallRadius;
      if (b.x - r >= s.x && b.x + r <= s.x + s.width && b.y - r >= s.y && b.y + r <= s.y + s.height) {
        a->holdAtStart(*raw, Real(0));
        break;
      }
    }
  }
  auto idOf = [&](const std::string& name) {
    const std::optional<GizmoId> id = board->find(name);
    if (!id) throw std::invalid_argument("board names an unknown gizmo '" + name + "'");
    return *id;
  };
  for (const ConnectSpec& c : spec.connections) {
    const GizmoId source = idOf(c.source), target = idOf(c.target);
    board->connect(source, target);
    // A teleporter's exit is the first teleporter it is connected to (d-g-n's Teleporter.java);
    // a portal's is the cell its line names.
    auto* from = dynamic_cast<Teleporter<Real>*>(&board->gizmo(source));
    const auto* to = dynamic_cast<const Teleporter<Real>*>(&board->gizmo(target));
    if (from && to && !from->hasExit()) from->setExit(target, to->centre());
  }
  for (const KeyConnectSpec& k : spec.keyConnections) board->keyConnect(k.key, k.direction, idOf(k.target));
  return board;
}

}  // namespace gizmo
