// make bench: triangles against polygonal cells (export.cells) — the periodic ten-strip
// laminate of the homogenisation tests (stiffness ratio 3, layers across and along the
// load) against its exact layered modulus, and the default cell against the Richardson
// limit of its modulus; each at several densities as triangles, as polygons on the same
// mesh, as polygons at about the triangles' cell count, and as polygons at about their
// solve seconds: cells, checkMesh's max non-orthogonality and skewness, the mixed load's
// modulus and its error, the solve's seconds. Then Kirsch's plate with a hole: sigma_xx
// along the symmetry line above the hole against Kirsch's solution. Each case in a child
// process, three times (median). Writes bench/results.json ("dual").
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/homogenise.hpp"
#include "analysis/richardson.hpp"
#include "bench/child.hpp"
#include "common/errors.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "export/foam_options.hpp"
#include "export/foam_solver.hpp"
#include "export/kirsch.hpp"
#include "export/polymesh.hpp"
#include "pipelines/config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/laminate.hpp"
#include "pipelines/mesh_job.hpp"
#include "pipelines/run_command.hpp"
#include "pipelines/tessellate_job.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

using Cells = FoamOptions::Cells;

struct Family {
  std::string name;
  std::string config;  // ini text; empty: the default cell
  std::vector<int> densities;  // triangles per grain
  double exact = 0.0;  // the exact modulus, Pa; 0: the default cell's Richardson limit
};

const fs::path kDir = fs::temp_directory_path() / "grainmesh-bench-dual";

// checkMesh's number after `label` in its log (NaN when absent).
double logged(const std::string& log, const std::string& label) {
  const auto at = log.find(label);
  return at == std::string::npos ? std::nan("") : std::stod(log.substr(at + label.size()));
}

