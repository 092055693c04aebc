#include "export/element_mesh.hpp"

#include <algorithm>
#include <bit>
#include <optional>
#include <set>

#include "common/errors.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

namespace {

// Bit s set when point p lies on side s of the cell.
std::vector<unsigned> side_bits(const ElementMesh& m) {
  std::vector<unsigned> bits(m.points.size(), 0u);
  for (std::size_t p = 0; p < m.points.size(); ++p)
    for (int axis = 0; axis < m.dimensions; ++axis) {
      if (m.points[p][axis] == m.cell.lo[axis]) bits[p] |= 1u << (2 * axis);
      if (m.points[p][axis] == m.cell.hi[axis]) bits[p] |= 1u << (2 * axis + 1);
    }
  return bits;
}

// Follows a high-side point's images down to the point on no high side.
struct Images {
  std::vector<std::array<int, 3>> low;  // per point and axis: its image on the low side, or -1
  int root(int p, std::array<bool, 3>& across) const {
    for (bool moved = true; moved;) {
      moved = false;
      for (int axis = 0; axis < 3 && !moved; ++axis)
        if (low[p][axis] >= 0) {
          across[axis] = true;
          p = low[p][axis];
          moved = true;
        }
    }
    return p;
  }
};

}  // namespace

ElementMesh element_mesh(const ExportMesh<2>& m) {
  const std::optional<TriMesh> tri = as_triangles(m.mesh);
  if (!tri) throw GeometryError("a finite-element mesh file takes triangles; this mesh has polygonal cells");
  ElementMesh e{.dimensions = 2, .points = {}, .elements = {}, .grain = m.grain, .phase = m.phase,
                .phases = m.phases, .cell = Box3{{m.cell.lo.x, m.cell.lo.y, 0.0}, {m.cell.hi.x, m.cell.hi.y, 0.0}},
                .periodic = m.periodic, .pairs = m.pairs};
  e.points.reserve(tri->points.size());
  for (const Vec2& p : tri->points) e.points.push_back({p.x, p.y, 0.0});
  e.elements.reserve(tri->triangles.size());
  for (const auto& t : tri->triangles) e.elements.push_back({t[0], t[1], t[2], -1});
  return e;
}

ElementMesh element_mesh(const ExportMesh<3>& m) {
  return {.dimensions = 3, .points = m.mesh.points, .elements = m.mesh.tets, .grain = m.grain, .phase = m.phase,
          .phases = m.phases, .cell = m.cell, .periodic = m.periodic, .pairs = m.pairs};
}

const char* side_name(const ElementMesh&, int s) { return kSideNames3[s]; }

std::vector<std::vector<std::array<int, 3>>> side_facets(const ElementMesh& m) {
  // A facet all of whose corners lie on one side is on the cell's boundary (the mesh fills
  // the cell), and met once.
  const std::vector<unsigned> bits = side_bits(m);
  std::vector<std::vector<std::array<int, 3>>> facets(m.sides());
  const int n = m.corners();
  for (const auto& el : m.elements)
    for (int skip = 0; skip < n; ++skip) {
      std::array<int, 3> f{-1, -1, -1};
      unsigned common = ~0u;
      for (int k = 1, i = 0; k < n; ++k) {
        // The facet opposite corner `skip`, its corners in cyclic order from the next one.
        f[i++] = el[(skip + k) % n];
        common &= bits[f[i - 1]];
      }
      if (common == 0u) continue;
      const int side = std::countr_zero(common);
      // Tetrahedra: (skip+1, skip+2, skip+3) faces inward for odd skip; turn it outward.
      if (n == 4 && skip % 2 == 1) std::swap(f[1], f[2]);
      facets[side].push_back(f);
    }
  return facets;
}

std::vector<std::vector<int>> side_points(const ElementMesh& m) {
  const std::vector<unsigned> bits = side_bits(m);
  std::vector<std::vector<int>> points(m.sides());
  for (std::size_t p = 0; p < m.points.size(); ++p)
    for (int s = 0; s < m.sides(); ++s)
      if (bits[p] & (1u << s)) points[s].push_back(static_cast<int>(p));
  return points;
}

std::vector<PeriodicTie> periodic_ties(const ElementMesh& m) {
  std::vector<PeriodicTie> ties;
  if (!m.periodic) return ties;
  Images images{std::vector<std::array<int, 3>>(m.points.size(), {-1, -1, -1})};
  for (int axis = 0; axis < m.dimensions; ++axis)
    for (const auto& [low, high] : m.pairs.axis[axis]) {
      if (images.low[high][axis] >= 0 && images.low[high][axis] != low)
        throw GeometryError("periodic pairs: point " + std::to_string(high) + " has two images across axis " +
                            std::to_string(axis));
      images.low[high][axis] = low;
    }
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    const auto& low = images.low[p];
    if (low[0] < 0 && low[1] < 0 && low[2] < 0) continue;
    PeriodicTie tie{.point = static_cast<int>(p)};
    tie.root = images.root(tie.point, tie.across);
    // The same root whichever axis is followed first: the pairs are consistent.
    for (int axis = 0; axis < 3; ++axis) {
      if (low[axis] < 0) continue;
      std::array<bool, 3> across{};
      across[axis] = true;
      if (images.root(low[axis], across) != tie.root || across != tie.across)
        throw GeometryError("periodic pairs: point " + std::to_string(p) + " has images on different roots");
    }
    ties.push_back(tie);
  }
  return ties;
}

std::vector<int> grains_of(const ElementMesh& m) {
  const std::set<int> grains(m.grain.begin(), m.grain.end());
  return {grains.begin(), grains.end()};
}

}  // namespace grainmesh
