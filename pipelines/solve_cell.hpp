// A cell's cases solved and homogenised, for a plane or a solid cell (solve_cell_2d.cpp,
// solve_cell_3d.cpp): the typed answer (analysis/answer.hpp: the effective properties with
// the bounds that hold for them, a broken bound a warning, the phases' stress statistics),
// and the pictures and results.vtu of the solved fields beside it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "analysis/answer.hpp"
#include "analysis/homogenise.hpp"
#include "analysis/homogenise_3d.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/solve.hpp"
#include "common/deadline.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"
#include "grains/grain_mesh.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/tessellation_json.hpp"

namespace grainmesh {

// The answer of a plane (D = 2: Voigt size 3) or solid (D = 3: Voigt size 6) cell.
template <int D>
using CellAnswer = Answer<voigt_size(D)>;
// A run's answer, of either cell.
using RunAnswer = std::variant<CellAnswer<2>, CellAnswer<3>>;

// OpenFOAM's checkMesh on the run's first case in `dir` (report["case"] names the cases,
// which share one mesh) before it is solved: report.json's mesh_check {case,
// failed_checks, failures}, and a failed check a warning (check_mesh.hpp).
void check_case_mesh(const std::filesystem::path& dir, const Deadline& deadline, Json& report, Warnings& warnings);

// What the answers of a plane (D = 2) or solid (D = 3) cell are computed from and written
// beside: the run's staging directory `dir` (cases in it), its tessellation, the exported
// mesh and the polyMesh its cases were written on, the export's options, the run's time
// limit and its pictures (none when picture_width is 0; 2D: the field maps, all of them
// with all_pictures; 3D: sections at z = section_z) with their length unit.
template <int D>
struct SolveInput {
  const std::filesystem::path& dir;
  const StagedOutput& staged;
  const CellTessellation<D>& t;
  const ExportMesh<D>& e;
  const std::conditional_t<D == 2, PolyMesh, FoamMesh3>& pm;
  const FoamOptions& foam;
  const Deadline& deadline;
  int picture_width = 0;
  bool all_pictures = false;  // 2D only
  double section_z = 0.0;     // 3D only, mesh units
  std::string unit{};         // the pictures' length unit (length_unit_name of convert_to_meters)
  // The finite elements' coarse level (homogenise.solver or reference = fe): the cell
  // meshed coarser (fe_coarse_mesh); they solve on it and on its nested refinement
  // (fe_cell_answer). None without them.
  const ExportMesh<D>* fe_mesh = nullptr;
  int refine = 0;                    // mesh.refine: how often fe_mesh (and e) was split after meshing
  Solver solver = Solver::openfoam;  // homogenise.solver: whose answer is reported
  bool fe_mesh_file = false;         // the finite elements' fine level written as fe_mesh.vtu
};

// The mixed (thesis) load's answer (case/): the modulus (2D: in the plane state; 3D:
// under uniaxial strain) with the bounds that hold for it (mixed_bounds), the phases'
// stresses (`mixed`), the pictures; a broken bound is added to `warnings`.
CellAnswer<2> homogenise_mixed(const SolveInput<2>& in, std::vector<std::string>& warnings);
CellAnswer<3> homogenise_mixed(const SolveInput<3>& in, std::vector<std::string>& warnings);

// The periodic load cases' answer (case_NAME/): the stiffness judged, with its symmetry
// error, engineering constants and bounds, the phases' stresses per load case, the xx
// case's pictures. Under a temperature change (foam.delta_T) also the thermal case
// (case_thermal/): the effective thermal expansion with Levin's exact relation beside it
// (more than 1 % off a warning), the free state's phase stresses (`thermal`: the residual
// stress; `thermal_xx`: cooled, then pulled as the xx case) and its pictures. A broken
// bound is added to `warnings`. With a reference mesh, the finite-element reference beside
// the answer (reference_answer), an answer more than 1 % off it a warning.
CellAnswer<2> homogenise_periodic(const SolveInput<2>& in, std::vector<std::string>& warnings);
CellAnswer<3> homogenise_periodic(const SolveInput<3>& in, std::vector<std::string>& warnings);

// The periodic cell's answer by finite elements alone (homogenise.solver = fe without
// --solve: no OpenFOAM case is solved, so no stress statistics and no field pictures).
CellAnswer<2> homogenise_fe(const SolveInput<2>& in, std::vector<std::string>& warnings);
CellAnswer<3> homogenise_fe(const SolveInput<3>& in, std::vector<std::string>& warnings);

// The finite elements' part of a periodic cell's answer, solved on two levels:
// in.fe_mesh and its nested refinement (split_nested), the finer one's answer with the
// error estimate from both (fe_levels), its mesh written as fe_mesh.vtu in in.dir when
// in.fe_mesh_file. Under solver openfoam the reference beside OpenFOAM's answer `solved`
// (add_reference); under solver fe the answer (fe_answer) with the phases at `fractions`,
// and OpenFOAM's answer beside it with its stresses when `solved`. A broken bound a
// warning ending in `advice`'s.
template <int D>
CellAnswer<D> fe_cell_answer(const SolveInput<D>& in, const std::vector<double>& fractions, const AnswerAdvice& advice,
                             std::optional<CellAnswer<D>> solved, std::vector<std::string>& warnings);

}  // namespace grainmesh
