#include "analysis/traction.hpp"

#include <cmath>
#include <limits>

#include "common/errors.hpp"

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

// The face's area vector (metres squared), out of the cell centred at `owner_centre`
// (metres), and its centre.
struct FaceGeometry {
  Vec2 S, centre;
  double area;
};
FaceGeometry face_geometry(const PolyMesh& pm, int f, double scale, double thickness, Vec2 owner_centre) {
  const auto [a, b] = face_edge(pm, f);
  const Vec2 centre = 0.5 * scale * (a + b);
  Vec2 S = thickness * scale * scale * Vec2{b.y - a.y, a.x - b.x};  // thickness and edge in metres
  if (dot(S, centre - owner_centre) < 0.0) S = -S;
  return {S, centre, norm(S)};
}

}  // namespace

int patch_index(const PolyMesh& pm, const std::string& name) {
  for (std::size_t p = 0; p < pm.patches.size(); ++p)
    if (pm.patches[p].name == name) return static_cast<int>(p);
  return -1;
}

DiscreteTraction::DiscreteTraction(const PolyMesh& pm, const ExportMesh& m, const FoamOptions& o, FieldValues D,
                                   FieldValues grad_D, FieldValues sigma)
    : pm_(pm),
      scale_(o.convert_to_meters),
      thickness_(pm.thickness),
      harmonic_(harmonic_stiffness(m, o)),
      D_(std::move(D)),
      grad_(std::move(grad_D)),
      sigma_(std::move(sigma)) {
  centre_.resize(pm.cells);
  gamma_.resize(pm.cells);
  volume_.resize(pm.cells);
  for (int c = 0; c < pm.cells; ++c) {
    centre_[c] = scale_ * cell_centroid(m.mesh, static_cast<std::size_t>(c));
    volume_[c] = cell_area(m.mesh, static_cast<std::size_t>(c)) * thickness_ * scale_ * scale_ * scale_;
    gamma_[c] = lame(m.phases[m.phase[c]], o.plane_stress).gamma();
  }
  patch_of_face_.assign(pm.faces(), -1);
  jump_.assign(pm.patches.size(), {0.0, 0.0});
  for (std::size_t p = 0; p < pm.patches.size(); ++p) {
    const PolyMesh::Patch& patch = pm.patches[p];
    for (int f = patch.start; f < patch.start + patch.size; ++f) patch_of_face_[f] = static_cast<int>(p);
    if (patch.type != "cyclic") continue;
    // The jump the case gives the low patch of each pair: the macroscopic strain times
    // the separation; the high patch has its negative.
    const std::array<double, 3> e = cyclic_strain(m, o);  // xx, yy, xy
    const bool x_pair = patch.name == "left" || patch.name == "right";
    const double L = scale_ * (x_pair ? m.cell.width() : m.cell.height());
    std::array<double, 2> j = x_pair ? std::array<double, 2>{e[0] * L, e[2] * L} : std::array<double, 2>{e[2] * L, e[1] * L};
    if (patch.name == "right" || patch.name == "top") j = {-j[0], -j[1]};
    jump_[p] = j;
  }
}

DiscreteTraction::Neighbour DiscreteTraction::neighbour(int f) const {
  if (f < pm_.internal_faces()) return {pm_.neighbour[f], {}, {0.0, 0.0}};
  const int p = patch_of_face_[f];
  const PolyMesh::Patch& patch = pm_.patches[p];
  if (patch.type != "cyclic") return {};
  const PolyMesh::Patch& other = pm_.patches[patch_index(pm_, patch.neighbour_patch)];
  // Face k of a cyclic patch pairs with face k of its neighbour patch, which lies at this
  // one plus the separation.
  return {pm_.owner[other.start + (f - patch.start)], -scale_ * Vec2{patch.separation.x, patch.separation.y}, jump_[p]};
}

