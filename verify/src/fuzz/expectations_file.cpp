// The expectation file's grammar (expectations.hpp): one expectation a line, words separated by
// blanks, `#` to the end of a line a comment.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "gizmo/core/decimal_text.hpp"
#include "gizmo/verify/fuzz/expectations.hpp"

namespace gizmo::verify::fuzz {

std::string_view expectationKindName(ExpectationKind kind) {
  switch (kind) {
    case ExpectationKind::Reaches: return "reaches";
    case ExpectationKind::Avoids: return "avoids";
    case ExpectationKind::RestsAtMost: return "rests-at-most";
    case ExpectationKind::Hit: return "hit";
    case ExpectationKind::StaysOnBoard: return "stays-on-board";
  }
  return "?";
}

namespace {

const char* const kGrammar =
    "reaches ABSORBER within SECONDS [ball NAME], avoids X0 Y0 X1 Y1 [ball NAME], "
    "rests-at-most SECONDS [ball NAME], hit GIZMO at-least N within SECONDS, stays-on-board [ball NAME]";

// The words of one line, read left to right; every complaint names the line.
class LineReader {
 public:
  LineReader(std::vector<std::string> words, std::string source)
      : words_(std::move(words)), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& what) const { throw ExpectationError(source_ + ": " + what); }
  bool atEnd() const { return next_ == words_.size(); }

  std::string word(const char* what) {
    if (atEnd()) fail(std::string("missing ") + what + " after '" + words_.back() + "'");
    return words_[next_++];
  }
  void keyword(const char* expected) {
    const std::string w = word(expected);
    if (w != expected) fail("expected '" + std::string(expected) + "', not '" + w + "'");
  }
  double number(const char* what) {
    const std::string w = word(what);
    double value = 0;
    if (parseDecimalDouble(w, value) != DecimalParse::Ok || !std::isfinite(value))
      fail(std::string(what) + " must be a number, not '" + w + "'");
    return value;
  }
  double seconds(const char* what) {
    const double s = number(what);
    if (!(s > 0)) fail(std::string(what) + " must be more than 0 s, not " + words_[next_ - 1]);
    return s;
  }
  long count(const char* what) {
    const std::string w = word(what);
    long value = 0;
    const auto [end, error] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (error != std::errc() || end != w.data() + w.size() || value < 1)
      fail(std::string(what) + " must be a whole number of at least 1, not '" + w + "'");
    return value;
  }
  // `ball NAME` at the end of the line, or nothing.
  std::string optionalBall() {
    if (atEnd()) return {};
    keyword("ball");
    return word("the ball's name");
  }
  void end() const {
    if (!atEnd()) fail("unexpected '" + words_[next_] + "' after the end of the expectation");
  }

 private:
  std::vector<std::string> words_;
  std::string source_;
  std::size_t next_ = 0;
};

Expectation parseLine(LineReader& in, const std::string& source) {
  Expectation e;
  e.source = source;
  const std::string kind = in.word("an expectation");
  if (kind == "reaches") {
    e.kind = ExpectationKind::Reaches;
    e.gizmo = in.word("the absorber's name");
    in.keyword("within");
    e.seconds = in.seconds("the time");
    e.ball = in.optionalBall();
  } else if (kind == "avoids") {
    e.kind = ExpectationKind::Avoids;
    e.x0 = in.number("X0");
    e.y0 = in.number("Y0");
    e.x1 = in.number("X1");
    e.y1 = in.number("Y1");
    if (!(e.x0 < e.x1) || !(e.y0 < e.y1)) in.fail("the rectangle X0 Y0 X1 Y1 needs X0 < X1 and Y0 < Y1");
    e.ball = in.optionalBall();
  } else if (kind == "rests-at-most") {
    e.kind = ExpectationKind::RestsAtMost;
    e.seconds = in.seconds("the longest rest");
    e.ball = in.optionalBall();
  } else if (kind == "hit") {
    e.kind = ExpectationKind::Hit;
    e.gizmo = in.word("the gizmo's name");
    in.keyword("at-least");
    e.count = in.count("the number of hits");
    in.keyword("within");
    e.seconds = in.seconds("the time");
  } else if (kind == "stays-on-board") {
    e.kind = ExpectationKind::StaysOnBoard;
    e.ball = in.optionalBall();
  } else {
    in.fail("'" + kind + "' is no expectation; one of: " + kGrammar);
  }
  in.end();
  return e;
}

}  // namespace

std::vector<Expectation> parseExpectations(std::string_view text, const std::string& fileName) {
  std::vector<Expectation> out;
  std::istringstream lines{std::string(text)};
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream split(line);
    std::vector<std::string> words;
    for (std::string w; split >> w;) words.push_back(w);
    if (words.empty()) continue;
    const std::string source = fileName + ":" + std::to_string(number);
    LineReader in(std::move(words), source);
    out.push_back(parseLine(in, source));
  }
  if (out.empty()) throw ExpectationError(fileName + ": no expectation in the file (one of: " + kGrammar + ")");
  return out;
}

std::vector<Expectation> readExpectationFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ExpectationError(path + ": cannot open the expectation file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseExpectations(text.str(), path);
}

double expectationHorizon(const std::vector<Expectation>& expectations) {
  double horizon = 0;
  for (const Expectation& e : expectations)
    if (e.kind == ExpectationKind::Reaches || e.kind == ExpectationKind::Hit) horizon = std::max(horizon, e.seconds);
  return horizon;
}

}  // namespace gizmo::verify::fuzz
