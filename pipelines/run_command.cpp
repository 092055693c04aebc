#include "pipelines/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>

#include "common/errors.hpp"
#include "common/format.hpp"
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

std::string config_fingerprint(const Config& c) {
  std::string text;
  for (const auto& [key, value] : c.entries())
    if (key != "mesh.threads" && key != kTimeLimitKey) text += key + "=" + value + "\n";
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
  for (const unsigned char ch : text) h = (h ^ ch) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

void check_run_config(const Config& c) {
  c.check_keys(run_config_keys());
  read_tessellate_job(c.subset(tessellate_config_keys()));
  read_foam_options(c.subset(export_config_keys()));
}

namespace {

// The solved case's answer in report.json, the pictures of its fields, and warnings for a
// modulus outside the bounds that hold for the same load (added to `warnings`).
Json solve_run(const std::filesystem::path& dir, const StagedOutput& staged, const Tessellation& t, const GrainMesh& m,
               const ExportMesh& e, const FoamOptions& foam, const Deadline& deadline, int picture_width,
               std::vector<std::string>& warnings) {
  const Homogenised h = solve_and_homogenise(dir / "case", e, foam, deadline, staged.failed_dir() / "case");
  Json effective{{"modulus", h.modulus},
                 {"sigma_xx", h.sigma_xx},
                 {"sigma_yy", h.sigma_yy},
                 {"sigma_xy", h.sigma_xy},
                 {"strain_xx", h.strain_xx},
                 {"corrections", h.corrections},
                 {"final_residual", h.final_residual},
                 {"component_residuals", h.component_residuals},
                 {"result", std::filesystem::relative(h.result_dir, dir).string()}};
  // Pictures of the solution over the cells, grain boundaries drawn (the thesis' 3.14-3.15).
  const std::vector<CellStress> sigma = read_cell_stress(h.result_dir / kStressField);
  std::vector<double> sxx, syy, sxy;
  for (const CellStress& s : sigma) sxx.push_back(s.xx), syy.push_back(s.yy), sxy.push_back(s.xy);
  const std::vector<std::pair<std::string, std::pair<std::vector<double>, std::string>>> pictures{
      {"stress_xx.png", {sxx, "sigma_xx (Pa)"}},
      {"stress_yy.png", {syy, "sigma_yy (Pa)"}},
      {"stress_xy.png", {sxy, "tau_xy (Pa)"}},
      {"displacement.png", {read_cell_displacement(h.result_dir / "D"), "|D| (m)"}}};
  for (const auto& [name, field] : pictures)
    write_mesh_png(dir / name, m.mesh,
                   {.width_px = picture_width, .outline_by = {}, .view = {}, .field = field.first,
                    .field_name = field.second});
  if (foam.uniaxial) return effective;  // the bounds are for the default load (mean eps_yy zero)
  std::vector<double> fractions;
  for (const PhaseStats& p : t.stats.phases) fractions.push_back(p.achieved_fraction);
  const ElasticBounds b = elastic_bounds(e.phases, fractions, foam.plane_stress);
  effective["voigt"] = b.voigt;
  effective["reuss"] = b.reuss;
  if (b.hs_lower) effective["hashin_shtrikman"] = {{"lower", *b.hs_lower}, {"upper", *b.hs_upper}};
  auto outside = [&](double bound, const std::string& name, bool above) {
    constexpr double kRounding = 1e-6;  // relative: bounds that coincide (one material) are met to rounding
    if (above ? h.modulus <= bound * (1 + kRounding) : h.modulus >= bound * (1 - kRounding)) return;
    warnings.push_back("effective.modulus " + to_text(h.modulus, 4) + " Pa lies " + (above ? "above" : "below") + " " + name +
                 " " + to_text(bound, 4) + " Pa by " + to_text(100.0 * std::abs(h.modulus / bound - 1.0), 2) +
                 " %: a finite cell is not isotropic, and the area average of cell stresses is biased next to "
                 "phase interfaces (see README)");
  };
  // Voigt and Reuss hold for every microstructure; Hashin-Shtrikman for isotropic ones.
  outside(b.voigt, "the Voigt bound", true);
  outside(b.reuss, "the Reuss bound", false);
  if (b.hs_upper && h.modulus <= b.voigt) outside(*b.hs_upper, "the Hashin-Shtrikman upper bound", true);
  if (b.hs_lower && h.modulus >= b.reuss) outside(*b.hs_lower, "the Hashin-Shtrikman lower bound", false);
  return effective;
}

}  // namespace

void run_run_command(const Config& c, const std::filesystem::path& out, bool solve, bool quiet) {
  c.check_keys(run_config_keys());
  check_output_replaceable(out, "run");
  // Each stage reads its part; every value is checked before any work is done.
  const Config tess_config = c.subset(tessellate_config_keys());
  const Config mesh_config = c.subset(mesh_config_keys());
  const TessellateJob tess_job = read_tessellate_job(tess_config);
  const FoamOptions foam = read_foam_options(c.subset(export_config_keys()));
  if (solve && foam.traction != 0.0)
    c.fail("load.traction", "--solve homogenises under an imposed displacement; remove load.traction");
  Warnings warnings;
  const TessellationOptions& to = tess_job.options;
  for (const std::string& w :
       check_load(Box{{0.0, 0.0}, {to.width, to.height}}, to.periodic, foam_phases(to.phases), foam))
    warnings.add(w);
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
  auto end_stage_line = [&] {
    if (show) std::fprintf(stderr, "\r\033[K");
  };

  auto clock = std::chrono::steady_clock::now();
  stage("tessellating");
  const Tessellation t = run_tessellate_job(tess_job, tess_config);
  check_phases_have_grains(t, tess_job, tess_config);
  const double tessellate_seconds = since(clock);
  end_stage_line();
  for (const std::string& w : tessellation_warnings(t)) warnings.add(w);

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
  end_stage_line();
  for (const std::string& w : mesh_warnings(m, q, mesh_job.options)) warnings.add(w);

  StagedOutput staged(out, "run");
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

  Json phases = Json::array();
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    phases.push_back({{"name", t.phases[p].name},
                      {"target_fraction", t.stats.phases[p].target_fraction},
                      {"achieved_fraction", t.stats.phases[p].achieved_fraction},
                      {"grains", t.stats.phases[p].grains}});
  Json report{{"config", c.source()},
              {"config_fingerprint", config_fingerprint(c)},
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
                {"cells_per_grain_mean", static_cast<double>(m.mesh.triangles.size()) / t.stats.grains},
                {"unconverged_regions", m.unconverged_regions}}},
              {"seconds",
               {{"tessellate", tessellate_seconds}, {"mesh", mesh_seconds}, {"export", export_seconds}}},
              {"case", "case"},
              {"solved", solve}};
  add_time_limit(report, tess_job.options.deadline);

  double solve_seconds = 0.0;
  if (solve) {
    clock = std::chrono::steady_clock::now();
    stage("solving with solidDisplacementFoam");
    std::vector<std::string> solve_warnings;
    try {
      report["effective"] = solve_run(dir, staged, t, m, e, foam, tess_job.options.deadline, mesh_job.picture_width,
                                      solve_warnings);
    } catch (const SolveError& err) {
      // Kept for a look: the case with the solver's log, as OUT.failed.
      end_stage_line();
      report["failed"] = err.what();
      report["peak_memory_mib"] = peak_memory_mib();
      try {
        write_report(staged, report, warnings);
        staged.keep_as_failed();
      } catch (const IoError& io) {
        throw SolveError(std::string(err.what()) + " (but it could not be kept: " + io.what() + ")");
      }
      throw;
    }
    solve_seconds = since(clock);
    end_stage_line();
    for (const std::string& w : solve_warnings) warnings.add(w);
  }
  report["seconds"]["solve"] = solve_seconds;
  report["seconds"]["total"] = since(start);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();
  end_stage_line();

  std::printf("grainmesh run: %d grains, %zu cells (q_min %.3f, q_mean %.3f), %.2f s\n  wrote %s/{tessellation.json, "
              "tessellation.png, mesh.vtu, mesh.png, case/, config.ini, report.json}\n  the case: %s/case/Allrun runs "
              "checkMesh and solidDisplacementFoam\n",
              t.stats.grains, m.mesh.triangles.size(), q.q_min, q.q_mean, since(start), out.string().c_str(),
              out.string().c_str());
  if (solve) {
    const Json& eff = report["effective"];
    std::printf("  solved: effective modulus %.4g Pa", eff["modulus"].get<double>());
    if (eff.contains("reuss"))
      std::printf(" (Reuss %.4g, Voigt %.4g)", eff["reuss"].get<double>(), eff["voigt"].get<double>());
    std::printf(", %d corrections\n", eff["corrections"].get<int>());
  }
  if (!warnings.all().empty())
    std::printf("  %zu warning%s (stderr and report.json)\n", warnings.all().size(), warnings.all().size() > 1 ? "s" : "");
}

}  // namespace grainmesh
