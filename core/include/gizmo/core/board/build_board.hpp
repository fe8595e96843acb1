#pragma once
// A GameBoard from a board's plain-data description (what the readers produce).
#include <memory>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/board_spec.hpp"

namespace gizmo {

// The spec's gravity and friction replace those in `params`; everything else (model, maximum
// tick, friction step) comes from `params`. The spec must have passed checkBoardSpec.
template <class Real>
std::unique_ptr<GameBoard<Real>> buildBoard(const BoardSpec& spec, PhysicsParams<Real> params);

}  // namespace gizmo

namespace gizmo {
extern template std::unique_ptr<GameBoard<float>> buildBoard<float>(const BoardSpec&, PhysicsParams<float>);
extern template std::unique_ptr<GameBoard<double>> buildBoard<double>(const BoardSpec&, PhysicsParams<double>);
extern template std::unique_ptr<GameBoard<long double>> buildBoard<long double>(const BoardSpec&,
                                                                                PhysicsParams<long double>);
#if GIZMO_HAS_MULTIPRECISION
extern template std::unique_ptr<GameBoard<Float128>> buildBoard<Float128>(const BoardSpec&, PhysicsParams<Float128>);
extern template std::unique_ptr<GameBoard<MpfrReal>> buildBoard<MpfrReal>(const BoardSpec&, PhysicsParams<MpfrReal>);
#endif
}  // namespace gizmo
