#include "analysis/traction.hpp"

#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "export/foam_geometry.hpp"
#include "export/foam_solver.hpp"
#include "export/pin_translation.hpp"

namespace grainmesh {

namespace {

// The 2D edge of side face f (its points below the extruded copy), as a -> b.
std::array<Vec2, 2> face_edge(const PolyMesh& pm, int f) {
  const int n = static_cast<int>(pm.points2d.size());
  std::array<Vec2, 2> e{};
  int k = 0;
  for (int i = pm.face_start[f]; i < pm.face_start[f + 1] && k < 2; ++i)
    if (pm.face_points[i] < n) e[k++] = pm.points2d[pm.face_points[i]];
  return e;
}

// The face's area vector (metres squared) out of its owner, and its centre: a 2D case's
// side face from its edge (z 0, as the cell centres; out of the owner centred at
// `owner_centre`, metres), a 3D face as OpenFOAM has it (foam_face).
struct FaceGeometry {
  Vec3 S, centre;
  double area;
};
FaceGeometry face_geometry(const PolyMesh& pm, int f, double scale, double thickness, Vec3 owner_centre) {
  Vec3 S, centre;
  if (pm.points3d.empty()) {
    const auto [a, b] = face_edge(pm, f);
    centre = Vec3{0.5 * scale * (a.x + b.x), 0.5 * scale * (a.y + b.y), 0.0};
    S = thickness * scale * scale * Vec3{b.y - a.y, a.x - b.x, 0.0};  // thickness and edge in metres
    if (dot(S, centre - owner_centre) < 0.0) S = -S;
  } else {
    // Turning out of the owner by construction (a polyhedron need not be convex).
    const FoamFace face = foam_face(pm, f);
    centre = scale * face.centre;
    S = scale * scale * face.area;
  }
  return {S, centre, norm(S)};
}

}  // namespace

DiscreteTraction::DiscreteTraction(const PolyMesh& pm, const FoamCell& cell, const std::vector<int>& phase,
                                   const FoamOptions& o, std::vector<Vec3> centre, std::vector<double> volume,
                                   FieldValues D, FieldValues grad_D, FieldValues sigma)
    : pm_(pm),
      scale_(o.convert_to_meters),
      thickness_(pm.thickness),
      dimensions_(cell.dimensions()),
      compact_(compact_normal_stress(cell, o)),
      centre_(std::move(centre)),
      volume_(std::move(volume)),
      harmonic_(harmonic_stiffness(cell, o)),
      D_(std::move(D)),
      grad_(std::move(grad_D)),
      sigma_(std::move(sigma)) {
  gamma_.resize(pm.cells);
  for (int c = 0; c < pm.cells; ++c) gamma_[c] = lame(cell.phases[phase[c]], o.plane_stress).gamma();
  patch_of_face_.assign(pm.faces(), -1);
  jump_.assign(pm.patches.size(), Vec3{});
  for (std::size_t p = 0; p < pm.patches.size(); ++p) {
    const PolyMesh::Patch& patch = pm.patches[p];
    for (int f = patch.start; f < patch.start + patch.size; ++f) patch_of_face_[f] = static_cast<int>(p);
    if (patch.type != "cyclic") continue;
    // The jump the case gives the low patch of each pair; the high patch has its negative.
    const Vec3 j = cyclic_jump(cyclic_strain(cell, o), patch.name, cell, scale_);
    const bool high = patch.name == "right" || patch.name == "top" || patch.name == "front";
    jump_[p] = high ? -j : j;
  }
}

DiscreteTraction::DiscreteTraction(const PolyMesh& pm, const ExportMesh<2>& m, const FoamOptions& o, FieldValues D,
                                   FieldValues grad_D, FieldValues sigma)
    : DiscreteTraction(pm, foam_cell(m), m.phase, o, {}, {}, std::move(D), std::move(grad_D), std::move(sigma)) {
  centre_.resize(pm.cells);
  volume_.resize(pm.cells);
  for (int c = 0; c < pm.cells; ++c) {
    const Vec2 centroid = cell_centroid(m.mesh, static_cast<std::size_t>(c));
    centre_[c] = scale_ * Vec3{centroid.x, centroid.y, 0.0};
    volume_[c] = cell_area(m.mesh, static_cast<std::size_t>(c)) * thickness_ * scale_ * scale_ * scale_;
  }
}

DiscreteTraction::DiscreteTraction(const FoamMesh3& m, const FoamCell& cell, const FoamOptions& o, FieldValues D,
                                   FieldValues grad_D, FieldValues sigma)
    : DiscreteTraction(m.mesh, cell, m.phase, o, {}, {}, std::move(D), std::move(grad_D), std::move(sigma)) {
  const double s = scale_;
  for (const Vec3 c : m.centre) centre_.push_back(s * c);
  for (const double v : m.volume) volume_.push_back(v * s * s * s);
}

DiscreteTraction::Neighbour DiscreteTraction::neighbour(int f) const {
  if (f < pm_.internal_faces()) return {pm_.neighbour[f], {}, {}};
  const int p = patch_of_face_[f];
  const PolyMesh::Patch& patch = pm_.patches[p];
  if (patch.type != "cyclic") return {};
  const PolyMesh::Patch& other = pm_.patches[patch_index(pm_, patch.neighbour_patch)];
  // Face k of a cyclic patch pairs with face k of its neighbour patch, which lies at this
  // one plus the separation.
  return {pm_.owner[other.start + (f - patch.start)], -(scale_ * patch.separation), jump_[p]};
}

bool DiscreteTraction::pinned(int f) const {
  const int p = patch_of_face_[f];
  return p >= 0 && is_pin_patch(pm_.patches[p]);
}

Vec3 DiscreteTraction::face_force(int f) const {
  if (pinned(f)) return -1.0 * faces_force(pm_.owner[f], f);
  const Neighbour nb = neighbour(f);
  if (nb.cell < 0) throw GeometryError("face " + std::to_string(f) + " is neither internal nor cyclic");
  const int P = pm_.owner[f], N = nb.cell;
  const Vec3 CP = centre_[P], CN = centre_[N] + nb.shift;
  const FaceGeometry g = face_geometry(pm_, f, scale_, thickness_, CP);
  const Vec3 n = g.S / g.area;
  // OpenFOAM's linear weight of the owner, and its non-orthogonal delta and correction.
  const double own = std::abs(dot(g.S, g.centre - CP)), nei = std::abs(dot(g.S, CN - g.centre));
  const double w = nei / (own + nei);
  const Vec3 d = CN - CP;
  const double delta = 1.0 / std::max(dot(n, d), 0.05 * norm(d));
  const Vec3 k = n - delta * d;
  // OpenFOAM's harmonic is 1 / reverseLinear(1 / gamma): each side's compliance weighted
  // by its own distance to the face, as in a series of two springs.
  const double gamma = harmonic_ ? 1.0 / ((1 - w) / gamma_[P] + w / gamma_[N]) : w * gamma_[P] + (1 - w) * gamma_[N];
  // Tensors as OpenFOAM orders them: grad(D)_ij = d D_j / d x_i, at index 3 i + j;
  // sigma symmetric: xx xy xz yy yz zz.
  static constexpr int kSymmetric[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  Vec3 F;
  if (!compact_) {
    for (int j = 0; j < dimensions_; ++j)
      for (int i = 0; i < dimensions_; ++i)
        F[j] += g.S[i] * (w * sigma_[P][kSymmetric[i][j]] + (1 - w) * sigma_[N][kSymmetric[i][j]]);
    return F;
  }
  auto grad = [&](int c, int i, int j) { return grad_[c][3 * i + j]; };
  auto X = [&](int c, int i, int j) { return sigma_[c][kSymmetric[i][j]] - gamma_[c] * grad(c, i, j); };
  for (int j = 0; j < dimensions_; ++j) {
    double sn = delta * (D_[N][j] - nb.jump[j] - D_[P][j]);
    for (int i = 0; i < dimensions_; ++i) sn += k[i] * (w * grad(P, i, j) + (1 - w) * grad(N, i, j));
    F[j] = gamma * g.area * sn;
    for (int i = 0; i < dimensions_; ++i) F[j] += g.S[i] * (w * X(P, i, j) + (1 - w) * X(N, i, j));
  }
  return F;
}

Vec3 DiscreteTraction::side_force(const std::string& side) const {
  Vec3 sum{};
  for (const std::string& name : {side, pin_patch_of(side)}) {
    const int patch = patch_index(pm_, name);
    if (patch < 0) continue;
    const PolyMesh::Patch& p = pm_.patches[patch];
    for (int f = p.start; f < p.start + p.size; ++f) sum += face_force(f);
  }
  return sum;
}

Vec3 DiscreteTraction::faces_force(int c, int except) const {
  // Every face of the mesh looked at: a slow scan, for checks and the two pinned faces.
  Vec3 sum{};
  for (int f = 0; f < pm_.faces(); ++f) {
    const bool owned = pm_.owner[f] == c, neighboured = f < pm_.internal_faces() && pm_.neighbour[f] == c;
    if (f == except || (!owned && !neighboured)) continue;
    const int p = patch_of_face_[f];
    if (p >= 0 && pm_.patches[p].type == "empty") continue;
    if (p >= 0 && pm_.patches[p].type != "cyclic" && !(pinned(f) && except < 0))
      return {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};
    const Vec3 F = face_force(f);
    sum += owned ? F : -F;
  }
  return sum;
}

Vec3 DiscreteTraction::cell_imbalance(int c) const { return faces_force(c, -1); }

FieldValues DiscreteTraction::virial_stress_tensor() const {
  FieldValues out{.width = 6, .values = std::vector<double>(6 * static_cast<std::size_t>(pm_.cells), 0.0)};
  auto add = [&](int c, Vec3 face_centre, Vec3 F) {
    const Vec3 r = face_centre - centre_[c];
    double* s = out.values.data() + 6 * static_cast<std::size_t>(c);  // xx xy xz yy yz zz
    s[0] += r.x * F.x, s[3] += r.y * F.y, s[5] += r.z * F.z;
    s[1] += 0.5 * (r.x * F.y + r.y * F.x), s[2] += 0.5 * (r.x * F.z + r.z * F.x), s[4] += 0.5 * (r.y * F.z + r.z * F.y);
  };
  for (int f = 0; f < pm_.faces(); ++f) {
    const int p = patch_of_face_[f];
    if (p >= 0 && pm_.patches[p].type == "empty") continue;
    if (p >= 0 && pm_.patches[p].type != "cyclic" && !pinned(f))
      throw GeometryError("virial_stress: patch " + pm_.patches[p].name + " is neither cyclic, pinned nor empty");
    const int P = pm_.owner[f];
    const Vec3 F = face_force(f);
    const Vec3 centre = face_geometry(pm_, f, scale_, thickness_, centre_[P]).centre;
    add(P, centre, F);
    if (p < 0) add(pm_.neighbour[f], centre, -F);  // a cyclic or pinned face's partner adds its own
  }
  for (int c = 0; c < pm_.cells; ++c)
    for (int i = 0; i < 6; ++i) out.values[6 * static_cast<std::size_t>(c) + static_cast<std::size_t>(i)] /= volume_[c];
  return out;
}

std::vector<StressState> DiscreteTraction::virial_stress() const {
  if (dimensions_ != 2) throw GeometryError("virial_stress: of a 2D case only");
  const FieldValues v = virial_stress_tensor();
  std::vector<StressState> out(v.size());
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = {.xx = v[c][0], .yy = v[c][3], .zz = 0.0, .xy = v[c][1]};
  return out;
}

Vec3 written_patch_force(const PolyMesh& pm, const ExportMesh<2>& m, const FoamOptions& o, int patch,
                         const FieldValues& sigma) {
  const PolyMesh::Patch& p = pm.patches[patch];
  Vec3 sum{};
  for (int f = p.start; f < p.start + p.size; ++f) {
    const Vec2 owner = o.convert_to_meters * cell_centroid(m.mesh, static_cast<std::size_t>(pm.owner[f]));
    const FaceGeometry g = face_geometry(pm, f, o.convert_to_meters, pm.thickness, Vec3{owner.x, owner.y, 0.0});
    const double* s = sigma[static_cast<std::size_t>(f - p.start)];
    sum += Vec3{g.S.x * s[0] + g.S.y * s[1], g.S.x * s[1] + g.S.y * s[3], 0.0};
  }
  return sum;
}

}  // namespace grainmesh
