#pragma once
// The XML board format of MIT 6.170 (docs/board-files.md §3, "The XML format"), through pugixml.
#include <string>
#include <string_view>

#include "gizmo/io/read_result.hpp"

namespace gizmo::io {

// Reads a whole XML board. Throws InputError (file:line:column of each element or attribute at
// fault) when the XML is not well-formed, does not follow the board schema, or the board fails
// checkBoardSpec.
ReadResult readXmlBoard(std::string_view content, const std::string& fileName);

}  // namespace gizmo::io
