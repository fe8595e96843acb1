#pragma once
// The core's templates, compiled once per scalar: each instantiate_*.cpp names one scalar.
#include "gizmo/core/board/build_board_impl.hpp"
#include "gizmo/core/board/game_board_impl.hpp"
#include "gizmo/core/board/game_board_state_impl.hpp"

#define GIZMO_INSTANTIATE_CORE(Real)                                                    \
  namespace gizmo {                                                                      \
  template class GameBoard<Real>;                                                        \
  template std::unique_ptr<GameBoard<Real>> buildBoard<Real>(const BoardSpec&, PhysicsParams<Real>); \
  }
