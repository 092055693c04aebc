#include "tessellate/neper_import.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "common/errors.hpp"
#include "common/ring.hpp"
#include "tessellate/cut.hpp"
#include "tessellate/read_tessellation.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/tessellate_3d.hpp"
#include "tessellate/validate_3d.hpp"

namespace grainmesh {

namespace {

// What both dimensions refuse: another dimension, a domain not a box, periodicity.
void check_kind(const NeperTess& n, int dimensions, const std::string& source) {
  const char* box = dimensions == 2 ? "square" : "cube";
  if (n.dimensions != dimensions)
    throw GeometryError(source + ": a " + std::to_string(n.dimensions) + "D tessellation where a " +
                        std::to_string(dimensions) + "D one is read");
  if (n.domain_type != box)
    throw GeometryError(source + ": a " + n.domain_type + " domain: grainmesh meshes a " + box + " (a box) cell");
  if (n.periodic)
    throw GeometryError(source + ": a periodic tessellation (**periodicity): periodic Neper tessellations are not "
                                 "read yet; write it without -periodicity");
}

// A vertex in the cell's frame (the domain's low corner at the origin); -0 made +0.
Vec3 in_cell(const NeperTess& n, const Vec3& v) {
  return {(v.x - n.domain.lo.x) + 0.0, (v.y - n.domain.lo.y) + 0.0, (v.z - n.domain.lo.z) + 0.0};
}

}  // namespace

Tessellation plane_tessellation(const NeperTess& n, const std::vector<Phase>& phases, Arrangement arrangement,
                                Rng& rng, const std::string& source) {
  check_kind(n, 2, source);
  Tessellation t;
  t.width = n.domain.hi.x - n.domain.lo.x;
  t.height = n.domain.hi.y - n.domain.lo.y;
  t.periodic = false;
  t.phases = phases;
  // Each cell a counter-clockwise polygon; an edge's endpoints in one order for both sides.
  std::vector<CutPolygon> polys;
  for (int c = 0; c < n.cells(); ++c) {
    std::vector<int> ring = n.faces[c];
    std::vector<Vec2> pts;
    for (int v : ring) {
      const Vec3 p = in_cell(n, n.vertices[v]);
      pts.push_back({p.x, p.y});
    }
    if (polygon_area(pts) < 0.0) {
      std::reverse(ring.begin(), ring.end());
      std::reverse(pts.begin(), pts.end());
    }
    CutPolygon poly{.grain = c, .phase = 0, .corners = {}, .edges = {}};
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const std::size_t next = (k + 1) % ring.size();
      poly.corners.push_back({pts[k], 0, 0});
      const bool forward = ring[k] < ring[next];
      poly.edges.push_back({forward ? pts[k] : pts[next], forward ? pts[next] : pts[k], 0, 0});
    }
    polys.push_back(std::move(poly));
  }
  cut_into_cell(polys, t, -1, -1);
  // Grains: the cells, their seeds, their neighbours across the edges, their areas.
  std::set<std::pair<int, int>> touching;
  for (const TessEdge& e : t.edges)
    if (e.left >= 0 && e.right >= 0 && t.regions[e.left].grain != t.regions[e.right].grain)
      touching.insert(std::minmax(t.regions[e.left].grain, t.regions[e.right].grain));
  const auto neighbours = neighbour_lists(polys.size(), touching);
  std::vector<double> areas(polys.size(), 0.0);
  for (const Region& r : t.regions) areas[r.grain] += region_area(t, r);
  const double total = t.width * t.height;
  double sum = 0.0;
  for (double a : areas) sum += a;
  if (std::abs(sum - total) > 1e-9 * total)
    throw GeometryError(source + ": the cells cover an area of " + std::to_string(sum) + ", the domain " +
                        std::to_string(total));
  const std::vector<int> label = phases_by_rules(areas, neighbours, phases, arrangement, total, rng);
  for (int c = 0; c < n.cells(); ++c) {
    const Vec3 s = in_cell(n, n.seeds[c]);
    t.grains.push_back(Grain{.id = c, .phase = label[c], .seed = {s.x, s.y}, .area = 0.0,
                             .neighbours = neighbours[c], .matrix = false});
  }
  for (Region& r : t.regions) r.phase = t.grains[r.grain].phase;
  double edges = 0.0, touches = 0.0;
  for (const Region& r : t.regions) edges += static_cast<double>(r.rings[0].size());
  for (const auto& l : neighbours) touches += static_cast<double>(l.size());
  t.stats.edges_per_grain_mean = edges / n.cells();
  t.stats.neighbours_mean = touches / n.cells();
  measure_read_tessellation(t, source);
  return t;
}

