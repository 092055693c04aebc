// The 3D periodic homogenisation against exact answers: one material gives its own
// isotropic tensor, and laminates (grains from seeds in a row: slabs normal to x) the
// exact layered tensor.
#include <cmath>
#include <filesystem>
#include <vector>

#include <catch2/catch.hpp>

#include "analysis/bounds.hpp"
#include "analysis/homogenise_3d.hpp"
#include "analysis/traction.hpp"
#include "export/foam_case_3d.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "helpers.hpp"
#include "pipelines/laminate.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

// Writes the six load cases of `e` under `o` into `dir` and solves them, two at a time.
PeriodicHomogenised<6> solve_six(const ExportMesh<3>& e, const FoamOptions& o, const fs::path& dir, FoamMesh3& fm) {
  std::vector<fs::path> dirs;
  for (const LoadCase<6>& c : periodic_load_cases(e, o)) {
    dirs.push_back(dir / ("case_" + c.name));
    fs::create_directories(dirs.back());
    fm = write_foam_case(dirs.back(), e, load_case_options(o, c));
  }
  return solve_periodic(dirs, e, fm, o, 2);
}

// The largest difference of two tensors over the largest entry of the second.
double relative_difference(const Stiffness<6>& c, const Stiffness<6>& exact) {
  double worst = 0.0, scale = 0.0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      worst = std::max(worst, std::abs(c[i][j] - exact[i][j]));
      scale = std::max(scale, std::abs(exact[i][j]));
    }
  return worst / scale;
}

std::string show(const Stiffness<6>& c) {
  std::string s;
  for (const auto& row : c) {
    for (double x : row) s += std::to_string(x / 1e9) + " ";
    s += "\n";
  }
  return s;
}

}  // namespace

TEST_CASE("3D homogenisation: one material, six periodic load cases solved, balanced, at the imposed strain",
          "[homogenise3d][dual3d][solve]") {
  Tessellation3Options to;
  to.grains = 12;
  to.lloyd_iterations = 2;
  const FoamPhase carbide{"WC", 700e9, 0.24};
  to.phases = {Phase{"WC", 0.0, true, carbide.youngs_modulus, carbide.poisson_ratio, {}}};
  Rng rng(5);
  const Tessellation3 t = tessellate_3d(to, rng);
  const ExportMesh<3> e = grain_export_mesh(t, mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 240)}));
  const Stiffness<6> exact = isotropic_stiffness<6>(carbide);
  for (const auto cells : {FoamOptions::Cells::triangles, FoamOptions::Cells::polygons}) {
    const bool dual = cells == FoamOptions::Cells::polygons;
    CAPTURE(dual);
    FoamOptions o{.displacement = 1e-3 * t.width};
    o.cells = cells;
    test::ScratchDir dir("one3d");
    FoamMesh3 fm;
    const PeriodicHomogenised<6> h = solve_six(e, o, dir.path(), fm);
    const PolyMesh& pm = fm.mesh;
    INFO("face forces:\n" << show(h.stiffness) << "volume averages:\n" << show(h.volume_average_stiffness));
    // On the tetrahedra solidDisplacementFoam's plain form, on their dual the compact one,
    // both with least-squares gradients: a uniform strain is their exact solution, so the
    // face forces give the isotropic tensor to rounding.
    CHECK(relative_difference(h.stiffness, exact) < 1e-9);
    // The jumps impose the mean strain exactly: over a periodic cell the volume mean of
    // the cell stresses is the tensor times the imposed strain whatever the field.
    CHECK(relative_difference(h.volume_average_stiffness, exact) < 1e-9);
    // The dual converges in tens of corrections (the tetrahedra take hundreds).
    if (dual)
      for (const LoadCaseResult<6>& c : h.cases) CHECK(c.run.corrections < 100);
    // The face forces are the solver's own: every cell balanced at convergence (the
    // shear case, where all three components move).
    const LoadCaseResult<6>& shear = h.cases[5];
    const FieldValues grad = dual ? read_cell_field(shear.run.result_dir / kGradientField, "tensor",
                                                    static_cast<std::size_t>(pm.cells))
                                  : FieldValues{};
    const DiscreteTraction traction(fm, foam_cell(e), load_case_options(o, shear.load), shear.fields.displacement,
                                    grad, shear.fields.stress);
    double largest = 0.0, worst = 0.0;
    for (int f = 0; f < pm.internal_faces(); ++f) largest = std::max(largest, norm(traction.face_force(f)));
    for (int c = 0; c < pm.cells; ++c) worst = std::max(worst, norm(traction.cell_imbalance(c)));
    CHECK(worst < 1e-6 * largest);
  }
}

