#include "grains/conformity.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/point_key.hpp"
#include "domain/polygon.hpp"

namespace grainmesh {

PeriodicPairs pair_periodic_nodes(const Tessellation& t, const std::vector<Vec2>& points) {
  if (!t.periodic) return {};
  try {
    return pair_by_position(points, Box{{0.0, 0.0}, {t.width, t.height}});
  } catch (const GeometryError& e) {
    throw GeometryError(std::string("mesh: ") + e.what());
  }
}

namespace {

// The checks, written once for triangles and for cells of any shape.
template <typename Mesh>
Conformity check_cells(const Tessellation& t, const Mesh& mesh, const std::vector<int>& grain,
                       const std::vector<int>& phase, const PeriodicPairs& pairs, double area_tolerance) {
  const double W = t.width, H = t.height;
  Conformity c;
  if (phase.size() != cell_count(mesh) || grain.size() != cell_count(mesh))
    throw GeometryError("conformity: the mesh needs a grain and a phase for each of its cells");
  // Nodes: no two at one place, and every tessellation vertex among them.
  PointMap<int> node;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (!node.emplace(point_key(mesh.points[v]), static_cast<int>(v)).second)
      throw GeometryError("conformity: two nodes at " + to_text(mesh.points[v]));
  for (const Vec2 v : t.vertices)
    if (!node.count(point_key(v))) throw GeometryError("conformity: the tessellation vertex " + to_text(v) + " is no mesh node");
  const auto edges = mesh_edges(mesh);  // throws for an edge of three cells
  for (const MeshEdge& e : edges) {
    if (e.right >= 0) continue;
    ++c.boundary_edges;
    const Vec2 a = mesh.points[e.a], b = mesh.points[e.b];
    if (cell_side(t, a, b) == kNoSide)
      throw GeometryError("conformity: edge " + to_text(a) + " - " + to_text(b) + " has one cell but lies inside the periodic cell");
  }
  // Each cell inside the region of its grain: its centroid strictly inside one of the
  // grain's regions and its corners no farther than rounding from it.
  std::vector<std::vector<int>> regions_of(t.grains.size());
  std::vector<PolygonDistance> dist;
  dist.reserve(t.regions.size());
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    PolygonRings rings;
    for (const auto& ring : t.regions[r].rings) rings.push_back(ring_points(t.vertices, ring));
    dist.emplace_back(rings);
    regions_of[t.regions[r].grain].push_back(static_cast<int>(r));
  }
  const double tol = 1e-12 * std::max(W, H);
  std::vector<double> area(t.grains.size(), 0.0);
  for (std::size_t k = 0; k < cell_count(mesh); ++k) {
    const int g = grain[k];
    const std::string cell = "conformity: cell " + std::to_string(k);
    if (g < 0 || static_cast<std::size_t>(g) >= t.grains.size()) throw GeometryError(cell + " names grain " + std::to_string(g));
    const Vec2 centre = cell_centroid(mesh, k);
    bool inside = false;
    for (int r : regions_of[g]) {
      if (!dist[r].contains(centre)) continue;
      inside = true;
      for (int v : cell_ring(mesh, k))
        if (dist[r](mesh.points[v]) > tol) throw GeometryError(cell + " reaches out of its grain " + std::to_string(g));
    }
    if (!inside) throw GeometryError(cell + " lies outside its grain " + std::to_string(g));
    if (phase[k] != t.grains[g].phase)
      throw GeometryError(cell + " has phase " + std::to_string(phase[k]) + ", its grain " + std::to_string(g) +
                          " phase " + std::to_string(t.grains[g].phase));
    area[g] += cell_area(mesh, k);
  }
  for (const Grain& g : t.grains) {
    const double err = std::abs(area[g.id] - g.area) / g.area;
    c.max_area_error = std::max(c.max_area_error, err);
    if (err > area_tolerance)
      throw GeometryError("conformity: grain " + std::to_string(g.id) + " has mesh area " + to_text(area[g.id], 12) +
                          " for polygon area " + to_text(g.area, 12));
  }
  if (t.periodic) {
    std::size_t left = 0, bottom = 0;
    for (const Vec2 p : mesh.points) {
      left += p.x == 0.0 ? 1 : 0;
      bottom += p.y == 0.0 ? 1 : 0;
    }
    if (pairs.axis[0].size() != left || pairs.axis[1].size() != bottom)
      throw GeometryError("conformity: not every node on the left or bottom side is paired");
    for (const auto& [a, b] : pairs.axis[0])
      c.max_pair_mismatch = std::max(c.max_pair_mismatch, norm(mesh.points[b] - mesh.points[a] - Vec2{W, 0.0}));
    for (const auto& [a, b] : pairs.axis[1])
      c.max_pair_mismatch = std::max(c.max_pair_mismatch, norm(mesh.points[b] - mesh.points[a] - Vec2{0.0, H}));
    if (c.max_pair_mismatch > tol) throw GeometryError("conformity: periodic node pairs do not match");
  }
  return c;
}

}  // namespace

Conformity check_conformity(const Tessellation& t, const GrainMesh& m, double area_tolerance) {
  return check_cells(t, m.mesh, m.grain, m.phase, m.pairs, area_tolerance);
}

Conformity check_conformity(const Tessellation& t, const LabelledCells& m, double area_tolerance) {
  return check_cells(t, m.mesh, m.grain, m.phase, m.pairs, area_tolerance);
}

}  // namespace grainmesh
