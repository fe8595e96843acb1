#pragma once
// Valid random boards from an explicit seed: gizmos of every kind and orientation without
// overlap, balls at rest, crawling, ordinary and very fast, some placed exactly on cell tops so
// that they start in contact, and triggers wired at random. Used by the soak tests.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/cell_occupancy.hpp"

namespace gizmo::test {

inline BoardSpec randomBoard(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto real = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto whole = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  BoardSpec s;
  s.gravity = whole(0, 3) == 0 ? 0 : real(0, 60);
  s.mu = whole(0, 2) == 0 ? 0 : real(0, 0.1);
  s.mu2 = s.mu == 0 ? 0 : real(0, 0.1);
  CellOccupancy cells;
  const int gizmos = whole(0, 40);
  for (int i = 0; i < gizmos; ++i) {
    GizmoSpec g;
    g.type = GizmoType(whole(0, 5));
    g.name = "G" + std::to_string(i);
    const bool flipper = g.type == GizmoType::LeftFlipper || g.type == GizmoType::RightFlipper;
    g.width = g.height = flipper ? 2 : 1;
    if (g.type == GizmoType::Absorber) {
      g.width = whole(1, 6);
      g.height = whole(1, 3);
    }
    g.x = whole(0, kBoardSize - g.width);
    g.y = whole(0, kBoardSize - g.height);
    g.orientation = g.type == GizmoType::Absorber ? 0 : 90 * whole(0, 3);
    if (!cells.place(g)) continue;
    s.gizmos.push_back(g);
    if (whole(0, 2) == 0) s.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, g.name, {}});
    if (whole(0, 3) == 0)
      s.connections.push_back(ConnectSpec{g.name, s.gizmos[std::size_t(whole(0, int(s.gizmos.size()) - 1))].name, {}});
  }
  // Half the triangles are boosters, half the circles teleporters (each with an exit), a quarter of
  // the squares sinks, a third of the teleporters portals (an exit cell anywhere), a third of the
  // flippers spinners and a third of the sinks spawners, chosen by a stream of their own so that the other draws
  // stay as they were before the additions (docs/physics.md, "Gizmos other programs added").
  std::mt19937_64 own(seed ^ 0x6164646974696f6eULL);
  for (GizmoSpec& g : s.gizmos)
    if (g.type == GizmoType::Triangle && own() % 2 == 0) g.type = GizmoType::Booster;
  for (GizmoSpec& g : s.gizmos)
    if (g.type == GizmoType::Circle && own() % 2 == 0) g.type = GizmoType::Teleporter;
  std::vector<std::string> teleporters;
  for (const GizmoSpec& g : s.gizmos)
    if (g.type == GizmoType::Teleporter) teleporters.push_back(g.name);
  for (const std::string& from : teleporters) {
    const std::string& to = teleporters[own() % teleporters.size()];
    const bool twice = std::any_of(s.connections.begin(), s.connections.end(),
                                   [&](const ConnectSpec& c) { return c.source == from && c.target == to; });
    if (!twice) s.connections.push_back(ConnectSpec{from, to, {}});
  }
  for (GizmoSpec& g : s.gizmos)
    if (g.type == GizmoType::Square && own() % 4 == 0) g.type = GizmoType::Sink;
  for (GizmoSpec& g : s.gizmos)
    if (g.type == GizmoType::Teleporter && own() % 3 == 0) {
      g.type = GizmoType::Portal;
      g.exitX = int(own() % kBoardSize);
      g.exitY = int(own() % kBoardSize);
    }
  for (GizmoSpec& g : s.gizmos)
    if ((g.type == GizmoType::LeftFlipper || g.type == GizmoType::RightFlipper) && own() % 3 == 0)
      g.type = GizmoType::Spinner;
  for (GizmoSpec& g : s.gizmos)
    if (g.type == GizmoType::Sink && own() % 3 == 0) g.type = GizmoType::Spawner;
  const int balls = whole(1, 12);
  for (int i = 0; i < balls; ++i) {
    BallSpec b;
    b.name = "B" + std::to_string(i);
    const int pace = whole(0, 3);
    const double speed = pace == 0 ? 0 : pace == 1 ? real(0, 0.05) : pace == 2 ? real(0, 50) : real(100, 2000);
    const double angle = real(0, 6.283185307179586);
    b.vx = speed * std::cos(angle);  // test data only: the simulator never calls libm
    b.vy = speed * std::sin(angle);
    b.x = whole(0, 1) ? whole(1, 19) + 0.5 : real(0.3, 19.7);
    b.y = whole(0, 2) == 0 ? whole(1, 19) - 0.25 : real(0.3, 19.7);  // on a cell's top edge
    s.balls.push_back(b);
    if (!checkBoardSpec(s).empty()) s.balls.pop_back();
  }
  return s;
}

}  // namespace gizmo::test
