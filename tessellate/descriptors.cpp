#include "tessellate/descriptors.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

namespace grainmesh {

namespace {

// The region on the cell's side of an edge along a cell side.
int inner_region(const TessEdge& e) { return e.left >= 0 ? e.left : e.right; }

}  // namespace

std::vector<PhaseDescriptors> phase_descriptors(const Tessellation& t) {
  std::vector<PhaseDescriptors> d(t.phases.size());
  for (const Region& r : t.regions) d[r.phase].area += region_area(t, r);

  // A boundary between regions a and b of length `length`.
  auto add = [&](int a, int b, double length) {
    const Region& ra = t.regions[a];
    const Region& rb = t.regions[b];
    if (ra.grain == rb.grain) return;  // pieces of one grain
    if (ra.phase == rb.phase) {
      d[ra.phase].own_boundary += length;
    } else {
      d[ra.phase].other_boundary += length;
      d[rb.phase].other_boundary += length;
    }
  };

  // Each left (bottom) side vertex's partner on the right (top) side, and the edges along
  // the right and top sides by their vertices: the region across a periodic side.
  std::map<int, int> partner_x(t.partners.axis[0].begin(), t.partners.axis[0].end());
  std::map<int, int> partner_y(t.partners.axis[1].begin(), t.partners.axis[1].end());
  std::map<std::pair<int, int>, int> side_edge;  // (v0, v1) sorted -> edge
  for (std::size_t k = 0; k < t.edges.size(); ++k) {
    const TessEdge& e = t.edges[k];
    const CellSide side = cell_side(t, t.vertices[e.v0], t.vertices[e.v1]);
    if (side == kRight || side == kTop) side_edge[std::minmax(e.v0, e.v1)] = static_cast<int>(k);
  }

  for (const TessEdge& e : t.edges) {
    const double length = norm(t.vertices[e.v1] - t.vertices[e.v0]);
    if (e.left >= 0 && e.right >= 0) {
      add(e.left, e.right, length);
      continue;
    }
    if (!t.periodic) continue;
    const CellSide side = cell_side(t, t.vertices[e.v0], t.vertices[e.v1]);
    if (side != kLeft && side != kBottom) continue;  // each pair of sides once, from left and bottom
    const std::map<int, int>& partner = side == kLeft ? partner_x : partner_y;
    const auto p0 = partner.find(e.v0), p1 = partner.find(e.v1);
    if (p0 == partner.end() || p1 == partner.end()) continue;
    const auto across = side_edge.find(std::minmax(p0->second, p1->second));
    if (across == side_edge.end()) continue;
    add(inner_region(e), inner_region(t.edges[across->second]), length);
  }

  for (PhaseDescriptors& p : d) {
    const Stereology s = stereology(2, p.area, p.own_boundary, p.other_boundary);
    p.contiguity = s.contiguity;
    p.intercept_length = s.intercept_length;
    p.mean_free_path = s.mean_free_path;
  }
  return d;
}

Stereology stereology(int dimensions, double size, double own_boundary, double other_boundary) {
  const double chord = dimensions == 2 ? std::numbers::pi : 4.0;
  const double boundary = 2.0 * own_boundary + other_boundary;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {.contiguity = boundary > 0.0 ? 2.0 * own_boundary / boundary : nan,
          .intercept_length = boundary > 0.0 ? chord * size / boundary : nan,
          .mean_free_path =
              other_boundary > 0.0 ? chord * size / other_boundary : std::numeric_limits<double>::infinity()};
}

}  // namespace grainmesh
