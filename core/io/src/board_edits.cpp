#include "board_edits.hpp"

namespace gizmo::io::detail {

const Ref* BoardEdits::find(const std::string& written) const {
  const auto it = names_.find(written);
  return it == names_.end() ? nullptr : &it->second;
}

void BoardEdits::created(const std::string& written, Ref ref) {
  taken_.insert(ref.name);
  names_[written] = std::move(ref);
}

void BoardEdits::addGizmo(const std::string& written, GizmoSpec g, int line) {
  std::string name = g.name;
  created(written, Ref{false, gizmos_.add(std::move(g)), line, std::move(name)});
}

void BoardEdits::addBall(const std::string& written, BallSpec b, int line) {
  std::string name = b.name;
  created(written, Ref{true, balls_.add(std::move(b)), line, std::move(name)});
}

void BoardEdits::remove(const std::string& written) {
  const auto it = names_.find(written);
  const Ref r = it->second;
  if (r.ball) balls_.remove(r.index);
  else gizmos_.remove(r.index);
  names_.erase(it);
  taken_.erase(r.name);
  // Its connections go with it.
  connections_.removeNaming(r.name);
  keyConnections_.removeNaming(r.name);
}

const ConnectSpec* BoardEdits::connect(ConnectSpec c) {
  std::pair<std::string, std::string> key{c.source, c.target};
  std::string source = c.source, target = c.target;
  return connections_.add(std::move(c), std::move(key), {std::move(source), std::move(target)});
}

const KeyConnectSpec* BoardEdits::keyConnect(KeyConnectSpec k) {
  std::tuple<int, int, std::string> key{k.key, static_cast<int>(k.direction), k.target};
  std::string target = k.target;
  return keyConnections_.add(std::move(k), std::move(key), {std::move(target)});
}

void BoardEdits::takeInto(BoardSpec& board) {
  board.gizmos = gizmos_.takeLive();
  board.balls = balls_.takeLive();
  board.connections = connections_.takeLive();
  board.keyConnections = keyConnections_.takeLive();
}

}  // namespace gizmo::io::detail
