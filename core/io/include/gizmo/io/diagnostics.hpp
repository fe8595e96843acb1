#pragma once
// What the readers say about a file: errors (the file is refused) and warnings (something was read
// leniently). Positions are 1-based; line 0 means "the whole file", column 0 "the whole line".
#include <stdexcept>
#include <string>
#include <vector>

namespace gizmo::io {

struct Diagnostic {
  std::string file;
  int line = 0;
  int column = 0;
  std::string message;
  bool error = true;  // false: a warning
};

// "file:line:column: error: message" ("warning:" for warnings); the column is left out when it is
// 0, and line and column when the line is 0.
std::string format(const Diagnostic& d);

// Thrown by every reader when a file cannot be loaded. It carries every error found (the readers
// cap the list; the last entry then says how many more there were).
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const noexcept { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace gizmo::io
