#pragma once
// A board as plain data: what a board file says, before any simulation exists.
// Readers produce it, writers consume it, and GameBoard is built from it. Numbers are doubles
// because board files hold decimals; every scalar of the precision ladder starts from the exact
// binary value of these doubles.
#include <cstddef>
#include <string>
#include <vector>

#include "gizmo/core/kinds/kind_list.hpp"

namespace gizmo {

// One enumerator per line of the kind list, in its order (kinds/kind_list.hpp). The lines after the
// standard kinds' (kStandardKindCount, gizmo_kinds.hpp) are gizmos that other Gizmoball programs added
// (docs/physics.md, "Gizmos other programs added").
#define GIZMO_KIND_ENUMERATOR(Name, stem) Name,
enum class GizmoType { GIZMO_KINDS(GIZMO_KIND_ENUMERATOR) };
#undef GIZMO_KIND_ENUMERATOR
#define GIZMO_KIND_COUNT(Name, stem) +1
inline constexpr int kGizmoTypeCount = 0 GIZMO_KINDS(GIZMO_KIND_COUNT);
#undef GIZMO_KIND_COUNT
enum class KeyDirection { Down, Up };

// Where a statement came from in its file (1-based; 0 when it was not read from a file).
struct SourcePos {
  int line = 0;
  int column = 0;
};

struct GizmoSpec {
  GizmoType type = GizmoType::Square;
  std::string name;
  int x = 0;  // upper-left corner of the bounding box, in L
  int y = 0;
  int orientation = 0;  // degrees clockwise on screen: 0, 90, 180 or 270
  int width = 1;        // bounding box in L: 1×1 bumpers, 2×2 flippers and spinners, w×h absorbers
  int height = 1;
  SourcePos where;
  int exitX = 0;  // a portal's exit cell (upper-left corner, in L); unused by the other gizmos
  int exitY = 0;
};

// The side of a gizmo's square box in L: 2 for flippers and spinners, 1 for the bumpers. An
// absorber's box is what its file says (0 here). Each kind's file says it (kinds/STEM.hpp, `side`);
// defined in core/src/kind_registry.cpp, where every kind's file is included.
int ownSide(GizmoType t);

struct BallSpec {
  std::string name;
  double x = 0, y = 0;    // centre, L
  double vx = 0, vy = 0;  // L/s
  SourcePos where;
};

struct ConnectSpec {
  std::string source;  // "OuterWalls" names the outer walls
  std::string target;
  SourcePos where;
};

struct KeyConnectSpec {
  int key = 0;  // Java key code
  KeyDirection direction = KeyDirection::Down;
  std::string target;
  SourcePos where;
};

struct BoardSpec {
  double gravity = 25.0;  // L/s², along +y (down)
  double mu = 0.025;      // friction per s
  double mu2 = 0.025;     // friction per L
  std::vector<BallSpec> balls;
  std::vector<GizmoSpec> gizmos;
  std::vector<ConnectSpec> connections;
  std::vector<KeyConnectSpec> keyConnections;
};

inline constexpr const char* kOuterWallsName = "OuterWalls";

// The name of the ball that a spawner added to a board as it ran, as gizmo `id`: it follows from
// the id and the names of the gizmos the board was built with (`names`, indexed by id), so that
// whatever knows the board's names names the ball as the board does. A name the board already
// has gets an underscore more (names stay [A-Za-z0-9_]+, so the writers write the board back).
inline std::string spawnedBallName(long long id, const std::vector<std::string>& names) {
  std::string name = "Spawned" + std::to_string(id);
  auto taken = [&] {
    for (const std::string& n : names)
      if (n == name) return true;
    return false;
  };
  while (taken()) name += "_";
  return name;
}
inline constexpr double kBallRadius = 0.25;
// The most balls a board file may hold.
inline constexpr std::size_t kMaxBalls = 10000;
// The most new balls spawners add to a board as it runs (balls a sink gives back do not count).
// Where spawners fire on hits that the spawned balls make (the walls connected to a spawner),
// the balls multiply: a generated board's run took 25 CPU minutes and 3 GB, unfinished, on its
// way to 10,000. Each new ball costs a row and a column of the pairs table and a place in every
// broad phase; 256 keep the largest boards here within a few times their built size.
inline constexpr std::size_t kMaxSpawnedBalls = 256;
inline constexpr int kBoardSize = 20;

}  // namespace gizmo
