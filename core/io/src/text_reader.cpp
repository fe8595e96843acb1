// The text board format: one command a line, executed in file order (docs/board-files.md).
#include "gizmo/io/text_reader.hpp"

#include <algorithm>
#include <map>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "gizmo/core/board_spec_check.hpp"
#include "parse_util.hpp"

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

constexpr CommandInfo kCommands[] = {
    {"Square", Cmd::Gizmo, GizmoType::Square, 4, "Square NAME X Y"},
    {"Circle", Cmd::Gizmo, GizmoType::Circle, 4, "Circle NAME X Y"},
    {"Triangle", Cmd::Gizmo, GizmoType::Triangle, 4, "Triangle NAME X Y"},
    {"LeftFlipper", Cmd::Gizmo, GizmoType::LeftFlipper, 4, "LeftFlipper NAME X Y"},
    {"RightFlipper", Cmd::Gizmo, GizmoType::RightFlipper, 4, "RightFlipper NAME X Y"},
    {"Absorber", Cmd::Absorber, GizmoType::Absorber, 6, "Absorber NAME X1 Y1 X2 Y2"},
    {"Ball", Cmd::Ball, GizmoType::Square, 6, "Ball NAME X Y VX VY"},
    {"Rotate", Cmd::Rotate, GizmoType::Square, 2, "Rotate NAME"},
    {"Delete", Cmd::Delete, GizmoType::Square, 2, "Delete NAME"},
    {"Move", Cmd::Move, GizmoType::Square, 4, "Move NAME X Y"},
    {"Connect", Cmd::Connect, GizmoType::Square, 3, "Connect PRODUCER CONSUMER"},
    {"KeyConnect", Cmd::KeyConnect, GizmoType::Square, 5, "KeyConnect key N down|up CONSUMER"},
    {"Gravity", Cmd::Gravity, GizmoType::Square, 2, "Gravity G"},
    {"Friction", Cmd::Friction, GizmoType::Square, 3, "Friction MU MU2"},
};

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
    int line = 0;  // where it was created
  };
  struct Unresolved {
    std::string name;
    SourcePos at;
    std::string message;
    int createdLater = 0;  // the first line after it that created the name, if any
  };

  SourcePos at(const Token& t) const { return SourcePos{line_, t.column}; }

  void readLine(std::string_view text) {
    if (!text.empty() && text.back() == '\r') {
      text.remove_suffix(1);
      rep_.lenient("crlf", SourcePos{line_, static_cast<int>(text.size()) + 1},
                   "Windows line ending (CR LF) read as a plain line end");
    }
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
      rep_.error(at(t[0]), quote(t[0].text) +
                               " is not part of the Gizmoball format; the commands are Square, Circle, Triangle, "
                               "LeftFlipper, RightFlipper, Absorber, Ball, Rotate, Delete, Move, Connect, "
                               "KeyConnect, Gravity and Friction");
      if (t.size() >= 2) failed_.insert(std::string(t[1].text));
      return;
    }
    if (t[0].text != cmd->canonical) keywordCase(t[0], cmd->canonical);
    if (t.size() < cmd->tokens) {
      rep_.error(at(t[0]), std::string(cmd->canonical) + " needs " + std::to_string(cmd->tokens - 1) + " value" +
                               (cmd->tokens == 2 ? "" : "s") + " (" + std::string(cmd->usage) + ") but the line has " +
                               std::to_string(t.size() - 1));
      if ((cmd->cmd == Cmd::Gizmo || cmd->cmd == Cmd::Absorber || cmd->cmd == Cmd::Ball) && t.size() >= 2)
        failed_.insert(std::string(t[1].text));
      return;
    }
    if (t.size() > cmd->tokens) {
      const Token& extra = t[cmd->tokens];
      rep_.error(at(extra), "unexpected " + quote(extra.text) + " after the end of the command: " +
                                std::string(cmd->usage) + " takes " + std::to_string(cmd->tokens - 1) + " value" +
                                (cmd->tokens == 2 ? "" : "s") +
                                (extra.text[0] == '#' ? " (comments must be on a line of their own)" : ""));
      if ((cmd->cmd == Cmd::Gizmo || cmd->cmd == Cmd::Absorber || cmd->cmd == Cmd::Ball)) failed_.insert(std::string(t[1].text));
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
  SourcePos whereOf(const Ref& r) const { return r.ball ? balls_[r.index].where : gizmos_[r.index].where; }

  // Checks a new name; false (with an error reported) when it cannot be used.
  bool newName(const Token& t) {
    const std::string name(t.text);
    if (std::string p = nameProblem(name); !p.empty()) {
      rep_.error(at(t), p);
      failed_.insert(name);
      return false;
    }
    if (name == kOuterWallsName) {
      rep_.error(at(t), "the name OuterWalls is reserved for the outer walls");
      failed_.insert(name);
      return false;
    }
    if (const auto it = names_.find(name); it != names_.end()) {
      rep_.error(at(t), "the name " + quote(name) + " is already used by the " + kindOf(it->second) + " created on line " +
                            std::to_string(it->second.line) + "; names must be unique");
      return false;
    }
    return true;
  }

  void created(const std::string& name, Ref ref) {
    ref.line = line_;
    names_[name] = ref;
    // Unknown-name errors about this name learn that it is created later.
    if (const auto it = pending_.find(name); it != pending_.end()) {
      for (const std::size_t i : it->second) unresolved_[i].createdLater = line_;
      pending_.erase(it);
    }
  }

  void createGizmo(const CommandInfo& cmd, const std::vector<Token>& t) {
    bool ok = newName(t[1]);
    const bool nameOk = ok;
    const std::string name(t[1].text);
    GizmoSpec g;
    g.type = cmd.type;
    g.name = name;
    g.where = at(t[0]);
    long long v[4] = {0, 0, 0, 0};
    static const char* whats[] = {"the x coordinate", "the y coordinate", "the lower-right x coordinate",
                                  "the lower-right y coordinate"};
    const std::size_t count = cmd.cmd == Cmd::Absorber ? 4 : 2;
    for (std::size_t i = 0; i < count; ++i) ok = whole(t[2 + i], whats[i], v[i]) && ok;
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
      if (nameOk) failed_.insert(name);
      return;
    }
    g.x = static_cast<int>(v[0]);
    g.y = static_cast<int>(v[1]);
    if (cmd.cmd == Cmd::Absorber) {
      g.width = static_cast<int>(v[2] - v[0]);
      g.height = static_cast<int>(v[3] - v[1]);
    } else if (cmd.type == GizmoType::LeftFlipper || cmd.type == GizmoType::RightFlipper) {
      g.width = g.height = 2;
    }
    gizmos_.push_back(std::move(g));
    gizmoAlive_.push_back(1);
    created(name, Ref{false, gizmos_.size() - 1});
  }

  void createBall(const std::vector<Token>& t) {
    bool ok = newName(t[1]);
    const bool nameOk = ok;
    BallSpec b;
    b.name = std::string(t[1].text);
    b.where = at(t[0]);
    ok = decimal(t[2], "the x coordinate", b.x) && ok;
    ok = decimal(t[3], "the y coordinate", b.y) && ok;
    ok = decimal(t[4], "the x velocity", b.vx) && ok;
    ok = decimal(t[5], "the y velocity", b.vy) && ok;
    if (!ok) {
      if (nameOk) failed_.insert(b.name);
      return;
    }
    const std::string name = b.name;
    balls_.push_back(std::move(b));
    ballAlive_.push_back(1);
    created(name, Ref{true, balls_.size() - 1});
  }

  // The live object named by t, or null (the error is reported, or deferred so that it can say
  // whether the name is created later).
  const Ref* lookup(const Token& t, const std::string& what) {
    const std::string name(t.text);
    if (const auto it = names_.find(name); it != names_.end()) return &it->second;
    if (!failed_.count(name)) {
      std::string message = "there is no " + what + " named " + quote(name);
      if (toLowerAscii(name) == "outerwalls") message += " (the outer walls are named OuterWalls)";
      pending_[name].push_back(unresolved_.size());
      unresolved_.push_back(Unresolved{name, at(t), std::move(message), 0});
    }
    return nullptr;
  }

  void rotate(const std::vector<Token>& t) {
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
    const Ref* r = lookup(t[1], "gizmo or ball");
    if (!r) return;
    const std::string name(t[1].text);
    if (r->ball)
      ballAlive_[r->index] = 0;
    else
      gizmoAlive_[r->index] = 0;
    names_.erase(name);
    // Its connections go with it.
    if (const auto it = connectionsOf_.find(name); it != connectionsOf_.end()) {
      for (const std::size_t i : it->second)
        if (connectionAlive_[i]) {
          connectionAlive_[i] = 0;
          connectionIndex_.erase({connections_[i].source, connections_[i].target});
        }
      connectionsOf_.erase(it);
    }
    if (const auto it = keyConnectionsOf_.find(name); it != keyConnectionsOf_.end()) {
      for (const std::size_t i : it->second)
        if (keyAlive_[i]) {
          keyAlive_[i] = 0;
          const KeyConnectSpec& k = keyConnections_[i];
          keyIndex_.erase({k.key, static_cast<int>(k.direction), k.target});
        }
      keyConnectionsOf_.erase(it);
    }
  }

  void move(const std::vector<Token>& t) {
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
      bool ok = whole(t[2], "the x coordinate", x);
      ok = whole(t[3], "the y coordinate", y) && ok;
      if (!ok) return;
      GizmoSpec& g = gizmos_[r->index];
      g.x = static_cast<int>(x);
      g.y = static_cast<int>(y);
      g.where = at(t[0]);
    }
  }

  bool target(const Token& t) {
    if (t.text == kOuterWallsName) {
      rep_.error(at(t), "the outer walls cannot be a connection target: they have no action");
      return false;
    }
    return lookup(t, "gizmo") != nullptr;
  }

  void connect(const std::vector<Token>& t) {
    bool ok = t[1].text == kOuterWallsName || lookup(t[1], "gizmo") != nullptr;
    ok = target(t[2]) && ok;
    if (!ok) return;
    ConnectSpec c{std::string(t[1].text), std::string(t[2].text), at(t[0])};
    const auto [it, inserted] = connectionIndex_.emplace(std::make_pair(c.source, c.target), connections_.size());
    if (!inserted) {
      rep_.lenient("duplicate-connection", at(t[0]),
                   "this connection repeats the one on line " + std::to_string(connections_[it->second].where.line) +
                       "; the repetition is ignored");
      return;
    }
    connectionsOf_[c.source].push_back(connections_.size());
    connectionsOf_[c.target].push_back(connections_.size());
    connections_.push_back(std::move(c));
    connectionAlive_.push_back(1);
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
    if (whole(t[2], "the key code", key)) {
      if (std::string p = keyCodeProblem(key); !p.empty()) {
        rep_.error(at(t[2]), p);
        ok = false;
      }
    } else {
      ok = false;
    }
    KeyDirection direction = KeyDirection::Down;
    const std::string dir = toLowerAscii(t[3].text);
    if (dir == "down" || dir == "up") {
      direction = dir == "down" ? KeyDirection::Down : KeyDirection::Up;
      if (t[3].text != dir) keywordCase(t[3], dir);
    } else {
      rep_.error(at(t[3]), "the key direction must be down or up, not " + quote(t[3].text));
      ok = false;
    }
    ok = target(t[4]) && ok;
    if (!ok) return;
    KeyConnectSpec k{static_cast<int>(key), direction, std::string(t[4].text), at(t[0])};
    const auto [it, inserted] =
        keyIndex_.emplace(std::make_tuple(k.key, static_cast<int>(k.direction), k.target), keyConnections_.size());
    if (!inserted) {
      rep_.lenient("duplicate-connection", at(t[0]),
                   "this connection repeats the one on line " +
                       std::to_string(keyConnections_[it->second].where.line) + "; the repetition is ignored");
      return;
    }
    keyConnectionsOf_[k.target].push_back(keyConnections_.size());
    keyConnections_.push_back(std::move(k));
    keyAlive_.push_back(1);
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
    for (Unresolved& u : unresolved_) {
      if (u.createdLater > 0)
        u.message += " at this point (it is created later, on line " + std::to_string(u.createdLater) +
                     "; commands take effect in file order)";
      rep_.error(u.at, std::move(u.message));
    }
    BoardSpec board;
    board.gravity = gravity_;
    board.mu = mu_;
    board.mu2 = mu2_;
    for (std::size_t i = 0; i < gizmos_.size(); ++i)
      if (gizmoAlive_[i]) board.gizmos.push_back(std::move(gizmos_[i]));
    for (std::size_t i = 0; i < balls_.size(); ++i)
      if (ballAlive_[i]) board.balls.push_back(std::move(balls_[i]));
    for (std::size_t i = 0; i < connections_.size(); ++i)
      if (connectionAlive_[i]) board.connections.push_back(std::move(connections_[i]));
    for (std::size_t i = 0; i < keyConnections_.size(); ++i)
      if (keyAlive_[i]) board.keyConnections.push_back(std::move(keyConnections_[i]));
    for (SpecProblem& p : checkBoardSpec(board)) rep_.error(p.where, std::move(p.message));
    return board;
  }

  std::string_view content_;
  Reporter& rep_;
  int line_ = 0;

  std::vector<GizmoSpec> gizmos_;
  std::vector<char> gizmoAlive_;
  std::vector<BallSpec> balls_;
  std::vector<char> ballAlive_;
  std::unordered_map<std::string, Ref> names_;               // live objects
  std::unordered_map<std::string, std::vector<std::size_t>> pending_;  // unresolved_ entries by name
  std::unordered_set<std::string> failed_;  // names whose statement failed: no second error about them
  std::vector<Unresolved> unresolved_;

  std::vector<ConnectSpec> connections_;
  std::vector<char> connectionAlive_;
  std::map<std::pair<std::string, std::string>, std::size_t> connectionIndex_;  // live ones
  std::unordered_map<std::string, std::vector<std::size_t>> connectionsOf_;
  std::vector<KeyConnectSpec> keyConnections_;
  std::vector<char> keyAlive_;
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
  BoardSpec board = TextReader(content, rep).run();
  rep.throwIfFailed();
  return ReadResult{std::move(board), rep.warnings()};
}

}  // namespace gizmo::io
