#pragma once
// Writing boards in canonical form. Reading what was written gives back the same BoardSpec
// (SourcePos aside) for every board that the readers accept.
#include <string>

#include "gizmo/core/board_spec.hpp"

namespace gizmo::io {

// XML: <board gravity friction1 friction2>, then the balls, <gizmos>, <connections> (connect
// elements, then keyConnect elements), each in the spec's order. Numbers are the shortest decimal
// that reads back to the same double. Triangles and flippers always carry orientation; squares
// and circles only when it is not 0.
std::string writeXmlBoard(const BoardSpec& board);

// Text: Gravity and Friction lines, the gizmos (each followed by one Rotate line per quarter turn
// of its orientation), the balls, the Connect lines, the KeyConnect lines.
std::string writeTextBoard(const BoardSpec& board);

}  // namespace gizmo::io
