#include "tessellate/neper_import.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/ring.hpp"
#include "tessellate/cut.hpp"
#include "tessellate/laguerre_3d.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/tessellate_3d.hpp"
#include "tessellate/torus.hpp"
#include "tessellate/validate_3d.hpp"

namespace grainmesh {

namespace {

// How far (x the longest period) a periodic image may lie from its primary moved by whole
// periods: Neper writes coordinates to 12 decimals.
constexpr double kImageTolerance = 1e-9;

// What both dimensions refuse: another dimension, a domain not a box (Neper 4 calls a 2D
// square domain a cube; a rotated one is not a box of ours), periodicity along some axes
// only or with periods that are not the domain's.
void check_kind(const NeperTess& n, int dimensions, const std::string& source) {
  const char* box = dimensions == 2 ? "square" : "cube";
  if (n.dimensions != dimensions)
    throw GeometryError(source + ": a " + std::to_string(n.dimensions) + "D tessellation where a " +
                        std::to_string(dimensions) + "D one is read");
  if (n.domain_type != "cube" && n.domain_type != box)
    throw GeometryError(source + ": a " + n.domain_type + " domain: grainmesh meshes a " + box + " (a box) cell");
  // Its corners are the corners of their bounding box, the sides along the axes.
  const Vec3 size = n.domain.hi - n.domain.lo;
  const double scale = std::max({size.x, size.y, size.z});
  std::set<int> corners;
  for (const Vec3& p : n.domain_vertices) {
    int corner = 0;
    bool at_corner = true;
    for (int a = 0; a < dimensions; ++a) {
      const bool high = std::abs(p[a] - n.domain.hi[a]) <= 1e-9 * scale;
      at_corner = at_corner && (high || std::abs(p[a] - n.domain.lo[a]) <= 1e-9 * scale);
      corner |= (high ? 1 : 0) << a;
    }
    if (at_corner) corners.insert(corner);
  }
  if (n.domain_vertices.size() != (1u << dimensions) || corners.size() != (1u << dimensions) ||
      (dimensions == 2 && size.z > 1e-9 * scale))
    throw GeometryError(source + ": the domain is not a " + box +
                        " with sides along the axes (rotated or cut?): grainmesh meshes such a box");
  if (!n.periodic) return;
  for (int a = 0; a < dimensions; ++a) {
    const char axis = static_cast<char>('x' + a);
    if (!n.periodic_axes[a])
      throw GeometryError(source + ": periodic along some axes only (not " + axis +
                          "): grainmesh reads tessellations periodic along every axis, or none");
    if (std::abs(n.period[a] - size[a]) > 1e-9 * size[a])
      throw GeometryError(source + ": the period along " + axis + " is " + to_text(n.period[a]) +
                          ", the domain's side " + to_text(size[a]));
  }
}

// A vertex in the cell's frame (the domain's low corner at the origin); -0 made +0.
Vec3 in_cell(const NeperTess& n, const Vec3& v) {
  return {(v.x - n.domain.lo.x) + 0.0, (v.y - n.domain.lo.y) + 0.0, (v.z - n.domain.lo.z) + 0.0};
}

// Each vertex as a lattice point: its primary (through chains of images) moved by whole
// periods; a vertex of a file that is not periodic is its own primary. Each image is
// checked to lie where its primary moved by its shift lies.
std::vector<LatticeCorner> lattice_vertices(const NeperTess& n, int dimensions, const std::string& source) {
  const int count = static_cast<int>(n.vertices.size());
  std::vector<LatticeCorner> out(count);
  for (int v = 0; v < count; ++v) out[v].base = v;
  if (!n.periodic) return out;
  std::vector<int> parent(count, -1);
  std::vector<std::array<int, 3>> step(count);
  for (const NeperTess::Image& image : n.vertex_images) {
    if (parent[image.vertex] >= 0)
      throw GeometryError(source + ": periodic vertex " + std::to_string(image.vertex + 1) + " is listed twice");
    parent[image.vertex] = image.primary;
    step[image.vertex] = image.shift;
  }
  const Vec3 size = n.domain.hi - n.domain.lo;
  const double scale = std::max({size.x, size.y, dimensions == 3 ? size.z : 0.0});
  for (int v = 0; v < count; ++v) {
    LatticeCorner& c = out[v];
    for (int steps = 0; parent[c.base] >= 0; ++steps) {
      if (steps > count) throw GeometryError(source + ": the periodic vertices' primaries form a loop");
      for (int a = 0; a < 3; ++a) c.shift[a] += step[c.base][a];
      c.base = parent[c.base];
    }
    for (int a = 0; a < dimensions; ++a) {
      const double off = n.vertices[v][a] - (n.vertices[c.base][a] + c.shift[a] * size[a]);
      if (std::abs(off) > kImageTolerance * scale)
        throw GeometryError(source + ": vertex " + std::to_string(v + 1) + " is not its primary, vertex " +
                            std::to_string(c.base + 1) + ", moved by whole periods (off by " + to_text(off, 3) + ")");
    }
  }
  return out;
}

// A face or an edge of whole cells as a key that is the same for each periodic image of
// it: its corners' primaries with their shifts relative to its least corner's, sorted.
using ImageKey = std::vector<std::pair<int, std::array<int, 3>>>;
ImageKey image_key(const std::vector<LatticeCorner>& ring) {
  ImageKey key;
  for (const LatticeCorner& c : ring) key.emplace_back(c.base, c.shift);
  std::sort(key.begin(), key.end());
  const std::array<int, 3> origin = key.front().second;
  for (auto& [base, shift] : key)
    for (int a = 0; a < 3; ++a) shift[a] -= origin[a];
  std::sort(key.begin(), key.end());
  return key;
}

// The cells sharing a face (2D: an edge), periodic images included: `sides[c]` are cell
// c's faces as rings of lattice corners.
std::vector<std::vector<int>> shared_side_neighbours(
    const std::vector<std::vector<std::vector<LatticeCorner>>>& sides) {
  std::map<ImageKey, std::vector<int>> owners;
  for (int c = 0; c < static_cast<int>(sides.size()); ++c)
    for (const auto& side : sides[c]) owners[image_key(side)].push_back(c);
  std::set<std::pair<int, int>> touching;
  for (const auto& [key, cells] : owners)
    for (std::size_t i = 0; i < cells.size(); ++i)
      for (std::size_t j = i + 1; j < cells.size(); ++j)
        if (cells[i] != cells[j]) touching.insert(std::minmax(cells[i], cells[j]));
  return neighbour_lists(sides.size(), touching);
}

// Each cell's phase: from its group through the table, or by our rules from the cells'
// sizes (areas or volumes) and neighbours.
std::vector<int> cell_phases(const NeperTess& n, const NeperPhases& ph, const std::vector<double>& sizes,
                             const std::vector<std::vector<int>>& neighbours, double total, Rng& rng,
                             const std::string& source) {
  if (ph.group_phases.empty()) return phases_by_rules(sizes, neighbours, ph.phases, ph.arrangement, total, rng);
  if (n.groups.empty()) throw UnnamedLabelError(source + ": has no cell groups (*group) to take the phases from");
  std::vector<int> phase(n.cells(), -1);
  std::map<int, int> missing;  // group -> cells
  for (int c = 0; c < n.cells(); ++c) {
    if (n.groups[c] >= 0) phase[c] = phase_of_label(ph.group_phases, static_cast<std::uint32_t>(n.groups[c]));
    if (phase[c] < 0) ++missing[n.groups[c]];
  }
  if (!missing.empty()) {
    const auto& [group, cells] = *missing.begin();
    throw UnnamedLabelError(
        source + ": group " + std::to_string(group) + " (" + std::to_string(cells) + (cells == 1 ? " cell" : " cells") +
        ") has no phase in the table" +
        (missing.size() > 1 ? " (nor " + std::to_string(missing.size() - 1) + " other groups)" : ""));
  }
  return phase;
}

// The lattice corners of a face's ring.
std::vector<LatticeCorner> corners_of(const std::vector<int>& ring, const std::vector<LatticeCorner>& lattice) {
  std::vector<LatticeCorner> out;
  for (int v : ring) out.push_back(lattice[v]);
  return out;
}

Vec3 unwrapped(const std::vector<Vec3>& bases, const LatticeCorner& c, Vec3 size) {
  const Vec3 b = bases[c.base];
  return {b.x + c.shift[0] * size.x, b.y + c.shift[1] * size.y, b.z + c.shift[2] * size.z};
}

}  // namespace

Tessellation plane_tessellation(const NeperTess& n, const NeperPhases& ph, Rng& rng, const std::string& source) {
  check_kind(n, 2, source);
  Tessellation t;
  const Vec3 size = n.domain.hi - n.domain.lo;
  t.width = size.x;
  t.height = size.y;
  t.periodic = n.periodic;
  t.phases = ph.phases;
  const std::vector<LatticeCorner> lattice = lattice_vertices(n, 2, source);
  // Each cell a counter-clockwise ring of corners (primaries and shifts) of a graph whose
  // vertices are the primaries; its edges as the cells' sides.
  TorusGraph g;
  g.width = t.width;
  g.height = t.height;
  g.periodic = n.periodic;
  for (const Vec3& v : n.vertices) {
    const Vec3 p = in_cell(n, v);
    g.vertices.push_back({p.x, p.y});
  }
  std::vector<std::vector<std::vector<LatticeCorner>>> sides(n.cells());
  for (int c = 0; c < n.cells(); ++c) {
    std::vector<Corner> ring;
    for (int v : n.faces[c]) ring.push_back({lattice[v].base, lattice[v].shift[0], lattice[v].shift[1]});
    std::vector<Vec2> pts;
    for (const Corner& k : ring) pts.push_back(g.point(k));
    if (polygon_area(pts) < 0.0) std::reverse(ring.begin(), ring.end());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Corner& a = ring[k];
      const Corner& b = ring[(k + 1) % ring.size()];
      sides[c].push_back({{a.v, {a.i, a.j, 0}}, {b.v, {b.i, b.j, 0}}});
    }
    g.rings.push_back(std::move(ring));
  }
  std::vector<int> cells(n.cells());
  for (int c = 0; c < n.cells(); ++c) cells[c] = c;
  cut_into_cell(cell_polygons(g, cells), t, -1, -1);
  // Grains: the cells, their seeds, their neighbours across their sides, their areas.
  const auto neighbours = shared_side_neighbours(sides);
  std::vector<double> areas(n.cells(), 0.0);
  for (const Region& r : t.regions) areas[r.grain] += region_area(t, r);
  const double total = t.width * t.height;
  double sum = 0.0;
  for (double a : areas) sum += a;
  if (std::abs(sum - total) > 1e-9 * total)
    throw GeometryError(source + ": the cells cover an area of " + std::to_string(sum) + ", the domain " +
                        std::to_string(total));
  const std::vector<int> label = cell_phases(n, ph, areas, neighbours, total, rng, source);
  for (int c = 0; c < n.cells(); ++c) {
    const Vec3 s = in_cell(n, n.seeds[c]);
    t.grains.push_back(Grain{
        .id = c, .phase = label[c], .seed = {s.x, s.y}, .area = 0.0, .neighbours = neighbours[c], .matrix = false});
  }
  for (Region& r : t.regions) r.phase = t.grains[r.grain].phase;
  double edges = 0.0, touches = 0.0;
  for (const auto& ring : g.rings) edges += static_cast<double>(ring.size());
  for (const auto& l : neighbours) touches += static_cast<double>(l.size());
  t.stats.edges_per_grain_mean = edges / n.cells();
  t.stats.neighbours_mean = touches / n.cells();
  measure_read_tessellation(t, source);
  return t;
}

