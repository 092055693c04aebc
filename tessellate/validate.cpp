#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/ring.hpp"
#include "tessellate/validate.hpp"

namespace grainmesh {

namespace {

// Every index names something that exists (what the other checks rely on).
void check_indices(const Tessellation& t) {
  const int nv = static_cast<int>(t.vertices.size()), nr = static_cast<int>(t.regions.size());
  const auto vertex = [&](int v) { return v >= 0 && v < nv; };
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (t.grains[g].phase < 0 || t.grains[g].phase >= static_cast<int>(t.phases.size()))
      throw GeometryError("tessellation: grain " + std::to_string(g) + " names phase " +
                          std::to_string(t.grains[g].phase) + ", which does not exist");
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    const Region& region = t.regions[r];
    if (region.grain < 0 || region.grain >= static_cast<int>(t.grains.size()))
      throw GeometryError("tessellation: region " + std::to_string(r) + " names grain " + std::to_string(region.grain) +
                          ", which does not exist");
    if (region.phase < 0 || region.phase >= static_cast<int>(t.phases.size()))
      throw GeometryError("tessellation: region " + std::to_string(r) + " names phase " + std::to_string(region.phase) +
                          ", which does not exist");
    if (region.rings.empty()) throw GeometryError("tessellation: region " + std::to_string(r) + " has no ring");
    for (const auto& ring : region.rings)
      for (int v : ring)
        if (!vertex(v))
          throw GeometryError("tessellation: region " + std::to_string(r) + " names vertex " + std::to_string(v) +
                              ", which does not exist");
  }
  for (std::size_t k = 0; k < t.edges.size(); ++k) {
    const TessEdge& e = t.edges[k];
    if (!vertex(e.v0) || !vertex(e.v1) || e.left < -1 || e.left >= nr || e.right < -1 || e.right >= nr)
      throw GeometryError("tessellation: edge " + std::to_string(k) + " names a vertex or region that does not exist");
  }
  for (const auto* pairs : {&t.partners.axis[0], &t.partners.axis[1]})
    for (const auto& [a, b] : *pairs)
      if (!vertex(a) || !vertex(b)) throw GeometryError("tessellation: a periodic partner names a vertex that does not exist");
}

// Rings counter-clockwise and simple, regions covering the cell, grains numbered by
// position with their regions' area and phase.
void check_areas(const Tessellation& t) {
  const double W = t.width, H = t.height;
  double total = 0.0;
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    for (const auto& ring : t.regions[r].rings) {
      const std::vector<Vec2> pts = ring_points(t.vertices, ring);
      if (!(polygon_area(pts) > 0.0)) throw GeometryError("tessellation: region " + std::to_string(r) + " has a ring that is not counter-clockwise");
      if (!ring_is_simple(pts)) throw GeometryError("tessellation: region " + std::to_string(r) + " has a ring that is not simple");
    }
    total += region_area(t, t.regions[r]);
  }
  if (std::abs(total - W * H) > 1e-9 * W * H)
    throw GeometryError("tessellation: region areas sum to " + std::to_string(total) + ", not W x H");
  // Grains are numbered by position; each grain's recorded area is the area of its regions
  // (what the mesh is checked against), and its regions carry its phase.
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (t.grains[g].id != static_cast<int>(g))
      throw GeometryError("tessellation: grain " + std::to_string(g) + " has id " + std::to_string(t.grains[g].id));
  std::vector<double> grain_area(t.grains.size(), 0.0);
  for (const Region& r : t.regions) {
    if (r.phase != t.grains[r.grain].phase)
      throw GeometryError("tessellation: a region of grain " + std::to_string(r.grain) + " has phase " +
                          std::to_string(r.phase) + ", its grain " + std::to_string(t.grains[r.grain].phase));
    grain_area[r.grain] += region_area(t, r);
  }
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (!(std::abs(grain_area[g] - t.grains[g].area) <= 1e-9 * grain_area[g]))
      throw GeometryError("tessellation: grain " + std::to_string(g) + " records area " + to_text(t.grains[g].area, 12) +
                          " but its regions cover " + to_text(grain_area[g], 12));
}

// The edges exactly the rings' segments, each once, with the regions on their sides; the
// periodic partners in place.
void check_edges(const Tessellation& t) {
  const double W = t.width, H = t.height;
  std::map<std::pair<int, int>, std::size_t> edge_of;
  std::vector<int> uses(t.edges.size(), 0);
  for (std::size_t k = 0; k < t.edges.size(); ++k) {
    const TessEdge& e = t.edges[k];
    if (e.v0 == e.v1) throw GeometryError("tessellation: edge " + std::to_string(k) + " joins a vertex to itself");
    if (e.left == e.right) throw GeometryError("tessellation: an edge has the same region on both sides");
    if ((e.left < 0 || e.right < 0) && cell_side(t, t.vertices[e.v0], t.vertices[e.v1]) == kNoSide)
      throw GeometryError("tessellation: an edge with one side lies inside the cell");
    if (!edge_of.emplace(std::minmax(e.v0, e.v1), k).second)
      throw GeometryError("tessellation: two edges join vertices " + std::to_string(e.v0) + " and " + std::to_string(e.v1));
  }
  for (std::size_t r = 0; r < t.regions.size(); ++r)
    for (std::size_t q = 0; q < t.regions[r].rings.size(); ++q) {
      const auto& ring = t.regions[r].rings[q];
      const bool hole = q > 0;  // counter-clockwise too: the region lies on its right
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const int a = ring[k], b = ring[(k + 1) % ring.size()];
        const auto it = edge_of.find(std::minmax(a, b));
        if (it == edge_of.end())
          throw GeometryError("tessellation: region " + std::to_string(r) + " runs from vertex " + std::to_string(a) +
                              " to " + std::to_string(b) + " along no edge");
        const TessEdge& e = t.edges[it->second];
        if (((e.v0 == a) != hole ? e.left : e.right) != static_cast<int>(r))
          throw GeometryError("tessellation: edge " + std::to_string(it->second) + " does not have region " +
                              std::to_string(r) + " on the side its ring says");
        ++uses[it->second];
      }
    }
  for (std::size_t k = 0; k < t.edges.size(); ++k)
    if (uses[k] != (t.edges[k].left >= 0) + (t.edges[k].right >= 0))
      throw GeometryError("tessellation: edge " + std::to_string(k) + " is not a segment of the regions it names");
  const double tol = 1e-12 * std::max(W, H);
  for (const auto& [l, r] : t.partners.axis[0])
    if (std::abs(t.vertices[r].x - t.vertices[l].x - W) > tol || std::abs(t.vertices[r].y - t.vertices[l].y) > tol)
      throw GeometryError("tessellation: x partners do not match");
  for (const auto& [b, u] : t.partners.axis[1])
    if (std::abs(t.vertices[u].y - t.vertices[b].y - H) > tol || std::abs(t.vertices[u].x - t.vertices[b].x) > tol)
      throw GeometryError("tessellation: y partners do not match");
}

}  // namespace

void validate(const Tessellation& t) {
  check_indices(t);
  check_areas(t);
  check_edges(t);
}

}  // namespace grainmesh