Vec2 DiscreteTraction::face_force(int f) const {
  const Neighbour nb = neighbour(f);
  if (nb.cell < 0) throw GeometryError("face " + std::to_string(f) + " is neither internal nor cyclic");
  const int P = pm_.owner[f], N = nb.cell;
  const Vec2 CP = centre_[P], CN = centre_[N] + nb.shift;
  const FaceGeometry g = face_geometry(pm_, f, scale_, thickness_, CP);
  const Vec2 n = g.S / g.area;
  // OpenFOAM's linear weight of the owner, and its non-orthogonal delta and correction.
  const double own = std::abs(dot(g.S, g.centre - CP)), nei = std::abs(dot(g.S, CN - g.centre));
  const double w = nei / (own + nei);
  const Vec2 d = CN - CP;
  const double delta = 1.0 / std::max(dot(n, d), 0.05 * norm(d));
  const Vec2 k = n - delta * d;
  // OpenFOAM's harmonic is 1 / reverseLinear(1 / gamma): each side's compliance weighted
  // by its own distance to the face, as in a series of two springs.
  const double gamma = harmonic_ ? 1.0 / ((1 - w) / gamma_[P] + w / gamma_[N]) : w * gamma_[P] + (1 - w) * gamma_[N];
  // Tensors as OpenFOAM orders them: grad(D)_ij = d D_j / d x_i, at index 3 i + j;
  // sigma symmetric at xx 0, xy 1, yy 3.
  auto grad = [&](int c, int i, int j) { return grad_[c][3 * i + j]; };
  auto sig = [&](int c, int i, int j) {
    const double* s = sigma_[c];
    return i == 0 && j == 0 ? s[0] : i == 1 && j == 1 ? s[3] : s[1];
  };
  auto X = [&](int c, int i, int j) { return sig(c, i, j) - gamma_[c] * grad(c, i, j); };
  const double Sv[2] = {g.S.x, g.S.y}, kv[2] = {k.x, k.y};
  double F[2] = {0.0, 0.0};
  for (int j = 0; j < 2; ++j) {
    double sn = delta * (D_[N][j] - nb.jump[j] - D_[P][j]);
    for (int i = 0; i < 2; ++i) sn += kv[i] * (w * grad(P, i, j) + (1 - w) * grad(N, i, j));
    F[j] = gamma * g.area * sn;
    for (int i = 0; i < 2; ++i) F[j] += Sv[i] * (w * X(P, i, j) + (1 - w) * X(N, i, j));
  }
  return {F[0], F[1]};
}

Vec2 DiscreteTraction::patch_force(int patch) const {
  const PolyMesh::Patch& p = pm_.patches[patch];
  Vec2 sum{};
  for (int f = p.start; f < p.start + p.size; ++f) sum += face_force(f);
  return sum;
}

Vec2 DiscreteTraction::cell_imbalance(int c) const {
  // Every face of every cell, once: a slow scan, for checks.
  Vec2 sum{};
  for (int f = 0; f < pm_.faces(); ++f) {
    const bool owned = pm_.owner[f] == c, neighboured = f < pm_.internal_faces() && pm_.neighbour[f] == c;
    if (!owned && !neighboured) continue;
    const int p = patch_of_face_[f];
    if (p >= 0 && pm_.patches[p].type == "empty") continue;
    if (p >= 0 && pm_.patches[p].type != "cyclic") return {std::numeric_limits<double>::quiet_NaN(), 0.0};
    const Vec2 F = face_force(f);
    sum += owned ? F : -F;
  }
  return sum;
}

std::vector<StressState> DiscreteTraction::virial_stress() const {
  std::vector<StressState> out(static_cast<std::size_t>(pm_.cells));
  auto add = [&](int c, Vec2 face_centre, Vec2 F) {
    const Vec2 r = face_centre - centre_[c];
    StressState& s = out[static_cast<std::size_t>(c)];
    s.xx += r.x * F.x, s.yy += r.y * F.y, s.xy += 0.5 * (r.x * F.y + r.y * F.x);
  };
  for (int f = 0; f < pm_.faces(); ++f) {
    const int p = patch_of_face_[f];
    if (p >= 0 && pm_.patches[p].type == "empty") continue;
    if (p >= 0 && pm_.patches[p].type != "cyclic")
      throw GeometryError("virial_stress: patch " + pm_.patches[p].name + " is neither cyclic nor empty");
    const int P = pm_.owner[f];
    const Vec2 F = face_force(f);
    const Vec2 centre = face_geometry(pm_, f, scale_, thickness_, centre_[P]).centre;
    add(P, centre, F);
    if (p < 0) add(pm_.neighbour[f], centre, -F);  // a cyclic face's partner adds its own
  }
  for (int c = 0; c < pm_.cells; ++c) {
    StressState& s = out[static_cast<std::size_t>(c)];
    s.xx /= volume_[c], s.yy /= volume_[c], s.xy /= volume_[c];
  }
  return out;
}

Vec2 written_patch_force(const PolyMesh& pm, const ExportMesh& m, const FoamOptions& o, int patch,
                         const FieldValues& sigma) {
  const PolyMesh::Patch& p = pm.patches[patch];
  Vec2 sum{};
  for (int f = p.start; f < p.start + p.size; ++f) {
    const FaceGeometry g =
        face_geometry(pm, f, o.convert_to_meters, pm.thickness, o.convert_to_meters * cell_centroid(m.mesh, static_cast<std::size_t>(pm.owner[f])));
    const double* s = sigma[static_cast<std::size_t>(f - p.start)];
    sum += Vec2{g.S.x * s[0] + g.S.y * s[1], g.S.x * s[1] + g.S.y * s[3]};
  }
  return sum;
}

}  // namespace grainmesh
