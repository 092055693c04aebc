#include "export/polymesh_3d.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <string>

#include "common/errors.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/pin_translation.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

namespace {

using Triangle = std::array<int, 3>;

// A boundary face: its points turning outward from its tetrahedron, the owner.
struct BoundaryFace {
  Triangle points;
  int owner;
};

Triangle sorted(Triangle t) {
  std::sort(t.begin(), t.end());
  return t;
}

void add_face(PolyMesh& pm, const Triangle& f, int owner) {
  pm.face_start.push_back(static_cast<int>(pm.face_points.size()));
  pm.face_points.insert(pm.face_points.end(), f.begin(), f.end());
  pm.owner.push_back(owner);
}

// The high side's faces as the images of the low side's, in their order, each turned to
// start at the image of its partner's first point (the partner's points reversed).
std::vector<BoundaryFace> image_faces(const std::vector<BoundaryFace>& low, const std::vector<BoundaryFace>& high,
                                      const std::vector<std::pair<int, int>>& pairs, int axis) {
  const std::map<int, int> image(pairs.begin(), pairs.end());
  std::map<Triangle, int> owner;
  for (const BoundaryFace& f : high) owner.emplace(sorted(f.points), f.owner);
  const std::string unpaired = std::string("export: the faces of ") + kSideNames3[2 * axis] + " and " +
                               kSideNames3[2 * axis + 1] + " do not pair (is the mesh periodic?)";
  if (low.size() != high.size()) throw GeometryError(unpaired);
  std::vector<BoundaryFace> out;
  for (const BoundaryFace& f : low) {
    Triangle t{};
    for (int k = 0; k < 3; ++k) {
      const auto it = image.find(f.points[k]);
      if (it == image.end()) throw GeometryError(unpaired);
      t[k] = it->second;
    }
    const auto it = owner.find(sorted(t));
    if (it == owner.end()) throw GeometryError(unpaired);
    out.push_back({{t[0], t[2], t[1]}, it->second});
  }
  return out;
}

}  // namespace

int box_side_of(const std::vector<Vec3>& p, const std::array<int, 3>& f, const Box3& box) {
  for (int a = 0; a < 3; ++a)
    for (int high = 0; high < 2; ++high) {
      const double at = high ? box.hi[a] : box.lo[a];
      if (p[f[0]][a] == at && p[f[1]][a] == at && p[f[2]][a] == at) return 2 * a + high;
    }
  return -1;
}

PolyMesh::Patch side_patch(int s, Vec3 box, const FoamOptions& o) {
  PolyMesh::Patch p;
  p.name = kSideNames3[s];
  const int axis = s / 2;
  if (o.cyclic) {
    p.type = "cyclic";
    p.neighbour_patch = kSideNames3[s ^ 1];
    Vec3 shift{};
    shift[axis] = box[axis];
    p.separation = s % 2 == 0 ? shift : -1.0 * shift;
  } else if (s == 1 || (o.uniaxial && (s == 3 || s == 5))) {
    p.type = "patch";
  } else {
    p.type = "symmetryPlane";
  }
  return p;
}

PolyMesh build_polymesh(const ExportMesh<3>& m, const FoamOptions& o) {
  if (o.cyclic && !m.periodic) throw ConfigError("export.cyclic: the mesh is not periodic");
  const auto& tets = m.mesh.tets;
  PolyMesh pm;
  pm.points3d = m.mesh.points;
  pm.cells = static_cast<int>(tets.size());
  // Each tetrahedron's faces turning outward: opposite corner k, for a positive abcd.
  constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::vector<std::pair<Triangle, std::pair<int, int>>> faces;  // sorted points, (tet, k)
  faces.reserve(4 * tets.size());
  for (int t = 0; t < pm.cells; ++t)
    for (int k = 0; k < 4; ++k)
      faces.push_back({sorted({tets[t][kFace[k][0]], tets[t][kFace[k][1]], tets[t][kFace[k][2]]}), {t, k}});
  std::sort(faces.begin(), faces.end());
  auto outward = [&](int t, int k) { return Triangle{tets[t][kFace[k][0]], tets[t][kFace[k][1]], tets[t][kFace[k][2]]}; };

  struct Internal {
    int owner, neighbour;
    Triangle points;  // outward from the owner
  };
  std::vector<Internal> internal;
  std::array<std::vector<BoundaryFace>, 6> sides;
  for (std::size_t i = 0; i < faces.size();) {
    const auto [t, k] = faces[i].second;
    if (i + 1 < faces.size() && faces[i + 1].first == faces[i].first) {
      const int u = faces[i + 1].second.first;  // t < u: the sort puts the lower tetrahedron first
      internal.push_back({t, u, outward(t, k)});
      i += 2;
      continue;
    }
    const int side = box_side_of(pm.points3d, faces[i].first, m.cell);
    if (side < 0) throw GeometryError("export: a boundary face of tetrahedron " + std::to_string(t) + " lies on no side of the box");
    sides[side].push_back({outward(t, k), t});
    ++i;
  }
  std::sort(internal.begin(), internal.end(), [](const Internal& x, const Internal& y) {
    return x.owner != y.owner ? x.owner < y.owner : x.neighbour < y.neighbour;
  });
  for (const Internal& f : internal) {
    add_face(pm, f.points, f.owner);
    pm.neighbour.push_back(f.neighbour);
  }
  for (auto& side : sides)
    std::sort(side.begin(), side.end(), [](const BoundaryFace& x, const BoundaryFace& y) {
      return x.owner != y.owner ? x.owner < y.owner : x.points < y.points;
    });
  if (o.cyclic)
    for (int a = 0; a < 3; ++a) sides[2 * a + 1] = image_faces(sides[2 * a], sides[2 * a + 1], m.pairs.axis[a], a);
  for (int s = 0; s < 6; ++s) {
    if (sides[s].empty()) throw GeometryError(std::string("export: no face lies on the box's ") + kSideNames3[s] + " side");
    PolyMesh::Patch p = side_patch(s, m.cell.size(), o);
    p.start = pm.faces();
    p.size = static_cast<int>(sides[s].size());
    for (const BoundaryFace& f : sides[s]) add_face(pm, f.points, f.owner);
    pm.patches.push_back(p);
  }
  pm.face_start.push_back(static_cast<int>(pm.face_points.size()));
  if (o.cyclic) pin_translation(pm, m.phase, {});
  add_zones(m.grain, m.phase, m.phases, o.grain_zones, pm);
  return pm;
}

}  // namespace grainmesh
