#include "pipelines/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <map>

#include "export/foam.hpp"
#include "export/picture.hpp"
#include "mesh/quality.hpp"
#include "pipelines/default_config.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/homogenise.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/tessellate_command.hpp"
#include "tessellate/tessellation_json.hpp"

namespace grainmesh {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

std::vector<std::string> run_config_keys() {
  std::vector<std::string> keys = tessellate_config_keys();
  for (const auto& k : mesh_config_keys()) keys.push_back(k);
  for (const auto& k : export_config_keys()) keys.push_back(k);
  return keys;
}

const char* default_run_config() { return kDefaultRunConfig; }

std::string config_ini(const Config& config) {
  // "a.b.c" is key c of section [a.b]; sections in order of first appearance.
  std::vector<std::string> order;
  std::map<std::string, std::string> body;
  for (const auto& [key, value] : config.entries()) {
    const auto dot = key.rfind('.');
    const std::string section = dot == std::string::npos ? "" : key.substr(0, dot);
    if (!body.count(section)) order.push_back(section);
    body[section] += key.substr(dot + 1) + " = " + value + "\n";
  }
  std::string text = "# The resolved config of a grainmesh run: `grainmesh run config.ini -o OUT` repeats it.\n";
  for (const std::string& s : order) text += "\n[" + s + "]\n" + body[s];
  return text;
}

void check_run_config(const Config& c) {
  c.check_keys(run_config_keys());
  read_tessellate_job(c.subset(tessellate_config_keys()));
  read_foam_options(c.subset(export_config_keys()));
}

void run_run_command(const Config& c, const std::filesystem::path& out, bool solve, bool quiet) {
  c.check_keys(run_config_keys());
  check_output_replaceable(out);
  // Each stage reads its part; every value is checked before any work is done.
  const Config tess_config = c.subset(tessellate_config_keys());
  const Config mesh_config = c.subset(mesh_config_keys());
  const TessellateJob tess_job = read_tessellate_job(tess_config);
  const FoamOptions foam = read_foam_options(c.subset(export_config_keys()));
  if (solve && foam.traction != 0.0)
    c.fail("load.traction", "--solve homogenises under an imposed displacement; remove load.traction");
  const auto start = std::chrono::steady_clock::now();
  // The stage on one line of a terminal, rewritten in place (at most ten times a second).
  const bool show = !quiet && isatty(STDERR_FILENO) != 0;
  auto last_shown = start - std::chrono::seconds(1);
  auto stage = [&](const std::string& what, bool force = true) {
    if (!show) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - last_shown < std::chrono::milliseconds(100)) return;
    last_shown = now;
    std::fprintf(stderr, "\r\033[Kgrainmesh run: %s (%.1f s)", what.c_str(), since(start));
    std::fflush(stderr);
  };

  auto clock = std::chrono::steady_clock::now();
  stage("tessellating");
  const Tessellation t = run_tessellate_job(tess_job, tess_config);
  const double tessellate_seconds = since(clock);

  clock = std::chrono::steady_clock::now();
  MeshJob mesh_job = read_mesh_job(mesh_config, t);
  mesh_job.options.distmesh.deadline = tess_job.options.deadline;  // one guard for the whole run
  stage("meshing");
  if (show)
    mesh_job.options.progress = [&](int done, int total) {
      stage("meshing: " + std::to_string(done) + " / " + std::to_string(total) + " regions", done == total);
    };
  const GrainMesh m = mesh_tessellation(t, mesh_job.options);
  check_conformity(t, m);
  const double mesh_seconds = since(clock);
  const MeshQuality q = measure_quality(m.mesh);

  StagedOutput staged(out);
  const std::filesystem::path dir = staged.dir();
  write_text_file(dir / "tessellation.json", tessellation_to_json(t));
  write_tessellation_png(dir / "tessellation.png", t, {.width_px = tess_job.picture_width});
  write_mesh_files(dir, t, m, mesh_job.picture_width);

  clock = std::chrono::steady_clock::now();
  stage("exporting");
  const ExportMesh e = grain_export_mesh(t, m);
  std::filesystem::create_directories(dir / "case");
  write_foam_case(dir / "case", e, foam);
  const double export_seconds = since(clock);
  write_text_file(dir / "config.ini", config_ini(c));

