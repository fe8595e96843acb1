#include "board_kinds.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace gizmo::realboards {
namespace {

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t`"), b = s.find_last_not_of(" \t`\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// A markdown table row split at " | " (cells may hold a lone '|' escaped as "\|").
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string body = row.substr(2);  // after "| "
  std::size_t at = 0;
  while (true) {
    const std::size_t bar = body.find(" | ", at);
    if (bar == std::string::npos) {
      out.push_back(trim(body.substr(at)));
      break;
    }
    out.push_back(trim(body.substr(at, bar - at)));
    at = bar + 3;
  }
  return out;
}

std::ifstream open(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  return in;
}

}  // namespace

std::map<std::string, BoardKind> readBoardKinds(const std::string& sourcesMd, const std::string& unlistedTsv) {
  std::map<std::string, BoardKind> kinds;
  std::ifstream md = open(sourcesMd);
  std::string line;
  // "| # | File | Repo | Path | Commit | Format | Bytes | Content | Kind | Unusual |"
  while (std::getline(md, line)) {
    if (line.rfind("| ", 0) != 0) continue;
    const std::vector<std::string> c = cells(line);
    if (c.size() < 10 || c[0].empty() || c[0].find_first_not_of("0123456789") != std::string::npos) continue;
    if (c[8].size() != 1) continue;
    const std::string format = c[5].substr(0, c[5].find(' '));
    kinds[c[1]] = BoardKind{format, c[8][0], "SOURCES.md"};
  }
  std::ifstream tsv = open(unlistedTsv);
  while (std::getline(tsv, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string file, format, kind, why;
    std::getline(fields, file, '\t');
    std::getline(fields, format, '\t');
    std::getline(fields, kind, '\t');
    std::getline(fields, why);
    if (kind.size() != 1) throw std::runtime_error(unlistedTsv + ": bad line: " + line);
    kinds[file] = BoardKind{format, kind[0], "unlisted.tsv: " + why};
  }
  return kinds;
}

}  // namespace gizmo::realboards
