#pragma once
// Where a command's board and key script come from: a file, or the built-in spec example.
#include <optional>
#include <string>
#include <vector>

#include "gizmo/core/run/run.hpp"
#include "gizmo/io/read_result.hpp"

namespace gizmo::cli {

extern const char* const kDefaultBoardName;
extern const char* const kDefaultBoardText;

// Exit codes of every command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;
inline constexpr int kExitBadInput = 2;

struct LoadedBoard {
  BoardSpec spec;
  std::string name;                   // what to call it in output
  std::vector<std::string> warnings;  // what the reader read leniently, one io::format line each
};

// Reads the board at path, or the built-in one when path is empty; prints the reader's
// warnings to stderr. With strict, a board read leniently is refused instead: its warnings are
// the errors. Throws io::InputError.
LoadedBoard loadBoard(const std::string& path, bool strict = false);
std::vector<TimedKey> loadKeys(const std::string& path);

}  // namespace gizmo::cli
