#pragma once
// How `gizmo render` and `gizmo play` write their files: whole or not at all (a temporary name,
// renamed at the end), the base64 text that carries binary arrays inside an HTML page, and the
// filling of a page's template.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace gizmo::cli {

// Writes `content` to a temporary file next to `path`, then renames it to `path`; throws
// std::runtime_error (naming the path) when either step fails, leaving no file behind.
void writeFileWhole(const std::string& path, const std::string& content);

std::string base64(const std::uint8_t* bytes, std::size_t size);

// Fills a page template's `marker` (its first occurrence) with `with`; throws std::logic_error
// when the template lacks it. The pages of `gizmo render` and `gizmo play` are made this way.
void replaceMarker(std::string& text, const std::string& marker, const std::string& with);
// Text as HTML shows it: <, > and & escaped.
std::string escapeHtml(const std::string& s);

// An array's bytes as the page reads them (little-endian, as typed arrays are on every machine a
// browser runs on that this project builds for).
template <class T>
std::string base64Of(const std::vector<T>& values) {
  std::vector<std::uint8_t> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return base64(bytes.data(), bytes.size());
}

}  // namespace gizmo::cli
