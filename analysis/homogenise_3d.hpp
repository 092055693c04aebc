// Homogenisation of a periodic 3D cell: six load cases, each a macroscopic strain imposed
// as the jump of the displacement across the three cyclic pairs, solved by
// solidDisplacementFoam; the mean stress of each from the forces through right, top and
// front (traction.hpp: exact for the discrete solution, unlike the volume average of the
// cell stresses, kept beside it); the 6 x 6 effective stiffness column by column.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/foam_fields.hpp"
#include "analysis/load_case.hpp"
#include "analysis/solve.hpp"
#include "analysis/solved_state.hpp"
#include "common/deadline.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

// A symmetric tensor in Voigt order: xx, yy, zz, yz, xz, xy (strains as tensor components).
using Voigt6 = std::array<double, 6>;

// The six load cases of `m` under `o`: a mean strain e = load_strain (displacement / width)
// in xx, yy, zz, and engineering shears e in yz, xz, xy (tensor components e / 2); with a
// temperature change (o.delta_T) a seventh, `thermal`: the change at the mean strain the
// phases would take free, each on its own (the volume mean of alpha delta_T, in xx, yy
// and zz), which leaves only the phases' mismatch to carry (analysis/thermal.hpp).
std::vector<LoadCase<6>> periodic_load_cases(const ExportMesh<3>& m, const FoamOptions& o);

// Solves the load cases written by write_foam_case into `case_dirs` (in the order of
// periodic_load_cases(m, o), each with load_case_options; `fm` the mesh it wrote,
// the same for all), up to `parallel` at a time, and assembles the stiffness. A failing
// case throws SolveError naming it (the first in order when several fail).
PeriodicHomogenised<6> solve_periodic(const std::vector<std::filesystem::path>& case_dirs, const ExportMesh<3>& m,
                                      const FoamMesh3& fm, const FoamOptions& o, int parallel,
                                      const Deadline& deadline = {},
                                      const std::vector<std::filesystem::path>& cases_shown_as = {});

// The thesis' mixed load in 3D (write_foam_case without cyclic: right pulled by
// load.displacement, symmetry planes on the other sides, so the cell is held from
// straining sideways): solved, the mean stress through right from the force there (sigma's
// face values, S . sigma_f), the strain displacement / width, their ratio the modulus
// under uniaxial strain (C11 of an isotropic cell). Errors as run_solver.
MixedHomogenised<6> solve_mixed(const std::filesystem::path& case_dir, const ExportMesh<3>& m, const FoamMesh3& fm,
                                const FoamOptions& o, const Deadline& deadline = {},
                                const std::filesystem::path& case_shown_as = {});


}  // namespace grainmesh
