// Uniform grids of square cells, for "what lies near p" among points and segments:
// GridFrame numbers the cells of a bounded nx x ny grid and walks rings of them around a
// cell, nearest first; CellLists lists fixed items (points, segments) by the cells they
// touch; HashGrid is an unbounded grid that keeps only the cells in use, for points that
// arrive one at a time anywhere in the plane.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

// nx x ny cells `cell` wide, the first with its lower left corner at `lo`. Cell (x, y)
// has index y nx + x. nx = ny = 0: no grid.
struct GridFrame {
  Vec2 lo{};
  double cell = 1.0;
  int nx = 0, ny = 0;

  bool empty() const { return nx == 0 || ny == 0; }
  std::size_t cells() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(x); }
  bool contains(int x, int y) const { return x >= 0 && x < nx && y >= 0 && y < ny; }
  // The column and row holding a coordinate, floor((v - lo) / cell): beyond the grid
  // for coordinates outside it.
  int column(double x) const { return static_cast<int>(std::floor((x - lo.x) / cell)); }
  int row(double y) const { return static_cast<int>(std::floor((y - lo.y) / cell)); }
  // The same, moved to the nearest column or row of the grid.
  int clamped_column(double x) const { return clamped((x - lo.x) / cell, nx); }
  int clamped_row(double y) const { return clamped((y - lo.y) / cell, ny); }

  // Calls visit(x, y) for each cell of the grid on the square ring r around (cx, cy)
  // (r = 0: the cell itself): row by row upwards, the ring's first and last rows whole,
  // the rows between at their two ends.
  template <typename Visit>
  void for_ring(int cx, int cy, int r, Visit&& visit) const {
    const int x0 = cx - r, x1 = cx + r, y0 = cy - r, y1 = cy + r;
    for (int y = std::max(0, y0); y <= std::min(ny - 1, y1); ++y) {
      if (y == y0 || y == y1) {
        for (int x = std::max(0, x0); x <= std::min(nx - 1, x1); ++x) visit(x, y);
      } else {
        if (x0 >= 0 && x0 < nx) visit(x0, y);
        if (x1 >= 0 && x1 < nx) visit(x1, y);
      }
    }
  }

 private:
  static int clamped(double v, int n) {
    return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(n - 1)));
  }
};

// Items 0 .. n-1 listed by the cells they touch, in compressed rows; each cell lists its
// items in ascending order. Built in two passes over cells_of(k, emit), which calls
// emit(c) once for each cell index c (< cells) that item k touches.
class CellLists {
 public:
  CellLists() = default;
  template <typename CellsOf>
  CellLists(std::size_t cells, std::size_t items, CellsOf&& cells_of) : start_(cells + 1, 0) {
    for (std::size_t k = 0; k < items; ++k) cells_of(k, [&](std::size_t c) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < items; ++k)
      cells_of(k, [&](std::size_t c) { items_[fill[c]++] = static_cast<int>(k); });
  }
  std::span<const int> operator[](std::size_t c) const {
    return {items_.data() + start_[c], start_[c + 1] - start_[c]};
  }

 private:
  std::vector<std::size_t> start_;  // cell c lists items_[start_[c] .. start_[c + 1])
  std::vector<int> items_;
};

// Cells `cell` wide over the whole plane, cell (i, j) holding the values added to it in
// the order they came; only cells in use are stored.
template <typename T>
class HashGrid {
 public:
  explicit HashGrid(double cell) : cell_(cell) {}
  double cell() const { return cell_; }
  // The cell index holding a coordinate, floor(v / cell).
  std::int64_t cell_of(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  void add(std::int64_t i, std::int64_t j, T value) { cells_[{i, j}].push_back(std::move(value)); }
  // The values in cell (i, j); nullptr when it holds none.
  const std::vector<T>* at(std::int64_t i, std::int64_t j) const {
    const auto it = cells_.find({i, j});
    return it == cells_.end() ? nullptr : &it->second;
  }

 private:
  using Key = std::pair<std::int64_t, std::int64_t>;  // whole: cells of tiny points far out stay apart
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(k.first) * 1000003u + static_cast<std::uint64_t>(k.second));
    }
  };
  double cell_;
  std::unordered_map<Key, std::vector<T>, KeyHash> cells_;
};

}  // namespace grainmesh
