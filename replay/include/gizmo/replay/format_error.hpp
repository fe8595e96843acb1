#pragma once
// The one exception of the replay byte layer: the bytes being read are not a valid encoding.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace gizmo::replay {

// what() reads "<description> at byte <offset>". The offset is relative to the buffer the failing
// reader was given; a caller that knows where that buffer sits (file, chunk) adds that context.
class FormatError : public std::runtime_error {
 public:
  FormatError(const std::string& description, std::uint64_t offset);
  std::uint64_t offset() const noexcept { return offset_; }
  // The description alone, for a caller that adds context and throws again.
  const std::string& description() const noexcept { return description_; }

 private:
  std::string description_;
  std::uint64_t offset_;
};

}  // namespace gizmo::replay
