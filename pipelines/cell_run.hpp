// One dimension's stages of `grainmesh run` (cell_run_2d.cpp, cell_run_3d.cpp), called in
// order by the one run driver (run_command.cpp), which times them and measures their
// memory, stages the output, writes config.ini and report.json, keeps a failed solve as
// OUT.failed, drops the cases when asked and prints the lines every run prints. Only what
// differs between a plane and a solid cell is here: its types and its kernels.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "pipelines/report.hpp"
#include "pipelines/run_plan.hpp"
#include "pipelines/solve_cell.hpp"
#include "pipelines/stage_line.hpp"

namespace grainmesh {

// The seconds of the run's stages that its summary shows.
struct RunSeconds {
  double tessellate = 0.0, total = 0.0;
};

class CellRun {
 public:
  virtual ~CellRun() = default;
  // The microstructure, from the tessellation job (randomness from its seed alone); what
  // is doubtful about it into `warnings`. Throws ConfigError naming the key at fault.
  virtual void tessellate(Warnings& warnings) = 0;
  // Meshes the microstructure and checks the mesh's conformity; progress on `stage`.
  virtual void mesh(const StageLine& stage, Warnings& warnings) = 0;
  // Writes the tessellation's and the mesh's files (and pictures) into `dir`; returns
  // report.json's fields on them (dimensions, the cell, statistics, mesh).
  virtual Json write_geometry(const std::filesystem::path& dir, Warnings& warnings) = 0;
  // Exports the mesh and writes the cases into `dir`: the mixed load's case/ or the
  // periodic load cases' case_NAME/. Returns their directory names; what is doubtful about
  // the cases' mesh into `warnings`.
  virtual std::vector<std::string> write_cases(const std::filesystem::path& dir, Warnings& warnings) = 0;
  // report.json's fields on the cases once written (case_format, case_cells, ...).
  virtual Json case_fields() const = 0;
  // The cells the cases are solved on (a convergence study's measure of refinement).
  virtual std::size_t solved_cells() const = 0;
  // The stage line while solving.
  virtual std::string solving() const = 0;
  // Solves the cases in `dir` and homogenises (--solve), or without --solve homogenises by
  // finite elements alone (homogenise.solver = fe); what is doubtful into `warnings`.
  // Throws SolveError when a solve fails.
  virtual RunAnswer solve(const std::filesystem::path& dir, const StagedOutput& staged,
                          std::vector<std::string>& warnings) = 0;
  // The run's lines on stdout (what was made and written into `out`, and `answer` when
  // solved), but for the warnings' count.
  virtual void print_summary(const std::filesystem::path& out, const RunSeconds& seconds,
                             const RunAnswer* answer) const = 0;
};

std::unique_ptr<CellRun> make_cell_run(const RunPlan& plan, const CellJobs<2>& jobs);
std::unique_ptr<CellRun> make_cell_run(const RunPlan& plan, const CellJobs<3>& jobs);

// Whether a case of `cells` cells is written binary: export.format's choice when given,
// binary above kBinaryCaseAboveCells otherwise.
inline bool binary_case(const RunPlan& plan, std::size_t cells) {
  return plan.formats.binary.value_or(cells > kBinaryCaseAboveCells);
}

}  // namespace grainmesh
