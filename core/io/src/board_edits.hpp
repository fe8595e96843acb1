#pragma once
// Internal to gizmo::io: the text reader's edit model, in one place. A text board's commands run
// in file order and edit what earlier lines made: Move and Rotate change a gizmo or ball, Delete
// removes it with every connection to or from it, and a name that Delete frees may be used again.
// The indexes handed out (a name's Ref, the connections listed under a name) must stay valid while
// later lines edit, so nothing is erased: an entry is marked removed (EditedList), and the board
// takes the live ones in the order they were created. The reader decides what a line means and
// what to report; this class only keeps the lists and the indexes that find their entries.
#include <cstddef>
#include <initializer_list>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "edited_list.hpp"
#include "gizmo/core/board_spec.hpp"

namespace gizmo::io::detail {

// One kind of connection: a link that repeats a live one (the same Key) is refused, and removing
// an object removes every live link listed under its name.
template <class T, class Key>
class LinkList {
 public:
  // Adds `link`, listed under each of `ends` (board names). Null when added; else the live link it
  // repeats, and nothing is added.
  const T* add(T link, Key key, std::initializer_list<std::string> ends) {
    const auto [it, inserted] = live_.emplace(key, links_.size());
    if (!inserted) return &links_[it->second];
    for (const std::string& end : ends) naming_[end].push_back(links_.size());
    keys_.push_back(std::move(key));
    links_.add(std::move(link));
    return nullptr;
  }
  // Removes the live links listed under `name`.
  void removeNaming(const std::string& name) {
    const auto it = naming_.find(name);
    if (it == naming_.end()) return;
    for (const std::size_t i : it->second)
      if (links_.remove(i)) live_.erase(keys_[i]);
    naming_.erase(it);
  }
  std::vector<T> takeLive() { return links_.takeLive(); }

 private:
  EditedList<T> links_;
  std::vector<Key> keys_;                                             // each link's key, by index
  std::map<Key, std::size_t> live_;                                   // the live links by key
  std::unordered_map<std::string, std::vector<std::size_t>> naming_;  // links by the names of their ends
};

// A live gizmo or ball, found by the name the file writes.
struct Ref {
  bool ball = false;
  std::size_t index = 0;
  int line = 0;      // where it was created
  std::string name;  // its name on the board (the file may write it otherwise)
};

class BoardEdits {
 public:
  // The live object the file writes `written`, or null.
  const Ref* find(const std::string& written) const;
  // Whether a live object has the board name `name`.
  bool taken(const std::string& name) const { return taken_.count(name) > 0; }

  // Creates a gizmo or ball (named on the board as its spec says) that later lines write `written`;
  // a name written again means the latest.
  void addGizmo(const std::string& written, GizmoSpec g, int line);
  void addBall(const std::string& written, BallSpec b, int line);

  GizmoSpec& gizmo(const Ref& r) { return gizmos_[r.index]; }
  const GizmoSpec& gizmo(const Ref& r) const { return gizmos_[r.index]; }
  BallSpec& ball(const Ref& r) { return balls_[r.index]; }

  // Deletes the live object written `written` (it must exist) and its connections; its names are
  // free again.
  void remove(const std::string& written);

  // Adds a connection between live objects; null, or the live one it repeats (nothing is added).
  const ConnectSpec* connect(ConnectSpec c);
  const KeyConnectSpec* keyConnect(KeyConnectSpec k);

  // The live entries, in the order they were created, moved into the board.
  void takeInto(BoardSpec& board);

 private:
  void created(const std::string& written, Ref ref);

  EditedList<GizmoSpec> gizmos_;
  EditedList<BallSpec> balls_;
  std::unordered_map<std::string, Ref> names_;  // live objects by the name the file writes
  std::unordered_set<std::string> taken_;       // the board names of live objects
  LinkList<ConnectSpec, std::pair<std::string, std::string>> connections_;
  LinkList<KeyConnectSpec, std::tuple<int, int, std::string>> keyConnections_;
};

}  // namespace gizmo::io::detail
