// make bench: the pipeline on periodic two-phase WC-Co cells of 1,000, 10,000 and
// 100,000 grains: seconds per stage (tessellate, mesh, export of the OpenFOAM case),
// triangles per second, peak memory, on 1 and 2 threads. The 1,000-grain cell is also
// meshed by Gmsh from the same polygons (a .geo written here, every grain boundary one
// shared line, so the grains' meshes conform), as a peer. Also compares the per-region
// mesher with the thesis' global Algorithm 3 on its 6-fibre cell. Each case runs in a
// child process, three times (median), so that its peak memory
// is its own. Prints tables and updates bench/results.json ("mesh").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "bench/peers.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "grains/conformity.hpp"
#include "grains/grain_mesh.hpp"
#include "mesh/quality.hpp"
#include "pipelines/domain_command.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/validate.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

struct CellCase {
  std::string name;
  int grains;
  double triangles_per_grain;
  int threads;
  int runs;
};

// A periodic unit-aspect WC-Co cell (15 % Co, grain mode) with 3 Lloyd iterations and
// grains of unit area.
Tessellation wc_co_cell(int grains) {
  TessellationOptions o;
  o.width = std::sqrt(static_cast<double>(grains));
  o.height = o.width;
  o.grains = grains;
  o.lloyd_iterations = 3;
  o.phase_mode = PhaseMode::grain;
  o.arrangement = Arrangement::dispersed;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.15, false, 211e9, 0.31, {}}};
  Rng rng(1);
  return tessellate(o, rng);
}

// The element size of `n` equilateral triangles per unit area.
double size_for(double n) { return std::sqrt(4.0 / (n * std::sqrt(3.0))); }

// The three stages, each timed: tessellate, mesh, export (ASCII polyMesh, zones, fields).
Json measure_cell(const CellCase& c) {
  auto start = std::chrono::steady_clock::now();
  const Tessellation t = wc_co_cell(c.grains);
  const double tessellate_seconds = since(start);
  start = std::chrono::steady_clock::now();
  const GrainMesh m =
      mesh_tessellation(t, {.size = size_for(c.triangles_per_grain), .phase_size = {}, .threads = c.threads});
  const double mesh_seconds = since(start);
  const fs::path dir = fs::temp_directory_path() / ("grainmesh-bench-cell-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  start = std::chrono::steady_clock::now();
  write_foam_case(dir, grain_export_mesh(t, m), {});
  const double export_seconds = since(start);
  fs::remove_all(dir);
  const MeshQuality q = measure_quality(m.mesh);
  Json row{{"seconds", tessellate_seconds + mesh_seconds + export_seconds},
           {"tessellate_seconds", tessellate_seconds},
           {"mesh_seconds", mesh_seconds},
           {"mesh_regions_seconds", m.regions_seconds},
           {"export_seconds", export_seconds}};
  row.update(mesh_measures(m.mesh, q));
  row["triangles_per_grain"] = static_cast<double>(m.mesh.triangles.size()) / t.stats.grains;
  row["triangles_per_second"] = static_cast<double>(m.mesh.triangles.size()) / mesh_seconds;
  row["max_non_orthogonality_deg"] = q.max_non_orthogonality_deg;
  row["max_area_error"] = check_conformity(t, m).max_area_error;
  row["unconverged_regions"] = m.unconverged_regions;
  return row;
}

// The tessellation as a Gmsh .geo: a point per vertex (mesh size h), a line per edge, a
// plane surface per region whose curve loops run along its rings over those lines.
void write_geo(const Tessellation& t, double h, const fs::path& file) {
  std::ofstream out(file);
  out.precision(17);
  out << "// " << t.grains.size() << " grains, every grain boundary one line shared by both sides.\n";
  for (std::size_t v = 0; v < t.vertices.size(); ++v)
    out << "Point(" << v + 1 << ") = {" << t.vertices[v].x << ", " << t.vertices[v].y << ", 0, " << h << "};\n";
  std::map<std::pair<int, int>, int> line;  // (from, to) -> signed line id
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const int id = static_cast<int>(e) + 1, a = t.edges[e].v0, b = t.edges[e].v1;
    out << "Line(" << id << ") = {" << a + 1 << ", " << b + 1 << "};\n";
    line[{a, b}] = id;
    line[{b, a}] = -id;
  }
  int loop = 0;
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    std::vector<int> loops;
    for (const auto& ring : t.regions[r].rings) {
      out << "Curve Loop(" << ++loop << ") = {";
      for (std::size_t k = 0; k < ring.size(); ++k)
        out << (k ? ", " : "") << line.at({ring[k], ring[(k + 1) % ring.size()]});
      out << "};\n";
      loops.push_back(loop);
    }
    out << "Plane Surface(" << r + 1 << ") = {";
    for (std::size_t k = 0; k < loops.size(); ++k) out << (k ? ", " : "") << loops[k];
    out << "};\n";
  }
  out << "Mesh.MeshSizeMax = " << h << ";\n";
}

