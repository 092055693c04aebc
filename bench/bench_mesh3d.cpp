// make bench: 3D cells of 100 and 1,000 Lloyd-relaxed periodic grains meshed at about 500
// tetrahedra per grain, each run in a fresh child process: seconds per stage (tessellate,
// surfaces, TetGen filling on all cores), peak memory, and the quality (radius ratio,
// dihedral angles; of the tetrahedra touching a grain surface and of the others apart).
// Prints a table and writes bench/results.json ("mesh3d").
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "tessellate/tessellation_3d.hpp"

using namespace grainmesh;

namespace {

struct Case {
  std::string name;
  int grains;
  double per_grain;      // tetrahedra wanted per grain
  double limit_seconds;  // the goal, 0 = none
};

Json measure(const Case& c) {
  Tessellation3Options o;
  o.width = o.height = o.depth = std::cbrt(static_cast<double>(c.grains)) * 0.5;  // grains of about 0.6 diameter
  o.grains = c.grains;
  o.lloyd_iterations = 5;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.15, false, 211e9, 0.31, {}}};
  Rng rng(1);
  const auto start = std::chrono::steady_clock::now();
  const Tessellation3 t = tessellate_3d(o, rng);
  const double tessellate_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double v = o.width * o.height * o.depth / static_cast<double>(t.grains.size()) / c.per_grain;
  const GrainMesh3 m = mesh_tessellation_3d(t, {.size = std::cbrt(6.0 * std::sqrt(2.0) * v)});
  check_conformity(t, m);
  const TetQuality q = measure_quality(m.mesh);
  // The same measures over the tetrahedra with a point on a surface, and the rest.
  TetMesh surface, inner;
  surface.points = inner.points = m.mesh.points;
  for (const auto& tet : m.mesh.tets) {
    bool touches = false;
    for (int p : tet) touches = touches || p < m.surface_points;
    (touches ? surface : inner).tets.push_back(tet);
  }
  const TetQuality qs = measure_quality(surface), qi = measure_quality(inner);
  return {{"seconds", tessellate_seconds + m.seconds},
          {"tessellate_seconds", tessellate_seconds},
          {"surface_seconds", m.surface_seconds},
          {"fill_seconds", m.fill_seconds},
          {"grains", t.grains.size()},
          {"points", m.mesh.points.size()},
          {"cells", m.mesh.tets.size()},
          {"cells_per_grain_mean", static_cast<double>(m.mesh.tets.size()) / static_cast<double>(t.grains.size())},
          {"q_min", q.q_min},
          {"q_mean", q.q_mean},
          {"min_dihedral_deg", q.min_dihedral_deg},
          {"share_dihedral_below_10", q.share_dihedral_below_10},
          {"surface_tets_q_mean", qs.q_mean},
          {"surface_tets_min_dihedral_deg", qs.min_dihedral_deg},
          {"inner_tets_q_mean", qi.q_mean},
          {"inner_tets_min_dihedral_deg", qi.min_dihedral_deg},
          {"tessellation_sharpest_dihedral_deg", t.stats.sharpest_dihedral_deg}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source = argc > 1 ? argv[1] : ".";
  const std::vector<Case> cases{
      {"100 grains, 500 tets/grain", 100, 500, 0},
      {"1000 grains, 500 tets/grain", 1000, 500, 60},
  };
  Json results = Json::array();
  std::printf("%-30s %8s %8s %8s %9s %8s %7s %8s %8s %9s\n", "case", "tess s", "surf s", "fill s", "cells", "q_mean",
              "q_min", "min dih", "<10 deg", "peak MiB");
  std::fflush(stdout);
  for (const Case& c : cases) {
    Json row = median_in_children(1, [&] { return measure(c); });
    if (row.contains("error")) {
      std::printf("%-30s error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    std::printf("%-30s %8.2f %8.2f %8.2f %9zu %8.3f %7.3f %8.2f %8.4f %9.1f\n", c.name.c_str(),
                row["tessellate_seconds"].get<double>(), row["surface_seconds"].get<double>(),
                row["fill_seconds"].get<double>(), row["cells"].get<std::size_t>(), row["q_mean"].get<double>(),
                row["q_min"].get<double>(), row["min_dihedral_deg"].get<double>(),
                row["share_dihedral_below_10"].get<double>(), row["peak_memory_mib"].get<double>());
    std::printf("%-30s surface tets q_mean %.3f min dihedral %.2f; inner q_mean %.3f min dihedral %.2f\n", "",
                row["surface_tets_q_mean"].get<double>(), row["surface_tets_min_dihedral_deg"].get<double>(),
                row["inner_tets_q_mean"].get<double>(), row["inner_tets_min_dihedral_deg"].get<double>());
    std::fflush(stdout);
    Json labelled{{"case", c.name}};
    labelled.update(row);
    if (c.limit_seconds > 0) labelled["limit_seconds"] = c.limit_seconds;
    results.push_back(labelled);
  }
  write_results(source / "bench" / "results.json", "mesh3d",
                "one run each in a fresh process; TetGen on all cores", results);
  return 0;
}
