#include "analysis/homogenise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "analysis/foam_fields.hpp"
#include "analysis/stress_recovery.hpp"
#include "analysis/traction.hpp"
#include "common/errors.hpp"
#include "common/side_by_side.hpp"

namespace grainmesh {

std::array<double, 3> volume_average(const CaseFields& fields, const ExportMesh<2>& m) {
  const std::vector<StressState> sigma = stress_states(fields, /*plane_stress=*/false);  // in-plane parts only
  std::array<double, 3> s{};
  double area = 0.0;
  for (std::size_t k = 0; k < sigma.size(); ++k) {  // cell k is triangle k
    const double a = cell_area(m.mesh, k);
    s[0] += a * sigma[k].xx;
    s[1] += a * sigma[k].yy;
    s[2] += a * sigma[k].xy;
    area += a;
  }
  return {s[0] / area, s[1] / area, s[2] / area};
}

std::vector<LoadCase<3>> periodic_load_cases(const ExportMesh<2>& m, const FoamOptions& o) {
  std::vector<LoadCase<3>> cases = mechanical_load_cases<3>(load_strain(foam_cell(m), o));
  if (o.delta_T == 0.0) return cases;
  double area = 0.0, free = 0.0;
  for (std::size_t t = 0; t < m.phase.size(); ++t) {
    const double a = cell_area(m.mesh, t);
    area += a;
    free += a * free_expansion(m.phases[m.phase[t]], o.plane_stress);
  }
  const double e = free / area * o.delta_T;
  cases.push_back(thermal_load_case<3>(e, o.delta_T));
  return cases;
}

namespace {

// The mean stress of a solved periodic case from the forces through right and top, and
// each cell's virial stress from the same forces.
struct Balanced {
  std::array<double, 3> mean{};  // xx, yy, xy
  std::vector<StressState> virial;
};
Balanced periodic_stress(const std::filesystem::path& result_dir, const CaseFields& fields, const ExportMesh<2>& m,
                         const PolyMesh& pm, const FoamOptions& o) {
  const std::size_t cells = static_cast<std::size_t>(pm.cells);
  const DiscreteTraction traction(pm, m, o, fields.displacement,
                                  read_cell_field(result_dir / kGradientField, "tensor", cells), fields.stress);
  const double s2 = o.convert_to_meters * o.convert_to_meters;
  const Vec3 right = traction.side_force("right") / (m.cell.height() * pm.thickness * s2);
  const Vec3 top = traction.side_force("top") / (m.cell.width() * pm.thickness * s2);
  // The shear through right and through top: equal in the continuum, nearly so here.
  return {{right.x, top.y, 0.5 * (right.y + top.x)}, traction.virial_stress()};
}

}  // namespace

MixedHomogenised<3> solve_mixed(const std::filesystem::path& case_dir, const ExportMesh<2>& m, const PolyMesh& pm,
                                const FoamOptions& o, const Deadline& deadline,
                                const std::filesystem::path& case_shown_as) {
  MixedHomogenised<3> h;
  h.run = run_solver(case_dir, foam_cell(m), o, deadline, case_shown_as);
  h.fields = read_case_fields(h.run.result_dir, m.phases, m.phase, o);
  h.cell_stress = recovered_stress(h.fields, m, o);
  // The force through `right`: the load the cell carries. From sigma's face values there,
  // or on a cyclic case, which writes none, from the cell fields.
  if (o.cyclic) {
    h.sigma_xx = periodic_stress(h.run.result_dir, h.fields, m, pm, o).mean[0];
  } else {
    const int right = patch_index(pm, "right");
    const PolyMesh::Patch& patch = pm.patches[right];
    const FieldValues sigma =
        read_patch_field(h.run.result_dir / kStressField, "symmTensor", "right", static_cast<std::size_t>(patch.size));
    const Vec3 force = written_patch_force(pm, m, o, right, sigma);
    h.sigma_xx = force.x / (m.cell.height() * pm.thickness * o.convert_to_meters * o.convert_to_meters);
  }
  // Left held, right moved by the displacement: the mean of d(ux)/dx over the cell is
  // exactly displacement / width.
  h.strain_xx = o.cyclic ? cyclic_strain(foam_cell(m), o)[0] : o.displacement / m.cell.width();
  h.modulus = h.sigma_xx / h.strain_xx;
  h.volume_average = volume_average(h.fields, m);
  h.volume_average_modulus = h.volume_average[0] / h.strain_xx;
  return h;
}

PeriodicHomogenised<3> solve_periodic(const std::vector<std::filesystem::path>& case_dirs, const ExportMesh<2>& m,
                                      const PolyMesh& pm, const FoamOptions& o, int parallel, const Deadline& deadline,
                                      const std::vector<std::filesystem::path>& cases_shown_as) {
  const std::vector<LoadCase<3>> loads = periodic_load_cases(m, o);
  const int n = static_cast<int>(loads.size());
  if (case_dirs.size() != loads.size()) throw GeometryError("solve_periodic: a case directory per load case is needed");
  PeriodicHomogenised<3> h;
  h.cases.resize(loads.size());
  auto solve = [&](int k) {
    LoadCaseResult<3>& r = h.cases[k];
    r.load = loads[k];
    const FoamOptions ok = load_case_options(o, r.load);
    const std::filesystem::path shown = cases_shown_as.empty() ? std::filesystem::path() : cases_shown_as[k];
    r.run = run_solver(case_dirs[k], foam_cell(m), ok, deadline, shown, r.load.name);
    r.fields = read_case_fields(r.run.result_dir, m.phases, m.phase, ok);
    r.cell_stress = recovered_stress(r.fields, m, ok);
    Balanced balanced = periodic_stress(r.run.result_dir, r.fields, m, pm, ok);
    r.stress = balanced.mean;
    r.virial_stress = std::move(balanced.virial);
    r.volume_average = volume_average(r.fields, m);
  };
  // Side by side, `parallel` at a time (each solver is one process); the shear case first,
  // as it takes longest.
  std::vector<int> order{2, 0, 1};
  if (n == 4) order.insert(order.begin() + 1, 3);
  side_by_side(order, parallel, solve);
  assemble_stiffness(h);
  return h;
}

}  // namespace grainmesh
