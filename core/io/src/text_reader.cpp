// The text board format: one command a line, executed in file order (docs/board-files.md). What
// the lines make is kept in the edit model (board_edits.hpp); how other programs write lines
// differently is the dialects table's (text_dialects.cpp), which this reader asks.
#include "gizmo/io/text_reader.hpp"

#include <array>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "board_edits.hpp"
#include "board_repair.hpp"
#include "foreign_format.hpp"
#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "key_names.hpp"
#include "parse_util.hpp"
#include "text_additions.hpp"
#include "text_dialects.hpp"

namespace gizmo::io {
namespace {

using namespace detail;

enum class Cmd { Gizmo, Ball, Rotate, Delete, Move, Connect, KeyConnect, Gravity, Friction };

struct CommandInfo {
  std::string_view canonical;
  Cmd cmd;
  GizmoType type;  // for Cmd::Gizmo
  std::size_t tokens;
  std::string_view usage;
};

// The gizmos' commands come from their kinds (gizmo_kinds.hpp); the others are the format's own.
constexpr CommandInfo kOtherCommands[] = {
    {"Ball", Cmd::Ball, GizmoType::Square, 6, "Ball NAME X Y VX VY"},
    {"Rotate", Cmd::Rotate, GizmoType::Square, 2, "Rotate NAME"},
    {"Delete", Cmd::Delete, GizmoType::Square, 2, "Delete NAME"},
    {"Move", Cmd::Move, GizmoType::Square, 4, "Move NAME X Y"},
    {"Connect", Cmd::Connect, GizmoType::Square, 3, "Connect PRODUCER CONSUMER"},
    {"KeyConnect", Cmd::KeyConnect, GizmoType::Square, 5, "KeyConnect key N down|up CONSUMER"},
    {"Gravity", Cmd::Gravity, GizmoType::Square, 2, "Gravity G"},
    {"Friction", Cmd::Friction, GizmoType::Square, 3, "Friction MU MU2"},
};

constexpr auto kCommands = [] {
  std::array<CommandInfo, std::size(kGizmoKinds) + std::size(kOtherCommands)> all{};
  std::size_t n = 0;
  for (const GizmoKindInfo& k : kGizmoKinds) all[n++] = {k.textCommand, Cmd::Gizmo, k.type, textTokens(k), k.textUsage};
  for (const CommandInfo& c : kOtherCommands) all[n++] = c;
  return all;
}();

const CommandInfo* findCommand(std::string_view word) {
  const std::string lower = toLowerAscii(word);
  for (const CommandInfo& c : kCommands)
    if (toLowerAscii(c.canonical) == lower) return &c;
  return nullptr;
}

class TextReader {
 public:
  TextReader(std::string_view content, Reporter& rep) : content_(content), rep_(rep) {}

  BoardSpec run() {
    std::size_t pos = 0;
    if (const std::optional<DialectReading> r = readDialect(DialectStage::FileStart, DialectInput{.text = content_})) {
      rep_.lenient(r->kind, SourcePos{1, r->column}, r->message);
      pos = static_cast<std::size_t>(r->value);  // DialectOutcome::Skip, the only one of this stage
    }
    while (true) {
      const std::size_t nl = content_.find('\n', pos);
      const std::size_t end = nl == std::string_view::npos ? content_.size() : nl;
      ++line_;
      readLine(content_.substr(pos, end - pos));
      if (nl == std::string_view::npos) break;
      pos = nl + 1;
    }
    return finish();
  }

 private:
  struct Unresolved {
    std::string name;
    SourcePos at;
    std::string message;
    int createdLater = 0;  // the first line after it that created the name, if any
  };

  SourcePos at(const Token& t) const { return SourcePos{line_, t.column}; }

