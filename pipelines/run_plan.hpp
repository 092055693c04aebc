// `grainmesh run`'s config read and checked once, before any work: the run plan (its specification).
// The run (run_command.cpp) takes only this plan; errors found later (a phase left without
// grains, a size too fine for the cell) name their key through the jobs' ConfigOrigin.
// The dimension of the cell is decided here, once, by cell_dimensions.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "analysis/answer.hpp"
#include "analysis/homogenise.hpp"
#include "export/foam_options.hpp"
#include "pipelines/config.hpp"
#include "pipelines/drawing.hpp"
#include "pipelines/element_files.hpp"
#include "pipelines/mesh_job.hpp"
#include "pipelines/tessellate_job.hpp"

namespace grainmesh {

// The jobs of a D-dimensional cell's tessellation and mesh.
template <int D>
struct CellJobs {
  TessellateJob<D> tessellate;
  MeshJob<D> mesh;
};

// The most nested refinements mesh.refine takes: 4^4 (8^4) times the cells.
inline constexpr int kMaxRefine = 4;

struct RunPlan {
  std::string source;        // the config's file ("default" for the embedded one)
  std::string fingerprint;   // config_fingerprint of the config
  std::string resolved_ini;  // config.ini: the config as resolved, with what the defaults meant
  std::variant<CellJobs<2>, CellJobs<3>> cell;
  FoamOptions foam;
  ExportFormats formats;  // export.format: the case's encoding when given (else binary when large), mesh files
  Boundary boundary = Boundary::mixed;
  Solver solver = Solver::openfoam;  // homogenise.solver: where a periodic cell's answer comes from
  bool fe_reference = false;  // homogenise.reference = fe: the finite-element reference beside the answer
  int refine = 0;  // mesh.refine: the mesh split in nested refinement so often before the solves
  Pictures pictures = Pictures::all;
  bool solve = false;
  bool keep_cases = true;               // output.cases = keep (answers: dropped once solved)
  std::vector<std::string> warnings;    // what the config's load makes doubtful (check_load)

  int dimensions() const { return cell.index() == 0 ? 2 : 3; }
  // Whether the run solves by finite elements: the answer's solver or its reference.
  bool solves_fe() const { return solver == Solver::fe || fe_reference; }
  // Whether the run has an answer: solved by OpenFOAM (--solve), or by finite elements
  // without it.
  bool answers() const { return solve || solver == Solver::fe; }
};

// Reads and checks every key of a run config (`solve`: the run solves, --solve).
// Throws ConfigError naming the key.
RunPlan read_run_plan(const Config& config, bool solve);

}  // namespace grainmesh
