// The edges of a mesh of cells given as counter-clockwise rings (triangles or polygons):
// what mesh_edges(TriMesh) and mesh_edges(CellMesh) share. Internal to gm_mesh.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "mesh/mesh_edge.hpp"

namespace grainmesh::mesh_detail {

// `ring(c)` gives cell c's corners for c < cells; `noun` names a cell in errors.
template <typename Ring>
std::vector<MeshEdge> edges_of_rings(std::size_t points, std::size_t cells, Ring&& ring, const std::string& noun) {
  // Half-edges bucketed by their lower end (a counting sort, linear), each bucket (a few
  // half-edges) put in order of the higher end by a stable insertion sort, so that equal
  // edges stay in cell order.
  struct HalfEdge {
    int high, a, b, cell;
  };
  std::vector<std::size_t> start(points + 2, 0);
  std::size_t halves = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const std::span<const int> r = ring(c);
    for (std::size_t k = 0; k < r.size(); ++k) {
      const int a = r[k], b = r[(k + 1) % r.size()];
      if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= points || static_cast<std::size_t>(b) >= points)
        throw GeometryError("mesh: " + noun + " " + std::to_string(c) + " has a point id out of range");
      ++start[static_cast<std::size_t>(std::min(a, b)) + 2];
      ++halves;
    }
  }
  for (std::size_t v = 2; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<HalfEdge> half(halves);
  for (std::size_t c = 0; c < cells; ++c) {
    const std::span<const int> r = ring(c);
    for (std::size_t k = 0; k < r.size(); ++k) {
      const int a = r[k], b = r[(k + 1) % r.size()];
      half[start[static_cast<std::size_t>(std::min(a, b)) + 1]++] = {std::max(a, b), a, b, static_cast<int>(c)};
    }
  }
  for (std::size_t v = 0; v < points; ++v)
    for (std::size_t i = start[v] + 1; i < start[v + 1]; ++i)
      for (std::size_t j = i; j > start[v] && half[j - 1].high > half[j].high; --j) std::swap(half[j - 1], half[j]);
  auto same = [](const HalfEdge& x, const HalfEdge& y) { return std::min(x.a, x.b) == std::min(y.a, y.b) && x.high == y.high; };

  std::vector<MeshEdge> edges;
  edges.reserve(half.size() / 2 + 1);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i + 1;
    while (j < half.size() && same(half[j], half[i])) ++j;
    const HalfEdge& h = half[i];
    if (j - i > 2)
      throw GeometryError("mesh: edge " + std::to_string(h.a) + "-" + std::to_string(h.b) + " has " +
                          std::to_string(j - i) + " " + noun + "s");
    if (j - i == 2) {
      const HalfEdge& g = half[i + 1];
      if (g.a == h.a)
        throw GeometryError("mesh: " + noun + "s " + std::to_string(h.cell) + " and " + std::to_string(g.cell) +
                            " are oriented inconsistently");
      edges.push_back({h.a, h.b, h.cell, g.cell});
    } else {
      edges.push_back({h.a, h.b, h.cell, -1});
    }
    i = j;
  }
  return edges;
}

}  // namespace grainmesh::mesh_detail