  void readLine(std::string_view text) {
    if (const std::optional<DialectReading> r = readDialect(DialectStage::LineEnd, DialectInput{.text = text})) {
      warn(*r);
      text.remove_suffix(static_cast<std::size_t>(r->value));  // DialectOutcome::StripLineEnd
    }
    const std::optional<std::vector<Token>> tokens =
        tokenizeLine(text, line_, rep_, "the line is longer than 65536 bytes; no board line is that long");
    if (!tokens) return;
    const std::vector<Token>& t = *tokens;
    if (t.empty()) return;
    if (const std::optional<DialectReading> r = readDialect(DialectStage::Line, DialectInput{.tokens = &t})) {
      if (!readOn(*r, t)) return;
    }
    const CommandInfo* cmd = findCommand(t[0].text);
    if (!cmd) {
      if (const Addition* a = findAddition(t[0].text)) {
        ++commandLines_;
        addition(*a, t);
        return;
      }
      unknownCommand(t);
      return;
    }
    ++commandLines_;
    const CommandView view{cmd->canonical, cmd->usage, cmd->tokens, roleOf(cmd->cmd), cmd->type};
    const DialectInput line{.tokens = &t, .command = &view};
    if (const std::optional<DialectReading> r = readDialect(DialectStage::Claim, line)) {
      if (!readOn(*r, t)) return;
    }
    keyword(t[0], cmd->canonical);
    if (t.size() != cmd->tokens) {
      const std::optional<DialectReading> r = readDialect(DialectStage::Values, line);
      if (!r) {
        wrongValueCount(*cmd, t);
        return;
      }
      if (!readOn(*r, t)) return;
    }
    switch (cmd->cmd) {
      case Cmd::Gizmo: createGizmo(*cmd, t); break;
      case Cmd::Ball: createBall(t); break;
      case Cmd::Rotate: rotate(t); break;
      case Cmd::Delete: remove(t); break;
      case Cmd::Move: move(t); break;
      case Cmd::Connect: connect(t); break;
      case Cmd::KeyConnect: keyConnect(t); break;
      case Cmd::Gravity: gravity(t); break;
      case Cmd::Friction: friction(t); break;
    }
  }

  static CommandRole roleOf(Cmd c) {
    switch (c) {
      case Cmd::Gizmo: return CommandRole::Gizmo;
      case Cmd::Ball: return CommandRole::Ball;
      case Cmd::Connect: return CommandRole::Connect;
      default: return CommandRole::Other;
    }
  }

  void warn(const DialectReading& r) { rep_.lenient(r.kind, SourcePos{line_, r.column}, r.message); }

  // What a dialect row says of a whole line (stages Line, Claim, Values): false when the line
  // ends there, true when it is read on as the format.
  bool readOn(const DialectReading& r, const std::vector<Token>& t) {
    switch (r.outcome) {
      case DialectOutcome::IgnoreLine: warn(r); return false;
      case DialectOutcome::AsAddition: addition(*r.addition, t); return false;  // the addition warns
      case DialectOutcome::ReadOn: warn(r); return true;
      case DialectOutcome::ReadOnUnlessConsumerLeftOut:
        if (namesLeftOut(t[2], t[0])) return false;
        warn(r);
        return true;
      case DialectOutcome::LeaveOutName:
        warn(r);
        if (t.size() >= 2) leftOut_[std::string(t[1].text)] = std::string(t[0].text);
        return false;
      case DialectOutcome::LeaveOutNewName:
        warn(r);
        if (t.size() >= 2) leaveOutName(t[1], t[0]);
        return false;
      default: return true;  // the outcomes of the other stages do not come here
    }
  }

  // The format's own errors: a command with fewer values than it has is malformed, and values
  // after a command say something this reader cannot know (no dialect row read them).
  void wrongValueCount(const CommandInfo& cmd, const std::vector<Token>& t) {
    if (t.size() < cmd.tokens) {
      rep_.error(at(t[0]), std::string(cmd.canonical) + " needs " + std::to_string(cmd.tokens - 1) + " value" +
                               (cmd.tokens == 2 ? "" : "s") + " (" + std::string(cmd.usage) + ") but the line has " +
                               std::to_string(t.size() - 1));
      const bool creates = cmd.cmd == Cmd::Gizmo || cmd.cmd == Cmd::Ball;
      if (creates && t.size() >= 2) failed_.insert(std::string(t[1].text));
      return;
    }
    const Token& extra = t[cmd.tokens];
    rep_.error(at(extra), "unexpected " + quote(extra.text) +
                              " after the end of the command: " + std::string(cmd.usage) + " takes " +
                              std::to_string(cmd.tokens - 1) + " value" + (cmd.tokens == 2 ? "" : "s") +
                              (extra.text[0] == '#' ? " (comments must be on a line of their own)" : ""));
  }

  // A keyword of the format that the reader matched without regard to case.
  void keyword(const Token& t, std::string_view canonical) {
    if (const std::optional<DialectReading> r =
            readDialect(DialectStage::Keyword, DialectInput{.token = &t, .keyword = canonical}))
      warn(*r);
  }

