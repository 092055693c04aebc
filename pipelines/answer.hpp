// A solve's answer as report.json gives it: the case(s) solved and homogenised, the
// effective properties with the bounds that hold for them (a broken bound a warning),
// the phases' stress statistics, and the pictures and results.vtu of the solved fields.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/homogenise.hpp"
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

namespace grainmesh {

// What a solve adds to report.json: `effective` and `stresses`.
struct Answer {
  Json effective;
  Json stresses;
};


// OpenFOAM's checkMesh on the run's first case in `dir` (report["case"] names the cases,
// which share one mesh) before it is solved: report.json's mesh_check {case,
// failed_checks, failures}, and a failed check a warning (check_mesh.hpp).
void check_case_mesh(const std::filesystem::path& dir, const Deadline& deadline, Json& report, Warnings& warnings);

// What the answers are computed from and written beside: the run's staging directory
// `dir` (cases in it), its tessellation and exported mesh, the export's options,
// the run's time limit and its pictures (none when picture_width is 0) with their unit.
struct SolveInput {
  const std::filesystem::path& dir;
  const StagedOutput& staged;
  const Tessellation& t;
  const ExportMesh& e;
  const PolyMesh& pm;
  const FoamOptions& foam;
  const Deadline& deadline;
  int picture_width;
  bool all_pictures;
  const std::string& unit;  // the pictures' length unit (length_unit_name of convert_to_meters)
};

// The mixed (thesis) load's answer in report.json (case/), with the bounds that hold for
// it; a broken bound is added to `warnings`.
Answer homogenise_mixed(const SolveInput& in, std::vector<std::string>& warnings);

// The periodic load cases' answer (case_NAME/): the stiffness tensor, its engineering
// constants, the bounds, and with a thermal load the residual state; a broken bound or
// Levin's relation missed is added to `warnings`.
Answer homogenise_periodic(const SolveInput& in, std::vector<std::string>& warnings);

}  // namespace grainmesh
