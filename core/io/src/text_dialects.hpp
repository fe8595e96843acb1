#pragma once
// Internal to gizmo::io: the dialects of the text format, one row per quirk of what other
// Gizmoball programs write (docs/board-files.md §2 and §7). The reader is a plain reader of the
// format; at each point where some program's files differ from it (a stage below), it asks this
// table, and the first row that recognises the input says what to report and what to do.
//
// Each row holds the function that recognises its quirk and words its warning, so a quirk's code
// sits with its row and a dialect is added (or dropped) by one row here: the reader knows only the
// few outcomes, which it applies in one switch per stage. (An enum of quirks with a switch in the
// reader would spread each quirk over two files; a class per quirk would be heavier than a table.)
// The commands that other programs added are in text_additions.cpp, not here: a row here changes
// how a line of the format is read, an addition is a command word the format does not have.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/board_spec.hpp"
#include "parse_util.hpp"
#include "text_additions.hpp"

namespace gizmo::io::detail {

// Where the reader asks, and what it gives the rows (DialectInput's fields that are set).
enum class DialectStage {
  FileStart,  // the file's content, before its first line (text)
  LineEnd,    // a line as read, before it is split (text)
  Line,       // a line's words, before the first is looked up as a command (tokens)
  Claim,      // a command line of the format, before it is read: another program's? (tokens, command)
  Keyword,    // a keyword of the format, matched without regard to case (token, keyword)
  Values,     // a command line with fewer or more values than the command has (tokens, command)
  Whole,      // a whole number (token)
  Cell,       // a gizmo's coordinate (token)
  Key,        // a KeyConnect's key that is not a number (token)
  Direction,  // a KeyConnect's direction that is neither down nor up (token)
  LaterName,  // a Connect or KeyConnect that names a gizmo that does not exist at its line
};

// What the reader does when a row recognises its input; after it, the reader goes on unless the
// outcome ends the line.
enum class DialectOutcome {
  Skip,                         // FileStart: `value` bytes at the start are not part of the board
  StripLineEnd,                 // LineEnd: `value` bytes at the end are the line end
  IgnoreLine,                   // the line is ignored
  AsAddition,                   // the line is another program's command: `addition`
  ReadOn,                       // the line is read as the format (the words the row is about are ignored)
  ReadOnUnlessConsumerLeftOut,  // ReadOn, unless the consumer (token 2) is left out: then the line is
  LeaveOutName,                 // the line is left out, and so are the later commands that name token 1
  LeaveOutNewName,              // the same, unless an object of that name exists (it is not replaced)
  UseValue,                     // the number is read as `value`
  LeaveOutConnection,           // the connection is left out
  DownAndUp,                    // the key connection is read as two, down and up
  MakeAtEnd,                    // the connection is made at the end of the file, when what it names exists
};

enum class CommandRole { Gizmo, Ball, Connect, Other };

// A command of the format, as the reader's command table describes it.
struct CommandView {
  std::string_view canonical;  // "Circle"
  std::string_view usage;      // "Circle NAME X Y"
  std::size_t tokens = 0;      // the command word and its values
  CommandRole role = CommandRole::Other;
  GizmoType type = GizmoType::Square;  // for a gizmo
};

struct DialectInput {
  std::string_view text = {};
  const std::vector<Token>* tokens = nullptr;
  const CommandView* command = nullptr;
  const Token* token = nullptr;
  std::string_view keyword = {};  // the keyword's standard spelling
};

struct DialectReading {
  DialectOutcome outcome = DialectOutcome::ReadOn;
  std::string kind;  // the warning's kind: one warning per kind and file
  int column = 0;    // where the warning points, on the reader's line (1 on FileStart)
  std::string message;
  long long value = 0;
  const Addition* addition = nullptr;
};

struct Dialect {
  std::string_view what;        // the quirk, in plain words
  std::string_view programs;    // who writes it (as text_additions.cpp names them)
  std::string_view recognised;  // how the row tells it
  std::string_view reading;     // what the reader does
  DialectStage stage;
  std::optional<DialectReading> (*read)(const DialectInput&);
};

// Every row, in the order they are asked.
std::span<const Dialect> dialects();

// The reading of the first row of `stage` that recognises `in`, if any.
std::optional<DialectReading> readDialect(DialectStage stage, const DialectInput& in);

}  // namespace gizmo::io::detail