  static DialectInput word(const Token& t) { return DialectInput{.token = &t}; }

  // A line whose first word is no command of the format, nor another program's addition that
  // this reader knows: left out, with one warning per word and a count. The name after it, when
  // it is not one the board has, is taken for what the line would create, and the commands that
  // name it are left out too. A file with no line of the format at all is no board (finish).
  void unknownCommand(const std::vector<Token>& t) {
    if (!firstUnknown_) firstUnknown_ = Unknown{std::string(t[0].text), at(t[0])};
    const bool names = t.size() >= 2 && !edits_.find(std::string(t[1].text)) &&
                       !leftOut_.count(std::string(t[1].text)) && nameProblem(t[1].text).empty();
    rep_.lenient("unknown-command:" + toLowerAscii(t[0].text), at(t[0]),
                 quote(t[0].text) +
                     " is not a command of the Gizmoball format (Square, Circle, Triangle, "
                     "LeftFlipper, RightFlipper, Absorber, Ball, Rotate, Delete, Move, Connect, KeyConnect, Gravity, "
                     "Friction) nor another program's that this reader knows; the line is left out" +
                     (names ? ", and so are the commands that name " + quote(t[1].text) : std::string()));
    if (names) leftOut_[std::string(t[1].text)] = std::string(t[0].text);
  }

  // What a left-out line would have created: later commands that name it are left out.
  void leaveOutName(const Token& name, const Token& command) {
    const std::string written(name.text);
    if (edits_.find(written)) return;  // an object of that name exists; the line does not replace it
    leftOut_[written] = std::string(command.text);
  }

  bool whole(const Token& t, const std::string& what, long long& out) {
    if (const std::optional<DialectReading> r = readDialect(DialectStage::Whole, word(t))) {
      warn(*r);
      out = r->value;  // DialectOutcome::UseValue
      return true;
    }
    const Whole w = parseWhole(t.text, what);
    if (!w.ok) {
      rep_.error(at(t), w.problem);
      return false;
    }
    out = w.value;
    return true;
  }

  bool decimal(const Token& t, const std::string& what, double& out) {
    const Number n = parseDecimal(t.text, what);
    if (!n.ok) {
      rep_.error(at(t), n.problem);
      return false;
    }
    out = n.value;
    return true;
  }

  std::string kindOf(const Ref& r) const {
    return r.ball ? std::string("ball") : std::string(gizmoTypeWord(edits_.gizmo(r).type));
  }

  // The name an object written `written` gets on the board: the same when it is a valid name not
  // yet taken; else one that is (invalid characters become '_', a taken one gains _2, _3, …),
  // with a warning. Empty when the name cannot be used at all (reported).
  std::string newName(const Token& t, const std::string& what) {
    const std::string written(t.text);
    if (written == kOuterWallsName) {
      rep_.error(at(t), "the name OuterWalls is reserved for the outer walls");
      failed_.insert(written);
      return {};
    }
    std::string base = written;
    const bool invalid = !nameProblem(written).empty();
    if (invalid)
      for (char& c : base)
        if (!nameProblem(std::string_view(&c, 1)).empty()) c = '_';
    std::string name = base;
    for (int k = 2; edits_.taken(name) || name == kOuterWallsName; ++k) name = base + "_" + std::to_string(k);
    if (invalid)
      rep_.lenient("name-characters", at(t),
                   quote(written) + " is not a standard name (names use only letters, digits and _); the " + what +
                       " is named " + quote(name) + " (later commands that name " + quote(written) + " mean it)");
    else if (name != written) {
      const Ref* r = edits_.find(written);
      rep_.lenient("name-twice", at(t),
                   "the name " + quote(written) + " is already used" +
                       (r ? " by the " + kindOf(*r) + " created on line " + std::to_string(r->line) : std::string()) +
                       "; this " + what + " is named " + quote(name) + " (later commands that name " + quote(written) +
                       " mean it)");
    }
    return name;
  }

  // What the reader keeps about a name besides the board (edits_) when an object takes it.
  void created(const std::string& written) {
    leftOut_.erase(written);
    // Unknown-name errors about this name learn that it is created later.
    if (const auto it = pending_.find(written); it != pending_.end()) {
      for (const std::size_t i : it->second) unresolved_[i].createdLater = line_;
      pending_.erase(it);
    }
  }