// Writes the case, runs checkMesh on it and solves it: cells, checkMesh's worst faces,
// the solve's seconds and the homogenised answer.
Json check_and_solve(const ExportMesh<2>& e, const FoamOptions& o, MixedHomogenised<3>& h) {
  fs::remove_all(kDir);
  fs::create_directories(kDir);
  const PolyMesh pm = write_foam_case(kDir, e, o);
  const std::string log_file = (kDir / "checkMesh.log").string();
  const std::string command = "cd '" + kDir.string() + "' && WM_PROJECT_DIR=" + kFoamProjectDir + " checkMesh > '" +
                              log_file + "' 2>&1";
  if (std::system(command.c_str()) != 0) throw IoError("checkMesh failed in " + kDir.string());
  std::stringstream log;
  log << std::ifstream(log_file).rdbuf();
  Json row{{"cells", e.mesh.cells()},
           {"non_orthogonality_max_deg", logged(log.str(), "Mesh non-orthogonality Max: ")},
           {"non_orthogonality_mean_deg", logged(log.str(), "average: ")},
           {"skewness_max", logged(log.str(), "Max skewness = ")},
           {"mesh_ok", log.str().find("Mesh OK.") != std::string::npos}};
  const auto start = std::chrono::steady_clock::now();
  h = solve_mixed(kDir, e, pm, o);
  row["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return row;
}

Json measure(const Family& f, Cells cells, int per_grain) {
  const std::vector<std::string> set{"mesh.triangles_per_grain=" + std::to_string(per_grain)};
  const Config config = f.config.empty() ? Config::from_text(default_run_config(), "default config", set)
                                         : Config::from_text(f.config, f.name, set);
  const Config tess_config = config.subset(tessellate_config_keys());
  const Tessellation t = run_tessellate_job(read_tessellate_job<2>(tess_config));
  const GrainMesh m = mesh_tessellation(t, read_mesh_job(config.subset(mesh_config_keys()), t).options);
  FoamOptions o = read_foam_options(config.subset(export_config_keys()));
  o.cells = cells;
  MixedHomogenised<3> h;
  Json row = check_and_solve(export_mesh(t, m, cells), o, h);
  row["triangles"] = m.mesh.triangles.size();
  row["modulus"] = h.modulus;
  fs::remove_all(kDir);
  return row;
}

const char* shape_name(Cells cells) { return cells == Cells::polygons ? "polygons" : "triangles"; }

// One measured row, printed and kept; `reference` the exact or limit modulus.
Json row(const Family& f, Cells cells, const std::string& compare, int per_grain, double reference, Json& results,
         int runs = 3) {
  std::fflush(stdout);  // a child must not inherit what the parent has yet to print
  Json r = median_in_children(runs, [&] { return measure(f, cells, per_grain); });
  if (r.contains("error")) throw GeometryError(f.name + ": " + r["error"].get<std::string>());
  r["modulus_error"] = r["modulus"].get<double>() / reference - 1.0;
  std::printf("%-16s %-10s %-12s %6d %7zu %10.2e %8.1f %8.1f %6.2f %11.5e %7.2f\n", f.name.c_str(), shape_name(cells),
              compare.c_str(), per_grain, r["cells"].get<std::size_t>(), r["modulus_error"].get<double>(),
              r["non_orthogonality_max_deg"].get<double>(), r["non_orthogonality_mean_deg"].get<double>(),
              r["skewness_max"].get<double>(), r["modulus"].get<double>(), r["seconds"].get<double>());
  Json labelled{{"case", f.name}, {"shape", shape_name(cells)}, {"compare", compare}, {"triangles_per_grain", per_grain}};
  labelled.update(r);
  results.push_back(labelled);
  return r;
}

// The default cell's modulus limit: Richardson from polygons at 400, 800 and 1,600
// triangles per grain (they converge monotonically; the triangles' values do not).
double default_limit(const Family& f, Json& results) {
  std::vector<double> values, cells;
  for (int per_grain : {400, 800, 1600}) {
    std::fflush(stdout);  // a child must not inherit what the parent has yet to print
    const Json r = median_in_children(1, [&] { return measure(f, Cells::polygons, per_grain); });
    if (r.contains("error")) throw GeometryError(f.name + ": " + r["error"].get<std::string>());
    values.push_back(r["modulus"].get<double>());
    cells.push_back(r["cells"].get<double>());
  }
  // h ~ 1 / sqrt(cells): the levels' ratio in h, from the first to the last of the three.
  const RichardsonEstimate e = richardson(values, std::pow(cells[2] / cells[0], 0.25));
  std::printf("default cell: polygons' modulus at 400, 800, 1600 triangles per grain %.5e %.5e %.5e: Richardson limit "
              "%.5e (order %.2f)\n",
              values[0], values[1], values[2], e.limit, e.order.value_or(NAN));
  results.push_back({{"case", "default cell limit"}, {"values", values}, {"cells", cells}, {"limit", e.limit},
                     {"order", e.order.value_or(NAN)}, {"asymptotic", e.asymptotic}});
  return e.limit;
}

// Kirsch's plate (tests/export/kirsch.hpp): sigma_xx in the cells along the symmetry line
// x = 0 from the hole up to 3 R, against Kirsch's solution.
Json kirsch_row(Cells cells, double h0) {
  const double R = test::kHoleRadius;
  const ExportMesh<2> triangles = test::plate_with_hole(h0);
  bool corner = false;  // the top of the hole is a node: the line's first cell starts there
  for (const Vec2 p : triangles.mesh.points) corner |= std::abs(p.x) < 1e-12 && std::abs(p.y - R) < 1e-12;
  if (!corner) throw GeometryError("Kirsch: no mesh node at the top of the hole (h0 " + std::to_string(h0) + ")");
  const ExportMesh<2> e = cells == Cells::polygons ? polygon_cells(triangles) : triangles;
  MixedHomogenised<3> h;
  Json row = check_and_solve(e, {.convert_to_meters = 1.0, .traction = test::kPlateTraction, .uniaxial = true}, h);
  const FieldValues sigma = read_cell_field(h.run.result_dir / kStressField, "symmTensor", e.mesh.cells());
  double sum = 0.0, worst = 0.0, top = 0.0, nearest = 1e300;
  int n = 0;
  for (std::size_t k = 0; k < e.mesh.cells(); ++k) {
    const std::span<const int> ring = e.mesh.cell(k);
    bool on_line = false;  // a side on x = 0
    for (std::size_t i = 0; i < ring.size(); ++i)
      on_line |= std::abs(e.mesh.points[ring[i]].x) < 1e-9 && std::abs(e.mesh.points[ring[(i + 1) % ring.size()]].x) < 1e-9;
    const Vec2 centre = cell_centroid(e.mesh, k);
    if (!on_line || centre.y > 3 * R) continue;
    const double error = std::abs(sigma[k][0] / test::kirsch_sigma_xx(centre) - 1.0);
    sum += error;
    worst = std::max(worst, error);
    ++n;
    if (centre.y < nearest) nearest = centre.y, top = error;
  }
  row["line_cells"] = n;
  row["mean_error"] = sum / n;
  row["max_error"] = worst;
  row["top_error"] = top;
  fs::remove_all(kDir);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const test::Material hard{600e9, 0.2}, soft{200e9, 0.3};
  const std::array<double, 4> exact = test::laminate(hard, soft, 0.3);  // layers normal to x
  std::vector<Family> families;
  for (const bool across : {true, false})
    families.push_back({std::string("laminate ") + (across ? "across" : "along"), test::laminate_config(hard, soft, across, 0.0),
                        {50, 200, 800}, across ? exact[0] : exact[1]});
  families.push_back({"default cell", "", {100, 400}, 0.0});

  Json results = Json::array();
  std::printf("%-16s %-10s %-12s %6s %7s %10s %8s %8s %6s %11s %7s\n", "dual", "cells", "compared", "tpg", "count",
              "error", "nonorth", "mean", "skew", "modulus", "seconds");
  for (const Family& f : families) {
    const double reference = f.exact > 0.0 ? f.exact : default_limit(f, results);
    for (const int d : f.densities) {
      const Json tri = row(f, Cells::triangles, "same mesh", d, reference, results);
      const Json poly = row(f, Cells::polygons, "same mesh", d, reference, results);
      // Polygons from a finer mesh: about the triangles' cells, then about their seconds.
      const int d_cells = static_cast<int>(std::lround(d * tri["cells"].get<double>() / poly["cells"].get<double>()));
      const Json cells = row(f, Cells::polygons, "equal cells", d_cells, reference, results);
      const int d_time = static_cast<int>(std::lround(d_cells * tri["seconds"].get<double>() / cells["seconds"].get<double>()));
      row(f, Cells::polygons, "equal time", d_time, reference, results);
    }
  }
  // Kirsch: triangles, polygons of the same mesh, and polygons of a finer mesh with about
  // the triangles' cells (h0 scaled by the square root of the cell ratio).
  double tri_cells = 0.0, poly_cells = 0.0;
  for (const auto& [cells, compare] : {std::pair{Cells::triangles, "same mesh"}, std::pair{Cells::polygons, "same mesh"},
                                       std::pair{Cells::polygons, "equal cells"}}) {
    // (h0 rounded to 1e-4: the plate's config fixes no point, and at h0 = 0.018343 the
    // mesher leaves the corner where the hole meets x = 0 without a node.)
    const double h0 = std::string(compare) == "equal cells" ? std::round(250.0 * std::sqrt(poly_cells / tri_cells)) / 1e4 : 0.025;
    std::fflush(stdout);
    Json r = median_in_children(3, [&] { return kirsch_row(cells, h0); });
    if (r.contains("error")) throw GeometryError("Kirsch: " + r["error"].get<std::string>());
    if (std::string(compare) == "same mesh") (cells == Cells::triangles ? tri_cells : poly_cells) = r["cells"].get<double>();
    std::printf("Kirsch %-9s %-11s h0 %.4f %7zu cells, sigma_xx along x = 0 up to 3R (%d cells): mean error %.2f %%, "
                "worst %.2f %%, top of the hole %.2f %%; nonorth %.1f, %.2f s\n",
                shape_name(cells), compare, h0, r["cells"].get<std::size_t>(), r["line_cells"].get<int>(),
                100 * r["mean_error"].get<double>(), 100 * r["max_error"].get<double>(), 100 * r["top_error"].get<double>(),
                r["non_orthogonality_max_deg"].get<double>(), r["seconds"].get<double>());
    Json labelled{{"case", "Kirsch"}, {"shape", shape_name(cells)}, {"compare", compare}, {"h0", h0}};
    labelled.update(r);
    results.push_back(labelled);
  }
  write_results(source / "bench" / "results.json", "dual",
                "median of 3 runs, each in a fresh process; seconds = solve_mixed() (mixed load); modulus_error = "
                "modulus / reference - 1, the reference the exact layered modulus (laminates) or the Richardson limit of "
                "the polygons' modulus at 400, 800 and 1,600 triangles per grain (default cell); compare: same mesh, or "
                "polygons of a finer mesh at about the triangles' cell count or solve seconds",
                results);
  return 0;
}
