#include "parse_util.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "gizmo/core/decimal_text.hpp"

namespace gizmo::io::detail {

std::string toLowerAscii(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

namespace {
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNameChar(char c) { return isDigit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

// The decimal grammar: [+-]? (D+ (. D*)? | . D+) ([eE] [+-]? D+)?
bool decimalSyntax(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t expDigits = 0;
    while (i < s.size() && isDigit(s[i])) ++i, ++expDigits;
    if (expDigits == 0) return false;
  }
  return i == s.size();
}

std::string show(std::string_view token) { return quote(token); }
}  // namespace

std::string quote(std::string_view text) {
  if (text.size() > 64) return "'" + std::string(text.substr(0, 61)) + "...'";
  return "'" + std::string(text) + "'";
}

std::string controlCharacterProblem(unsigned char c) {
  static const char* hex = "0123456789ABCDEF";
  return std::string("unexpected control character (byte 0x") + hex[c >> 4] + hex[c & 15] + ")";
}

std::string nameProblem(std::string_view name) {
  if (name.empty()) return "a name cannot be empty";
  for (char c : name)
    if (!isNameChar(c)) return show(name) + " is not a valid name: names use only letters, digits and _";
  return {};
}

Number parseDecimal(std::string_view token, const std::string& what) {
  Number n;
  if (token.empty()) {
    n.problem = what + " is empty";
    return n;
  }
  if (!decimalSyntax(token)) {
    const std::string lower = toLowerAscii(token);
    const std::string_view unsigned_ = std::string_view(lower).substr(lower[0] == '+' || lower[0] == '-' ? 1 : 0);
    if (unsigned_ == "nan" || unsigned_ == "inf" || unsigned_ == "infinity")
      n.problem = what + " must be a finite number, not " + show(token);
    else if (unsigned_.substr(0, 2) == "0x") n.problem = what + " must be a decimal number, not " + show(token);
    else n.problem = what + " must be a number, not " + show(token);
    return n;
  }
  // std::from_chars (parseDecimalDouble) takes no leading '+'.
  const std::string_view digits = token[0] == '+' ? token.substr(1) : token;
  double v = 0;
  const DecimalParse r = parseDecimalDouble(digits, v);
  if (r == DecimalParse::OutOfRange) {
    n.problem = what + " " + show(token) + " is out of range";
    return n;
  }
  if (r != DecimalParse::Ok || !std::isfinite(v)) {
    n.problem = what + " must be a number, not " + show(token);
    return n;
  }
  n.ok = true;
  n.value = v;
  return n;
}

Whole parseWhole(std::string_view token, const std::string& what) {
  Whole w;
  const Number n = parseDecimal(token, what);
  if (!n.ok) {
    w.problem = n.problem;
    return w;
  }
  if (std::fabs(n.value) > kMaxWhole) {
    w.problem = what + " " + show(token) + " is too large (the limit is 1000000000)";
    return w;
  }
  if (n.value != std::floor(n.value)) {
    w.problem = what + " must be a whole number, not " + show(token);
    return w;
  }
  w.ok = true;
  w.value = static_cast<long long>(n.value);
  w.writtenAsDecimal = token.find_first_of(".eE") != std::string_view::npos;
  return w;
}

std::string shortest(double v) { return shortestDecimal(v); }

LineIndex::LineIndex(std::string_view content) : bom_(startsWithBom(content)) {
  starts_.push_back(0);
  for (std::size_t i = 0; i < content.size(); ++i)
    if (content[i] == '\n') starts_.push_back(i + 1);
}

SourcePos LineIndex::position(std::size_t offset) const {
  const auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
  const std::size_t line = static_cast<std::size_t>(it - starts_.begin());  // ≥ 1: starts_[0] = 0
  std::size_t column = offset - starts_[line - 1] + 1;
  if (line == 1 && bom_ && column > kBom.size()) column -= kBom.size();
  return SourcePos{static_cast<int>(line), static_cast<int>(column)};
}

namespace {
bool before(const SourcePos& a, std::size_t aSeq, const SourcePos& b, std::size_t bSeq) {
  if (a.line != b.line) return a.line < b.line;
  if (a.column != b.column) return a.column < b.column;
  return aSeq < bSeq;
}
}  // namespace

void Reporter::error(SourcePos at, std::string message) {
  ++errorCount_;
  errors_.push_back(Entry{at, seq_++, std::move(message), 1});
  if (errors_.size() >= 4 * kMaxReportedErrors) sortAndTrim();
}

void Reporter::sortAndTrim() {
  std::sort(errors_.begin(), errors_.end(),
            [](const Entry& a, const Entry& b) { return before(a.at, a.seq, b.at, b.seq); });
  if (errors_.size() > kMaxReportedErrors) errors_.resize(kMaxReportedErrors);
}

void Reporter::lenient(const std::string& kind, SourcePos at, std::string message) {
  auto [it, inserted] = lenient_.try_emplace(kind);
  Entry& e = it->second;
  if (inserted || before(at, seq_, e.at, e.seq)) {
    e.at = at;
    e.seq = seq_;
    e.message = std::move(message);
  }
  if (!inserted) ++e.count;
  ++seq_;
}

std::vector<Diagnostic> Reporter::warnings() const {
  std::vector<const Entry*> entries;
  for (const auto& [kind, e] : lenient_) entries.push_back(&e);
  std::sort(entries.begin(), entries.end(),
            [](const Entry* a, const Entry* b) { return before(a->at, a->seq, b->at, b->seq); });
  std::vector<Diagnostic> out;
  for (const Entry* e : entries) {
    std::string message = e->message;
    if (e->count > 1) message += " (and " + std::to_string(e->count - 1) + " more like this)";
    out.push_back(Diagnostic{file_, e->at.line, e->at.column, std::move(message), false});
  }
  return out;
}

void Reporter::throwErrors() {
  sortAndTrim();
  std::vector<Diagnostic> out;
  for (const Entry& e : errors_) out.push_back(Diagnostic{file_, e.at.line, e.at.column, e.message, true});
  if (errorCount_ > errors_.size()) {
    const std::size_t more = errorCount_ - errors_.size();
    out.push_back(Diagnostic{file_, 0, 0,
                             "and " + std::to_string(more) + " more error" + (more == 1 ? "" : "s") +
                                 " (only the first " + std::to_string(kMaxReportedErrors) + " are shown)",
                             true});
  }
  throw InputError(std::move(out));
}

void fail(const std::string& file, SourcePos at, const std::string& message) {
  throw InputError({Diagnostic{file, at.line, at.column, message, true}});
}

std::string readWholeFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) fail(path, {}, "cannot read the file: it does not exist");
  if (fs::is_directory(st)) fail(path, {}, "cannot read the file: it is a directory");
  if (!fs::is_regular_file(st)) fail(path, {}, "cannot read the file: it is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, {}, "cannot open the file for reading");
  std::string content;
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    content.append(buf, static_cast<std::size_t>(in.gcount()));
    if (content.size() > kMaxFileBytes) fail(path, {}, "the file is larger than 16 MiB, the limit for board files");
  }
  if (in.bad()) fail(path, {}, "error while reading the file");
  return content;
}

void rejectNul(std::string_view content, const std::string& file) {
  const std::size_t nul = content.find('\0');
  if (nul == std::string_view::npos) return;
  fail(file, LineIndex(content).position(nul), "the file contains a NUL byte: it is not a text file");
}

std::optional<std::vector<Token>> tokenizeLine(std::string_view text, int line, Reporter& rep,
                                               const std::string& tooLong) {
  if (text.size() > kMaxLineBytes) {
    rep.error(SourcePos{line, 1}, tooLong);
    return std::nullopt;
  }
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if ((c < 0x20 && c != '\t') || c == 0x7F) {
      rep.error(SourcePos{line, static_cast<int>(i) + 1}, controlCharacterProblem(c));
      return std::nullopt;
    }
  }
  std::vector<Token> tokens;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == ' ' || text[i] == '\t') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    tokens.push_back(Token{text.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return tokens;
}

}  // namespace gizmo::io::detail
