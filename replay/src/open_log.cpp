// Opening a replay log (replay.hpp: openLog): its header read into the run it records, the
// precision checked, and the board's gizmo names for the views. Recording, walking, seeking and
// replaying have files of their own (recording.cpp, decision_stream.cpp, seeking.cpp,
// replaying.cpp), each written once over the scalar and dispatched on the log's precision.
#include "gizmo/replay/replay.hpp"

#include "gizmo/core/board/build_board.hpp"
#include "gizmo/replay/chunk.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_header.hpp"

namespace gizmo::replay {

std::string gizmoName(const std::vector<std::string>& names, GizmoId id) {
  if (id >= 0 && std::size_t(id) < names.size()) return names[std::size_t(id)];
  return id == kNoGizmo ? "" : id > 0 ? spawnedBallName(id, names) : "#" + std::to_string(id);
}

OpenedLog openLog(std::unique_ptr<ByteSource> source, bool verifyChecksums) {
  LogReader reader(std::move(source), verifyChecksums);
  LogHeader header = decodeHeader(reader.headerPayload(), reader.formatVersion());
  RunRequest request = requestOf(header);
  const std::optional<PrecisionChoice> precision = parsePrecision(header.precision);
  if (!precision) throw FormatError("header: unknown precision '" + header.precision + "'", 0);
  if (!recordable(*precision)) throw FormatError("header: precision '" + header.precision + "' cannot be recorded", 0);
  std::vector<std::string> names;
  const auto board = buildBoard<double>(request.board, PhysicsParams<double>());
  for (std::size_t g = 0; g < board->gizmoCount(); ++g) names.push_back(board->gizmo(GizmoId(g)).name());
  return OpenedLog{std::move(reader), std::move(header), std::move(request), *precision, std::move(names)};
}

OpenedLog openLog(const std::string& path) {
  try {
    return openLog(ByteSource::file(path));
  } catch (const FormatError& e) {
    throw FormatError(path + ": " + e.description(), e.offset());
  }
}

}  // namespace gizmo::replay