Tessellation3 solid_tessellation(const NeperTess& n, const std::vector<Phase>& phases, Arrangement arrangement,
                                 Rng& rng, const std::string& source) {
  check_kind(n, 3, source);
  Tessellation3 t;
  const Vec3 size = n.domain.hi - n.domain.lo;
  t.width = size.x;
  t.height = size.y;
  t.depth = size.z;
  t.periodic = false;
  t.phases = phases;
  for (const Vec3& v : n.vertices) t.vertices.push_back(in_cell(n, v));
  // Each face between the polyhedra that list it: its ring's normal from back into front
  // (found from the polyhedra's centroids, whatever the file's signs), a box face turned
  // to face out of its one polyhedron.
  std::vector<Vec3> centroid(n.cells());
  for (int c = 0; c < n.cells(); ++c) {
    std::set<int> corners;
    for (int f : n.polyhedra[c])
      for (int v : n.faces[std::abs(f) - 1]) corners.insert(v);
    for (int v : corners) centroid[c] += t.vertices[v];
    centroid[c] = centroid[c] / static_cast<double>(corners.size());
  }
  std::vector<std::vector<int>> owners(n.faces.size());
  for (int c = 0; c < n.cells(); ++c)
    for (int f : n.polyhedra[c]) owners[std::abs(f) - 1].push_back(c);
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const auto& own = owners[f];
    if (own.empty() || own.size() > 2)
      throw GeometryError(source + ": face " + std::to_string(f + 1) + " belongs to " + std::to_string(own.size()) +
                          " polyhedra");
    Face3 face{.ring = n.faces[f], .back = own[0], .front = own.size() == 2 ? own[1] : -1};
    const Vec3 normal = ring_normal(t.vertices, face.ring), at = t.vertices[face.ring[0]];
    if (dot(normal, centroid[own[0]] - at) > 0.0) {  // own[0] lies in front
      if (face.front >= 0) std::swap(face.back, face.front);
      else std::reverse(face.ring.begin(), face.ring.end());
    }
    t.faces.push_back(std::move(face));
  }
  for (int c = 0; c < n.cells(); ++c) {
    Region3 r{.grain = c, .phase = 0, .faces = {}, .volume = 0.0};
    for (int f : n.polyhedra[c]) r.faces.push_back(std::abs(f) - 1);
    t.regions.push_back(std::move(r));
    t.regions.back().volume = region_volume(t, t.regions.back());  // (it finds its own faces' sides by its index)
  }
  std::set<std::pair<int, int>> touching;
  for (const Face3& f : t.faces)
    if (f.front >= 0) touching.insert(std::minmax(f.back, f.front));
  const auto neighbours = neighbour_lists(n.cells(), touching);
  std::vector<double> volumes;
  for (const Region3& r : t.regions) volumes.push_back(r.volume);
  const double total = t.width * t.height * t.depth;
  const std::vector<int> label = phases_by_rules(volumes, neighbours, phases, arrangement, total, rng);
  for (int c = 0; c < n.cells(); ++c) {
    t.grains.push_back(Grain3{.id = c, .phase = label[c], .seed = in_cell(n, n.seeds[c]), .volume = volumes[c],
                              .faces = static_cast<int>(n.polyhedra[c].size()), .neighbours = neighbours[c]});
    t.regions[c].phase = label[c];
  }
  try {
    validate(t);
  } catch (const GeometryError& e) {
    throw GeometryError(source + ": " + e.what());
  }
  measure_tessellation(t);
  return t;
}

}  // namespace grainmesh