  // A command another program added: the gizmo it creates, or the line itself, is left out.
  void addition(const Addition& a, const std::vector<Token>& t) {
    const std::string word(t[0].text);
    switch (a.kind) {
      case AdditionKind::Gizmo:
        rep_.lenient("addition:" + toLowerAscii(word), at(t[0]),
                     quote(word) + " (" + std::string(a.what) + ", from " + std::string(a.program) +
                         ") is not a gizmo this simulator knows; it is left out" +
                         (t.size() >= 2 ? ", and so are the commands that name " + quote(t[1].text) : std::string()));
        if (t.size() >= 2) {
          const std::string written(t[1].text);
          if (const Ref* r = edits_.find(written); r && !r->ball) {
            // A gizmo of the same name exists; the addition does not replace it.
          } else {
            leftOut_[written] = word;
          }
        }
        return;
      case AdditionKind::Decoration:
        rep_.lenient("addition:" + toLowerAscii(word), at(t[0]),
                     quote(word) + " lines (" + std::string(a.what) + ", from " + std::string(a.program) +
                         ") do not change how the board plays; ignored");
        return;
      case AdditionKind::Input:
        rep_.lenient("addition:" + toLowerAscii(word), at(t[0]),
                     quote(word) + " (" + std::string(a.what) + ", from " + std::string(a.program) +
                         ") is an input this simulator does not have; the line is ignored");
        return;
    }
  }

  // A command that names what an addition created: dropped, with one warning per kind.
  bool namesLeftOut(const Token& name, const Token& command) {
    const auto it = leftOut_.find(std::string(name.text));
    if (it == leftOut_.end()) return false;
    rep_.lenient("names-left-out", at(command),
                 quote(command.text) + " names " + quote(name.text) + ", the " + quote(it->second) +
                     " that is left out; the command is ignored");
    return true;
  }

  // A gizmo coordinate: a whole number.
  bool cell(const Token& t, const std::string& what, long long& out) {
    if (const std::optional<DialectReading> r = readDialect(DialectStage::Cell, word(t))) {
      warn(*r);
      out = r->value;  // DialectOutcome::UseValue
      return true;
    }
    return whole(t, what, out);
  }

  void createGizmo(const CommandInfo& cmd, const std::vector<Token>& t) {
    const std::string written(t[1].text);
    const std::string name = newName(t[1], gizmoTypeWord(cmd.type));
    bool ok = !name.empty();
    const bool nameOk = ok;
    GizmoSpec g;
    g.type = cmd.type;
    g.name = name;
    g.where = at(t[0]);
    long long v[4] = {0, 0, 0, 0};
    static const char* whats[] = {"the x coordinate", "the y coordinate", "the lower-right x coordinate",
                                  "the lower-right y coordinate"};
    static const char* exitWhats[] = {"the x coordinate", "the y coordinate", "the exit's x coordinate",
                                      "the exit's y coordinate"};
    // After its cell, a kind's line gives its lower-right corner (a kind sized by its line) or its
    // exit's cell (kinds/STEM.hpp: side 0, exitCell).
    const bool sized = sizedByLine(cmd.type), exitCell = gizmoKind(cmd.type).exitCell;
    const std::size_t count = cmd.tokens - 2;
    for (std::size_t i = 0; i < count; ++i) ok = cell(t[2 + i], exitCell ? exitWhats[i] : whats[i], v[i]) && ok;
    if (ok && sized) {
      const std::string corner = std::string("the ") + gizmoTypeWord(cmd.type) + "'s lower-right corner must lie ";
      if (v[2] <= v[0]) {
        rep_.error(at(t[4]), corner + "right of its upper-left corner (X2 = " + std::to_string(v[2]) +
                                 " is not more than X1 = " + std::to_string(v[0]) + ")");
        ok = false;
      } else if (v[3] <= v[1]) {
        rep_.error(at(t[5]), corner + "below its upper-left corner (Y2 = " + std::to_string(v[3]) +
                                 " is not more than Y1 = " + std::to_string(v[1]) + ")");
        ok = false;
      }
    }
    if (!ok) {
      if (nameOk) failed_.insert(written);
      return;
    }
    g.x = static_cast<int>(v[0]);
    g.y = static_cast<int>(v[1]);
    if (sized) {
      g.width = static_cast<int>(v[2] - v[0]);
      g.height = static_cast<int>(v[3] - v[1]);
    } else {
      g.width = g.height = ownSide(cmd.type);
    }
    if (exitCell) {
      g.exitX = static_cast<int>(v[2]);
      g.exitY = static_cast<int>(v[3]);
    }
    edits_.addGizmo(written, std::move(g), line_);
    created(written);
  }

