// Key scripts: "TIME down|up KEYCODE" a line. This project's own format, so it is read strictly:
// no leniency beyond '#' comment lines, blank lines and CR LF line ends.
#include "gizmo/io/key_script.hpp"

#include "gizmo/core/board_spec_check.hpp"
#include "parse_util.hpp"

namespace gizmo::io {
namespace {

using namespace detail;

}  // namespace

std::vector<KeyInput> readKeyScript(std::string_view content, const std::string& fileName) {
  if (content.size() > kMaxFileBytes) fail(fileName, {}, "the file is larger than 16 MiB, the limit for key scripts");
  Reporter rep(fileName);
  std::vector<KeyInput> inputs;
  bool havePrevious = false;
  double previous = 0;
  int previousLine = 0;
  int line = 0;
  std::size_t pos = 0;
  while (true) {
    const std::size_t nl = content.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? content.size() : nl;
    std::string_view text = content.substr(pos, end - pos);
    ++line;
    pos = nl + 1;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    const bool last = nl == std::string_view::npos;
    auto at = [&](int column) { return SourcePos{line, column}; };
    [&] {
      const std::optional<std::vector<Token>> tokens =
          tokenizeLine(text, line, rep, "the line is longer than 65536 bytes");
      if (!tokens) return;
      const std::vector<Token>& t = *tokens;
      if (t.empty() || t[0].text[0] == '#') return;
      if (t.size() < 3) {
        rep.error(at(t[0].column), "a key input is TIME down|up KEYCODE (for example '1.25 down 32'); this line has " +
                                       std::to_string(t.size()) + " value" + (t.size() == 1 ? "" : "s"));
        return;
      }
      if (t.size() > 3) {
        rep.error(at(t[3].column), "unexpected " + quote(t[3].text) + ": a key input is TIME down|up KEYCODE" +
                                       (t[3].text[0] == '#' ? " (comments must be on a line of their own)" : ""));
        return;
      }
      KeyInput in;
      in.where = at(t[0].column);
      bool ok = true;
      const Number time = parseDecimal(t[0].text, "the time");
      if (!time.ok) {
        rep.error(at(t[0].column), time.problem);
        ok = false;
      } else if (time.value < 0) {
        rep.error(at(t[0].column), "the time " + quote(t[0].text) + " is negative; times start at 0");
        ok = false;
      } else if (havePrevious && time.value < previous) {
        rep.error(at(t[0].column), "the time " + quote(t[0].text) + " is earlier than the time " + shortest(previous) +
                                       " on line " + std::to_string(previousLine) + "; times must not decrease");
        ok = false;
      } else {
        in.time = time.value;
        havePrevious = true;
        previous = time.value;
        previousLine = line;
      }
      if (t[1].text == "down" || t[1].text == "up") {
        in.direction = t[1].text == "down" ? KeyDirection::Down : KeyDirection::Up;
      } else {
        rep.error(at(t[1].column), "the key direction must be down or up, not " + quote(t[1].text));
        ok = false;
      }
      const Whole key = parseWhole(t[2].text, "the key code");
      if (!key.ok) {
        rep.error(at(t[2].column), key.problem);
        ok = false;
      } else if (key.writtenAsDecimal) {
        rep.error(at(t[2].column), "the key code must be written as a whole number, not " + quote(t[2].text));
        ok = false;
      } else if (std::string p = keyCodeProblem(key.value); !p.empty()) {
        rep.error(at(t[2].column), p);
        ok = false;
      } else {
        in.key = static_cast<int>(key.value);
      }
      if (ok) inputs.push_back(in);
    }();
    if (last) break;
  }
  rep.throwIfFailed();
  return inputs;
}

std::vector<KeyInput> readKeyScriptFile(const std::string& path) { return readKeyScript(readWholeFile(path), path); }

}  // namespace gizmo::io