namespace {

// Each face between the polyhedra that list it (one or two): GeometryError otherwise.
std::vector<std::vector<int>> face_owners(const NeperTess& n, const std::string& source) {
  std::vector<std::vector<int>> owners(n.faces.size());
  for (int c = 0; c < n.cells(); ++c)
    for (int f : n.polyhedra[c]) owners[std::abs(f) - 1].push_back(c);
  for (std::size_t f = 0; f < n.faces.size(); ++f)
    if (owners[f].empty() || owners[f].size() > 2)
      throw GeometryError(source + ": face " + std::to_string(f + 1) + " belongs to " +
                          std::to_string(owners[f].size()) + " polyhedra");
  return owners;
}

// A solid cut by the domain (not periodic): its faces as they are, each ring's normal from
// back into front (found from the polyhedra's centroids, whatever the file's signs), a box
// face turned to face out of its one polyhedron.
void bounded_cells(const NeperTess& n, const std::vector<std::vector<int>>& owners, Tessellation3& t) {
  for (const Vec3& v : n.vertices) t.vertices.push_back(in_cell(n, v));
  std::vector<Vec3> centroid(n.cells());
  for (int c = 0; c < n.cells(); ++c) {
    std::set<int> corners;
    for (int f : n.polyhedra[c])
      for (int v : n.faces[std::abs(f) - 1]) corners.insert(v);
    for (int v : corners) centroid[c] += t.vertices[v];
    centroid[c] = centroid[c] / static_cast<double>(corners.size());
  }
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const auto& own = owners[f];
    Face3 face{.ring = n.faces[f], .back = own[0], .front = own.size() == 2 ? own[1] : -1};
    const Vec3 normal = ring_normal(t.vertices, face.ring), at = t.vertices[face.ring[0]];
    if (dot(normal, centroid[own[0]] - at) > 0.0) {  // own[0] lies in front
      if (face.front >= 0)
        std::swap(face.back, face.front);
      else
        std::reverse(face.ring.begin(), face.ring.end());
    }
    t.faces.push_back(std::move(face));
  }
  for (int c = 0; c < n.cells(); ++c) {
    Region3 r{.grain = c, .phase = 0, .faces = {}, .volume = 0.0};
    for (int f : n.polyhedra[c]) r.faces.push_back(std::abs(f) - 1);
    t.regions.push_back(std::move(r));
  }
}