  Json effective;
  double solve_seconds = 0.0;
  if (solve) {
    clock = std::chrono::steady_clock::now();
    stage("solving with solidDisplacementFoam");
    const Homogenised h = solve_and_homogenise(dir / "case", e, foam, tess_job.options.deadline);
    solve_seconds = since(clock);
    std::vector<double> fractions;
    for (const PhaseStats& p : t.stats.phases) fractions.push_back(p.achieved_fraction);
    effective = {{"modulus", h.modulus},
                 {"sigma_xx", h.sigma_xx},
                 {"sigma_yy", h.sigma_yy},
                 {"sigma_xy", h.sigma_xy},
                 {"strain_xx", h.strain_xx},
                 {"corrections", h.corrections},
                 {"final_residual", h.final_residual}};
    // Pictures of the solution over the cells, grain boundaries drawn (the thesis' 3.14-3.15).
    const std::vector<CellStress> sigma = read_cell_stress(dir / "case/1/sigma");
    std::vector<double> sxx, syy, sxy;
    for (const CellStress& s : sigma) sxx.push_back(s.xx), syy.push_back(s.yy), sxy.push_back(s.xy);
    const std::vector<std::pair<std::string, std::pair<std::vector<double>, std::string>>> pictures{
        {"stress_xx.png", {sxx, "sigma_xx (Pa)"}},
        {"stress_yy.png", {syy, "sigma_yy (Pa)"}},
        {"stress_xy.png", {sxy, "tau_xy (Pa)"}},
        {"displacement.png", {read_cell_displacement(dir / "case/1/D"), "|D| (m)"}}};
    for (const auto& [name, field] : pictures)
      write_mesh_png(dir / name, m.mesh,
                     {.width_px = mesh_job.picture_width, .outline_by = {}, .view = {}, .field = field.first,
                      .field_name = field.second});
    if (!foam.uniaxial) {  // the bounds are for the default load (mean eps_yy zero)
      const ElasticBounds b = elastic_bounds(e.phases, fractions, foam.plane_stress);
      effective["voigt"] = b.voigt;
      effective["reuss"] = b.reuss;
      if (b.hs_lower) effective["hashin_shtrikman"] = {{"lower", *b.hs_lower}, {"upper", *b.hs_upper}};
    }
  }

  Json phases = Json::array();
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    phases.push_back({{"name", t.phases[p].name},
                      {"target_fraction", t.stats.phases[p].target_fraction},
                      {"achieved_fraction", t.stats.phases[p].achieved_fraction}});
  Json report{{"command", "run"},
              {"config", c.source()},
              {"seed", tess_job.seed},
              {"grains", t.stats.grains},
              {"phases", phases},
              {"mesh",
               {{"points", m.mesh.points.size()},
                {"cells", m.mesh.triangles.size()},
                {"q_min", q.q_min},
                {"q_mean", q.q_mean},
                {"min_angle_deg", q.min_angle_deg},
                {"max_non_orthogonality_deg", q.max_non_orthogonality_deg},
                {"cells_per_grain_mean", static_cast<double>(m.mesh.triangles.size()) / t.stats.grains}}},
              {"seconds",
               {{"tessellate", tessellate_seconds},
                {"mesh", mesh_seconds},
                {"export", export_seconds},
                {"solve", solve_seconds},
                {"total", since(start)}}},
              {"case", "case"},
              {"peak_memory_mib", peak_memory_mib()}};
  add_time_limit(report, tess_job.options.deadline);
  if (solve) report["effective"] = effective;
  write_json(dir / "report.json", report);
  staged.commit();
  if (show) std::fprintf(stderr, "\r\033[K");

  std::printf("grainmesh run: %d grains, %zu cells (q_min %.3f, q_mean %.3f), %.2f s\n  wrote %s/{tessellation.json, "
              "tessellation.png, mesh.vtu, mesh.png, case/, config.ini, report.json}\n  the case: %s/case/Allrun runs "
              "checkMesh and solidDisplacementFoam\n",
              t.stats.grains, m.mesh.triangles.size(), q.q_min, q.q_mean, since(start), out.string().c_str(),
              out.string().c_str());
  if (solve)
    std::printf("  solved: effective modulus %.4g Pa (Reuss %.4g, Voigt %.4g), %d corrections\n",
                effective["modulus"].get<double>(), effective.value("reuss", 0.0), effective.value("voigt", 0.0),
                effective["corrections"].get<int>());
}

}  // namespace grainmesh
