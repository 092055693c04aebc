#include "analysis/homogenise_3d.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/phase_statistics.hpp"
#include "analysis/traction.hpp"
#include "common/errors.hpp"
#include "common/side_by_side.hpp"
#include "export/foam_geometry.hpp"

namespace grainmesh {

namespace {

// Voigt index of the tensor component (i, j).
constexpr int kVoigt[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};

// The mean stress of a solved case from the forces through right, top and front: row i of
// the stress is the force through the side normal to axis i over its area; the shears
// from the two sides that carry each, averaged (equal in the continuum, nearly so here);
// and each cell's virial stress, from the same face forces.
struct Balanced3 {
  Voigt6 mean{};
  FieldValues virial;
};
Balanced3 periodic_stress_3d(const std::filesystem::path& result_dir, const CaseFields& fields, const ExportMesh<3>& m,
                             const FoamMesh3& fm, const FoamOptions& o) {
  const FoamCell cell = foam_cell(m);
  // The plain form's face force is S . sigma_f: no gradient needed (nor written).
  const FieldValues grad = compact_normal_stress(cell, o)
                               ? read_cell_field(result_dir / kGradientField, "tensor", static_cast<std::size_t>(fm.mesh.cells))
                               : FieldValues{};
  const DiscreteTraction traction(fm, cell, o, fields.displacement, grad, fields.stress);
  const double s2 = o.convert_to_meters * o.convert_to_meters;
  const Vec3 box = m.cell.size();
  const std::array<Vec3, 3> row{traction.side_force("right") / (box.y * box.z * s2),
                                traction.side_force("top") / (box.x * box.z * s2),
                                traction.side_force("front") / (box.x * box.y * s2)};
  Balanced3 out{.mean = {}, .virial = traction.virial_stress_tensor()};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.mean[kVoigt[i][j]] += (i == j ? 1.0 : 0.5) * row[i][j];
  return out;
}

// The volume average of the cell stresses (OpenFOAM's order xx xy xz yy yz zz).
Voigt6 volume_average(const CaseFields& fields, const FoamMesh3& fm) {
  Voigt6 s{};
  double volume = 0.0;
  for (std::size_t k = 0; k < fm.volume.size(); ++k) {
    const double v = fm.volume[k];
    const double* c = fields.stress[k];
    const Voigt6 cell{c[0], c[3], c[5], c[4], c[2], c[1]};
    for (int i = 0; i < 6; ++i) s[i] += v * cell[i];
    volume += v;
  }
  for (double& x : s) x /= volume;
  return s;
}

}  // namespace

std::vector<LoadCase<6>> periodic_load_cases(const ExportMesh<3>& m, const FoamOptions& o) {
  std::vector<LoadCase<6>> cases = mechanical_load_cases<6>(load_strain(foam_cell(m), o));
  if (o.delta_T == 0.0) return cases;
  std::vector<double> volume;
  for (const auto& v : m.mesh.tets) {
    const std::vector<Vec3>& p = m.mesh.points;
    volume.push_back(tet_volume(p[v[0]], p[v[1]], p[v[2]], p[v[3]]));
  }
  const std::vector<double> fraction = phase_volume_fractions(volume, m.phase, static_cast<int>(m.phases.size()));
  double free = 0.0;
  for (std::size_t p = 0; p < fraction.size(); ++p) free += fraction[p] * m.phases[p].alpha;
  cases.push_back(thermal_load_case<6>(free * o.delta_T, o.delta_T));
  return cases;
}

PeriodicHomogenised<6> solve_periodic(const std::vector<std::filesystem::path>& case_dirs, const ExportMesh<3>& m,
                                      const FoamMesh3& fm, const FoamOptions& o, int parallel,
                                      const Deadline& deadline,
                                      const std::vector<std::filesystem::path>& cases_shown_as) {
  const std::vector<LoadCase<6>> loads = periodic_load_cases(m, o);
  if (case_dirs.size() != loads.size())
    throw GeometryError("solve_periodic: a case directory per load case is needed");
  PeriodicHomogenised<6> h;
  h.cases.resize(loads.size());
  // The shear cases first: they take longest.
  std::vector<int> order{3, 4, 5, 0, 1, 2};
  if (loads.size() > 6) order.push_back(6);
  side_by_side(order, parallel, [&](int k) {
    LoadCaseResult<6>& r = h.cases[static_cast<std::size_t>(k)];
    r.load = loads[static_cast<std::size_t>(k)];
    const FoamOptions ok = load_case_options(o, r.load);
    const std::filesystem::path shown = cases_shown_as.empty() ? std::filesystem::path() : cases_shown_as[k];
    r.run = run_solver(case_dirs[k], foam_cell(m), ok, deadline, shown, r.load.name);
    r.fields = read_case_fields(r.run.result_dir, m.phases, fm.phase, ok);
    Balanced3 balanced = periodic_stress_3d(r.run.result_dir, r.fields, m, fm, ok);
    r.stress = balanced.mean;
    r.virial_stress = std::move(balanced.virial);
    r.volume_average = volume_average(r.fields, fm);
  });
  assemble_stiffness(h);
  return h;
}

MixedHomogenised<6> solve_mixed(const std::filesystem::path& case_dir, const ExportMesh<3>& m, const FoamMesh3& fm,
                                const FoamOptions& o, const Deadline& deadline,
                                const std::filesystem::path& case_shown_as) {
  MixedHomogenised<6> r;
  r.run = run_solver(case_dir, foam_cell(m), o, deadline, case_shown_as);
  r.fields = read_case_fields(r.run.result_dir, static_cast<std::size_t>(fm.mesh.cells));
  const PolyMesh& pm = fm.mesh;
  const PolyMesh::Patch& right = pm.patches[static_cast<std::size_t>(patch_index(pm, "right"))];
  const FieldValues sigma = read_patch_field(r.run.result_dir / kStressField, "symmTensor", "right",
                                             static_cast<std::size_t>(right.size));
  // S . sigma_f's x component (sigma: xx xy xz yy yz zz), in metres squared and pascals.
  double force = 0.0;
  for (int k = 0; k < right.size; ++k) {
    const Vec3 S = (o.convert_to_meters * o.convert_to_meters) * foam_face(pm, right.start + k).area;
    force += S.x * sigma[k][0] + S.y * sigma[k][1] + S.z * sigma[k][2];
  }
  r.sigma_xx = force / (m.cell.size().y * m.cell.size().z * o.convert_to_meters * o.convert_to_meters);
  r.strain_xx = load_strain(foam_cell(m), o);
  r.modulus = r.sigma_xx / r.strain_xx;
  r.volume_average = volume_average(r.fields, fm);
  r.volume_average_modulus = r.volume_average[0] / r.strain_xx;
  return r;
}

}  // namespace grainmesh
