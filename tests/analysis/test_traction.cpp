// The force through faces as solidDisplacementFoam's discrete equation has it: at
// convergence every cell's faces carry forces that add up to zero, also across cyclic
// faces with a jump, and under a temperature change - the test that the flux is the
// solver's own, not an estimate.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "analysis/foam_fields.hpp"
#include "analysis/homogenise.hpp"
#include "analysis/solve.hpp"
#include "analysis/traction.hpp"
#include "common/random.hpp"
#include "export/foam_case.hpp"
#include "grains/grain_mesh.hpp"
#include "helpers.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellate.hpp"

using namespace grainmesh;

TEST_CASE("the discrete traction balances on every cell of a solved periodic two-phase case, for each load case "
          "and a thermal one",
          "[analysis][traction][openfoam]") {
  TessellationOptions to;
  to.width = 3.0;
  to.height = 1.7;
  to.grains = 30;
  to.periodic = true;
  to.lloyd_iterations = 3;
  to.phases = {Phase{"WC", 0.0, true, 800e9, 0.1, 5e-6}, Phase{"Co", 0.25, false, 300e9, 0.3, 14e-6}};
  Rng rng(3);
  const Tessellation t = tessellate(to, rng);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.1, .phase_size = {}});
  const ExportMesh<2> e = grain_export_mesh(t, m);
  // A mean strain of 1e-3 and, in the fourth case, cooling by 500 K.
  const FoamOptions periodic{.cyclic = true, .displacement = 1e-3 * to.width, .delta_T = -500.0};
  const std::vector<LoadCase<3>> loads = periodic_load_cases(e, periodic);
  REQUIRE(loads.size() == 4);
  for (const LoadCase<3>& load : loads) {
    INFO("load case " << load.name);
    test::ScratchDir dir("traction");
    const FoamOptions o = load_case_options(periodic, load);
    const PolyMesh pm = write_foam_case(dir.path(), e, o);
    // Solved a thousand times further than usual: what is left over is then the formula's.
    write_control_dict(dir.path(), foam_cell(e), o, kMaxCorrections, 1e-3);
    const SolveRun run = run_solver(dir.path(), foam_cell(e), o);
    // The whole stress: under the temperature change, sigmaD less the thermal stress.
    CaseFields fields = read_case_fields(run.result_dir, e.phases, e.phase, o);
    const DiscreteTraction traction(pm, e, o, std::move(fields.displacement),
                                    read_cell_field(run.result_dir / kGradientField, "tensor",
                                                    static_cast<std::size_t>(pm.cells)),
                                    std::move(fields.stress));
    // The scale: the largest force through one face.
    double largest = 0.0;
    for (int f = 0; f < pm.internal_faces(); ++f) largest = std::max(largest, norm(traction.face_force(f)));
    double worst = 0.0;
    int worst_cell = -1, bad = 0;
    for (int c = 0; c < pm.cells; ++c) {
      const double imbalance = norm(traction.cell_imbalance(c));
      if (imbalance > 1e-6 * largest) ++bad;
      if (imbalance > worst) worst = imbalance, worst_cell = c;
    }
    INFO("largest face force " << largest << ", worst imbalance " << worst << " at cell " << worst_cell << ", " << bad
                               << " of " << pm.cells << " cells above 1e-6");
    CHECK(worst < 1e-6 * largest);
    // The cells' virial stresses add up to the forces through the sides.
    const std::vector<StressState> virial = traction.virial_stress();
    double area = 0.0;
    StressState sum;
    for (int c = 0; c < pm.cells; ++c) {
      const double a = cell_area(e.mesh, static_cast<std::size_t>(c));
      area += a;
      sum.xx += a * virial[c].xx, sum.yy += a * virial[c].yy, sum.xy += a * virial[c].xy;
    }
    const double s2 = o.convert_to_meters * o.convert_to_meters;
    const Vec3 through_right = traction.side_force("right") / (e.cell.height() * pm.thickness * s2);
    const Vec3 through_top = traction.side_force("top") / (e.cell.width() * pm.thickness * s2);
    const double stress_scale = std::max({std::abs(through_right.x), std::abs(through_top.y), std::abs(through_right.y)});
    CHECK(std::abs(sum.xx / area - through_right.x) < 1e-6 * stress_scale);
    CHECK(std::abs(sum.yy / area - through_top.y) < 1e-6 * stress_scale);
    CHECK(std::abs(sum.xy / area - 0.5 * (through_right.y + through_top.x)) < 1e-6 * stress_scale);
    // What goes in on the left comes out on the right (and bottom, top).
    const Vec3 left = traction.side_force("left"), right = traction.side_force("right");
    const Vec3 bottom = traction.side_force("bottom"), top = traction.side_force("top");
    CHECK(norm(left + right) < 1e-6 * norm(right));
    CHECK(norm(bottom + top) < 1e-6 * norm(top));
    // And the load is carried: the loaded direction's force has the strain's sign.
    if (load.name == "xx") CHECK(right.x > 0.0);
    if (load.name == "yy") CHECK(top.y > 0.0);
    if (load.name == "xy") CHECK((right.y > 0.0 && top.x > 0.0));
    // Cooled and held at the area mean of the phases' free contractions: more than the cell
    // contracts free, as the stiffer carbide contracts less, so the sides are in compression.
    if (load.name == "thermal") CHECK((right.x < 0.0 && top.y < 0.0));
  }
}
