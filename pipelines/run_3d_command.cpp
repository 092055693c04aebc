#include "pipelines/run_3d_command.hpp"

#include <unistd.h>

#include <cstdio>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/memory.hpp"
#include "export/foam_case_3d.hpp"
#include "pipelines/answer_3d.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/mesh_3d_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/run_config.hpp"
#include "pipelines/stage_line.hpp"
#include "pipelines/tessellate_3d_command.hpp"
#include "view/picture.hpp"

namespace grainmesh {

namespace {

// The cases of the run in `dir`: the mixed load in case/, the six periodic load cases (and
// the thermal one) each in case_NAME/. Returns their directory names and the mesh they were written on.
std::vector<std::string> write_cases_3d(const std::filesystem::path& dir, const ExportMesh3& e, const FoamOptions& o,
                                        Boundary boundary, FoamMesh3& fm) {
  std::vector<std::string> names;
  if (boundary == Boundary::mixed) {
    names.push_back("case");
    std::filesystem::create_directories(dir / "case");
    fm = write_foam_case_3d(dir / "case", e, o);
    return names;
  }
  // One mesh for the load cases (their options differ in the strain and temperature
  // alone), its files written once and copied.
  for (const LoadCase<6>& lc : periodic_load_cases(e, o)) {
    const bool first = names.empty();
    names.push_back(load_case_dir(lc));
    std::filesystem::create_directories(dir / names.back());
    const FoamOptions case_options = load_case_options(o, lc);
    if (first) fm = foam_mesh_3d(e, case_options);
    write_foam_case_3d(dir / names.back(), e, fm, case_options,
                       first ? std::filesystem::path() : dir / names.front() / "constant" / "polyMesh");
  }
  return names;
}

// The run's lines on stdout: what was made and written, and the answer when solved.
void print_run_3d_summary(const std::filesystem::path& out, const Tessellation3& t, const GrainMesh3& m, const Json& report, const std::vector<std::string>& case_dirs,
                          const FoamMesh3& fm, const FoamOptions& foam, Boundary boundary, bool solve,
                          bool pictures, const Warnings& warnings) {
  print_tessellation_3d_summary(t, report["seconds"]["tessellate"].get<double>());
  print_mesh_3d_summary(report["mesh"], m.seconds);
  const char* cases = case_dirs.size() == 1 ? "case/"
                      : case_dirs.size() == 6 ? "case_xx/ ... case_xy/ (six load cases)"
                                              : "case_xx/ ... case_xy/, case_thermal/ (seven load cases)";
  std::printf("  cases: %s (%d %s cells)\n", cases, fm.mesh.cells, foam.cells == FoamOptions::Cells::polygons ? "polyhedral" : "tetrahedral");
  if (solve && boundary == Boundary::mixed) {
    const Json& eff = report["effective"];
    std::printf("  solved: modulus under uniaxial strain %.4g Pa", eff["modulus"].get<double>());
    if (eff.contains("voigt")) std::printf(" (Reuss %.4g, Voigt %.4g)", eff["reuss"].get<double>(), eff["voigt"].get<double>());
    std::printf(", %d corrections\n", eff["corrections"].get<int>());
  } else if (solve) {
    const Json& eff = report["effective"];
    const Json& C = eff["stiffness"];
    std::printf("  solved: C11 %.4g, C22 %.4g, C33 %.4g, C12 %.4g, C44 %.4g Pa; K %.4g, G %.4g Pa; symmetric to %.1e "
                "(6 load cases, at most %d corrections)\n",
                C["C11"].get<double>(), C["C22"].get<double>(), C["C33"].get<double>(), C["C12"].get<double>(),
                C["C44"].get<double>(), eff["bulk_modulus"].get<double>(), eff["shear_modulus"].get<double>(),
                eff["symmetry_error"].get<double>(), eff["corrections"].get<int>());
    if (eff.contains("thermal_expansion")) {
      const Json& a = eff["thermal_expansion"];
      std::printf("  thermal: free expansion %.4g, %.4g, %.4g 1/K (xx, yy, zz); residual stresses in report.json "
                  "(stresses.thermal)\n",
                  a["xx"].get<double>(), a["yy"].get<double>(), a["zz"].get<double>());
    }
  }
  // What is there (the pictures are optional), directories marked, case_* once.
  std::string written;
  bool cases_listed = false;
  for (const std::string& name : entry_names(out)) {
    const bool load_case = name.rfind("case_", 0) == 0;
    if (load_case && cases_listed) continue;
    cases_listed = cases_listed || load_case;
    written += (written.empty() ? "" : ", ") + (load_case ? std::string("case_*") : name) +
               (std::filesystem::is_directory(out / name) ? "/" : "");
  }
  std::printf("  wrote %s/{%s}%s\n", out.string().c_str(), written.c_str(),
              pictures ? (" (sections z = " + to_text(report["section_z"].get<double>()) + ")").c_str() : "");
  if (!warnings.all().empty())
    std::printf("  %zu warning%s (stderr and report.json)\n", warnings.all().size(), warnings.all().size() > 1 ? "s" : "");
}

// The solve and its answer into `report` (effective, stresses), its warnings into
// `warnings`. A solve that fails keeps the staged output as OUT.failed, its report saying
// why, and throws.
void solve_cases_3d(const SolveInput3& in, StagedOutput& staged, Boundary boundary, StageLine& stage, Json& report,
                    Warnings& warnings) {
  std::vector<std::string> solve_warnings;
  check_case_mesh(in.dir, in.deadline, report, warnings);
  try {
    Answer answer = boundary == Boundary::mixed ? homogenise_mixed_3d(in, solve_warnings)
                                                : homogenise_periodic_3d(in, solve_warnings);
    report["effective"] = std::move(answer.effective);
    report["effective"]["processes"] = in.foam.processes;
    report["stresses"] = std::move(answer.stresses);
  } catch (const SolveError& err) {
    // Kept for a look: the cases with the solver's logs, as OUT.failed.
    stage.end();
    report["failed"] = err.what();
    write_report(staged, report, warnings);
    staged.keep_as_failed();
    throw;
  }
  for (const std::string& w : solve_warnings) warnings.add(w);
}

}  // namespace

void run_run_3d_command(const Config& c, const std::filesystem::path& out, bool solve, bool quiet, bool summary) {
  check_run_3d_config(c);
  const bool keep_cases = read_keep_cases(c, solve);
  FoamOptions foam = read_foam_options_3d(c);
  const Boundary boundary = read_boundary(c);
  claim_output(out, "run");
  const Config tess_config = c.subset(tessellate_config_keys());
  const Tessellate3Job tess_job = read_tessellate_3d_job(tess_config);
  const auto start = Clock::now();
  StageLine stage(!quiet && isatty(STDERR_FILENO) != 0, start);
  Warnings warnings;
  Json seconds;

  auto clock = Clock::now();
  stage.show("tessellating");
  const Tessellation3 t = run_tessellate_3d_job(tess_job, tess_config, warnings);
  seconds["tessellate"] = since(clock);
  for (const std::string& w : check_load(FoamCell{foam_phases(t.phases), t.size(), t.periodic}, foam)) warnings.add(w);

  clock = Clock::now();
  Mesh3Job mesh_job = read_mesh_3d_job(c.subset(mesh_config_keys()), t);
  mesh_job.options.deadline = tess_job.options.deadline;  // one guard for the whole run
  stage.show("meshing " + std::to_string(t.regions.size()) + " regions");
  const GrainMesh3 m = run_mesh_3d_job(t, mesh_job);
  seconds["mesh"] = since(clock);

  StagedOutput staged(out, "run");
  const std::filesystem::path dir = staged.dir();
  Json report{{"config", c.source()}, {"config_fingerprint", config_fingerprint(c)}};
  const bool pictures = read_pictures(c) != Pictures::none;
  const std::string unit = length_unit_name(foam.convert_to_meters);  // the pictures' scale bars
  report.update(write_tessellation_3d_files(dir, t, tess_job, pictures, unit, warnings));
  report.update(write_mesh_3d_files(dir, t, m, mesh_job, warnings, pictures, unit));  // its grains and section_z: the same

  clock = Clock::now();
  stage.show("exporting");
  const ExportMesh3 e = grain_export_mesh_3d(t, m);
  if (!c.has("export.format") && e.mesh.tets.size() > kBinaryCaseAboveCells) foam.binary = true;
  FoamMesh3 fm;
  const std::vector<std::string> case_dirs = write_cases_3d(dir, e, foam, boundary, fm);
  seconds["export"] = since(clock);
  write_text_file(dir / "config.ini", config_ini(c));
  report["case"] = case_dirs.size() == 1 ? Json(case_dirs[0]) : Json(case_dirs);
  report["case_format"] = foam.binary ? "binary" : "ascii";
  report["case_cells"] = {{"shape", foam.cells == FoamOptions::Cells::polygons ? "polyhedra" : "tetrahedra"},
                          {"cells", fm.mesh.cells},
                          {"faces", fm.mesh.faces()}};
  report["solved"] = solve;

  if (solve) {
    clock = Clock::now();
    stage.show("solving with solidDisplacementFoam (" + std::to_string(case_dirs.size()) + " case" +
               (case_dirs.size() > 1 ? "s" : "") + ")");
    const SolveInput3 in{dir,  staged, t, e, fm, foam, tess_job.options.deadline,
                         pictures ? mesh_job.picture_width : 0, report["section_z"].get<double>(), unit};
    solve_cases_3d(in, staged, boundary, stage, report, warnings);
    seconds["solve"] = since(clock);
  }
  stage.end();
  if (!keep_cases) drop_cases(dir, case_dirs, report);
  seconds["total"] = since(start);
  report["seconds"] = seconds;
  add_time_limit(report, tess_job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();
  if (summary)
    print_run_3d_summary(out, t, m, report, case_dirs, fm, foam, boundary, solve, pictures, warnings);
}

}  // namespace grainmesh
