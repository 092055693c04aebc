#include "pipelines/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "common/errors.hpp"
#include "common/memory.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "export/foam_load.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"
#include "grains/conformity.hpp"
#include "mesh/quality.hpp"
#include "pipelines/answer.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/result_pictures.hpp"
#include "pipelines/run_3d_command.hpp"
#include "pipelines/stage_line.hpp"
#include "pipelines/tessellate_command.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/picture.hpp"

namespace grainmesh {

namespace {

// The largest of a report's per-stage figures.
double largest(const Json& stages) {
  double most = 0.0;
  for (const auto& [stage, value] : stages.items()) most = std::max(most, value.get<double>());
  return most;
}

// Each stage's peak resident memory (the solve's with the solver's processes), in MiB by
// stage name.
class StageMemoryLog {
 public:
  void begin(bool with_children = false) { meter_ = std::make_unique<StageMemory>(with_children); }
  void end(const char* name) {
    json_[name] = meter_->peak_mib();
    meter_.reset();
  }
  const Json& json() const { return json_; }

 private:
  Json json_ = Json::object();
  std::unique_ptr<StageMemory> meter_;
};

// What a run reads from its config, all checked before any work is done.
struct RunPlan {
  Config tess_config, mesh_config;
  TessellateJob tess_job;
  FoamOptions foam;
  Boundary boundary;
  Pictures pictures;  // they cost more than the rest of a small run's output
  bool keep_cases = true;
};

// The config's keys are known (check_keys) before this reads them.
RunPlan read_run_plan(const Config& c, bool solve, Warnings& warnings) {
  const Config tess_config = c.subset(tessellate_config_keys());
  RunPlan plan{tess_config, c.subset(mesh_config_keys()), read_tessellate_job(tess_config), read_run_foam_options(c),
               read_boundary(c), read_pictures(c), read_keep_cases(c, solve)};
  if (solve && plan.foam.traction != 0.0)
    c.fail("load.traction", "--solve homogenises under an imposed displacement; remove load.traction");
  const TessellationOptions& to = plan.tess_job.options;
  for (const std::string& w :
       check_load(FoamCell{foam_phases(to.phases), {to.width, to.height, 0.0}, to.periodic}, plan.foam))
    warnings.add(w);
  return plan;
}

// The cases of the run in `dir`: the mixed load in case/, the periodic load cases each in
// their own case_NAME/. Returns their directory names; `pm` gets the polyMesh.
std::vector<std::string> write_cases(const std::filesystem::path& dir, const ExportMesh& e, const FoamOptions& foam,
                                     Boundary boundary, PolyMesh& pm) {
  std::vector<std::string> case_dirs;
  if (boundary == Boundary::mixed) {
    case_dirs.push_back("case");
    std::filesystem::create_directories(dir / "case");
    pm = write_foam_case(dir / "case", e, foam);
    return case_dirs;
  }
  // One mesh for the load cases (their options differ in the strain and temperature
  // alone), its files written once and copied.
  for (const LoadCase<3>& lc : periodic_load_cases(e, foam)) {
    const bool first = case_dirs.empty();
    case_dirs.push_back(load_case_dir(lc));
    std::filesystem::create_directories(dir / case_dirs.back());
    if (first) {
      pm = write_foam_case(dir / case_dirs.back(), e, load_case_options(foam, lc));
      continue;
    }
    write_foam_case(dir / case_dirs.back(), e, pm, load_case_options(foam, lc),
                    dir / case_dirs.front() / "constant" / "polyMesh");
  }
  return case_dirs;
}

// The run's tessellation, its seconds and memory, its warnings.
Tessellation tessellate_stage(const RunPlan& plan, const StageLine& stage, StageMemoryLog& memory, Json& seconds,
                              Warnings& warnings) {
  const auto clock = Clock::now();
  memory.begin();
  stage.show("tessellating");
  Tessellation t = run_tessellate_job(plan.tess_job, plan.tess_config);
  check_phases_have_grains(t, plan.tess_job, plan.tess_config);
  seconds["tessellate"] = since(clock);
  memory.end("tessellate");
  stage.end();
  for (const std::string& w : tessellation_warnings(t)) warnings.add(w);
  return t;
}

// config.ini's note of what the defaults meant: the out-of-plane condition.
std::string plane_state_note(const FoamOptions& foam) {
  return std::string("2D: solved in ") + (foam.plane_stress ? "plane stress (load.plane_stress = true)"
                                                            : "plane strain (load.plane_stress = false, the default)");
}

// report.json of a run before the solve: what was made and how long each stage took.
Json run_report(const Config& c, const RunPlan& plan, const Tessellation& t, const GrainMesh& m, const MeshQuality& q,
                const ExportMesh& e, const std::vector<std::string>& case_dirs, const Json& seconds, const Json& memory,
                bool solve) {
  Json report{{"config", c.source()},
              {"config_fingerprint", config_fingerprint(c)},
              {"dimensions", 2},
              {"seed", plan.tess_job.seed},
              {"width", t.width},
              {"height", t.height},
              {"periodic", t.periodic},
              {"grains", t.stats.grains},
              {"phases", phases_json(t)},
              {"statistics", descriptors_json(t)},
              {"mesh",
               {{"points", m.mesh.points.size()},
                {"cells", m.mesh.triangles.size()},
                {"q_min", q.q_min},
                {"q_mean", q.q_mean},
                {"min_angle_deg", q.min_angle_deg},
                {"max_non_orthogonality_deg", q.max_non_orthogonality_deg},
                {"cells_per_grain_mean", static_cast<double>(m.mesh.triangles.size()) / t.stats.grains},
                {"unconverged_regions", m.unconverged_regions}}},
              {"seconds", seconds},
              {"memory_mib", memory},
              {"case", case_dirs.size() == 1 ? Json(case_dirs[0]) : Json(case_dirs)},
              {"case_format", plan.foam.binary ? "binary" : "ascii"},
              {"plane_state", plane_state(plan.foam)},
              {"solved", solve}};
  // Polygonal cells: how many the case has (mesh.cells counts the triangles they come from).
  if (plan.foam.cells == FoamOptions::Cells::polygons) report["case_cells"] = {{"shape", "polygons"}, {"cells", e.mesh.cells()}};
  add_time_limit(report, plan.tess_job.options.deadline);
  return report;
}

// The solve and its answer into `report` (effective, stresses); its warnings into
// `warnings`. A solve that fails keeps the staged output as OUT.failed, its report saying
// why, and throws. Returns the solve's seconds.
double solve_stage(const SolveInput& in, StagedOutput& staged, Boundary boundary, const StageLine& stage, StageMemoryLog& memory,
                   Json& report, Warnings& warnings) {
  const auto clock = Clock::now();
  memory.begin(true);
  stage.show("solving with solidDisplacementFoam");
  std::vector<std::string> solve_warnings;
  check_case_mesh(in.dir, in.deadline, report, warnings);
  try {
    Answer answer = boundary == Boundary::mixed ? homogenise_mixed(in, solve_warnings)
                                                : homogenise_periodic(in, solve_warnings);
    report["effective"] = std::move(answer.effective);
    report["effective"]["processes"] = in.foam.processes;
    report["stresses"] = std::move(answer.stresses);
  } catch (const SolveError& err) {
    // Kept for a look: the case with the solver's log, as OUT.failed.
    stage.end();
    report["failed"] = err.what();
    memory.end("solve");
    report["memory_mib"] = memory.json();
    report["peak_memory_mib"] = largest(memory.json());
    try {
      write_report(staged, report, warnings);
      staged.keep_as_failed();
    } catch (const IoError& io) {
      throw SolveError(std::string(err.what()) + " (but it could not be kept: " + io.what() + ")");
    }
    throw;
  }
  const double seconds = since(clock);
  memory.end("solve");
  stage.end();
  for (const std::string& w : solve_warnings) warnings.add(w);
  return seconds;
}

// The run's lines on stdout: what was made and written, and the answer when solved.
void print_summary(const std::filesystem::path& out, const Tessellation& t, const GrainMesh& m, const MeshQuality& q,
                   const Json& report, const RunPlan& plan, bool solve, const Warnings& warnings, double seconds) {
  // What is there (the pictures are optional), directories marked.
  std::string written;
  for (const std::string& name : entry_names(out))
    written += (written.empty() ? "" : ", ") + name + (std::filesystem::is_directory(out / name) ? "/" : "");
  std::printf("grainmesh run: %d grains, %zu cells (q_min %.3f, q_mean %.3f), %.2f s\n  wrote %s/{%s}\n  each case's "
              "Allrun runs checkMesh and solidDisplacementFoam\n",
              t.stats.grains, m.mesh.triangles.size(), q.q_min, q.q_mean, seconds, out.string().c_str(),
              written.c_str());
  if (solve && plan.boundary == Boundary::mixed) {
    const Json& eff = report["effective"];
    std::printf("  solved: effective modulus %.4g Pa", eff["modulus"].get<double>());
    if (eff.contains("reuss"))
      std::printf(" (Reuss %.4g, Voigt %.4g)", eff["reuss"].get<double>(), eff["voigt"].get<double>());
    std::printf(", %d corrections\n", eff["corrections"].get<int>());
  } else if (solve) {
    const Json& C = report["effective"]["stiffness"];
    std::printf("  solved: effective stiffness C11 %.4g, C22 %.4g, C12 %.4g, C66 %.4g Pa (%zu load cases, at most %d "
                "corrections)\n",
                C["C11"].get<double>(), C["C22"].get<double>(), C["C12"].get<double>(), C["C66"].get<double>(),
                report["effective"]["load_cases"].size(), report["effective"]["corrections"].get<int>());
    if (plan.foam.delta_T != 0.0) {
      const Json& a = report["effective"]["thermal_expansion"];
      std::printf("  thermal (%s): free in-plane expansion %.4g, %.4g 1/K (xx, yy)%s; residual stresses in report.json "
                  "(stresses.thermal)\n",
                  plan.foam.plane_stress ? "plane stress" : "plane strain", a["xx"].get<double>(), a["yy"].get<double>(),
                  plan.foam.plane_stress ? "" : " (held out of plane: not a 3D expansion, see docs/run.md)");
    }
  }
  if (!warnings.all().empty())
    std::printf("  %zu warning%s (stderr and report.json)\n", warnings.all().size(), warnings.all().size() > 1 ? "s" : "");
}

}  // namespace

void run_run_command(const Config& c, const std::filesystem::path& out, bool solve, bool quiet, bool summary) {
  c.check_keys(run_config_keys());
  if (cell_dimensions(c) == 3) return run_run_3d_command(c, out, solve, quiet, summary);
  claim_output(out, "run");
  Warnings warnings;
  RunPlan plan = read_run_plan(c, solve, warnings);
  const TessellateJob& tess_job = plan.tess_job;
  FoamOptions& foam = plan.foam;
  const auto start = Clock::now();
  StageLine stage(!quiet && isatty(STDERR_FILENO) != 0, start);
  StageMemoryLog memory;
  Json seconds;

  const Tessellation t = tessellate_stage(plan, stage, memory, seconds, warnings);

  auto clock = Clock::now();
  memory.begin();
  MeshJob mesh_job = read_mesh_job(plan.mesh_config, t);
  mesh_job.options.distmesh.deadline = tess_job.options.deadline;  // one guard for the whole run
  stage.show("meshing");
  if (stage.shown())
    mesh_job.options.progress = [&](int done, int total) {
      stage.show("meshing: " + std::to_string(done) + " / " + std::to_string(total) + " regions", done == total);
    };
  const GrainMesh m = mesh_tessellation(t, mesh_job.options);
  check_conformity(t, m);
  seconds["mesh"] = since(clock);
  const MeshQuality q = measure_quality(m.mesh);
  stage.end();
  for (const std::string& w : mesh_warnings(m, q, mesh_job.options)) warnings.add(w);

  StagedOutput staged(out, "run");
  const std::string unit = length_unit_name(foam.convert_to_meters);  // the pictures' scale bars
  const std::filesystem::path dir = staged.dir();
  write_text_file(dir / "tessellation.json", tessellation_to_json(t));
  if (plan.pictures != Pictures::none)
    write_tessellation_png(dir / "tessellation.png", t, tessellation_picture(t, tess_job.picture_width, unit));
  const int picture_width = plan.pictures != Pictures::none ? mesh_job.picture_width : 0;
  const bool all_pictures = plan.pictures == Pictures::all;
  write_mesh_files(dir, t, m, picture_width, all_pictures, unit);
  memory.end("mesh");

  clock = Clock::now();
  memory.begin();
  stage.show("exporting");
  const ExportMesh e = export_mesh(t, m, foam.cells);
  if (foam.cells == FoamOptions::Cells::polygons && all_pictures)  // the solved cells, as mesh_detail.png shows the triangles
    write_mesh_png(dir / "cells_detail.png", e.mesh,
                   {.width_px = picture_width, .fill_by = e.phase, .outline_by = e.grain, .view = detail_view(t),
                    .legend = phase_names(t), .scale_bar = true, .length_unit = unit});
  if (!c.has("export.format") && e.mesh.cells() > kBinaryCaseAboveCells) foam.binary = true;
  PolyMesh pm;
  const std::vector<std::string> case_dirs = write_cases(dir, e, foam, plan.boundary, pm);
  seconds["export"] = since(clock);
  memory.end("export");
  write_text_file(dir / "config.ini", config_ini(c, {plane_state_note(foam)}));
  Json report = run_report(c, plan, t, m, q, e, case_dirs, seconds, memory.json(), solve);

  const double solve_seconds =
      solve ? solve_stage(SolveInput{dir, staged, t, e, pm, foam, tess_job.options.deadline, picture_width,
                                     all_pictures, unit},
                          staged, plan.boundary, stage, memory, report, warnings)
            : 0.0;
  report["seconds"]["solve"] = solve_seconds;
  if (!plan.keep_cases) drop_cases(dir, case_dirs, report);
  report["seconds"]["total"] = since(start);
  report["memory_mib"] = memory.json();
  report["peak_memory_mib"] = largest(memory.json());
  write_report(staged, report, warnings);
  staged.commit();
  stage.end();
  if (summary) print_summary(out, t, m, q, report, plan, solve, warnings, since(start));
}

}  // namespace grainmesh