  void createBall(const std::vector<Token>& t) {
    const std::string written(t[1].text);
    const std::string name = newName(t[1], "ball");
    bool ok = !name.empty();
    const bool nameOk = ok;
    BallSpec b;
    b.name = name;
    b.where = at(t[0]);
    ok = decimal(t[2], "the x coordinate", b.x) && ok;
    ok = decimal(t[3], "the y coordinate", b.y) && ok;
    ok = decimal(t[4], "the x velocity", b.vx) && ok;
    ok = decimal(t[5], "the y velocity", b.vy) && ok;
    if (!ok) {
      if (nameOk) failed_.insert(written);
      return;
    }
    edits_.addBall(written, std::move(b), line_);
    created(written);
  }

  // The live object written t, or null (the error is reported, or deferred so that it can say
  // whether the name is created later).
  const Ref* lookup(const Token& t, const std::string& what) {
    const std::string written(t.text);
    if (const Ref* r = edits_.find(written)) return r;
    if (!failed_.count(written)) {
      std::string message = "there is no " + what + " named " + quote(written);
      if (toLowerAscii(written) == "outerwalls") message += " (the outer walls are named OuterWalls)";
      pending_[written].push_back(unresolved_.size());
      unresolved_.push_back(Unresolved{written, at(t), std::move(message), 0});
    }
    return nullptr;
  }

  void rotate(const std::vector<Token>& t) {
    if (namesLeftOut(t[1], t[0])) return;
    const Ref* r = lookup(t[1], "gizmo");
    if (!r) return;
    if (r->ball) {
      rep_.error(at(t[1]), "ball " + quote(t[1].text) + " cannot be rotated: only gizmos turn");
      return;
    }
    GizmoSpec& g = edits_.gizmo(*r);
    if (sizedByLine(g.type)) {
      rep_.error(at(t[1]), gizmoTypeWord(g.type) + (" " + quote(t[1].text)) + " cannot be rotated");
      return;
    }
    g.orientation = (g.orientation + 90) % 360;
    g.where = at(t[0]);
  }

  void remove(const std::vector<Token>& t) {
    if (namesLeftOut(t[1], t[0])) {
      leftOut_.erase(std::string(t[1].text));
      return;
    }
    if (!lookup(t[1], "gizmo or ball")) return;
    edits_.remove(std::string(t[1].text));
  }

  void move(const std::vector<Token>& t) {
    if (namesLeftOut(t[1], t[0])) return;
    const Ref* r = lookup(t[1], "gizmo or ball");
    if (!r) return;
    if (r->ball) {
      double x = 0, y = 0;
      bool ok = decimal(t[2], "the x coordinate", x);
      ok = decimal(t[3], "the y coordinate", y) && ok;
      if (!ok) return;
      BallSpec& b = edits_.ball(*r);
      b.x = x;
      b.y = y;
      b.where = at(t[0]);
    } else {
      long long x = 0, y = 0;
      bool ok = cell(t[2], "the x coordinate", x);
      ok = cell(t[3], "the y coordinate", y) && ok;
      if (!ok) return;
      GizmoSpec& g = edits_.gizmo(*r);
      g.x = static_cast<int>(x);
      g.y = static_cast<int>(y);
      g.where = at(t[0]);
    }
  }

  // A connection's end: its board name, "" when it names nothing now (the connection is then
  // deferred to the end of the file), or nullopt when it is wrong (reported).
  std::optional<std::string> end(const Token& t, bool source) {
    const std::string written(t.text);
    if (written == kOuterWallsName) {
      if (source) return written;
      rep_.error(at(t), "the outer walls cannot be a connection target: they have no action");
      return std::nullopt;
    }
    if (const Ref* r = edits_.find(written)) return r->name;
    if (failed_.count(written)) return std::nullopt;
    return std::string();
  }

