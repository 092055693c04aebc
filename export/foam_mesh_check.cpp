// checkMesh's geometric checks (primitiveMesh's skewness, non-orthogonality, volumes and
// aspect ratio) on a 3D polyMesh, from foam_geometry's faces and cells.
#include "export/foam_mesh_check.hpp"

#include <algorithm>
#include <cmath>

#include "export/foam_geometry.hpp"
#include "mesh/quality.hpp"

namespace grainmesh {

namespace {

// checkMesh's skewness of face f (mesh/quality.hpp).
double skewness(const PolyMesh& pm, int f, const FoamFace& face, Vec3 owner, Vec3 d) {
  return checkmesh_skewness(face.centre, face.area, owner, d, [&](Vec3 u) {
    double extent = 0.0;
    for (int k = pm.face_start[f]; k < pm.face_start[f + 1]; ++k)
      extent = std::max(extent, std::abs(dot(u, pm.points3d[pm.face_points[k]] - face.centre)));
    return extent;
  });
}

}  // namespace

FoamMeshCheck::FoamMeshCheck(const PolyMesh& pm, const std::vector<Vec3>& centre, const std::vector<double>& volume,
                             FoamCheckLimits limits)
    : pm_(pm), centre_(centre), volume_(volume), limits_(limits) {
  // A cyclic patch's face k pairs with its neighbour patch's face k.
  partner_.assign(static_cast<std::size_t>(pm.faces()), -1);
  shift_.assign(static_cast<std::size_t>(pm.faces()), Vec3{});
  for (const auto& p : pm.patches) {
    if (p.type != "cyclic") continue;
    const PolyMesh::Patch& q = pm.patches[static_cast<std::size_t>(patch_index(pm, p.neighbour_patch))];
    for (int k = 0; k < p.size; ++k) {
      partner_[p.start + k] = q.start + k;
      shift_[p.start + k] = -1.0 * p.separation;
    }
  }
}

int FoamMeshCheck::other(int f) const {
  if (f < pm_.internal_faces()) return pm_.neighbour[f];
  return partner_[f] >= 0 ? pm_.owner[partner_[f]] : -1;
}

bool FoamMeshCheck::fails(int f, Vec3 owner, Vec3 across) const {
  const FoamFace face = foam_face(pm_, f);
  if (other(f) < 0)
    return skewness(pm_, f, face, owner, checkmesh_boundary_d(face.centre, face.area, owner)) > limits_.skewness;
  const Vec3 d = across - owner;
  return checkmesh_non_orthogonality_deg(d, face.area) > limits_.non_orthogonality_deg ||
         skewness(pm_, f, face, owner, d) > limits_.skewness;
}

FoamCheckFailures FoamMeshCheck::failures() const {
  FoamCheckFailures out;
  std::vector<Vec3> closed(static_cast<std::size_t>(pm_.cells));  // the cells' faces' |area| per axis
  for (int f = 0; f < pm_.faces(); ++f) {
    const Vec3 a = foam_face(pm_, f).area;
    const Vec3 magnitude{std::abs(a.x), std::abs(a.y), std::abs(a.z)};
    closed[pm_.owner[f]] += magnitude;
    if (f < pm_.internal_faces()) closed[pm_.neighbour[f]] += magnitude;
    const int o = other(f);
    if (fails(f, centre_[pm_.owner[f]], o >= 0 ? across(f, centre_[o]) : Vec3{})) out.faces.push_back(f);
  }
  for (int c = 0; c < pm_.cells; ++c) {
    // OpenFOAM's aspect ratio: the larger of the face areas' largest to smallest component
    // sums and their total over that of a cube of the cell's volume.
    const Vec3 s = closed[c];
    const double v = std::max(volume_[c], 1e-300);
    const double aspect = std::max(std::max({s.x, s.y, s.z}) / std::max(std::min({s.x, s.y, s.z}), 1e-300),
                                   (s.x + s.y + s.z) / (6.0 * std::pow(v, 2.0 / 3.0)));
    if (volume_[c] <= 0.0 || aspect > limits_.aspect_ratio) out.cells.push_back(c);
  }
  return out;
}

}  // namespace grainmesh
