// The XML board format (MIT 6.170) through pugixml. pugixml checks well-formedness only; the
// board schema, the numbers and every position reported are checked here.
#include "gizmo/io/xml_reader.hpp"

#include <algorithm>
#include <initializer_list>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include <pugixml.hpp>

#include "board_repair.hpp"
#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "parse_util.hpp"

namespace gizmo::io {
namespace {

using namespace detail;

bool xmlSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && xmlSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && xmlSpace(s.back())) s.remove_suffix(1);
  return s;
}

std::string tag(std::string_view s) { return "<" + std::string(s) + ">"; }

// The attribute names of the start tag whose element name starts at nameOffset, with the offset of
// each, in document order (as pugixml keeps them). The tag is well-formed: pugixml accepted it.
std::vector<std::pair<std::string_view, std::size_t>> scanAttributes(std::string_view s, std::size_t nameOffset) {
  std::vector<std::pair<std::string_view, std::size_t>> out;
  std::size_t i = nameOffset;
  while (i < s.size() && !xmlSpace(s[i]) && s[i] != '/' && s[i] != '>') ++i;
  while (i < s.size()) {
    while (i < s.size() && xmlSpace(s[i])) ++i;
    if (i >= s.size() || s[i] == '/' || s[i] == '>') break;
    const std::size_t start = i;
    while (i < s.size() && !xmlSpace(s[i]) && s[i] != '=') ++i;
    out.emplace_back(s.substr(start, i - start), start);
    while (i < s.size() && xmlSpace(s[i])) ++i;
    if (i >= s.size() || s[i] != '=') break;
    ++i;
    while (i < s.size() && xmlSpace(s[i])) ++i;
    if (i >= s.size() || (s[i] != '"' && s[i] != '\'')) break;
    const std::size_t close = s.find(s[i], i + 1);
    if (close == std::string_view::npos) break;
    i = close + 1;
  }
  return out;
}

struct Attr {
  std::string_view value;  // trimmed of XML white space
  SourcePos at;
};

// " (did you mean <squareBumper>?)" when name differs from one of known only in case.
std::string caseHint(std::string_view name, const std::vector<std::string_view>& known) {
  const std::string lower = toLowerAscii(name);
  for (std::string_view k : known)
    if (toLowerAscii(k) == lower) return " (did you mean " + tag(k) + "?)";
  return {};
}

std::vector<std::string_view> gizmoElementNames() {
  std::vector<std::string_view> names;
  for (const GizmoKindInfo& k : kGizmoKinds) names.push_back(k.xmlElement);
  return names;
}

// "squareBumper, circleBumper, ... and spawner": every kind's element (gizmo_kinds.hpp).
std::string gizmoElementList() {
  const std::vector<std::string_view> names = gizmoElementNames();
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " and " : ", ";
    out += names[i];
  }
  return out;
}

class XmlReader {
 public:
  XmlReader(std::string_view content, Reporter& rep) : content_(content), rep_(rep), lines_(content) {}

