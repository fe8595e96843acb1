#include "gizmo/io/board_file.hpp"

#include "foreign_format.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"
#include "parse_util.hpp"

namespace gizmo::io {

static_assert(kMaxBoardFileBytes == detail::kMaxFileBytes);

ReadResult readBoardString(std::string_view content, const std::string& name) {
  if (content.size() > detail::kMaxFileBytes)
    detail::fail(name, {}, "the file is larger than 16 MiB, the limit for board files");
  if (const std::optional<std::string> foreign = detail::foreignFormat(content)) detail::fail(name, {}, *foreign);
  detail::rejectNul(content, name);
  std::string_view rest = content;
  if (detail::startsWithBom(rest)) rest.remove_prefix(detail::kBom.size());
  const std::size_t first = rest.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && rest[first] == '<') return readXmlBoard(content, name);
  return readTextBoard(content, name);
}

void refuseLeniency(const ReadResult& result) {
  if (result.warnings.empty()) return;
  std::vector<Diagnostic> errors = result.warnings;
  for (Diagnostic& d : errors) {
    d.error = true;
    d.message += " (refused: --strict reads a board only as written)";
  }
  throw InputError(std::move(errors));
}

ReadResult readBoardFile(const std::string& path) { return readBoardString(detail::readWholeFile(path), path); }

}  // namespace gizmo::io
