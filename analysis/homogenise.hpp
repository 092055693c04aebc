// Homogenisation of solved cases: the mean stress from the forces through the loaded
// sides (traction.hpp), the effective modulus under the thesis' load (`mixed`), and the
// effective in-plane stiffness tensor of a periodic cell from three load cases
// (`periodic`). The area average of cell stresses is kept beside each as
// `volume_average`: it mixes the phases in cells next to interfaces and so is biased.
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
#include "analysis/stress_measures.hpp"
#include "common/deadline.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// How the cell is loaded for homogenisation (config key homogenise.boundary).
enum class Boundary {
  mixed,     // the thesis: right side pulled, symmetry planes elsewhere; one modulus
  periodic,  // cyclic pairs, a macroscopic strain per load case; the stiffness tensor
};

// The area average of the cell stresses of a solved case: xx, yy, xy (Pa).
std::array<double, 3> volume_average(const CaseFields& fields, const ExportMesh<2>& m);

// Solves the case that write_foam_case wrote into `case_dir` (`pm` is what it returned)
// under the `mixed` load and homogenises (a cyclic case's force from its cell fields).
// Errors as run_solver.
MixedHomogenised<3> solve_mixed(const std::filesystem::path& case_dir, const ExportMesh<2>& m, const PolyMesh& pm,
                                const FoamOptions& o, const Deadline& deadline = {},
                                const std::filesystem::path& case_shown_as = {});

// The load cases of the periodic homogenisation of `m` under `o`: a macroscopic strain
// e = load_strain (o.displacement / width) in xx, in yy, and an engineering shear e in xy
// (a tensor component of half that); with a temperature change (o.delta_T), a fourth,
// `thermal`: the change at the mean strain the phases would take free, each expanding on
// its own (the area mean of free_expansion delta_T, in xx and yy). Near the answer, it
// is the answer for one material (no stress); and the solve needs a strain: a cell held
// at zero mean strain under a uniform thermal stress has a source of rounding noise
// alone, which its singular periodic system (a translation is free) turns into drift.
std::vector<LoadCase<3>> periodic_load_cases(const ExportMesh<2>& m, const FoamOptions& o);

// Solves the periodic load cases written by write_foam_case into `case_dirs` (in the
// order of periodic_load_cases(m, o), each with load_case_options; `pm`
// the mesh, the same for all), up to `parallel` at a time, and assembles the stiffness.
// A failing case throws SolveError naming it (the first in order when several fail).
// `cases_shown_as`: where the cases are to be found if they fail (or empty).
PeriodicHomogenised<3> solve_periodic(const std::vector<std::filesystem::path>& case_dirs, const ExportMesh<2>& m,
                                      const PolyMesh& pm, const FoamOptions& o, int parallel,
                                      const Deadline& deadline = {},
                                      const std::vector<std::filesystem::path>& cases_shown_as = {});


}  // namespace grainmesh
