#include "board_input.hpp"

#include <iostream>

#include "gizmo/io/board_file.hpp"
#include "gizmo/io/key_script.hpp"

namespace gizmo::cli {

LoadedBoard loadBoard(const std::string& path, bool strict) {
  const io::ReadResult r =
      path.empty() ? io::readBoardString(kDefaultBoardText, kDefaultBoardName) : io::readBoardFile(path);
  if (strict) io::refuseLeniency(r);
  LoadedBoard out{r.board, path.empty() ? std::string(kDefaultBoardName) : path, {}};
  for (const io::Diagnostic& d : r.warnings) {
    out.warnings.push_back(io::format(d));
    std::cerr << out.warnings.back() << '\n';
  }
  return out;
}

std::vector<TimedKey> loadKeys(const std::string& path) {
  std::vector<TimedKey> keys;
  if (path.empty()) return keys;
  for (const io::KeyInput& k : io::readKeyScriptFile(path)) keys.push_back(TimedKey{k.time, k.key, k.direction});
  return keys;
}

}  // namespace gizmo::cli
