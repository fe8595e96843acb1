#pragma once
// Internal to gizmo::io: what the readers share (limits, numbers, names, positions, diagnostics).
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "gizmo/io/diagnostics.hpp"

namespace gizmo::io::detail {

inline constexpr std::size_t kMaxFileBytes = std::size_t{16} << 20;  // 16 MiB
inline constexpr std::size_t kMaxLineBytes = std::size_t{64} << 10;  // 64 KiB, without the line end
inline constexpr std::size_t kMaxReportedErrors = 50;
inline constexpr double kMaxWhole = 1.0e9;  // whole numbers beyond this are refused as absurd

inline constexpr std::string_view kBom = "\xEF\xBB\xBF";
inline bool startsWithBom(std::string_view s) { return s.substr(0, 3) == kBom; }

std::string toLowerAscii(std::string_view s);

// 'text' in single quotes for a message, cut short (with "...") when it is very long.
std::string quote(std::string_view text);

// "unexpected control character (byte 0x0D)".
std::string controlCharacterProblem(unsigned char c);

// Empty when the name is letters, digits and '_' (at least one), else what is wrong.
std::string nameProblem(std::string_view name);

// A decimal number token: optional sign, digits with an optional fraction, optional exponent;
// finite. `what` names the value in messages ("the x coordinate").
struct Number {
  bool ok = false;
  double value = 0;
  std::string problem;
};
Number parseDecimal(std::string_view token, const std::string& what);

// A whole number, |value| <= kMaxWhole. A token with a fraction or an exponent whose value is
// whole ("3.0", "1e2") is accepted and flagged, so that the reader can warn.
struct Whole {
  bool ok = false;
  long long value = 0;
  bool writtenAsDecimal = false;
  std::string problem;
};
Whole parseWhole(std::string_view token, const std::string& what);

// The shortest decimal that reads back to the same double (std::to_chars).
std::string shortest(double v);

// Byte offset → line and column (1-based, in bytes; a UTF-8 byte order mark does not count).
class LineIndex {
 public:
  explicit LineIndex(std::string_view content);
  SourcePos position(std::size_t offset) const;

 private:
  std::vector<std::size_t> starts_;
  bool bom_ = false;
};

// Collects a reader's errors (keeping the kMaxReportedErrors earliest by position) and its
// lenient-reading warnings (one per kind, at the first place, with a count).
class Reporter;

// One word of a line and the column it starts at (1-based).
struct Token {
  std::string_view text;
  int column = 0;
};

// Splits one line (its line end already removed) at spaces and tabs. A line longer than
// kMaxLineBytes or holding a control character is reported (at `line`) and gives nullopt;
// `tooLong` is the message for the first.
std::optional<std::vector<Token>> tokenizeLine(std::string_view text, int line, Reporter& rep,
                                               const std::string& tooLong);

class Reporter {
 public:
  explicit Reporter(std::string file) : file_(std::move(file)) {}
  void error(SourcePos at, std::string message);
  void lenient(const std::string& kind, SourcePos at, std::string message);
  bool failed() const { return errorCount_ > 0; }
  std::vector<Diagnostic> warnings() const;
  [[noreturn]] void throwErrors();
  void throwIfFailed() {
    if (failed()) throwErrors();
  }

 private:
  struct Entry {
    SourcePos at;
    std::size_t seq = 0;
    std::string message;
    std::size_t count = 1;
  };
  void sortAndTrim();
  std::string file_;
  std::vector<Entry> errors_;
  std::size_t errorCount_ = 0;
  std::size_t seq_ = 0;
  std::map<std::string, Entry> lenient_;
};

// Throws a one-diagnostic InputError.
[[noreturn]] void fail(const std::string& file, SourcePos at, const std::string& message);

// The whole content of a regular file of at most kMaxFileBytes; InputError otherwise.
std::string readWholeFile(const std::string& path);
// InputError at the first NUL byte, if any.
void rejectNul(std::string_view content, const std::string& file);

}  // namespace gizmo::io::detail
