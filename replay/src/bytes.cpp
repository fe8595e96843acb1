#include "gizmo/replay/bytes.hpp"

#include <string>

#include "gizmo/replay/format_error.hpp"

namespace gizmo::replay::detail {

void throwUnderflow(std::size_t offset, std::size_t wanted, std::size_t available) {
  throw FormatError(
      "unexpected end of data: need " + std::to_string(wanted) + " byte(s), " + std::to_string(available) + " left",
      offset);
}

void throwBadVarint(std::size_t offset, const char* problem) { throw FormatError(problem, offset); }

}  // namespace gizmo::replay::detail
