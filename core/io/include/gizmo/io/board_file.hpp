#pragma once
// Reading a board without saying its format: XML when the first character other than white space
// (after an optional UTF-8 byte order mark) is '<', else the text format.
#include <cstddef>
#include <string>
#include <string_view>

#include "gizmo/io/read_result.hpp"

namespace gizmo::io {

inline constexpr std::size_t kMaxBoardFileBytes = std::size_t{16} << 20;  // 16 MiB

// Reads the file at path. Throws InputError when it is missing, unreadable, not a regular file,
// larger than kMaxBoardFileBytes, contains a NUL byte, or is not a valid board.
ReadResult readBoardFile(const std::string& path);

// The same for content already in memory; name is used in diagnostics.
ReadResult readBoardString(std::string_view content, const std::string& name);

// What --strict does with a board that was read: nothing when it was read as written, else
// throws InputError whose errors are its warnings (each one says what was read leniently).
void refuseLeniency(const ReadResult& result);

}  // namespace gizmo::io
