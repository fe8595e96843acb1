// Canonical board files. Numbers: the shortest decimal that reads back to the same double.
#include "gizmo/io/board_writer.hpp"

#include "gizmo/core/gizmo_kinds.hpp"
#include "parse_util.hpp"

namespace gizmo::io {
namespace {

using detail::shortest;

// Names that the readers accept need no escaping; anything else is escaped so that the XML
// stays well-formed whatever the BoardSpec holds.
std::string xmlEscaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

const char* direction(KeyDirection d) { return d == KeyDirection::Down ? "down" : "up"; }

std::string attr(const char* name, const std::string& value) { return std::string(" ") + name + "=\"" + value + "\""; }

}  // namespace

std::string writeXmlBoard(const BoardSpec& board) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<board" + attr("gravity", shortest(board.gravity)) + attr("friction1", shortest(board.mu)) +
         attr("friction2", shortest(board.mu2)) + ">\n";
  for (const BallSpec& b : board.balls) {
    out += "  <ball" + attr("name", xmlEscaped(b.name)) + attr("x", shortest(b.x)) + attr("y", shortest(b.y)) +
           attr("xVelocity", shortest(b.vx)) + attr("yVelocity", shortest(b.vy)) + "/>\n";
  }
  out += "  <gizmos>\n";
  for (const GizmoSpec& g : board.gizmos) {
    out += std::string("    <") + gizmoKind(g.type).xmlElement.data() + attr("name", xmlEscaped(g.name)) +
           attr("x", std::to_string(g.x)) + attr("y", std::to_string(g.y));
    if (sizedByLine(g.type)) out += attr("width", std::to_string(g.width)) + attr("height", std::to_string(g.height));
    if (gizmoKind(g.type).exitCell)
      out += attr("exitX", std::to_string(g.exitX)) + attr("exitY", std::to_string(g.exitY));
    // Whether a 0 orientation is written too is each kind's (kinds/STEM.hpp, xmlOrientationAlways).
    if (g.orientation != 0 || gizmoKind(g.type).xmlOrientationAlways)
      out += attr("orientation", std::to_string(g.orientation));
    out += "/>\n";
  }
  out += "  </gizmos>\n";
  out += "  <connections>\n";
  for (const ConnectSpec& c : board.connections)
    out +=
        "    <connect" + attr("sourceGizmo", xmlEscaped(c.source)) + attr("targetGizmo", xmlEscaped(c.target)) + "/>\n";
  for (const KeyConnectSpec& k : board.keyConnections)
    out += "    <keyConnect" + attr("key", std::to_string(k.key)) + attr("keyDirection", direction(k.direction)) +
           attr("targetGizmo", xmlEscaped(k.target)) + "/>\n";
  out += "  </connections>\n";
  out += "</board>\n";
  return out;
}

std::string writeTextBoard(const BoardSpec& board) {
  std::string out;
  out += "Gravity " + shortest(board.gravity) + "\n";
  out += "Friction " + shortest(board.mu) + " " + shortest(board.mu2) + "\n";
  for (const GizmoSpec& g : board.gizmos) {
    out += std::string(gizmoKind(g.type).textCommand) + " " + g.name + " " + std::to_string(g.x) + " " +
           std::to_string(g.y);
    if (sizedByLine(g.type))
      out += " " + std::to_string(static_cast<long long>(g.x) + g.width) + " " +
             std::to_string(static_cast<long long>(g.y) + g.height);
    if (gizmoKind(g.type).exitCell) out += " " + std::to_string(g.exitX) + " " + std::to_string(g.exitY);
    out += "\n";
    const int turns = (((g.orientation / 90) % 4) + 4) % 4;
    for (int i = 0; i < turns; ++i) out += "Rotate " + g.name + "\n";
  }
  for (const BallSpec& b : board.balls)
    out += "Ball " + b.name + " " + shortest(b.x) + " " + shortest(b.y) + " " + shortest(b.vx) + " " + shortest(b.vy) +
           "\n";
  for (const ConnectSpec& c : board.connections) out += "Connect " + c.source + " " + c.target + "\n";
  for (const KeyConnectSpec& k : board.keyConnections)
    out += "KeyConnect key " + std::to_string(k.key) + " " + direction(k.direction) + " " + k.target + "\n";
  return out;
}

}  // namespace gizmo::io
