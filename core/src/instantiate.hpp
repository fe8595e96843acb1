#pragma once
// The core's templates, compiled once per scalar: each instantiate_*.cpp names one scalar.
#include <cfloat>
#include "board/build_board_impl.hpp"
#include "board/game_board_building_impl.hpp"
#include "board/game_board_loop_impl.hpp"
#include "board/game_board_predict_impl.hpp"
#include "board/game_board_queries_impl.hpp"
#include "board/game_board_state_impl.hpp"
#include "kind_outline_impl.hpp"

// Every float and double operation must round to its type, as IEEE 754 says, for the same bits on
// every machine: FLT_EVAL_METHOD 0. i686's default x87 code (2) keeps 80-bit intermediates; its
// toolchain file asks for SSE2 instead (docs/determinism.md, "The x87 question").
static_assert(FLT_EVAL_METHOD == 0,
              "float and double must be evaluated in their own precision (on i686: -msse2 -mfpmath=sse)");

#define GIZMO_INSTANTIATE_CORE(Real)                                                                 \
  namespace gizmo {                                                                                  \
  template class GameBoard<Real>;                                                                    \
  template std::unique_ptr<GameBoard<Real>> buildBoard<Real>(const BoardSpec&, PhysicsParams<Real>); \
  template Shape<Real> restShape<Real>(const GizmoSpec&);                                            \
  }
