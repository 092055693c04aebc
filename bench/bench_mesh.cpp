// make bench: the mesh stage on tessellations. Each case runs in a child process, three
// times (median), so that its peak memory is its own; "seconds" is mesh_tessellation()
// alone (size field, seeding, every region, merge), the tessellation is timed apart.
// Also compares the per-region mesher with the thesis' global Algorithm 3 on its 6-fibre
// cell. Prints tables and writes bench/mesh_results.json.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "mesh/grain_mesh.hpp"
#include "mesh/quality.hpp"
#include "pipelines/domain_command.hpp"

using namespace grainmesh;

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

struct CellCase {
  std::string name;
  int grains;
  PhaseMode mode;
  double matrix_fraction;
  int threads;
  int runs;
};

// A periodic unit-aspect WC-Co cell with 3 Lloyd iterations, meshed at about 100
// triangles per grain.
Json measure_cell(const CellCase& c) {
  TessellationOptions o;
  o.width = std::sqrt(static_cast<double>(c.grains));  // grains of unit area
  o.height = o.width;
  o.grains = c.grains;
  o.lloyd_iterations = 3;
  o.phase_mode = c.mode;
  o.arrangement = Arrangement::dispersed;
  o.matrix_phase = 1;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24}, Phase{"Co", c.matrix_fraction, false, 211e9, 0.31}};
  Rng rng(1);
  auto start = std::chrono::steady_clock::now();
  const Tessellation t = tessellate(o, rng);
  const double tessellate_seconds = since(start);
  const double size = std::sqrt(4.0 / (100.0 * std::sqrt(3.0)));  // 100 equilateral triangles per unit area
  const GrainMesh m = mesh_tessellation(t, {.size = size, .phase_size = {}, .threads = c.threads});
  const Conformity conf = check_conformity(t, m);
  const MeshQuality q = measure_quality(m.mesh);
  return {{"seconds", m.seconds},
          {"tessellate_seconds", tessellate_seconds},
          {"points", m.mesh.points.size()},
          {"triangles", m.mesh.triangles.size()},
          {"triangles_per_grain", static_cast<double>(m.mesh.triangles.size()) / t.stats.grains},
          {"triangles_per_second", static_cast<double>(m.mesh.triangles.size()) / m.seconds},
          {"q_min", q.q_min},
          {"q_mean", q.q_mean},
          {"q_below_0_5", q.q_below_half},
          {"min_angle_deg", q.min_angle_deg},
          {"max_non_orthogonality_deg", q.max_non_orthogonality_deg},
          {"max_area_error", conf.max_area_error},
          {"unconverged_regions", m.unconverged_regions}};
}

// The thesis' 6-fibre cell (data/examples/fibres_6.ini) as regions: each fibre a
// polygon with edges of about h on its circle, the matrix the square with six holes.
Tessellation fibre_regions(double h) {
  const double r = 0.100398272208673;
  const std::vector<Vec2> centres{{1.0 / 6, 0.25}, {0.5, 0.25}, {5.0 / 6, 0.25},
                                  {1.0 / 6, 0.75}, {0.5, 0.75}, {5.0 / 6, 0.75}};
  Tessellation t;
  t.periodic = false;
  t.phases = {Phase{"matrix", 0.0, true, 3.0, 0.35}, Phase{"fibre", 0.19, false, 70.0, 0.22}};
  t.vertices = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  Region matrix{.grain = 0, .phase = 0, .rings = {{0, 1, 2, 3}}};
  for (int k = 0; k < 4; ++k) t.edges.push_back({k, (k + 1) % 4, 0, -1});
  const int n = static_cast<int>(std::ceil(2.0 * std::numbers::pi * r / h));
  t.grains.push_back({.id = 0, .phase = 0, .seed = {}, .area = 1.0, .neighbours = {}, .matrix = true});
  for (std::size_t f = 0; f < centres.size(); ++f) {
    const int first = static_cast<int>(t.vertices.size()), region = static_cast<int>(f) + 1;
    std::vector<int> ring;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * k / n;
      t.vertices.push_back(centres[f] + r * Vec2{std::cos(a), std::sin(a)});
      ring.push_back(first + k);
      t.edges.push_back({first + k, first + (k + 1) % n, region, 0});  // fibre on the left
    }
    matrix.rings.push_back(ring);  // holes are stored counter-clockwise too
    t.regions.push_back({.grain = region, .phase = 1, .rings = {ring}});
    t.grains.push_back({.id = region, .phase = 1, .seed = centres[f], .area = region_area(t, t.regions.back()),
                        .neighbours = {0}, .matrix = false});
    t.grains[0].area -= t.grains.back().area;
  }
  t.regions.insert(t.regions.begin(), matrix);
  validate(t);
  return t;
}

// Mesh area inside the fibres against the circles' exact area, relative.
double fibre_area_error(double mesh_fibre_area) {
  const double exact = 6.0 * std::numbers::pi * 0.100398272208673 * 0.100398272208673;
  return std::abs(mesh_fibre_area - exact) / exact;
}

