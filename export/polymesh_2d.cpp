#include "export/polymesh_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "common/cell_side.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_file.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "export/pin_translation.hpp"

namespace grainmesh {
namespace {

// The side of the cell a boundary edge lies on; within 1e-9 of the cell's size, so that
// meshes whose sides were projected (domain meshes) count too.
CellSide side_of(const Box& cell, Vec2 a, Vec2 b) {
  return side_along(cell, a, b, 1e-9 * std::max(cell.width(), cell.height()));
}

// A side face: the edge a -> b runs counter-clockwise round its owner.
struct SideFace {
  int a, b, owner;
};

template <typename Points>
void add_polymesh_face(PolyMesh& pm, const Points& pts, int owner) {
  pm.face_start.push_back(static_cast<int>(pm.face_points.size()));
  pm.face_points.insert(pm.face_points.end(), pts.begin(), pts.end());
  pm.owner.push_back(owner);
}
void add_polymesh_face(PolyMesh& pm, std::initializer_list<int> pts, int owner) {
  add_polymesh_face<std::initializer_list<int>>(pm, pts, owner);
}

// Orders the faces of a cyclic pair's high side as the images of the low side's (in their
// order) through the node pairs `pairs` (low, high). Throws GeometryError when a face of
// either side has no partner face.
void pair_cyclic_faces(const std::vector<SideFace>& low, std::vector<SideFace>& high,
                       const std::vector<std::pair<int, int>>& pairs, CellSide side) {
  std::unordered_map<int, int> image(pairs.begin(), pairs.end());
  auto key = [](int a, int b) { return static_cast<std::int64_t>(std::min(a, b)) << 32 | std::max(a, b); };
  std::unordered_map<std::int64_t, std::size_t> high_face;
  for (std::size_t k = 0; k < high.size(); ++k) high_face[key(high[k].a, high[k].b)] = k;
  const std::string unpaired = std::string("export: the faces of ") + side_name(side) + " and " +
                               side_name(static_cast<CellSide>(side ^ 1)) + " do not pair (is the mesh periodic?)";
  if (low.size() != high.size()) throw GeometryError(unpaired);
  std::vector<SideFace> ordered;
  ordered.reserve(high.size());
  for (const SideFace& f : low) {
    const auto a = image.find(f.a), b = image.find(f.b);
    const auto it = a == image.end() || b == image.end() ? high_face.end() : high_face.find(key(a->second, b->second));
    if (it == high_face.end()) throw GeometryError(unpaired);
    ordered.push_back(high[it->second]);
  }
  high = std::move(ordered);
}

// The boundary faces on the cell's sides (and `boundary` for the others), patch by patch:
// symmetry planes, the loaded `right`, or cyclic pairs whose faces match one to one.
void add_side_patches(const ExportMesh<2>& m, const FoamOptions& o, std::array<std::vector<SideFace>, 5>& sides,
                      PolyMesh& pm) {
  const CellMesh& mesh = m.mesh;
  const int n = static_cast<int>(mesh.points.size());
  auto add_face = [&](std::initializer_list<int> pts, int owner) { add_polymesh_face(pm, pts, owner); };
  // Side patches. A cyclic pair's low side lists its faces along the side and the high
  // side the images of them (through the mesh's periodic node pairs), so face i of one
  // matches face i of the other; the other patches list their faces by owner.
  if (o.cyclic && !m.periodic) throw ConfigError("export.cyclic: the mesh is not periodic");  // see check_load
  const bool cyclic = o.cyclic;
  // The load needs its patches: right carries it, left holds x, bottom (and top, unless
  // uniaxial) hold y. A side without mesh edges leaves the load or a rigid motion free.
  for (CellSide s : {kRight, kLeft, kBottom, kTop}) {
    if (!sides[s].empty() || (s == kTop && o.uniaxial)) continue;
    throw ConfigError(std::string("export: patch '") + side_name(s) + "' is empty: no mesh edge lies on the cell's " +
                      side_name(s) + " side (" + (is_vertical(s) ? "x = " : "y = ") + to_text(side_coordinate(m.cell, s)) + "), so " +
                      (s == kRight ? "the load has nothing to act on" : "nothing holds the cell there") +
                      "; the mesh's bounding box must have straight mesh edges on all four sides");
  }
  auto along = [&](const SideFace& f, CellSide side) {
    const Vec2 mid = 0.5 * (mesh.points[f.a] + mesh.points[f.b]);
    return is_vertical(side) ? mid.y : mid.x;
  };
  for (CellSide s : {kLeft, kRight, kBottom, kTop}) {
    if (cyclic && (s == kRight || s == kTop)) continue;  // ordered as the images of left and bottom below
    std::sort(sides[s].begin(), sides[s].end(), [&](const SideFace& x, const SideFace& y) {
      return cyclic ? along(x, s) < along(y, s) : x.owner < y.owner;
    });
  }
  if (cyclic) {
    if (!sides[kNoSide].empty())
      throw GeometryError("export: cyclic patches need every boundary edge on a side of the cell");
    for (CellSide s : {kLeft, kBottom}) pair_cyclic_faces(sides[s], sides[s ^ 1], s == kLeft ? m.pairs.axis[0] : m.pairs.axis[1], s);
  }
  const bool top_free = o.uniaxial;
  for (CellSide s : {kLeft, kRight, kBottom, kTop, kNoSide}) {
    if (s == kNoSide && sides[s].empty()) continue;
    PolyMesh::Patch p;
    p.name = side_name(s);
    p.start = pm.faces();
    p.size = static_cast<int>(sides[s].size());
    if (cyclic && s != kNoSide) {
      p.type = "cyclic";
      p.neighbour_patch = side_name(static_cast<CellSide>(s ^ 1));
      const Vec3 shift = is_vertical(s) ? Vec3{m.cell.width(), 0.0, 0.0} : Vec3{0.0, m.cell.height(), 0.0};
      p.separation = (s % 2 == 0) ? shift : -1.0 * shift;
    } else if (s == kLeft || s == kBottom || (s == kTop && !top_free)) {
      p.type = "symmetryPlane";
    } else {
      p.type = "patch";
    }
    // A coupled face starts at the point opposite its partner's first point: the high
    // side's faces start at their other end.
    const bool high = cyclic && (s == kRight || s == kTop);
    for (const SideFace& f : sides[s])
      high ? add_face({f.b, f.b + n, f.a + n, f.a}, f.owner) : add_face({f.a, f.b, f.b + n, f.a + n}, f.owner);
    pm.patches.push_back(p);
  }
}

}  // namespace


PolyMesh build_polymesh(const ExportMesh<2>& m, const FoamOptions& o) {
  const CellMesh& mesh = m.mesh;
  const int n = static_cast<int>(mesh.points.size());
  PolyMesh pm;
  pm.points2d = mesh.points;
  pm.cells = static_cast<int>(mesh.cells());
  const std::vector<MeshEdge> edges = mesh_edges(mesh);
  if (o.thickness > 0.0) {
    pm.thickness = o.thickness;
  } else {
    double sum = 0.0;
    for (const MeshEdge& e : edges) sum += norm(mesh.points[e.a] - mesh.points[e.b]);
    pm.thickness = edges.empty() ? 1.0 : sum / static_cast<double>(edges.size());
  }
  auto add_face = [&](std::initializer_list<int> pts, int owner) { add_polymesh_face(pm, pts, owner); };

  // Internal faces in upper-triangular order: by owner, then neighbour.
  struct Internal {
    int owner, neighbour, a, b;  // a -> b counter-clockwise round the owner
  };
  std::vector<Internal> internal;
  std::array<std::vector<SideFace>, 5> sides;
  for (const MeshEdge& e : edges) {
    if (e.right < 0) {
      sides[side_of(m.cell, mesh.points[e.a], mesh.points[e.b])].push_back({e.a, e.b, e.left});
    } else if (e.left < e.right) {
      internal.push_back({e.left, e.right, e.a, e.b});
    } else {
      internal.push_back({e.right, e.left, e.b, e.a});
    }
  }
  std::sort(internal.begin(), internal.end(), [](const Internal& x, const Internal& y) {
    return x.owner != y.owner ? x.owner < y.owner : x.neighbour < y.neighbour;
  });
  pm.face_start.reserve(internal.size() + 2 * mesh.cells() + 8);
  for (const Internal& f : internal) {
    add_face({f.a, f.b, f.b + n, f.a + n}, f.owner);
    pm.neighbour.push_back(f.neighbour);
  }

  add_side_patches(m, o, sides, pm);
  PolyMesh::Patch empty{.name = "frontAndBack", .type = "empty", .start = pm.faces(),
                        .size = 2 * pm.cells, .neighbour_patch = {}, .separation = {}};
  std::vector<int> ring;
  for (int c = 0; c < pm.cells; ++c) {  // z = 0, facing down: the ring reversed from its first corner
    const std::span<const int> v = mesh.cell(static_cast<std::size_t>(c));
    ring.assign(v.begin(), v.end());
    std::reverse(ring.begin() + 1, ring.end());
    add_polymesh_face(pm, ring, c);
  }
  for (int c = 0; c < pm.cells; ++c) {  // z = thickness, facing up
    ring.clear();
    for (int v : mesh.cell(static_cast<std::size_t>(c))) ring.push_back(v + n);
    add_polymesh_face(pm, ring, c);
  }
  pm.patches.push_back(empty);
  pm.face_start.push_back(static_cast<int>(pm.face_points.size()));
  if (o.cyclic) pin_translation(pm, m.phase, {m.cell.lo.x, m.cell.lo.y, 0.0});

  add_zones(m.grain, m.phase, m.phases, o.grain_zones, pm);
  return pm;
}


}  // namespace grainmesh