  BoardSpec run(const pugi::xml_document& doc) {
    pugi::xml_node root;
    for (pugi::xml_node n : doc.children()) {
      if (n.type() == pugi::node_element) {
        if (!root) {
          root = n;
          if (std::string_view(n.name()) != "board") {
            rep_.error(elementAt(n),
                       "the root element is " + tag(n.name()) + "; a board file's root element is <board>");
            rep_.throwErrors();
          }
        } else {
          rep_.error(elementAt(n),
                     "a second root element " + tag(n.name()) + ": a board file has exactly one root element, <board>");
        }
      } else if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata) {
        textError(n, "outside the <board> element");
      }
    }
    if (!root) {
      rep_.error(SourcePos{}, "the file holds no XML element; a board file's root element is <board>");
      rep_.throwErrors();
    }
    readBoard(root);
    if (schemaElements_ == 0 && leftOutElements_ > 0 && !rep_.failed()) {
      rep_.error(elementAt(root),
                 "no element of this <board> is one of the board schema's; it does not look like a "
                 "Gizmoball board");
      return std::move(board_);
    }
    dropConnectionsTo(board_, leftOut_, rep_);
    if (!rep_.failed()) repairPlacements(board_, rep_);
    for (SpecProblem& p : checkBoardSpec(board_)) rep_.error(p.where, std::move(p.message));
    return std::move(board_);
  }

 private:
  SourcePos elementAt(const pugi::xml_node& n) const {
    const std::ptrdiff_t off = n.offset_debug();  // the element's name, just after '<'
    return off > 0 ? lines_.position(static_cast<std::size_t>(off - 1)) : SourcePos{};
  }
  // The first character of a text node that is not white space.
  SourcePos textAt(const pugi::xml_node& n) const {
    const std::ptrdiff_t off = n.offset_debug();
    if (off < 0) return SourcePos{};
    std::size_t i = static_cast<std::size_t>(off);
    if (n.type() == pugi::node_pcdata)
      while (i < content_.size() && xmlSpace(content_[i])) ++i;
    return lines_.position(std::min(i, content_.size()));
  }

  void textError(const pugi::xml_node& n, const std::string& where) {
    rep_.error(textAt(n), std::string("unexpected text ") + where);
  }

  // The known attributes of e that are present, by name. Reports attributes given twice (error),
  // missing required ones (error, and returns false) and unknown ones (warning).
  bool attributes(const pugi::xml_node& e, std::initializer_list<std::string_view> required,
                  std::initializer_list<std::string_view> optional, std::map<std::string, Attr>& out) {
    const std::ptrdiff_t off = e.offset_debug();
    const auto positions = off > 0 ? scanAttributes(content_, static_cast<std::size_t>(off))
                                   : std::vector<std::pair<std::string_view, std::size_t>>{};
    const std::string element = e.name();
    bool ok = true;
    std::size_t index = 0;
    for (pugi::xml_attribute a : e.attributes()) {
      const std::string_view name = a.name();
      SourcePos at = elementAt(e);
      if (index < positions.size() && positions[index].first == name) at = lines_.position(positions[index].second);
      ++index;
      bool known = false;
      for (std::string_view k : required) known = known || k == name;
      for (std::string_view k : optional) known = known || k == name;
      if (!known) {
        const bool xmlMachinery = name.substr(0, 5) == "xmlns" || name.substr(0, 4) == "xsi:";
        if (!xmlMachinery)
          rep_.lenient("unknown-attribute:" + element + ":" + std::string(name), at,
                       "unknown attribute " + quote(name) + " on " + tag(element) + " ignored");
        continue;
      }
      if (out.count(std::string(name))) {
        rep_.error(at, "the attribute " + quote(name) + " is given twice");
        ok = false;
        continue;
      }
      out.emplace(std::string(name), Attr{trimmed(a.value()), at});
    }
    for (std::string_view k : required)
      if (!out.count(std::string(k))) {
        rep_.error(elementAt(e), tag(element) + " lacks the required attribute " + quote(k));
        ok = false;
      }
    return ok;
  }

  // Leaf elements hold nothing.
  void expectEmpty(const pugi::xml_node& e) {
    for (pugi::xml_node c : e.children()) {
      if (c.type() == pugi::node_element) rep_.error(elementAt(c), tag(e.name()) + " cannot contain " + tag(c.name()));
      else if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) textError(c, "inside " + tag(e.name()));
    }
  }

  bool whole(const Attr& a, const std::string& what, long long& out) {
    const Whole w = parseWhole(a.value, what);
    if (!w.ok) {
      rep_.error(a.at, w.problem);
      return false;
    }
    if (w.writtenAsDecimal)
      rep_.lenient("integral-decimal", a.at,
                   quote(a.value) + " is read as the whole number " + std::to_string(w.value) +
                       " (the schema has whole numbers here)");
    out = w.value;
    return true;
  }

  bool decimal(const Attr& a, const std::string& what, double& out) {
    const Number n = parseDecimal(a.value, what);
    if (!n.ok) {
      rep_.error(a.at, n.problem);
      return false;
    }
    out = n.value;
    return true;
  }

  bool name(const Attr& a, std::string& out) {
    if (std::string p = nameProblem(a.value); !p.empty()) {
      rep_.error(a.at, p);
      return false;
    }
    out = std::string(a.value);
    return true;
  }

  void readBoard(const pugi::xml_node& board) {
    std::map<std::string, Attr> attrs;
    attributes(board, {}, {"gravity", "friction1", "friction2"}, attrs);
    if (auto it = attrs.find("gravity"); it != attrs.end()) {
      double g = 0;
      if (decimal(it->second, "gravity", g)) {
        if (std::string p = gravityProblem(g); !p.empty()) rep_.error(it->second.at, p);
        else board_.gravity = g;
      }
    }
    const std::pair<const char*, double BoardSpec::*> frictions[] = {{"friction1", &BoardSpec::mu},
                                                                     {"friction2", &BoardSpec::mu2}};
    for (const auto& [attr, member] : frictions) {
      if (auto it = attrs.find(attr); it != attrs.end()) {
        const std::string which = member == &BoardSpec::mu ? "mu (friction1)" : "mu2 (friction2)";
        double v = 0;
        if (decimal(it->second, "friction " + which, v)) {
          if (std::string p = frictionProblem(which, v); !p.empty()) rep_.error(it->second.at, p);
          else board_.*member = v;
        }
      }
    }

    int phase = 0;  // 0: balls, 1: gizmos seen, 2: connections seen
    bool sawGizmos = false, sawConnections = false;
    for (pugi::xml_node c : board.children()) {
      if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
        textError(c, "inside <board>");
        continue;
      }
      if (c.type() != pugi::node_element) continue;
      const std::string_view n = c.name();
      if (n == "ball" || n == "gizmos" || n == "connections") ++schemaElements_;
      if (n == "ball") {
        if (phase > 0)
          rep_.lenient("order", elementAt(c),
                       "<ball> after " + std::string(phase == 1 ? "<gizmos>" : "<connections>") +
                           ": the schema puts the balls first (read anyway)");
        readBall(c);
      } else if (n == "gizmos") {
        if (sawGizmos)
          rep_.lenient("repeat", elementAt(c),
                       "a second <gizmos> element: the schema has one (its gizmos are read too)");
        else if (phase == 2)
          rep_.lenient("order", elementAt(c),
                       "<gizmos> after <connections>: the schema puts the gizmos first (read anyway)");
        sawGizmos = true;
        phase = std::max(phase, 1);
        readGizmos(c);
      } else if (n == "connections") {
        if (sawConnections)
          rep_.lenient("repeat", elementAt(c),
                       "a second <connections> element: the schema has one (its connections are read too)");
        sawConnections = true;
        phase = 2;
        readConnections(c);
      } else {
        leaveOutElement(c, "<board>",
                        "it holds <ball>, <gizmos> and <connections>" + caseHint(n, {"ball", "gizmos", "connections"}));
      }
    }
    if (!sawGizmos)
      rep_.lenient("missing-gizmos", elementAt(board),
                   "the board has no <gizmos> element; the schema requires one (read as empty)");
    if (!sawConnections)
      rep_.lenient("missing-connections", elementAt(board),
                   "the board has no <connections> element; the schema requires one (read as empty)");
  }

  void readBall(const pugi::xml_node& e) {
    expectEmpty(e);
    std::map<std::string, Attr> a;
    if (!attributes(e, {"name", "x", "y", "xVelocity", "yVelocity"}, {}, a)) return;
    BallSpec b;
    b.where = elementAt(e);
    bool ok = name(a.at("name"), b.name);
    ok = decimal(a.at("x"), "x", b.x) && ok;
    ok = decimal(a.at("y"), "y", b.y) && ok;
    ok = decimal(a.at("xVelocity"), "xVelocity", b.vx) && ok;
    ok = decimal(a.at("yVelocity"), "yVelocity", b.vy) && ok;
    if (ok) board_.balls.push_back(std::move(b));
  }

  void readGizmos(const pugi::xml_node& section) {
    std::map<std::string, Attr> ignored;
    attributes(section, {}, {}, ignored);
    for (pugi::xml_node c : section.children()) {
      if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
        textError(c, "inside <gizmos>");
        continue;
      }
      if (c.type() != pugi::node_element) continue;
      const GizmoKindInfo* kind = gizmoKindByXmlElement(c.name());
      if (!kind) {
        // Another program's spelling of ours (<SquareBumper>): read as ours, as the text reader
        // reads keywords in any case.
        for (const GizmoKindInfo& k : kGizmoKinds)
          if (toLowerAscii(k.xmlElement) == toLowerAscii(c.name())) kind = &k;
        if (kind)
          rep_.lenient("element-case", elementAt(c),
                       tag(c.name()) + " is written " + tag(kind->xmlElement) +
                           " in the schema; gizmo elements are read without regard to case");
      }
      if (!kind) {
        leaveOutElement(c, "<gizmos>",
                        "the gizmos are " + gizmoElementList() + caseHint(c.name(), gizmoElementNames()));
        continue;
      }
      readGizmo(c, kind->type);
    }
  }

  void readGizmo(const pugi::xml_node& e, GizmoType type) {
    expectEmpty(e);
    std::map<std::string, Attr> a;
    const bool sized = sizedByLine(type), exitCell = gizmoKind(type).exitCell;
    const bool ok0 = sized      ? attributes(e, {"name", "x", "y", "width", "height"}, {"orientation"}, a)
                     : exitCell ? attributes(e, {"name", "x", "y", "exitX", "exitY"}, {"orientation"}, a)
                                : attributes(e, {"name", "x", "y"}, {"orientation"}, a);
    if (!ok0) return;
    GizmoSpec g;
    g.type = type;
    g.where = elementAt(e);
    long long x = 0, y = 0, orientation = 0, width = 1, height = 1, exitX = 0, exitY = 0;
    if (!sized) width = height = ownSide(type);
    bool ok = name(a.at("name"), g.name);
    ok = whole(a.at("x"), "x", x) && ok;
    ok = whole(a.at("y"), "y", y) && ok;
    if (sized) {
      ok = whole(a.at("width"), "width", width) && ok;
      ok = whole(a.at("height"), "height", height) && ok;
    }
    if (exitCell) {
      ok = whole(a.at("exitX"), "exitX", exitX) && ok;
      ok = whole(a.at("exitY"), "exitY", exitY) && ok;
    }
    if (auto it = a.find("orientation"); it != a.end()) ok = whole(it->second, "orientation", orientation) && ok;
    if (!ok) return;
    g.x = static_cast<int>(x);
    g.y = static_cast<int>(y);
    g.orientation = static_cast<int>(orientation);
    g.width = static_cast<int>(width);
    g.height = static_cast<int>(height);
    g.exitX = static_cast<int>(exitX);
    g.exitY = static_cast<int>(exitY);
    board_.gizmos.push_back(std::move(g));
  }

  void readConnections(const pugi::xml_node& section) {
    std::map<std::string, Attr> ignored;
    attributes(section, {}, {}, ignored);
    for (pugi::xml_node c : section.children()) {
      if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
        textError(c, "inside <connections>");
        continue;
      }
      if (c.type() != pugi::node_element) continue;
      const std::string_view n = c.name();
      if (n == "connect") {
        readConnect(c);
      } else if (n == "keyConnect") {
        readKeyConnect(c);
      } else {
        leaveOutElement(c, "<connections>",
                        "it holds <connect> and <keyConnect>" + caseHint(n, {"connect", "keyConnect"}));
      }
    }
  }

  void readConnect(const pugi::xml_node& e) {
    expectEmpty(e);
    std::map<std::string, Attr> a;
    if (!attributes(e, {"sourceGizmo", "targetGizmo"}, {}, a)) return;
    ConnectSpec c{std::string(a.at("sourceGizmo").value), std::string(a.at("targetGizmo").value), elementAt(e)};
    const auto [it, inserted] = connections_.emplace(std::make_pair(c.source, c.target), c.where);
    if (!inserted) {
      duplicate(c.where, it->second);
      return;
    }
    board_.connections.push_back(std::move(c));
  }

  void readKeyConnect(const pugi::xml_node& e) {
    expectEmpty(e);
    std::map<std::string, Attr> a;
    if (!attributes(e, {"key", "keyDirection", "targetGizmo"}, {}, a)) return;
    KeyConnectSpec k;
    k.where = elementAt(e);
    k.target = std::string(a.at("targetGizmo").value);
    long long key = 0;
    bool ok = whole(a.at("key"), "key", key);
    if (ok) {
      if (std::string p = keyCodeProblem(key); !p.empty()) {
        rep_.error(a.at("key").at, p);
        ok = false;
      }
    }
    const Attr& dir = a.at("keyDirection");
    const std::string lower = toLowerAscii(dir.value);
    if (lower == "down" || lower == "up") {
      k.direction = lower == "down" ? KeyDirection::Down : KeyDirection::Up;
      if (dir.value != lower)
        rep_.lenient("keyword-case", dir.at,
                     quote(dir.value) + " is written " + quote(lower) + " in the schema; read without regard to case");
    } else {
      rep_.error(dir.at, "keyDirection must be down or up, not " + quote(dir.value));
      ok = false;
    }
    if (!ok) return;
    k.key = static_cast<int>(key);
    const auto [it, inserted] =
        keyConnections_.emplace(std::make_tuple(k.key, static_cast<int>(k.direction), k.target), k.where);
    if (!inserted) {
      duplicate(k.where, it->second);
      return;
    }
    board_.keyConnections.push_back(std::move(k));
  }

  // An element another program's schema has and ours does not: left out, with one warning per
  // element name and a count; what it names (its name attribute) is left out of the connections
  // too (dropConnectionsTo, board_repair.hpp). docs/board-files.md §2.
  void leaveOutElement(const pugi::xml_node& e, const std::string& parent, const std::string& hint) {
    const pugi::xml_attribute name = e.attribute("name");
    if (name) leftOut_.insert(std::string(trimmed(name.value())));
    ++leftOutElements_;
    rep_.lenient("unknown-element:" + std::string(e.name()), elementAt(e),
                 "unknown element " + tag(e.name()) + " in " + parent + " (" + hint + "); it is left out" +
                     (name ? ", and so are the connections that name " + quote(trimmed(name.value())) : std::string()));
  }

  void duplicate(const SourcePos& at, const SourcePos& first) {
    rep_.lenient(
        "duplicate-connection", at,
        "this connection repeats the one on line " + std::to_string(first.line) + "; the repetition is ignored");
  }

  std::string_view content_;
  Reporter& rep_;
  LineIndex lines_;
  BoardSpec board_;
  std::map<std::pair<std::string, std::string>, SourcePos> connections_;
  std::map<std::tuple<int, int, std::string>, SourcePos> keyConnections_;
  std::set<std::string> leftOut_;  // the names of elements left out
  std::size_t leftOutElements_ = 0;
  std::size_t schemaElements_ = 0;  // <ball>, <gizmos> and <connections> in <board>
};

}  // namespace

ReadResult readXmlBoard(std::string_view content, const std::string& fileName) {
  if (content.size() > kMaxFileBytes) fail(fileName, {}, "the file is larger than 16 MiB, the limit for board files");
  rejectNul(content, fileName);
  pugi::xml_document doc;
  // parse_fragment keeps text outside the root element so that it can be refused; UTF-8 without
  // conversion keeps pugixml's offsets equal to byte offsets in content.
  const pugi::xml_parse_result parsed =
      doc.load_buffer(content.data(), content.size(), pugi::parse_default | pugi::parse_fragment, pugi::encoding_utf8);
  if (!parsed) {
    const std::size_t offset = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, parsed.offset));
    fail(fileName, LineIndex(content).position(std::min(offset, content.size())),
         std::string("the XML is not well-formed: ") + parsed.description());
  }
  Reporter rep(fileName);
  BoardSpec board = XmlReader(content, rep).run(doc);
  rep.throwIfFailed();
  return ReadResult{std::move(board), rep.warnings()};
}

}  // namespace gizmo::io