  void connect(const std::vector<Token>& t) {
    if (namesLeftOut(t[1], t[0]) || namesLeftOut(t[2], t[0])) return;
    const std::optional<std::string> source = end(t[1], true), target = end(t[2], false);
    if (!source || !target) return;
    if (source->empty() || target->empty()) {
      if (const std::optional<DialectReading> later = laterName()) {
        deferred_.push_back(Deferred{std::string(t[1].text), std::string(t[2].text), 0, {}, at(t[0]), false, *later});
        return;
      }
      if (source->empty()) lookup(t[1], "gizmo");
      if (target->empty()) lookup(t[2], "gizmo");
      return;
    }
    addConnect(ConnectSpec{*source, *target, at(t[0])});
  }

  // A connection that names what does not exist yet: what the dialects table says of it
  // (DialectOutcome::MakeAtEnd), else it is an error of file order.
  std::optional<DialectReading> laterName() { return readDialect(DialectStage::LaterName, DialectInput{}); }

  void addConnect(ConnectSpec c) {
    const SourcePos where = c.where;
    if (const ConnectSpec* first = edits_.connect(std::move(c))) repeated(where, first->where);
  }

  void repeated(SourcePos where, SourcePos first) {
    rep_.lenient(
        "duplicate-connection", where,
        "this connection repeats the one on line " + std::to_string(first.line) + "; the repetition is ignored");
  }

  // The key code of a KeyConnect: a whole number, or a key's name as programs write it (Java's,
  // JavaFX's and the browsers' names, key_names.cpp). A word that names no key this reader knows
  // leaves the connection out (`unknownKey`), since no key of ours would trigger it.
  bool keyCode(const Token& t, long long& key, bool& unknownKey) {
    if (!parseDecimal(t.text, "the key code").ok) {
      if (const std::optional<DialectReading> r = readDialect(DialectStage::Key, word(t))) {
        warn(*r);
        if (r->outcome == DialectOutcome::UseValue) {
          key = r->value;
          return true;
        }
        unknownKey = true;  // DialectOutcome::LeaveOutConnection
        return false;
      }
    }
    if (!whole(t, "the key code", key)) return false;
    if (std::string p = keyCodeProblem(key); !p.empty()) {
      rep_.error(at(t), p);
      return false;
    }
    return true;
  }

  void keyConnect(const std::vector<Token>& t) {
    bool ok = true;
    if (toLowerAscii(t[1].text) != "key") {
      rep_.error(at(t[1]), "expected the word 'key' after KeyConnect, not " + quote(t[1].text));
      ok = false;
    } else {
      keyword(t[1], "key");
    }
    long long key = 0;
    bool unknownKey = false;
    ok = keyCode(t[2], key, unknownKey) && ok;
    std::vector<KeyDirection> directions;
    const std::string dir = toLowerAscii(t[3].text);
    if (dir == "down" || dir == "up") {
      directions.push_back(dir == "down" ? KeyDirection::Down : KeyDirection::Up);
      keyword(t[3], dir);
    } else if (const std::optional<DialectReading> r = readDialect(DialectStage::Direction, word(t[3]))) {
      directions = {KeyDirection::Down, KeyDirection::Up};  // DialectOutcome::DownAndUp
      warn(*r);
    } else {
      rep_.error(at(t[3]), "the key direction must be down or up, not " + quote(t[3].text));
      ok = false;
    }
    if (unknownKey) return;  // left out, with its warning
    if (namesLeftOut(t[4], t[0])) return;
    const std::optional<std::string> target = end(t[4], false);
    if (!ok || !target) return;
    std::optional<DialectReading> later;
    if (target->empty() && !(later = laterName())) {
      lookup(t[4], "gizmo");
      return;
    }
    for (const KeyDirection d : directions) {
      if (target->empty())
        deferred_.push_back(Deferred{{}, std::string(t[4].text), static_cast<int>(key), d, at(t[0]), true, *later});
      else addKeyConnect(KeyConnectSpec{static_cast<int>(key), d, *target, at(t[0])});
    }
  }

  void addKeyConnect(KeyConnectSpec k) {
    const SourcePos where = k.where;
    if (const KeyConnectSpec* first = edits_.keyConnect(std::move(k))) repeated(where, first->where);
  }