// Gmsh on the cell's polygons: its meshing time from its log, the whole process's, and
// the quality of the mesh it wrote.
Json gmsh_cell(const Tessellation& t, double h, int threads, const fs::path& scratch) {
  const fs::path geo = scratch / "cell.geo", msh = scratch / "cell.msh";
  write_geo(t, h, geo);
  const ProcessRun r = run_process({"gmsh", geo.string(), "-2", "-algo", "front2d", "-nt", std::to_string(threads),
                                    "-format", "msh22", "-o", msh.string()},
                                   scratch / "gmsh.log");
  if (r.exit_code != 0) return {{"error", "gmsh: exit code " + std::to_string(r.exit_code)}};
  Json row{{"seconds", gmsh_meshing_seconds(r.output)}, {"process_seconds", r.seconds}};
  row.update(mesh_measures(read_msh2(msh)));
  row["triangles_per_grain"] = row["triangles"].get<double>() / t.stats.grains;
  row["peak_memory_mib"] = r.peak_mib;
  return row;
}

// The thesis' 6-fibre cell (data/examples/fibres_6.ini) as regions: each fibre a
// polygon with edges of about h on its circle, the matrix the square with six holes.
Tessellation fibre_regions(double h) {
  const double r = 0.100398272208673;
  const std::vector<Vec2> centres{{1.0 / 6, 0.25}, {0.5, 0.25}, {5.0 / 6, 0.25},
                                  {1.0 / 6, 0.75}, {0.5, 0.75}, {5.0 / 6, 0.75}};
  Tessellation t;
  t.periodic = false;
  t.phases = {Phase{"matrix", 0.0, true, 3.0, 0.35, {}}, Phase{"fibre", 0.19, false, 70.0, 0.22, {}}};
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
  for (std::size_t k = 0; k < r.phase.size(); ++k)
    if (r.phase[k] == 1) fibre += triangle_area(r.mesh, static_cast<int>(k));
  return {{"seconds", r.stats.seconds},  {"triangles", r.mesh.triangles.size()},
          {"q_min", q.q_min},            {"q_mean", q.q_mean},
          {"min_angle_deg", q.min_angle_deg},
          {"max_non_orthogonality_deg", q.max_non_orthogonality_deg},
          {"interface_straddling", r.stats.interface_straddling},
          {"polygon_area_error", nullptr}, {"circle_area_error", fibre_area_error(fibre)}};
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const std::vector<CellCase> cells{
      {"1,000 grains, 1 thread", 1000, 100, 1, 3},
      {"1,000 grains, 2 threads", 1000, 100, 2, 3},
      {"1,000 grains at 130/grain, 1 thread", 1000, 130, 1, 3},
      {"1,000 grains at 130/grain, 2 threads", 1000, 130, 2, 3},
      {"10,000 grains, 1 thread", 10000, 100, 1, 3},
      {"10,000 grains, 2 threads", 10000, 100, 2, 3},
      {"100,000 grains, 1 thread", 100000, 100, 1, 3},
      {"100,000 grains, 2 threads", 100000, 100, 2, 3},
  };
  // A second argument runs one part only: "cells", "gmsh" or "fibres".
  const std::string only = argc > 2 ? argv[2] : "";
  const bool cells_on = only.empty() || only == "cells", gmsh_on = only.empty() || only == "gmsh",
             fibres_on = only.empty() || only == "fibres";
  Json results = Json::array();
  if (cells_on)
    std::printf("%-38s %7s %7s %7s %7s %9s %8s %9s %6s %6s %11s %9s\n", "periodic WC-Co cell (15 % Co)", "tess s",
                "mesh s", "export s", "total s", "triangles", "tri/grain", "tri/s", "q_min", "q_mean", "x mesh/regs",
                "peak MiB");
  std::map<std::pair<int, double>, Json> one_thread;  // (grains, tri/grain) -> its row
  for (const CellCase& c : cells) {
    if (!cells_on) break;
    Json row = median_in_children(c.runs, [&] { return measure_cell(c); });
    if (row.contains("error")) {
      std::printf("%-38s error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    std::string speedup = "-";
    if (c.threads == 1) {
      one_thread[{c.grains, c.triangles_per_grain}] = row;
    } else if (const auto it = one_thread.find({c.grains, c.triangles_per_grain}); it != one_thread.end()) {
      // The mesh stage as a whole, and its per-region meshing (the part that runs in parallel).
      for (const std::string key : {"mesh", "mesh_regions"})
        row[key + "_speedup_over_1_thread"] =
            it->second[key + "_seconds"].get<double>() / row[key + "_seconds"].get<double>();
      char text[32];
      std::snprintf(text, sizeof text, "%.2f/%.2f", row["mesh_speedup_over_1_thread"].get<double>(),
                    row["mesh_regions_speedup_over_1_thread"].get<double>());
      speedup = text;
    }
    std::printf("%-38s %7.2f %7.2f %7.2f %7.2f %9zu %8.1f %9.0f %6.3f %6.4f %11s %9.1f\n", c.name.c_str(),
                row["tessellate_seconds"].get<double>(), row["mesh_seconds"].get<double>(),
                row["export_seconds"].get<double>(), row["seconds"].get<double>(), row["triangles"].get<std::size_t>(),
                row["triangles_per_grain"].get<double>(), row["triangles_per_second"].get<double>(),
                row["q_min"].get<double>(), row["q_mean"].get<double>(), speedup.c_str(),
                row["peak_memory_mib"].get<double>());
    std::fflush(stdout);
    Json labelled{{"case", c.name}, {"mesher", "grainmesh"}, {"grains", c.grains}, {"threads", c.threads}};
    labelled.update(row);
    results.push_back(labelled);
  }

  // The peer: Gmsh on the same 1,000-grain polygons, at the same two densities.
  const fs::path scratch = fs::temp_directory_path() / "grainmesh-bench-gmsh-cell";
  if (gmsh_on && !gmsh_version(fs::temp_directory_path()).empty()) {
    fs::create_directories(scratch);
    const Tessellation t = wc_co_cell(1000);
    std::printf("\n%-38s %8s %9s %9s %8s %6s %6s %8s %9s\n", "the 1,000-grain cell by Gmsh (front2d)", "mesh s",
                "process s", "triangles", "tri/grain", "q_min", "q_mean", "q<0.5", "peak MiB");
    for (const double per_grain : {100.0, 130.0}) {
      // Gmsh makes about a fifth more triangles than we do at the same size: its size is
      // scaled (after one untimed run) so that its triangle count matches ours.
      const double h = size_for(per_grain);
      const Json probe = gmsh_cell(t, h, 2, scratch);
      if (probe.contains("error")) {
        std::printf("gmsh: %s\n", probe["error"].get<std::string>().c_str());
        return 1;
      }
      const auto ours = static_cast<double>(mesh_tessellation(t, {.size = h, .phase_size = {}}).mesh.triangles.size());
      const double scale = std::sqrt(probe["triangles"].get<double>() / ours);
      for (const int threads : {1, 2}) {
        std::vector<Json> samples;
        for (int run = 0; run < 3; ++run) samples.push_back(gmsh_cell(t, scale * h, threads, scratch));
        if (samples[0].contains("error")) {
          std::printf("gmsh: %s\n", samples[0]["error"].get<std::string>().c_str());
          return 1;
        }
        Json row = median_of(std::move(samples));
        const std::string name = "Gmsh, 1,000 grains at " + std::to_string(static_cast<int>(per_grain)) + "/grain, " +
                                 std::to_string(threads) + (threads == 1 ? " thread" : " threads");
        std::printf("%-38s %8.2f %9.2f %9zu %8.1f %6.3f %6.4f %8.4f %9.1f\n", name.c_str(), row["seconds"].get<double>(),
                    row["process_seconds"].get<double>(), row["triangles"].get<std::size_t>(),
                    row["triangles_per_grain"].get<double>(), row["q_min"].get<double>(), row["q_mean"].get<double>(),
                    row["q_below_0_5"].get<double>(), row["peak_memory_mib"].get<double>());
        std::fflush(stdout);
        Json labelled{{"case", name}, {"mesher", "Gmsh front2d"}, {"grains", 1000}, {"threads", threads},
                      {"size_over_ours", scale}};
        labelled.update(row);
        results.push_back(labelled);
      }
    }
    fs::remove_all(scratch);
  }

  if (fibres_on) {
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
  }
  if (!only.empty()) return 0;  // a part alone leaves bench/results.json as it was
  write_results(source / "bench" / "results.json", "mesh",
                "median of 3 runs, each in a fresh process; seconds = tessellate + mesh + "
                "export (ASCII case), each stage timed apart; Gmsh: its log's 2D meshing time, and the whole process",
                results);
  return 0;
}