// A periodic solid's whole cells, each its faces' rings of lattice corners turned to face
// out of it (its corners' centroid behind them), and their volumes.
std::vector<std::vector<std::vector<LatticeCorner>>> whole_cells(const NeperTess& n,
                                                                 const std::vector<LatticeCorner>& lattice,
                                                                 const std::vector<Vec3>& bases, Vec3 size,
                                                                 std::vector<double>& volumes) {
  std::vector<std::vector<std::vector<LatticeCorner>>> cells(n.cells());
  volumes.assign(n.cells(), 0.0);
  for (int c = 0; c < n.cells(); ++c) {
    std::set<int> corners;
    for (int f : n.polyhedra[c])
      for (int v : n.faces[std::abs(f) - 1]) corners.insert(v);
    Vec3 centre;
    for (int v : corners) centre += unwrapped(bases, lattice[v], size);
    centre = centre / static_cast<double>(corners.size());
    for (int f : n.polyhedra[c]) {
      std::vector<LatticeCorner> ring = corners_of(n.faces[std::abs(f) - 1], lattice);
      std::vector<Vec3> pts;
      for (const LatticeCorner& k : ring) pts.push_back(unwrapped(bases, k, size) - centre);
      Vec3 normal;
      for (std::size_t k = 0; k < pts.size(); ++k) normal += cross(pts[k], pts[(k + 1) % pts.size()]);
      if (dot(normal, pts[0]) < 0.0) {
        std::reverse(ring.begin(), ring.end());
        std::reverse(pts.begin(), pts.end());
      }
      for (std::size_t k = 1; k + 1 < pts.size(); ++k) volumes[c] += dot(pts[0], cross(pts[k], pts[k + 1])) / 6.0;
      cells[c].push_back(std::move(ring));
    }
  }
  return cells;
}

}  // namespace

