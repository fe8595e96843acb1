#pragma once
// What every board the readers accept must satisfy, for the reader fuzz targets: it passes
// checkBoardSpec (a board loads whole and valid, or not at all), and it survives the writers: the
// canonical XML and text of it read back to a board whose canonical XML is the same text (the
// writers print round-trip decimals, so equal text means an equal board). A broken promise
// aborts, which libFuzzer and the corpus runner report as a crash.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"

namespace gizmo::fuzzing {

[[noreturn]] inline void broken(const char* promise, const std::string& detail) {
  std::fprintf(stderr, "broken promise: %s\n%s\n", promise, detail.c_str());
  std::abort();
}

inline void checkAcceptedBoard(const BoardSpec& board) {
  if (!checkBoardSpec(board).empty()) broken("an accepted board passes checkBoardSpec", io::writeXmlBoard(board));
  const std::string xml = io::writeXmlBoard(board);
  try {
    const std::string again = io::writeXmlBoard(io::readXmlBoard(xml, "written.xml").board);
    if (again != xml) broken("board -> XML -> board is the same board", xml + "\nbecame\n" + again);
    const std::string viaText = io::writeXmlBoard(io::readTextBoard(io::writeTextBoard(board), "written.txt").board);
    if (viaText != xml) broken("board -> text -> board is the same board", xml + "\nbecame\n" + viaText);
  } catch (const io::InputError& e) {
    broken("what the writers write reads back", std::string(e.what()) + "\n" + xml);
  }
}

}  // namespace gizmo::fuzzing
