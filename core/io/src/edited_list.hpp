#pragma once
// Internal to gizmo::io: the text reader's edit model for what the file creates. Commands run in
// file order and a later Delete removes what an earlier line created, while the indexes handed
// out (Ref, the connections by name) must stay valid: so an entry is marked removed, not erased,
// and the board takes the live ones, in the order they were created.
#include <cstddef>
#include <utility>
#include <vector>

namespace gizmo::io::detail {

template <class T>
class EditedList {
 public:
  // Adds an entry; its index stays valid for the list's life.
  std::size_t add(T item) {
    items_.push_back(std::move(item));
    live_.push_back(1);
    return items_.size() - 1;
  }
  // Marks an entry removed; false when it was removed already.
  bool remove(std::size_t i) {
    if (!live_[i]) return false;
    live_[i] = 0;
    return true;
  }
  std::size_t size() const { return items_.size(); }
  T& operator[](std::size_t i) { return items_[i]; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  // The live entries in creation order, moved out.
  std::vector<T> takeLive() {
    std::vector<T> out;
    for (std::size_t i = 0; i < items_.size(); ++i)
      if (live_[i]) out.push_back(std::move(items_[i]));
    return out;
  }

 private:
  std::vector<T> items_;
  std::vector<char> live_;
};

}  // namespace gizmo::io::detail
