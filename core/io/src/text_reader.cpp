// The text board format: one command a line, executed in file order (docs/board-files.md).
#include "gizmo/io/text_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <map>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "board_repair.hpp"
#include "edited_list.hpp"
#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "key_names.hpp"
#include "parse_util.hpp"
#include "foreign_format.hpp"
#include "text_additions.hpp"

namespace gizmo::io {
namespace {

using namespace detail;

enum class Cmd { Gizmo, Absorber, Ball, Rotate, Delete, Move, Connect, KeyConnect, Gravity, Friction };

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
  for (const GizmoKindInfo& k : kGizmoKinds)
    all[n++] = {k.textCommand, k.type == GizmoType::Absorber ? Cmd::Absorber : Cmd::Gizmo, k.type, textTokens(k),
                k.textUsage};
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
    if (startsWithBom(content_)) {
      rep_.lenient("bom", SourcePos{1, 1}, "the UTF-8 byte order mark at the start of the file is ignored");
      pos = kBom.size();
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
  struct Ref {
    bool ball = false;
    std::size_t index = 0;
    int line = 0;      // where it was created
    std::string name;  // its name on the board (the file may write it otherwise)
  };
  struct Unresolved {
    std::string name;
    SourcePos at;
    std::string message;
    int createdLater = 0;  // the first line after it that created the name, if any
  };

  SourcePos at(const Token& t) const { return SourcePos{line_, t.column}; }

  void readLine(std::string_view text) {
    std::size_t crs = 0;
    while (!text.empty() && text.back() == '\r') text.remove_suffix(1), ++crs;
    if (crs == 1)
      rep_.lenient("crlf", SourcePos{line_, static_cast<int>(text.size()) + 1},
                   "Windows line ending (CR LF) read as a plain line end");
    else if (crs > 1)
      rep_.lenient("crcrlf", SourcePos{line_, static_cast<int>(text.size()) + 1},
                   "line ending CR CR LF (a CR LF file saved again through a CR LF conversion) read as a plain "
                   "line end");
    const std::optional<std::vector<Token>> tokens =
        tokenizeLine(text, line_, rep_, "the line is longer than 65536 bytes; no board line is that long");
    if (!tokens) return;
    const std::vector<Token>& t = *tokens;
    if (t.empty()) return;
    if (t[0].text[0] == '#') {
      rep_.lenient("comment", at(t[0]), "'#' comment lines are not part of the standard format; ignored");
      return;
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
    // d-g-n/CS308-GizmoBall's saver names every gizmo by its cell, X_Y; its spinner is another
    // gizmo than NiklavsM/Gizmoball's of the same spelling, which the core simulates.
    if (cmd->type == GizmoType::Spinner && cmd->cmd == Cmd::Gizmo && t.size() == 4 &&
        t[1].text == std::string(t[2].text) + "_" + std::string(t[3].text)) {
      addition(dgnSpinner(), t);
      return;
    }
    if (t[0].text != cmd->canonical) keywordCase(t[0], cmd->canonical);
    if (cmd->cmd == Cmd::Absorber && t.size() == 4) {
      // CraigR973/Gizmoball's later saver writes an absorber's upper-left corner only.
      rep_.lenient("absorber-corner", at(t[0]),
                   "this absorber has no lower-right corner (Absorber NAME X1 Y1 X2 Y2); it is left out, and so are "
                   "the commands that name " + quote(t[1].text));
      leftOut_[std::string(t[1].text)] = std::string(t[0].text);
      return;
    }
    const bool creates = cmd->cmd == Cmd::Gizmo || cmd->cmd == Cmd::Absorber || cmd->cmd == Cmd::Ball;
    if (t.size() < cmd->tokens) {
      // The format's own commands have their values, and a line short of them is malformed. A
      // gizmo that other programs added is spelled by each its own way: with fewer values (a
      // portal without its exit) it is another program's, left out with what names it.
      if (cmd->cmd == Cmd::Gizmo && !isStandardKind(cmd->type)) {
        rep_.lenient("too-few-values:" + toLowerAscii(cmd->canonical), at(t[0]),
                     std::string(cmd->canonical) + " takes " + std::to_string(cmd->tokens - 1) + " values (" +
                         std::string(cmd->usage) + ") but the line has " + std::to_string(t.size() - 1) +
                         "; it is another program's " + std::string(gizmoTypeWord(cmd->type)) +
                         ", left out" + (t.size() >= 2 ? ", and so are the commands that name " + quote(t[1].text)
                                                        : std::string()));
        if (t.size() >= 2) leaveOutName(t[1], t[0]);
        return;
      }
      rep_.error(at(t[0]), std::string(cmd->canonical) + " needs " + std::to_string(cmd->tokens - 1) + " value" +
                               (cmd->tokens == 2 ? "" : "s") + " (" + std::string(cmd->usage) + ") but the line has " +
                               std::to_string(t.size() - 1));
      if (creates && t.size() >= 2) failed_.insert(std::string(t[1].text));
      return;
    }
    if (t.size() == cmd->tokens + 1 && (cmd->cmd == Cmd::Gizmo || cmd->cmd == Cmd::Ball) && allLetters(t.back().text)) {
      rep_.lenient("trailing-word", at(t.back()),
                   "the word " + quote(t.back().text) + " after " + std::string(cmd->usage) +
                       " is ignored (rgallagher27/308gizmoball writes a flipper's side as true/false there, "
                       "LukeBev/GizmoBall a colour; their readers do not use it)");
    } else if (t.size() == cmd->tokens + 1 && cmd->cmd == Cmd::Connect && allLetters(t.back().text)) {
      if (namesLeftOut(t[2], t[0])) return;
      rep_.lenient("connect-action", at(t.back()),
                   "the action word " + quote(t.back().text) +
                       " (MIT 6.170's 'Connect PRODUCER CONSUMER ACTION') is ignored; the consumer performs its own "
                       "action");
    } else if (t.size() > cmd->tokens && creates) {
      // Values after what places a gizmo or a ball are its attributes in another program (a
      // circle's radius, a size, a colour) or a comment: it is placed from its own values.
      const Token& extra = t[cmd->tokens];
      rep_.lenient("extra-values:" + toLowerAscii(cmd->canonical), at(extra),
                   "what follows " + std::string(cmd->usage) + " (" + std::to_string(t.size() - cmd->tokens) +
                       " more, from " + quote(extra.text) + ") is ignored" +
                       (extra.text[0] == '#' ? " (the standard format has comments on lines of their own)"
                                             : "; it is placed from its own values"));
    } else if (t.size() > cmd->tokens) {
      // After any other command, more values say something this reader cannot know.
      const Token& extra = t[cmd->tokens];
      rep_.error(at(extra), "unexpected " + quote(extra.text) + " after the end of the command: " +
                                std::string(cmd->usage) + " takes " + std::to_string(cmd->tokens - 1) + " value" +
                                (cmd->tokens == 2 ? "" : "s") +
                                (extra.text[0] == '#' ? " (comments must be on a line of their own)" : ""));
      return;
    }
    switch (cmd->cmd) {
      case Cmd::Gizmo:
      case Cmd::Absorber: createGizmo(*cmd, t); break;
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

  // A line whose first word is no command of the format, nor another program's addition that
  // this reader knows: left out, with one warning per word and a count. The name after it, when
  // it is not one the board has, is taken for what the line would create, and the commands that
  // name it are left out too. A file with no line of the format at all is no board (finish).
  void unknownCommand(const std::vector<Token>& t) {
    if (!firstUnknown_) firstUnknown_ = Unknown{std::string(t[0].text), at(t[0])};
    const bool names = t.size() >= 2 && !names_.count(std::string(t[1].text)) &&
                       !leftOut_.count(std::string(t[1].text)) && nameProblem(t[1].text).empty();
    rep_.lenient("unknown-command:" + toLowerAscii(t[0].text), at(t[0]),
                 quote(t[0].text) + " is not a command of the Gizmoball format (Square, Circle, Triangle, "
                 "LeftFlipper, RightFlipper, Absorber, Ball, Rotate, Delete, Move, Connect, KeyConnect, Gravity, "
                 "Friction) nor another program's that this reader knows; the line is left out" +
                     (names ? ", and so are the commands that name " + quote(t[1].text) : std::string()));
    if (names) leftOut_[std::string(t[1].text)] = std::string(t[0].text);
  }

  // What a left-out line would have created: later commands that name it are left out.
  void leaveOutName(const Token& name, const Token& command) {
    const std::string written(name.text);
    if (names_.count(written)) return;  // an object of that name exists; the line does not replace it
    leftOut_[written] = std::string(command.text);
  }

  void keywordCase(const Token& t, std::string_view canonical) {
    rep_.lenient("keyword-case", at(t),
                 quote(t.text) + " is written " + quote(canonical) +
                     " in the standard format; keywords are read without regard to case");
  }

  bool whole(const Token& t, const std::string& what, long long& out) {
    const Whole w = parseWhole(t.text, what);
    if (!w.ok) {
      rep_.error(at(t), w.problem);
      return false;
    }
    if (w.writtenAsDecimal)
      rep_.lenient("integral-decimal", at(t),
                   quote(t.text) + " is read as the whole number " + std::to_string(w.value) +
                       " (the standard format writes whole numbers here)");
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
    return r.ball ? std::string("ball") : std::string(gizmoTypeWord(gizmos_[r.index].type));
  }

  // A key's name rather than a malformed number: it starts with a letter.
  static bool looksLikeWord(std::string_view s) {
    return !s.empty() && ((s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z'));
  }

  static bool allLetters(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); });
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
    for (int k = 2; taken_.count(name) || name == kOuterWallsName; ++k) name = base + "_" + std::to_string(k);
    if (invalid)
      rep_.lenient("name-characters", at(t),
                   quote(written) + " is not a standard name (names use only letters, digits and _); the " + what +
                       " is named " + quote(name) + " (later commands that name " + quote(written) + " mean it)");
    else if (name != written) {
      const auto it = names_.find(written);
      rep_.lenient("name-twice", at(t),
                   "the name " + quote(written) + " is already used" +
                       (it != names_.end() ? " by the " + kindOf(it->second) + " created on line " +
                                                 std::to_string(it->second.line)
                                           : std::string()) +
                       "; this " + what + " is named " + quote(name) + " (later commands that name " + quote(written) +
                       " mean it)");
    }
    return name;
  }

  void created(const std::string& written, const std::string& name, Ref ref) {
    ref.line = line_;
    ref.name = name;
    names_[written] = ref;
    taken_.insert(name);
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
          if (const auto it = names_.find(written); it != names_.end() && !it->second.ball) {
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

  // A gizmo coordinate: a whole number; a decimal with a fraction is read as the cell it starts in.
  bool cell(const Token& t, const std::string& what, long long& out) {
    const Whole w = parseWhole(t.text, what);
    if (!w.ok) {
      const Number n = parseDecimal(t.text, what);
      if (n.ok && std::fabs(n.value) <= kMaxWhole) {
        out = static_cast<long long>(std::floor(n.value));
        rep_.lenient("fractional-cell", at(t),
                     quote(t.text) + " is not a whole number; the gizmo is placed in the cell it starts in, " +
                         std::to_string(out));
        return true;
      }
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
    const std::size_t count = cmd.tokens - 2;
    for (std::size_t i = 0; i < count; ++i)
      ok = cell(t[2 + i], cmd.type == GizmoType::Portal ? exitWhats[i] : whats[i], v[i]) && ok;
    if (ok && cmd.cmd == Cmd::Absorber) {
      if (v[2] <= v[0]) {
        rep_.error(at(t[4]), "the absorber's lower-right corner must lie right of its upper-left corner (X2 = " +
                                 std::to_string(v[2]) + " is not more than X1 = " + std::to_string(v[0]) + ")");
        ok = false;
      } else if (v[3] <= v[1]) {
        rep_.error(at(t[5]), "the absorber's lower-right corner must lie below its upper-left corner (Y2 = " +
                                 std::to_string(v[3]) + " is not more than Y1 = " + std::to_string(v[1]) + ")");
        ok = false;
      }
    }
    if (!ok) {
      if (nameOk) failed_.insert(written);
      return;
    }
    g.x = static_cast<int>(v[0]);
    g.y = static_cast<int>(v[1]);
    if (cmd.cmd == Cmd::Absorber) {
      g.width = static_cast<int>(v[2] - v[0]);
      g.height = static_cast<int>(v[3] - v[1]);
    } else if (ownSide(cmd.type) == 2) {
      g.width = g.height = 2;
    } else if (cmd.type == GizmoType::Portal) {
      g.exitX = static_cast<int>(v[2]);
      g.exitY = static_cast<int>(v[3]);
    }
    created(written, name, Ref{false, gizmos_.add(std::move(g)), 0, {}});
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
    created(written, name, Ref{true, balls_.add(std::move(b)), 0, {}});
  }

  // The live object written t, or null (the error is reported, or deferred so that it can say
  // whether the name is created later).
  const Ref* lookup(const Token& t, const std::string& what) {
    const std::string written(t.text);
    if (const auto it = names_.find(written); it != names_.end()) return &it->second;
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
    GizmoSpec& g = gizmos_[r->index];
    if (g.type == GizmoType::Absorber) {
      rep_.error(at(t[1]), "absorber " + quote(t[1].text) + " cannot be rotated");
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
    const Ref* r = lookup(t[1], "gizmo or ball");
    if (!r) return;
    const std::string name = r->name;
    if (r->ball)
      balls_.remove(r->index);
    else
      gizmos_.remove(r->index);
    names_.erase(std::string(t[1].text));
    taken_.erase(name);
    // Its connections go with it.
    if (const auto it = connectionsOf_.find(name); it != connectionsOf_.end()) {
      for (const std::size_t i : it->second)
        if (connections_.remove(i)) connectionIndex_.erase({connections_[i].source, connections_[i].target});
      connectionsOf_.erase(it);
    }
    if (const auto it = keyConnectionsOf_.find(name); it != keyConnectionsOf_.end()) {
      for (const std::size_t i : it->second)
        if (keyConnections_.remove(i)) {
          const KeyConnectSpec& k = keyConnections_[i];
          keyIndex_.erase({k.key, static_cast<int>(k.direction), k.target});
        }
      keyConnectionsOf_.erase(it);
    }
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
      BallSpec& b = balls_[r->index];
      b.x = x;
      b.y = y;
      b.where = at(t[0]);
    } else {
      long long x = 0, y = 0;
      bool ok = cell(t[2], "the x coordinate", x);
      ok = cell(t[3], "the y coordinate", y) && ok;
      if (!ok) return;
      GizmoSpec& g = gizmos_[r->index];
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
    if (const auto it = names_.find(written); it != names_.end()) return it->second.name;
    if (failed_.count(written)) return std::nullopt;
    return std::string();
  }

  void connect(const std::vector<Token>& t) {
    if (namesLeftOut(t[1], t[0]) || namesLeftOut(t[2], t[0])) return;
    const std::optional<std::string> source = end(t[1], true), target = end(t[2], false);
    if (!source || !target) return;
    if (source->empty() || target->empty()) {
      deferred_.push_back(Deferred{std::string(t[1].text), std::string(t[2].text), 0, {}, at(t[0]), false});
      return;
    }
    addConnect(ConnectSpec{*source, *target, at(t[0])});
  }

  void addConnect(ConnectSpec c) {
    const auto [it, inserted] = connectionIndex_.emplace(std::make_pair(c.source, c.target), connections_.size());
    if (!inserted) {
      rep_.lenient("duplicate-connection", c.where,
                   "this connection repeats the one on line " + std::to_string(connections_[it->second].where.line) +
                       "; the repetition is ignored");
      return;
    }
    connectionsOf_[c.source].push_back(connections_.size());
    connectionsOf_[c.target].push_back(connections_.size());
    connections_.add(std::move(c));
  }

  // The key code of a KeyConnect: a whole number, or a key's name as programs write it (Java's,
  // JavaFX's and the browsers' names, key_names.cpp). A word that names no key this reader knows
  // leaves the connection out (`unknownKey`), since no key of ours would trigger it.
  bool keyCode(const Token& t, long long& key, bool& unknownKey) {
    if (!parseDecimal(t.text, "the key code").ok) {
      if (const std::optional<int> named = keyCodeOfName(t.text)) {
        key = *named;
        rep_.lenient("key-name", at(t),
                     "the key " + quote(t.text) + " is read as the key code " + std::to_string(key) +
                         " (programs write Java's, JavaFX's or the browsers' key names; the standard format writes "
                         "the code)");
        return true;
      }
      if (looksLikeWord(t.text)) {
        unknownKey = true;
        rep_.lenient("key-unknown", at(t),
                     "the key " + quote(t.text) + " is neither a key code nor a key name this reader knows; the "
                     "connection is left out");
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
    } else if (t[1].text != "key") {
      keywordCase(t[1], "key");
    }
    long long key = 0;
    bool unknownKey = false;
    ok = keyCode(t[2], key, unknownKey) && ok;
    std::vector<KeyDirection> directions;
    const std::string dir = toLowerAscii(t[3].text);
    if (dir == "down" || dir == "up") {
      directions.push_back(dir == "down" ? KeyDirection::Down : KeyDirection::Up);
      if (t[3].text != dir) keywordCase(t[3], dir);
    } else if (dir == "ondown" || dir == "change") {
      // Both programs ignore the word and perform the action on the press and on the release.
      directions = {KeyDirection::Down, KeyDirection::Up};
      rep_.lenient("key-direction:" + dir, at(t[3]),
                   quote(t[3].text) + " is read as two connections, down and up: " +
                       (dir == "ondown" ? std::string("ConfuddledPenguin/Gizmoball's reader ignores the word, and "
                                                      "every key it registers acts on the press and on the release")
                                        : std::string("jtax/Gizmoball-WJ2's reader ignores the word, and its key "
                                                      "listener triggers on the press and on the release")));
    } else {
      rep_.error(at(t[3]), "the key direction must be down or up, not " + quote(t[3].text));
      ok = false;
    }
    if (unknownKey) return;  // left out, with its warning
    if (namesLeftOut(t[4], t[0])) return;
    const std::optional<std::string> target = end(t[4], false);
    if (!ok || !target) return;
    for (const KeyDirection d : directions) {
      if (target->empty())
        deferred_.push_back(Deferred{{}, std::string(t[4].text), static_cast<int>(key), d, at(t[0]), true});
      else
        addKeyConnect(KeyConnectSpec{static_cast<int>(key), d, *target, at(t[0])});
    }
  }

  void addKeyConnect(KeyConnectSpec k) {
    const auto [it, inserted] =
        keyIndex_.emplace(std::make_tuple(k.key, static_cast<int>(k.direction), k.target), keyConnections_.size());
    if (!inserted) {
      rep_.lenient("duplicate-connection", k.where,
                   "this connection repeats the one on line " +
                       std::to_string(keyConnections_[it->second].where.line) + "; the repetition is ignored");
      return;
    }
    keyConnectionsOf_[k.target].push_back(keyConnections_.size());
    keyConnections_.add(std::move(k));
  }

  // Connections that named something not there at their line: made when it exists at the end of
  // the file (a saver that wrote connections before gizmos), else ignored.
  void resolveDeferred() {
    for (Deferred& d : deferred_) {
      std::string missing;
      std::string source = d.source, target;
      if (!d.key) {
        if (source != kOuterWallsName) {
          if (const auto it = names_.find(source); it != names_.end() && !it->second.ball) source = it->second.name;
          else missing = d.source;
        }
      }
      if (const auto it = names_.find(d.target); it != names_.end() && !it->second.ball) target = it->second.name;
      else if (missing.empty()) missing = d.target;
      if (!missing.empty()) {
        rep_.lenient("connection-unknown", d.where,
                     "there is no gizmo named " + quote(missing) + " in the file; the connection is ignored");
        continue;
      }
      rep_.lenient("connection-later", d.where,
                   "this connection names a gizmo that is created further down; it is made at the end of the file");
      if (d.key)
        addKeyConnect(KeyConnectSpec{d.code, d.direction, target, d.where});
      else
        addConnect(ConnectSpec{source, target, d.where});
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
      rep_.error(firstUnknown_->at, "no line of this file is a command of the Gizmoball format (the first line's "
                                    "word is " + quote(firstUnknown_->word) +
                                        "); it does not look like a Gizmoball board");
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
    board.gizmos = gizmos_.takeLive();
    board.balls = balls_.takeLive();
    board.connections = connections_.takeLive();
    board.keyConnections = keyConnections_.takeLive();
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
  };

  std::string_view content_;
  Reporter& rep_;
  int line_ = 0;

  EditedList<GizmoSpec> gizmos_;
  EditedList<BallSpec> balls_;
  std::unordered_map<std::string, Ref> names_;  // live objects by the name the file writes
  std::unordered_set<std::string> taken_;       // the board names of live objects
  std::unordered_map<std::string, std::string> leftOut_;  // names of left-out additions → their word
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

  EditedList<ConnectSpec> connections_;
  std::map<std::pair<std::string, std::string>, std::size_t> connectionIndex_;  // live ones
  std::unordered_map<std::string, std::vector<std::size_t>> connectionsOf_;
  EditedList<KeyConnectSpec> keyConnections_;
  std::map<std::tuple<int, int, std::string>, std::size_t> keyIndex_;
  std::unordered_map<std::string, std::vector<std::size_t>> keyConnectionsOf_;

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
