// The DistMesh engine's points: positions, the fixed ones first (they never move), and
// which free points are held on the interface (dI = 0). Points are added, removed and
// inserted only through here, so positions and flags stay in step.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

class PointSet {
 public:
  // Starts the set with `fixed` (these stay first and never move).
  void start(std::vector<Vec2> fixed) {
    fixed_ = fixed.size();
    p_ = std::move(fixed);
    on_interface_.assign(p_.size(), 0);
  }

  std::size_t size() const { return p_.size(); }
  std::size_t fixed() const { return fixed_; }
  const std::vector<Vec2>& positions() const { return p_; }
  Vec2& operator[](std::size_t i) { return p_[i]; }
  const Vec2& operator[](std::size_t i) const { return p_[i]; }

  bool on_interface(std::size_t i) const { return on_interface_[i] != 0; }
  void hold_on_interface(std::size_t i) { on_interface_[i] = 1; }

  void add(Vec2 q, bool on_interface = false) {
    p_.push_back(q);
    on_interface_.push_back(on_interface ? 1 : 0);
  }
  void pop_back() {
    p_.pop_back();
    on_interface_.pop_back();
  }
  // Removes point i (free); the points after it move down by one.
  void erase(std::size_t i) {
    p_.erase(p_.begin() + static_cast<std::ptrdiff_t>(i));
    on_interface_.erase(on_interface_.begin() + static_cast<std::ptrdiff_t>(i));
  }
  // A free point off the interface at index i; the points from i on move up by one.
  void insert(std::size_t i, Vec2 q) {
    p_.insert(p_.begin() + static_cast<std::ptrdiff_t>(i), q);
    on_interface_.insert(on_interface_.begin() + static_cast<std::ptrdiff_t>(i), 0);
  }
  // Removes every point i with drop[i] (never a fixed one), keeping the others' order.
  // Returns how many went.
  std::size_t remove(const std::vector<char>& drop) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < p_.size(); ++i)
      if (!drop[i]) {
        p_[out] = p_[i];
        on_interface_[out++] = on_interface_[i];
      }
    const std::size_t removed = p_.size() - out;
    p_.resize(out);
    on_interface_.resize(out);
    return removed;
  }

 private:
  std::vector<Vec2> p_;
  std::vector<char> on_interface_;
  std::size_t fixed_ = 0;
};

}  // namespace grainmesh