Tessellation3 solid_tessellation(const NeperTess& n, const NeperPhases& ph, Rng& rng, const std::string& source) {
  check_kind(n, 3, source);
  Tessellation3 t;
  const Vec3 size = n.domain.hi - n.domain.lo;
  t.width = size.x;
  t.height = size.y;
  t.depth = size.z;
  t.periodic = n.periodic;
  t.phases = ph.phases;
  const double total = t.width * t.height * t.depth;
  const std::vector<LatticeCorner> lattice = lattice_vertices(n, 3, source);
  const std::vector<std::vector<int>> owners = face_owners(n, source);
  std::vector<std::vector<std::vector<LatticeCorner>>> sides(n.cells());
  for (int c = 0; c < n.cells(); ++c)
    for (int f : n.polyhedra[c]) sides[c].push_back(corners_of(n.faces[std::abs(f) - 1], lattice));
  const auto neighbours = shared_side_neighbours(sides);
  std::vector<double> volumes(n.cells(), 0.0);
  LaguerreCut cut;
  if (n.periodic) {
    std::vector<Vec3> bases;
    for (const Vec3& v : n.vertices) bases.push_back(in_cell(n, v));
    cut = periodic_box_cut(bases, whole_cells(n, lattice, bases, size, volumes), size);
  } else {
    bounded_cells(n, owners, t);
    for (int c = 0; c < n.cells(); ++c) volumes[c] = region_volume(t, t.regions[c]);
  }
  const std::vector<int> label = cell_phases(n, ph, volumes, neighbours, total, rng, source);
  for (int c = 0; c < n.cells(); ++c)
    t.grains.push_back(Grain3{.id = c,
                              .phase = label[c],
                              .seed = in_cell(n, n.seeds[c]),
                              .volume = 0.0,
                              .faces = static_cast<int>(n.polyhedra[c].size()),
                              .neighbours = neighbours[c]});
  if (n.periodic) {
    std::vector<int> grain_of_piece;  // the cell's own
    for (const BoxPiece& piece : cut.pieces) grain_of_piece.push_back(piece.seed);
    assemble_box_cut(cut, grain_of_piece, t);
  }
  double sum = 0.0;
  for (Region3& r : t.regions) {
    r.phase = t.grains[r.grain].phase;
    r.volume = region_volume(t, r);
    t.grains[r.grain].volume += r.volume;
    sum += r.volume;
  }
  if (std::abs(sum - total) > 1e-9 * total)
    throw GeometryError(source + ": the cells fill a volume of " + to_text(sum) + ", the domain " + to_text(total));
  for (int c = 0; c < n.cells() && n.periodic; ++c)
    if (std::abs(t.grains[c].volume - volumes[c]) > 1e-9 * total)
      throw GeometryError(source + ": cell " + std::to_string(c + 1) + "'s pieces in the domain fill " +
                          to_text(t.grains[c].volume) + ", the cell " + to_text(volumes[c]) + " (is it convex?)");
  try {
    if (n.periodic) t.partners = box_partners(t);
    validate(t);
  } catch (const GeometryError& e) {
    throw GeometryError(source + ": " + e.what());
  }
  measure_tessellation(t);
  return t;
}

}  // namespace grainmesh