  // Connections that named something not there at their line (DialectOutcome::MakeAtEnd): made
  // when it exists at the end of the file, else ignored.
  void resolveDeferred() {
    for (Deferred& d : deferred_) {
      std::string missing;
      std::string source = d.source, target;
      if (!d.key) {
        if (source != kOuterWallsName) {
          if (const Ref* r = edits_.find(source); r && !r->ball) source = r->name;
          else missing = d.source;
        }
      }
      if (const Ref* r = edits_.find(d.target); r && !r->ball) target = r->name;
      else if (missing.empty()) missing = d.target;
      if (!missing.empty()) {
        rep_.lenient("connection-unknown", d.where,
                     "there is no gizmo named " + quote(missing) + " in the file; the connection is ignored");
        continue;
      }
      rep_.lenient(d.later.kind, d.where, d.later.message);
      if (d.key) addKeyConnect(KeyConnectSpec{d.code, d.direction, target, d.where});
      else addConnect(ConnectSpec{source, target, d.where});
    }
  }

  void gravity(const std::vector<Token>& t) {
    double g = 0;
    if (!decimal(t[1], "gravity", g)) return;
    if (std::string p = gravityProblem(g); !p.empty()) {
      rep_.error(at(t[1]), p);
      return;
    }
    gravity_ = g;
  }

  void friction(const std::vector<Token>& t) {
    double mu = 0, mu2 = 0;
    bool ok = decimal(t[1], "friction mu", mu);
    ok = decimal(t[2], "friction mu2", mu2) && ok;
    if (!ok) return;
    if (std::string p = frictionProblem("mu", mu); !p.empty()) {
      rep_.error(at(t[1]), p);
      ok = false;
    }
    if (std::string p = frictionProblem("mu2", mu2); !p.empty()) {
      rep_.error(at(t[2]), p);
      ok = false;
    }
    if (!ok) return;
    mu_ = mu;
    mu2_ = mu2;
  }

  BoardSpec finish() {
    if (commandLines_ == 0 && firstUnknown_) {
      rep_.error(firstUnknown_->at,
                 "no line of this file is a command of the Gizmoball format (the first line's "
                 "word is " +
                     quote(firstUnknown_->word) + "); it does not look like a Gizmoball board");
      return BoardSpec{};
    }
    for (Unresolved& u : unresolved_) {
      if (u.createdLater > 0)
        u.message += " at this point (it is created later, on line " + std::to_string(u.createdLater) +
                     "; commands take effect in file order)";
      rep_.error(u.at, std::move(u.message));
    }
    resolveDeferred();
    BoardSpec board;
    board.gravity = gravity_;
    board.mu = mu_;
    board.mu2 = mu2_;
    edits_.takeInto(board);
    if (!rep_.failed()) repairPlacements(board, rep_);
    for (SpecProblem& p : checkBoardSpec(board)) rep_.error(p.where, std::move(p.message));
    return board;
  }

  struct Deferred {
    std::string source;  // empty for a KeyConnect
    std::string target;
    int code = 0;
    KeyDirection direction = KeyDirection::Down;
    SourcePos where;
    bool key = false;
    DialectReading later;  // the dialect row that deferred it: its warning
  };

  std::string_view content_;
  Reporter& rep_;
  int line_ = 0;

  BoardEdits edits_;                                                   // what the file creates, as later lines edit it
  std::unordered_map<std::string, std::string> leftOut_;               // names of left-out additions → their word
  std::unordered_map<std::string, std::vector<std::size_t>> pending_;  // unresolved_ entries by name
  std::unordered_set<std::string> failed_;  // names whose statement failed: no second error about them
  struct Unknown {
    std::string word;
    SourcePos at;
  };
  std::optional<Unknown> firstUnknown_;  // the first line that is no command this reader knows
  std::size_t commandLines_ = 0;         // lines that are commands of the format
  std::vector<Unresolved> unresolved_;
  std::vector<Deferred> deferred_;

  double gravity_ = 25.0;
  double mu_ = 0.025;
  double mu2_ = 0.025;
};

}  // namespace

ReadResult readTextBoard(std::string_view content, const std::string& fileName) {
  Reporter rep(fileName);
  if (content.size() > kMaxFileBytes) fail(fileName, {}, "the file is larger than 16 MiB, the limit for board files");
  if (const std::optional<std::string> foreign = foreignFormat(content)) fail(fileName, {}, *foreign);
  BoardSpec board = TextReader(content, rep).run();
  rep.throwIfFailed();
  return ReadResult{std::move(board), rep.warnings()};
}

}  // namespace gizmo::io
