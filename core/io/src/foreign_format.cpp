#include "foreign_format.hpp"

#include <vector>

#include "parse_util.hpp"

namespace gizmo::io::detail {
namespace {

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool isNumber(std::string_view w) { return parseDecimal(w, "x").ok; }

// The lines of the content, as words, blank lines and '#' lines left out; at most `limit`.
std::vector<std::vector<std::string_view>> commandLines(std::string_view content, std::size_t limit) {
  std::vector<std::vector<std::string_view>> out;
  std::size_t pos = 0;
  while (pos <= content.size() && out.size() < limit) {
    std::size_t nl = content.find('\n', pos);
    if (nl == std::string_view::npos) nl = content.size();
    std::vector<std::string_view> w = words(content.substr(pos, nl - pos));
    if (!w.empty() && w[0][0] != '#') out.push_back(std::move(w));
    pos = nl + 1;
  }
  return out;
}

bool anyWordIs(const std::vector<std::string_view>& line, std::initializer_list<std::string_view> set) {
  const std::string lower = toLowerAscii(line[0]);
  for (std::string_view s : set)
    if (lower == s) return true;
  return false;
}

const std::string kNot = ", not a Gizmoball board of the text or XML format";

}  // namespace

std::optional<std::string> foreignFormat(std::string_view content) {
  if (content.size() >= 2 && static_cast<unsigned char>(content[0]) == 0xAC &&
      static_cast<unsigned char>(content[1]) == 0xED)
    return "this looks like a Java serialisation stream (binary, it starts with the bytes AC ED)" + kNot;
  std::string_view rest = startsWithBom(content) ? content.substr(kBom.size()) : content;
  const std::size_t first = rest.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return std::nullopt;
  if (rest[first] == '[' || rest[first] == '{')
    return std::string("this looks like a JSON file (it starts with '") + rest[first] + "')" + kNot;

  const auto lines = commandLines(rest, 4096);
  if (lines.empty()) return std::nullopt;
  if (lines[0][0].find('=') != std::string_view::npos)
    return "this looks like a file of key=value fields (" + quote(lines[0][0]) + " on its first line)" + kNot;

  std::size_t pixelLike = 0;  // lines "type x y width height [rotation]" with no name
  bool allPixelShaped = true;
  for (const auto& line : lines) {
    // MIT 6.170's 3-D Gizmoball (.g3d): three-component gravity, 3-D gizmo types, TimePerUpdate.
    if (anyWordIs(line, {"timeperupdate", "cube", "trianglea"}) ||
        (anyWordIs(line, {"gravity"}) && line.size() == 4 && isNumber(line[1]) && isNumber(line[2]) &&
         isNumber(line[3])))
      return "this looks like a 3-D Gizmoball board (" + quote(line[0]) + " is a command of the .g3d format)" + kNot;
    // Dialects whose gizmo words carry their kind (MartyPang's "SquareBumper NAME X Y W H",
    // kll0125's "AbsorberGizmo NAME X Y W H" in pixels): the geometry means something else.
    if (anyWordIs(line, {"squarebumper", "circlebumper", "trianglebumper", "trapezoidbumper", "absorbergizmo",
                         "connectgizmo", "connectkeydown"}))
      return "this looks like a board of another Gizmoball dialect (" + quote(line[0]) + " with its own coordinates)" +
             kNot;
    bool numbersOnly = line.size() >= 5 && line.size() <= 6;
    for (std::size_t i = 1; numbersOnly && i < line.size(); ++i) numbersOnly = isNumber(line[i]);
    if (!numbersOnly || isNumber(line[0])) allPixelShaped = false;
    // "Absorber NAME X1 Y1 X2 Y2" and "Ball NAME X Y VX VY" have this shape when NAME is digits.
    else if (!(line.size() == 6 && anyWordIs(line, {"absorber", "ball"}))) ++pixelLike;
  }
  // The ECNU maps ("triangle 77 505 50 50"): every line a type and four or five numbers, no name.
  if (allPixelShaped && pixelLike > 0)
    return "this looks like a pixel-coordinate map (" + quote(lines[0][0]) +
           " followed by x, y, width and height in pixels, without a name)" + kNot;
  return std::nullopt;
}

}  // namespace gizmo::io::detail
