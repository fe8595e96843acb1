#include "gizmo/verify/fuzz/run_description.hpp"

#include <charconv>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "gizmo/core/board_spec_check.hpp"
#include "gizmo/io/board_writer.hpp"

namespace gizmo::verify::fuzz {
namespace {

std::string shortest(double x) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

std::string exact(double x) {
  char hex[64];
  std::snprintf(hex, sizeof hex, "%a", x);
  return shortest(x) + " (" + hex + ")";
}

std::string describeEvent(EventKind kind, double time, GizmoId a, GizmoId b, std::int32_t feature,
                          std::uint64_t sequence) {
  std::ostringstream s;
  s << eventKindName(kind) << " t=" << exact(time) << " a=" << a << " b=" << b << " feature=" << feature << " #"
    << sequence;
  return s.str();
}

std::string writeKeyScript(const std::vector<TimedKey>& keys) {
  std::string out;
  for (const TimedKey& k : keys)
    out += shortest(k.time) + (k.direction == KeyDirection::Down ? " down " : " up ") + std::to_string(k.key) + "\n";
  return out;
}

std::string describeRun(const RunRequest& run) {
  std::ostringstream s;
  s << "model " << motionModelName(run.model) << ", max tick " << exact(run.maxTick) << ", duration "
    << exact(run.duration) << "\n";
  s << "keys (" << run.keys.size() << "):\n";
  for (const TimedKey& k : run.keys)
    s << "  " << exact(k.time) << (k.direction == KeyDirection::Down ? " down " : " up ") << k.key << "\n";
  s << "balls, exactly:\n";
  for (const BallSpec& b : run.board.balls)
    s << "  " << b.name << " x " << exact(b.x) << " y " << exact(b.y) << " vx " << exact(b.vx) << " vy " << exact(b.vy)
      << "\n";
  s << "gravity " << exact(run.board.gravity) << ", mu " << exact(run.board.mu) << ", mu2 " << exact(run.board.mu2)
    << "\n";
  s << io::writeXmlBoard(run.board);
  return s.str();
}

std::optional<std::string> boardDifference(const BoardSpec& a, const BoardSpec& b) {
  auto number = [](const char* what, double x, double y) -> std::optional<std::string> {
    if (sameBits(x, y)) return std::nullopt;
    return std::string(what) + ": " + exact(x) + " became " + exact(y);
  };
  if (auto d = number("gravity", a.gravity, b.gravity)) return d;
  if (auto d = number("mu", a.mu, b.mu)) return d;
  if (auto d = number("mu2", a.mu2, b.mu2)) return d;
  if (a.balls.size() != b.balls.size())
    return "ball count " + std::to_string(a.balls.size()) + " became " + std::to_string(b.balls.size());
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    const BallSpec &x = a.balls[i], &y = b.balls[i];
    if (x.name != y.name) return "ball " + std::to_string(i) + " name " + x.name + " became " + y.name;
    for (auto d : {number("x", x.x, y.x), number("y", x.y, y.y), number("vx", x.vx, y.vx), number("vy", x.vy, y.vy)})
      if (d) return "ball " + x.name + " " + *d;
  }
  if (a.gizmos.size() != b.gizmos.size())
    return "gizmo count " + std::to_string(a.gizmos.size()) + " became " + std::to_string(b.gizmos.size());
  for (std::size_t i = 0; i < a.gizmos.size(); ++i) {
    const GizmoSpec &x = a.gizmos[i], &y = b.gizmos[i];
    if (x.type != y.type || x.name != y.name || x.x != y.x || x.y != y.y || x.orientation != y.orientation ||
        x.width != y.width || x.height != y.height || x.exitX != y.exitX || x.exitY != y.exitY) {
      std::ostringstream s;
      s << "gizmo " << i << ": " << gizmoTypeWord(x.type) << " " << x.name << " at " << x.x << "," << x.y << " "
        << x.width << "x" << x.height << " orientation " << x.orientation << " became " << gizmoTypeWord(y.type) << " "
        << y.name << " at " << y.x << "," << y.y << " " << y.width << "x" << y.height << " orientation "
        << y.orientation;
      return s.str();
    }
  }
  if (a.connections.size() != b.connections.size()) return std::string("connection count differs");
  for (std::size_t i = 0; i < a.connections.size(); ++i)
    if (a.connections[i].source != b.connections[i].source || a.connections[i].target != b.connections[i].target)
      return "connection " + a.connections[i].source + " -> " + a.connections[i].target + " became " +
             b.connections[i].source + " -> " + b.connections[i].target;
  if (a.keyConnections.size() != b.keyConnections.size()) return std::string("key connection count differs");
  for (std::size_t i = 0; i < a.keyConnections.size(); ++i) {
    const KeyConnectSpec &x = a.keyConnections[i], &y = b.keyConnections[i];
    if (x.key != y.key || x.direction != y.direction || x.target != y.target)
      return "key connection " + std::to_string(i) + " (key " + std::to_string(x.key) + " to " + x.target + ") changed";
  }
  return std::nullopt;
}

}  // namespace gizmo::verify::fuzz
