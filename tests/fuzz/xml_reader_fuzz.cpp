// libFuzzer target for the XML board reader: any bytes are a board file. InputError is the reader
// refusing bad input, as it must; any other exception escapes and counts as a crash, as do
// sanitizer reports and the broken promises of board_reader_oracle.hpp.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "board_reader_oracle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const gizmo::io::ReadResult r =
        gizmo::io::readXmlBoard(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.xml");
    gizmo::fuzzing::checkAcceptedBoard(r.board);
  } catch (const gizmo::io::InputError&) {}
  return 0;
}