namespace {

// A laminate of ten slabs normal to x (seeds in a row), three of them soft, in a
// periodic cell 1 x 0.3 x 0.3 meshed at h = 0.04 (about 11k tetrahedra), solved on the
// tetrahedra or on their dual.
struct Laminate3 {
  PeriodicHomogenised<6> h;
  Stiffness<6> exact;
};
Laminate3 laminate_cell(double ratio, FoamOptions::Cells cells = FoamOptions::Cells::triangles) {
  Tessellation3Options to;
  to.width = 1.0;
  to.height = to.depth = 0.3;
  to.grains = 10;
  for (int i = 0; i < 10; ++i) to.seeds.push_back({(i + 0.5) / 10, 0.15, 0.15});
  to.min_edge = 0.0;  // no short edges to collapse: the slabs' faces stay planes of the box
  to.phases = {Phase{"hard", 0.0, true, 600e9, 0.22, {}}};
  Rng rng(1);
  const Tessellation3 t = tessellate_3d(to, rng);
  ExportMesh<3> e = grain_export_mesh(t, mesh_tessellation_3d(t, {.size = 0.04}));
  const test::Material hard{600e9, 0.22}, soft{600e9 / ratio, 0.3};
  e.phases = {FoamPhase{"hard", hard.E, hard.nu}, FoamPhase{"soft", soft.E, soft.nu}};
  // Soft: three neighbouring slabs clear of the box's sides (where the window cuts one).
  double soft_volume = 0.0;
  for (std::size_t k = 0; k < e.phase.size(); ++k) {
    const double x = t.grains[e.grain[k]].seed.x;
    e.phase[k] = x > 0.62 && x < 0.98 ? 1 : 0;
    const auto& v = e.mesh.tets[k];
    const auto& p = e.mesh.points;
    if (e.phase[k] == 1) soft_volume += tet_volume(p[v[0]], p[v[1]], p[v[2]], p[v[3]]);
  }
  REQUIRE(std::abs(soft_volume / (t.width * t.height * t.depth) - 0.3) < 1e-9);
  test::ScratchDir dir("laminate3d");
  FoamMesh3 fm;
  FoamOptions o{.displacement = 1e-3};
  o.cells = cells;
  return {solve_six(e, o, dir.path(), fm), test::laminate_3d(hard, soft, 0.3)};
}

// The nine orthotropic components' relative errors, and the largest of the others over C11.
struct LaminateErrors {
  std::array<double, 9> component;  // C11 C22 C33 C12 C13 C23 C44 C55 C66
  double others;
};
LaminateErrors laminate_errors(const Stiffness<6>& c, const Stiffness<6>& exact) {
  constexpr int kAt[9][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}, {3, 3}, {4, 4}, {5, 5}};
  LaminateErrors out{};
  for (int k = 0; k < 9; ++k) {
    const auto [i, j] = kAt[k];
    out.component[k] = std::abs(c[i][j] / exact[i][j] - 1);
  }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (exact[i][j] == 0.0) out.others = std::max(out.others, std::abs(c[i][j]) / exact[0][0]);
  return out;
}

}  // namespace

// The ratios both tests below take: the sanitizer build, there for memory and undefined
// behaviour, solves the same code once, at 3.
#ifdef GRAINMESH_SANITIZED
const std::vector<double> kLaminateRatios{3.0};
#else
const std::vector<double> kLaminateRatios{3.0, 20.0};
#endif

TEST_CASE("3D homogenisation: laminates of stiffness ratio 3 and 20, the exact layered tensor within 1 % at 3, the "
          "error in the shears across at 20",
          "[homogenise3d][solve]") {
  for (const double ratio : kLaminateRatios) {
    CAPTURE(ratio);
    const Laminate3 l = laminate_cell(ratio);
    INFO(show(l.h.stiffness) << "exact:\n" << show(l.exact));
    const LaminateErrors err = laminate_errors(l.h.stiffness, l.exact);
    if (ratio == 3.0) {
      // Measured: C55 and C66 +0.59 %, the others within 0.03 %.
      for (double e : err.component) CHECK(e < 0.01);
      CHECK(err.others < 1e-3);
      CHECK(symmetry_error(l.h.stiffness) < 1e-3);
    } else {
      // At the same mesh. Measured: C11 +0.96 %, C12 = C13 +0.80 %, C55 and C66 +3.4 %, the
      // others within 0.05 %: the error of the cells next to the interfaces, first order in
      // their size (C55 +1.1 % at h = 0.025 on a two-slab cell). Issue 24 asks 1 % for all
      // nine: not met by the shears across at this mesh; held here so that it does not get
      // worse.
      for (int k : {0, 1, 2, 3, 4, 5, 6}) CHECK(err.component[k] < 0.01);
      for (int k : {7, 8}) CHECK(err.component[k] < 0.04);
      CHECK(err.others < 2e-3);
      CHECK(symmetry_error(l.h.stiffness) < 2e-3);
    }
  }
}

