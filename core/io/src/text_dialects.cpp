#include "text_dialects.hpp"

#include <algorithm>
#include <cmath>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "key_names.hpp"

namespace gizmo::io::detail {
namespace {

using Reading = std::optional<DialectReading>;

bool allLetters(std::string_view s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); });
}

// A key's name rather than a malformed number: it starts with a letter.
bool looksLikeWord(std::string_view s) {
  return !s.empty() && ((s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z'));
}

bool creates(CommandRole r) { return r == CommandRole::Gizmo || r == CommandRole::Ball; }

std::size_t carriageReturns(std::string_view text) {
  std::size_t n = 0;
  while (n < text.size() && text[text.size() - 1 - n] == '\r') ++n;
  return n;
}

DialectReading lineEnd(std::string_view text, std::size_t crs, std::string kind, std::string message) {
  return {DialectOutcome::StripLineEnd, std::move(kind), static_cast<int>(text.size() - crs) + 1, std::move(message),
          static_cast<long long>(crs),  nullptr};
}

Reading keyDirection(const DialectInput& in, std::string_view word, std::string because) {
  const std::string dir = toLowerAscii(in.token->text);
  if (dir != word) return std::nullopt;
  return DialectReading{DialectOutcome::DownAndUp,
                        "key-direction:" + dir,
                        in.token->column,
                        quote(in.token->text) + " is read as two connections, down and up: " + because,
                        0,
                        nullptr};
}

// The rows. Sources as in text_additions.cpp: SOURCES.md of the real-board collection
// (docs/board-files.md §7) gives the file and line of each program's reading.
const Dialect kDialects[] = {
    {"a UTF-8 byte order mark", "editors that save UTF-8 so (no board of the collection has one)",
     "the file starts with the bytes EF BB BF", "skipped", DialectStage::FileStart,
     [](const DialectInput& in) -> Reading {
       if (!startsWithBom(in.text)) return std::nullopt;
       return DialectReading{DialectOutcome::Skip,
                             "bom",
                             1,
                             "the UTF-8 byte order mark at the start of the file is ignored",
                             static_cast<long long>(kBom.size()),
                             nullptr};
     }},
    {"Windows line ends",
     "Calluma93/Gizmoball, GregorMc/Gizmoball, ItsyPetkov/GizmoBall---Physics-Engine, "
     "YiFan-Evan/GizmoBallGame, d-g-n/CS308-GizmoBall, jtax/Gizmoball-WJ2, klawson6/cs308_w12_gizmoball",
     "one CR before the LF", "a plain line end", DialectStage::LineEnd,
     [](const DialectInput& in) -> Reading {
       if (carriageReturns(in.text) != 1) return std::nullopt;
       return lineEnd(in.text, 1, "crlf", "Windows line ending (CR LF) read as a plain line end");
     }},
    {"a CR LF file converted to CR LF again", "none of the collection; a file copied through a CR LF conversion twice",
     "more than one CR before the LF", "a plain line end", DialectStage::LineEnd,
     [](const DialectInput& in) -> Reading {
       const std::size_t crs = carriageReturns(in.text);
       if (crs < 2) return std::nullopt;
       return lineEnd(in.text, crs, "crcrlf",
                      "line ending CR CR LF (a CR LF file saved again through a CR LF conversion) read as a plain "
                      "line end");
     }},
    {"comment lines", "NiklavsM/Gizmoball (its reader skips them)", "the first word starts with '#'", "ignored",
     DialectStage::Line,
     [](const DialectInput& in) -> Reading {
       const Token& first = in.tokens->front();
       if (first.text[0] != '#') return std::nullopt;
       return DialectReading{DialectOutcome::IgnoreLine,
                             "comment",
                             first.column,
                             "'#' comment lines are not part of the standard format; ignored",
                             0,
                             nullptr};
     }},
    // d-g-n/CS308-GizmoBall's saver names every gizmo by its cell, X_Y; its spinner is another
    // gizmo than NiklavsM/Gizmoball's of the same spelling, which the core simulates.
    {"d-g-n's spinner, spelled as NiklavsM's", "d-g-n/CS308-GizmoBall", "Spinner NAME X Y whose NAME is X_Y",
     "left out as d-g-n's addition (text_additions.cpp), with what names it", DialectStage::Claim,
     [](const DialectInput& in) -> Reading {
       const std::vector<Token>& t = *in.tokens;
       if (in.command->role != CommandRole::Gizmo || in.command->type != GizmoType::Spinner || t.size() != 4 ||
           t[1].text != std::string(t[2].text) + "_" + std::string(t[3].text))
         return std::nullopt;
       return DialectReading{DialectOutcome::AsAddition, {}, t[0].column, {}, 0, &dgnSpinner()};
     }},
    {"keywords in another case",
     "NiklavsM/Gizmoball (lower-case commands), stu259/GizmoBall ('Leftflipper'), "
     "rgallagher27/308gizmoball and jtax/Gizmoball-WJ2 ('Key')",
     "a command word, 'key' or a direction matched only without regard to case", "as the keyword",
     DialectStage::Keyword,
     [](const DialectInput& in) -> Reading {
       if (in.token->text == in.keyword) return std::nullopt;
       return DialectReading{DialectOutcome::ReadOn,
                             "keyword-case",
                             in.token->column,
                             quote(in.token->text) + " is written " + quote(in.keyword) +
                                 " in the standard format; keywords are read without regard to case",
                             0,
                             nullptr};
     }},
    // CraigR973/Gizmoball's later saver writes an absorber's upper-left corner only.
    {"an absorber without its lower-right corner", "CraigR973/Gizmoball", "Absorber NAME X Y",
     "left out (there is no size to read), with the commands that name it", DialectStage::Values,
     [](const DialectInput& in) -> Reading {
       const std::vector<Token>& t = *in.tokens;
       if (in.command->role != CommandRole::Gizmo || in.command->type != GizmoType::Absorber || t.size() != 4)
         return std::nullopt;
       return DialectReading{DialectOutcome::LeaveOutName,
                             "absorber-corner",
                             t[0].column,
                             "this absorber has no lower-right corner (Absorber NAME X1 Y1 X2 Y2); it is left out, "
                             "and so are the commands that name " +
                                 quote(t[1].text),
                             0,
                             nullptr};
     }},
    // The format's own commands have their values, and a line short of them is malformed. A gizmo
    // that other programs added is spelled by each its own way: with fewer values (a portal
    // without its exit) it is another program's, left out with what names it.
    {"another program's gizmo of the same word, with fewer values",
     "programs whose gizmo of that word is not the one the core simulates (a Portal without its exit; no board of "
     "the collection)",
     "a gizmo other programs added, short of its values",
     "left out, with the commands that name it (unless that name exists)", DialectStage::Values,
     [](const DialectInput& in) -> Reading {
       const std::vector<Token>& t = *in.tokens;
       const CommandView& c = *in.command;
       if (t.size() >= c.tokens || c.role != CommandRole::Gizmo || isStandardKind(c.type)) return std::nullopt;
       return DialectReading{
           DialectOutcome::LeaveOutNewName,
           "too-few-values:" + toLowerAscii(c.canonical),
           t[0].column,
           std::string(c.canonical) + " takes " + std::to_string(c.tokens - 1) + " values (" + std::string(c.usage) +
               ") but the line has " + std::to_string(t.size() - 1) + "; it is another program's " +
               std::string(gizmoTypeWord(c.type)) + ", left out" +
               (t.size() >= 2 ? ", and so are the commands that name " + quote(t[1].text) : std::string()),
           0,
           nullptr};
     }},
    {"a word after a gizmo or ball",
     "rgallagher27/308gizmoball (a flipper's side, true/false), LukeBev/GizmoBall (a "
     "colour)",
     "one more word, of letters only, after a gizmo's or ball's values", "the word is ignored", DialectStage::Values,
     [](const DialectInput& in) -> Reading {
       const std::vector<Token>& t = *in.tokens;
       const CommandView& c = *in.command;
       if (t.size() != c.tokens + 1 || (c.role != CommandRole::Gizmo && c.role != CommandRole::Ball) ||
           !allLetters(t.back().text))
         return std::nullopt;
       return DialectReading{DialectOutcome::ReadOn,
                             "trailing-word",
                             t.back().column,
                             "the word " + quote(t.back().text) + " after " + std::string(c.usage) +
                                 " is ignored (rgallagher27/308gizmoball writes a flipper's side as true/false there, "
                                 "LukeBev/GizmoBall a colour; their readers do not use it)",
                             0,
                             nullptr};
     }},
    {"a Connect with an action", "MIT 6.170 staff examples (dwctsai/mit-6.170-gizmoball-3d)",
     "Connect PRODUCER CONSUMER WORD, a word of letters", "the word is ignored (the line, when CONSUMER is left out)",
     DialectStage::Values,
     [](const DialectInput& in) -> Reading {
       const std::vector<Token>& t = *in.tokens;
       if (t.size() != in.command->tokens + 1 || in.command->role != CommandRole::Connect || !allLetters(t.back().text))
         return std::nullopt;
       return DialectReading{DialectOutcome::ReadOnUnlessConsumerLeftOut,
                             "connect-action",
                             t.back().column,
                             "the action word " + quote(t.back().text) +
                                 " (MIT 6.170's 'Connect PRODUCER CONSUMER ACTION') is ignored; the consumer performs "
                                 "its own action",
                             0,
                             nullptr};
     }},
    // Values after what places a gizmo or a ball are its attributes in another program (a
    // circle's radius, a size, a colour) or a comment: it is placed from its own values.
    {"values after a gizmo's or ball's own",
     "JamesConway98/GizmoBall (a value after a triangle); "
     "programs that save a radius, a size or a colour; comments after a command",
     "more values after a gizmo's or ball's", "ignored: placed from its own values", DialectStage::Values,
     [](const DialectInput& in) -> Reading {
       const std::vector<Token>& t = *in.tokens;
       const CommandView& c = *in.command;
       if (t.size() <= c.tokens || !creates(c.role)) return std::nullopt;
       const Token& extra = t[c.tokens];
       return DialectReading{DialectOutcome::ReadOn,
                             "extra-values:" + toLowerAscii(c.canonical),
                             extra.column,
                             "what follows " + std::string(c.usage) + " (" + std::to_string(t.size() - c.tokens) +
                                 " more, from " + quote(extra.text) + ") is ignored" +
                                 (extra.text[0] == '#' ? " (the standard format has comments on lines of their own)"
                                                       : "; it is placed from its own values"),
                             0,
                             nullptr};
     }},
    {"whole numbers written as decimals", "NiklavsM/Gizmoball (5.0 coordinates), key codes written 76.0",
     "a whole value with a fraction or exponent: 3.0, 1e1", "the whole number", DialectStage::Whole,
     [](const DialectInput& in) -> Reading {
       const Whole w = parseWhole(in.token->text, {});
       if (!w.ok || !w.writtenAsDecimal) return std::nullopt;
       return DialectReading{DialectOutcome::UseValue,
                             "integral-decimal",
                             in.token->column,
                             quote(in.token->text) + " is read as the whole number " + std::to_string(w.value) +
                                 " (the standard format writes whole numbers here)",
                             w.value,
                             nullptr};
     }},
    {"gizmo coordinates with a fraction", "CraigR973/Gizmoball", "a decimal that is not whole: 12.5",
     "the cell it starts in (rounded down)", DialectStage::Cell,
     [](const DialectInput& in) -> Reading {
       if (parseWhole(in.token->text, {}).ok) return std::nullopt;
       const Number n = parseDecimal(in.token->text, {});
       if (!n.ok || std::fabs(n.value) > kMaxWhole) return std::nullopt;
       const auto cell = static_cast<long long>(std::floor(n.value));
       return DialectReading{DialectOutcome::UseValue,
                             "fractional-cell",
                             in.token->column,
                             quote(in.token->text) +
                                 " is not a whole number; the gizmo is placed in the cell it "
                                 "starts in, " +
                                 std::to_string(cell),
                             cell,
                             nullptr};
     }},
    // Java's, JavaFX's and the browsers' names (key_names.cpp).
    {"keys by name", "lejhy/Gizmoball (JavaFX's names)", "a key name key_names.cpp knows", "its Java key code",
     DialectStage::Key,
     [](const DialectInput& in) -> Reading {
       const std::optional<int> code = keyCodeOfName(in.token->text);
       if (!code) return std::nullopt;
       return DialectReading{DialectOutcome::UseValue,
                             "key-name",
                             in.token->column,
                             "the key " + quote(in.token->text) + " is read as the key code " + std::to_string(*code) +
                                 " (programs write Java's, JavaFX's or the browsers' key names; the standard format "
                                 "writes the code)",
                             *code,
                             nullptr};
     }},
    // A word that names no key this reader knows: no key of ours would trigger it.
    {"keys by a name no program knows", "none of the collection; a key name of some other toolkit",
     "a word, starting with a letter, that no row above reads", "the connection is left out", DialectStage::Key,
     [](const DialectInput& in) -> Reading {
       if (!looksLikeWord(in.token->text)) return std::nullopt;
       return DialectReading{DialectOutcome::LeaveOutConnection,
                             "key-unknown",
                             in.token->column,
                             "the key " + quote(in.token->text) +
                                 " is neither a key code nor a key name this reader "
                                 "knows; the connection is left out",
                             0,
                             nullptr};
     }},
    // Both programs ignore the word and perform the action on the press and on the release.
    {"the direction 'ondown'", "ConfuddledPenguin/Gizmoball", "KeyConnect key N ondown NAME",
     "two key connections, down and up", DialectStage::Direction,
     [](const DialectInput& in) -> Reading {
       return keyDirection(in, "ondown",
                           "ConfuddledPenguin/Gizmoball's reader ignores the word, and every key it registers acts on "
                           "the press and on the release");
     }},
    {"the direction 'change'", "jtax/Gizmoball-WJ2", "KeyConnect key N change NAME", "two key connections, down and up",
     DialectStage::Direction,
     [](const DialectInput& in) -> Reading {
       return keyDirection(in, "change",
                           "jtax/Gizmoball-WJ2's reader ignores the word, and its key listener triggers on the press "
                           "and on the release");
     }},
    // Without this row such a connection would be an error of file order, as a Rotate is.
    {"connections before gizmos", "CraigR973/Gizmoball, ItsyPetkov/GizmoBall---Physics-Engine",
     "a Connect or KeyConnect naming a gizmo that does not exist at its line",
     "made at the end of the file when the gizmo exists, else ignored", DialectStage::LaterName,
     [](const DialectInput&) -> Reading {
       return DialectReading{DialectOutcome::MakeAtEnd,
                             "connection-later",
                             0,
                             "this connection names a gizmo that is created further down; it is made at the end of "
                             "the file",
                             0,
                             nullptr};
     }},
};

}  // namespace

std::span<const Dialect> dialects() { return kDialects; }

std::optional<DialectReading> readDialect(DialectStage stage, const DialectInput& in) {
  for (const Dialect& d : kDialects)
    if (d.stage == stage)
      if (Reading r = d.read(in)) return r;
  return std::nullopt;
}

}  // namespace gizmo::io::detail
