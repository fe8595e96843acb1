#pragma once
// The kind of each board file of the real-board collection (../shared/boards/real): SOURCES.md's
// table (file, format, kind), plus unlisted.tsv here for the files that SOURCES.md does not list.
#include <map>
#include <string>

namespace gizmo::realboards {

struct BoardKind {
  std::string format;  // "TXT-CS308", "TXT-MIT", "XML-MIT" or "other" (SOURCES.md's first word)
  char kind = '?';     // S saved, H hand-written, T test fixture, M malformed on purpose, B by accident
  std::string source;  // "SOURCES.md" or "unlisted.tsv: <why>"
};

// File name → kind. Throws std::runtime_error when a table cannot be read.
std::map<std::string, BoardKind> readBoardKinds(const std::string& sourcesMd, const std::string& unlistedTsv);

// "other formats" are every format but the text and XML ones.
inline bool isBoardFormat(const BoardKind& k) { return k.format != "other"; }

}  // namespace gizmo::realboards