TEST_CASE("3D homogenisation on the dual: laminates of ratio 3 and 20, the error across the layers",
          "[homogenise3d][dual3d][solve]") {
  for (const double ratio : kLaminateRatios) {
    CAPTURE(ratio);
    const Laminate3 l = laminate_cell(ratio, FoamOptions::Cells::polygons);
    INFO(show(l.h.stiffness) << "exact:\n" << show(l.exact));
    const LaminateErrors err = laminate_errors(l.h.stiffness, l.exact);
    // Measured (h = 0.04): ratio 3: C11 0.15 %, C12 0.09 %, C55 = C66 2.85 %, the rest
    // within 0.08 %, symmetric to 1.5e-3; ratio 20: C11 1.30 %, C12 1.09 %, C23 0.48 %,
    // C55 = C66 14.9 %, symmetric to 5.2e-3. The normal components across are held by
    // the interface weighting (without it ratio 20's C11 was +6.0 %); the shears across
    // are not (issue 24 asks 1 %): the cells' least-squares gradients next to an
    // interface mix the two phases' strains. Held here so that they do not get worse.
    const double normal = ratio == 3.0 ? 0.005 : 0.02, shear = ratio == 3.0 ? 0.035 : 0.16;
    for (int k : {0, 1, 2, 3, 4, 5, 6}) CHECK(err.component[k] < normal);
    for (int k : {7, 8}) CHECK(err.component[k] < shear);
    CHECK(err.others < 2e-3);
    CHECK(symmetry_error(l.h.stiffness) < (ratio == 3.0 ? 2e-3 : 7e-3));
  }
}

TEST_CASE("3D homogenisation on the dual: a 100-grain WC-Co cell, symmetric, between Voigt and Reuss, K within "
          "Hashin-Shtrikman, G above the upper bound by the interfaces' error only",
          "[homogenise3d][dual3d][solve]") {
  Tessellation3Options to;
  to.grains = 100;
  to.lloyd_iterations = 2;
  const FoamPhase wc{"WC", 700e9, 0.24}, co{"Co", 211e9, 0.31};
  to.phases = {Phase{"WC", 0.0, true, wc.youngs_modulus, wc.poisson_ratio, {}},
               Phase{"Co", 0.2, false, co.youngs_modulus, co.poisson_ratio, {}}};
  Rng rng(5);
  const Tessellation3 t = tessellate_3d(to, rng);
  // At 640 tetrahedra per grain nominal (19 s); the sanitizer build, which meshes ten times
  // slower, at 160.
#ifdef GRAINMESH_SANITIZED
  constexpr double kTetsPerGrain = 160;
  constexpr double kShearExcess = 0.015;
#else
  constexpr double kTetsPerGrain = 640;
  constexpr double kShearExcess = 0.005;
#endif
  const ExportMesh<3> e =
      grain_export_mesh(t, mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, kTetsPerGrain)}));
  FoamOptions o{.displacement = 1e-3 * t.width};
  o.cells = FoamOptions::Cells::polygons;
  test::ScratchDir dir("wcco3d_dual");
  FoamMesh3 fm;
  const PeriodicHomogenised<6> h = solve_six(e, o, dir.path(), fm);
  std::vector<double> fraction(2, 0.0);
  double volume = 0.0;
  for (std::size_t c = 0; c < fm.volume.size(); ++c) {
    fraction[fm.phase[c]] += fm.volume[c];
    volume += fm.volume[c];
  }
  for (double& f : fraction) f /= volume;
  const TensorBounds<6> b = tensor_bounds<6>(e.phases, fraction);
  const Stiffness<6> C = symmetric_part(h.stiffness);
  INFO(show(h.stiffness) << "Co " << fraction[1] << ", K " << bulk_modulus(C) << " in [" << *b.bulk_lower << ", "
                         << *b.bulk_upper << "], G " << shear_modulus(C) << " in [" << *b.shear_lower << ", "
                         << *b.shear_upper << "]");
  // Measured (7d5fb70): G converges from above (the shears' error at the interfaces, see
  // the laminates): 227.96, 226.30 and 225.35 GPa at 200, 800 and 3,200 per grain against
  // the upper bound 226.16, +0.80 %, +0.06 %, -0.36 % (3,200 takes 76 s alone, too long
  // for make test); K 376.2, 375.5, 375.2 GPa in [363.8, 377.9]; symmetric to 3.4e-4,
  // 1.9e-4, 1.1e-4.
  CHECK(symmetry_error(h.stiffness) < 1e-3);
  CHECK(semidefinite_order(C, b.voigt));
  CHECK(semidefinite_order(b.reuss, C));
  CHECK(bulk_modulus(C) > *b.bulk_lower);
  CHECK(bulk_modulus(C) < *b.bulk_upper);
  CHECK(shear_modulus(C) > *b.shear_lower);
  CHECK(shear_modulus(C) < (1 + kShearExcess) * *b.shear_upper);
}