// At the element size that gives `triangles` equilateral triangles in the unit square.
Json fibres_per_region(std::size_t triangles) {
  const double h = std::sqrt(4.0 / (std::sqrt(3.0) * static_cast<double>(triangles)));
  const Tessellation t = fibre_regions(h);
  const GrainMesh m = mesh_tessellation(t, {.size = h, .phase_size = {}, .threads = 1, .feature_size = false});
  const Conformity conf = check_conformity(t, m);
  const MeshQuality q = measure_quality(m.mesh);
  double fibre = 0.0;
  for (std::size_t k = 0; k < m.phase.size(); ++k)
    if (m.phase[k] == 1) fibre += triangle_area(m.mesh, static_cast<int>(k));
  return {{"seconds", m.seconds},        {"h", h}, {"triangles", m.mesh.triangles.size()},
          {"q_min", q.q_min},            {"q_mean", q.q_mean},
          {"min_angle_deg", q.min_angle_deg},
          {"max_non_orthogonality_deg", q.max_non_orthogonality_deg},
          {"interface_straddling", 0},   {"polygon_area_error", conf.max_area_error},
          {"circle_area_error", fibre_area_error(fibre)}};
}

Json fibres_global(const std::filesystem::path& source) {
  const DistMeshResult r = mesh_domain(read_domain_job(Config::from_file(source / "data/examples/fibres_6.ini")));
  const MeshQuality q = measure_quality(r.mesh);
  double fibre = 0.0;
  for (std::size_t k = 0; k < r.mesh.region.size(); ++k)
    if (r.mesh.region[k] == 1) fibre += triangle_area(r.mesh, static_cast<int>(k));
  return {{"seconds", r.stats.seconds},  {"triangles", r.mesh.triangles.size()},
          {"q_min", q.q_min},            {"q_mean", q.q_mean},
          {"min_angle_deg", q.min_angle_deg},
          {"max_non_orthogonality_deg", q.max_non_orthogonality_deg},
          {"interface_straddling", r.stats.interface_straddling},
          {"polygon_area_error", nullptr}, {"circle_area_error", fibre_area_error(fibre)}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source = argc > 1 ? argv[1] : ".";
  const std::vector<CellCase> cells{
      {"1,000 grains, 1 thread", 1000, PhaseMode::grain, 0.15, 1, 3},
      {"1,000 grains, 2 threads", 1000, PhaseMode::grain, 0.15, 2, 3},
      {"10,000 grains, 1 thread", 10000, PhaseMode::grain, 0.15, 1, 3},
      {"10,000 grains, 2 threads", 10000, PhaseMode::grain, 0.15, 2, 3},
      {"100 grains binder 5 %, 2 threads", 100, PhaseMode::binder, 0.05, 2, 1},
  };
  const bool fibres_only = argc > 2 && std::string(argv[2]) == "fibres";
  Json results = Json::array();
  if (!fibres_only) std::printf("%-34s %8s %8s %9s %8s %10s %7s %7s %8s %9s\n", "case", "mesh s", "tess s", "triangles", "tri/grain",
              "tri/s", "q_min", "q_mean", "non-orth", "peak MiB");
  for (const CellCase& c : cells) {
    if (fibres_only) break;
    Json row = median_in_children(c.runs, [&] { return measure_cell(c); });
    if (row.contains("error")) {
      std::printf("%-34s error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    std::printf("%-34s %8.3f %8.3f %9zu %8.1f %10.0f %7.3f %7.4f %8.1f %9.1f\n", c.name.c_str(),
                row["seconds"].get<double>(), row["tessellate_seconds"].get<double>(),
                row["triangles"].get<std::size_t>(), row["triangles_per_grain"].get<double>(),
                row["triangles_per_second"].get<double>(), row["q_min"].get<double>(), row["q_mean"].get<double>(),
                row["max_non_orthogonality_deg"].get<double>(), row["peak_memory_mib"].get<double>());
    std::fflush(stdout);
    Json labelled{{"case", c.name}, {"grains", c.grains}, {"threads", c.threads}};
    labelled.update(row);
    results.push_back(labelled);
  }

  std::printf("\n%-34s %8s %9s %7s %7s %8s %10s %12s\n", "6-fibre cell (fibres_6.ini)", "seconds", "triangles", "q_min",
              "q_mean", "non-orth", "straddling", "circle area");
  // The per-region mesh at the global one's triangle count (the global mesher refines
  // the fibres' curved boundaries beyond h0).
  std::size_t global_triangles = 0;
  const std::vector<std::pair<std::string, std::function<Json()>>> fibres{
      {"global (thesis Algorithm 3)", [&] { return fibres_global(source); }},
      {"per region (shared seeds)", [&] { return fibres_per_region(global_triangles); }},
  };
  for (const auto& [name, run] : fibres) {
    Json row = median_in_children(3, run);
    if (!row.contains("error") && global_triangles == 0) global_triangles = row["triangles"].get<std::size_t>();
    if (row.contains("error")) {
      std::printf("%-34s error: %s\n", name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    std::printf("%-34s %8.4f %9zu %7.3f %7.4f %8.1f %10d %11.2e\n", name.c_str(), row["seconds"].get<double>(),
                row["triangles"].get<std::size_t>(), row["q_min"].get<double>(), row["q_mean"].get<double>(),
                row["max_non_orthogonality_deg"].get<double>(), row["interface_straddling"].get<int>(),
                row["circle_area_error"].get<double>());
    Json labelled{{"case", "fibres_6 " + name}};
    labelled.update(row);
    results.push_back(labelled);
  }
  write_results(source / "bench" / "mesh_results.json", "mesh",
                "median of 3 runs (1 for the binder cell), each in a fresh process; mesh seconds exclude the "
                "tessellation",
                results);
  return 0;
}
