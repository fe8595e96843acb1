// readXmlBoard where the build has no pugixml: the portable build for a target whose Debian
// registry has none (wasm32, riscv64; docs/determinism.md). Such a build reads text boards only,
// and says so instead of misreading an XML file.
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/xml_reader.hpp"

namespace gizmo::io {

ReadResult readXmlBoard(std::string_view, const std::string& fileName) {
  throw InputError({Diagnostic{fileName, 1, 1,
                               "an XML board, and this build of gizmo reads text boards only (it was built "
                               "without pugixml); convert the board to the text format with a full build "
                               "(board-files.md)",
                               true}});
}

}  // namespace gizmo::io
