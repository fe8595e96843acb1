#include "gizmo/replay/format_error.hpp"

namespace gizmo::replay {

FormatError::FormatError(const std::string& description, std::uint64_t offset)
    : std::runtime_error(description + " at byte " + std::to_string(offset)),
      description_(description),
      offset_(offset) {}

}  // namespace gizmo::replay
