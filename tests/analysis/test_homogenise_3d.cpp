// The 3D periodic homogenisation against exact answers: one material gives its own
// isotropic tensor, and laminates (grains from seeds in a row: slabs normal to x) the
// exact layered tensor.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "analysis/homogenise_3d.hpp"
#include "analysis/traction.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "helpers.hpp"
#include "tessellate/tessellation_3d.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

// Writes the six load cases of `e` under `o` into `dir` and solves them, two at a time.
PeriodicHomogenised3 solve_six(const ExportMesh3& e, const FoamOptions& o, const fs::path& dir, PolyMesh& pm) {
  std::vector<fs::path> dirs;
  for (const LoadCase3& c : periodic_load_cases_3d(e, o)) {
    dirs.push_back(dir / ("case_" + c.name));
    fs::create_directories(dirs.back());
    pm = write_foam_case_3d(dirs.back(), e, load_case_options_3d(o, c));
  }
  return solve_periodic_3d(dirs, e, pm, o, 2);
}

// The largest difference of two tensors over the largest entry of the second.
double relative_difference(const Stiffness6& c, const Stiffness6& exact) {
  double worst = 0.0, scale = 0.0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      worst = std::max(worst, std::abs(c[i][j] - exact[i][j]));
      scale = std::max(scale, std::abs(exact[i][j]));
    }
  return worst / scale;
}

std::string show(const Stiffness6& c) {
  std::string s;
  for (const auto& row : c) {
    for (double x : row) s += std::to_string(x / 1e9) + " ";
    s += "\n";
  }
  return s;
}

}  // namespace

TEST_CASE("3D homogenisation: one material, six periodic load cases solved, balanced, at the imposed strain",
          "[homogenise3d][solve]") {
  Tessellation3Options to;
  to.grains = 12;
  to.lloyd_iterations = 2;
  const FoamPhase carbide{"WC", 700e9, 0.24};
  to.phases = {Phase{"WC", 0.0, true, carbide.youngs_modulus, carbide.poisson_ratio, {}}};
  Rng rng(5);
  const Tessellation3 t = tessellate_3d(to, rng);
  const ExportMesh3 e = grain_export_mesh_3d(t, mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 300)}));
  const FoamOptions o{.displacement = 1e-3 * t.width};
  test::ScratchDir dir("one3d");
  PolyMesh pm;
  const PeriodicHomogenised3 h = solve_six(e, o, dir.path(), pm);
  const Stiffness6 exact = isotropic_stiffness_3d(carbide);
  INFO("face forces:\n" << show(h.stiffness) << "volume averages:\n" << show(h.volume_average_stiffness));
  // The jumps impose the mean strain exactly: over a periodic cell the volume mean of the
  // cells' Gauss gradients is the jump's, whatever the field, so on one material the mean
  // cell stress is the isotropic tensor times the imposed strain, to rounding.
  CHECK(relative_difference(h.volume_average_stiffness, exact) < 1e-9);
  // The face forces are the solver's own: every cell balanced at convergence (the shear
  // case, where all three components move).
  const LoadCaseResult3& shear = h.cases[5];
  const DiscreteTraction traction(pm, e, load_case_options_3d(o, shear.load), shear.fields.displacement,
                                  read_cell_field(shear.run.result_dir / kGradientField, "tensor",
                                                  static_cast<std::size_t>(pm.cells)),
                                  shear.fields.stress);
  double largest = 0.0, worst = 0.0;
  for (int f = 0; f < pm.internal_faces(); ++f) largest = std::max(largest, norm(traction.face_force(f)));
  for (int c = 0; c < pm.cells; ++c) worst = std::max(worst, norm(traction.cell_imbalance(c)));
  CHECK(worst < 1e-6 * largest);
  // What they give is solidDisplacementFoam's answer on tetrahedra: measured 3.0 % from the
  // exact tensor and 1.3 % from symmetric on this cell (issue 24 asks 0.1 %: not met, see
  // README); held here so that it does not get worse.
  CHECK(relative_difference(h.stiffness, exact) < 0.05);
  CHECK(symmetry_error(h.stiffness) < 0.02);
}
