// The boundaries of a label image's pieces on the lattice of pixel corners: traced into
// chains between junctions, then simplified within a tolerance without changing their
// topology (image_tessellation.cpp builds the tessellation from them).
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

enum Dir { kE = 0, kN = 1, kW = 2, kS = 3 };
constexpr double kPinchOffset = 0.25;  // pixels: how far a pinch's two corners move apart

// The boundaries on the lattice of pixel corners: vertex (i, j), 0 <= i <= nx, 0 <= j <= ny,
// at (i, j) in pixel units; an edge of it is a boundary where the pieces on its two sides
// differ (the image's border is not one of these: the sides are laid separately).
struct Lattice {
  int nx, ny;
  const std::vector<int>& piece;  // per pixel

  int at(int i, int j) const {
    return i < 0 || j < 0 || i >= nx || j >= ny ? -1 : piece[static_cast<std::size_t>(j) * nx + i];
  }
  // The pieces left and right of the edge leaving (i, j) in direction d.
  std::pair<int, int> sides(int i, int j, int d) const {
    switch (d) {
      case kE:
        return {at(i, j), at(i, j - 1)};
      case kN:
        return {at(i - 1, j), at(i, j)};
      case kW:
        return {at(i - 1, j - 1), at(i - 1, j)};
      default:
        return {at(i, j - 1), at(i - 1, j - 1)};
    }
  }
  bool boundary(int i, int j, int d) const {
    const auto [l, r] = sides(i, j, d);
    return l >= 0 && r >= 0 && l != r;
  }
  int degree(int i, int j) const {
    int n = 0;
    for (int d = 0; d < 4; ++d) n += boundary(i, j, d);
    return n;
  }
  bool on_side(int i, int j) const { return i == 0 || j == 0 || i == nx || j == ny; }
  // A piece touching itself across the corner (i, j): its two diagonal pixels one piece.
  bool pinch(int i, int j) const {
    return !on_side(i, j) && degree(i, j) == 4 && (at(i - 1, j - 1) == at(i, j) || at(i, j - 1) == at(i - 1, j));
  }
  bool junction(int i, int j) const { return on_side(i, j) || (degree(i, j) >= 3 && !pinch(i, j)); }
  // At a pinch, the two pieces apart from the one touching itself keep their corners: the
  // edge leaving in d continues along its partner, at the corner moved toward that pixel.
  int partner(int i, int j, int d) const {
    const bool ll_ur = at(i - 1, j - 1) == at(i, j);
    static constexpr std::array<int, 4> a{kS, kW, kN, kE}, b{kN, kE, kS, kW};
    return ll_ur ? a[d] : b[d];
  }
  Vec2 pinch_corner(int i, int j, int d) const {
    const bool ll_ur = at(i - 1, j - 1) == at(i, j);
    const int q = ll_ur ? (d == kE || d == kS ? 0 : 1) : (d == kE || d == kN ? 2 : 3);
    static constexpr std::array<double, 4> ox{1, -1, 1, -1}, oy{-1, 1, 1, -1};
    return {i + kPinchOffset * ox[q], j + kPinchOffset * oy[q]};
  }
  // The edge's index among the lattice's edges (horizontal ones first), for marking it.
  std::size_t edge(int i, int j, int d) const {
    const std::size_t horizontal = static_cast<std::size_t>(nx) * (ny + 1);
    switch (d) {
      case kE:
        return static_cast<std::size_t>(j) * nx + i;
      case kW:
        return static_cast<std::size_t>(j) * nx + i - 1;
      case kN:
        return horizontal + static_cast<std::size_t>(j) * (nx + 1) + i;
      default:
        return horizontal + static_cast<std::size_t>(j - 1) * (nx + 1) + i;
    }
  }
  std::size_t edges() const { return static_cast<std::size_t>(nx) * (ny + 1) + static_cast<std::size_t>(nx + 1) * ny; }
  long long vertex(int i, int j) const { return static_cast<long long>(j) * (nx + 1) + i; }
};

// A boundary between two junctions (or a closed one), as traced and as kept.
struct Chain {
  std::vector<Vec2> points;       // pixel units, from the first junction to the last
  long long first = 0, last = 0;  // lattice vertices of its ends (equal when closed)
  int left = -1, right = -1;      // pieces
  double tolerance = 0.0;
  std::vector<int> kept;  // indices into points, ascending, ends included
};

// Every boundary of the lattice, each once, as a chain between junctions (or closed).
std::vector<Chain> trace(const Lattice& L);

// Every chain kept at the tolerance (pixels), or finer where that changed the topology: a
// chain in conflict halves its tolerance until none is (at zero each chain is as traced).
void simplify_chains(std::vector<Chain>& chains, double tolerance, int nx, int ny);

}  // namespace grainmesh
