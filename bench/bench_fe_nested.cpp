// make bench: the finite elements' own error, measured under nested refinement
// (export/nested_split.hpp: every triangle split in four, every tetrahedron in eight; the
// same geometry at every level, the spaces nested). For each cell at a base density, the
// periodic finite-element stiffness on levels 0..L of its mesh: each level's unknowns and
// seconds, its largest relative difference from the finest level (stiffness entries of
// their own scale, K and G) and from the next level, and the ratio of successive
// differences (the convergence factor per split: 4 when the stiffness converges as h^2).
// Writes bench/results.json ("fe_nested").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/fe_homogenise.hpp"
#include "analysis/voigt.hpp"
#include "bench/child.hpp"
#include "export/export_mesh.hpp"
#include "export/nested_split.hpp"
#include "pipelines/config.hpp"
#include "pipelines/mesh_outputs.hpp"
#include "pipelines/run_config.hpp"
#include "pipelines/run_plan.hpp"
#include "pipelines/tessellate_job.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

template <int D>
ExportMesh<D> cell_mesh_of(const RunPlan& plan) {
  const auto& jobs = std::get<CellJobs<D>>(plan.cell);
  const auto t = run_tessellate_job(jobs.tessellate);
  Warnings warnings;
  const auto m = run_mesh_job(t, resolve_mesh_job(jobs.mesh, t), warnings);
  return grain_export_mesh(t, m);
}

// The largest relative difference of `a` from `b` over K, G and the entries of b's own scale.
template <std::size_t N>
double difference(const Stiffness<N>& a, const Stiffness<N>& b) {
  double largest = 0.0, most = 0.0;
  for (const auto& row : b)
    for (const double x : row) largest = std::max(largest, std::abs(x));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i; j < N; ++j)
      if (std::abs(b[i][j]) >= 0.01 * largest) most = std::max(most, std::abs(a[i][j] / b[i][j] - 1.0));
  most = std::max(most, std::abs(bulk_modulus(a) / bulk_modulus(b) - 1.0));
  return std::max(most, std::abs(shear_modulus(a) / shear_modulus(b) - 1.0));
}

template <int D>
Json levels(const RunPlan& plan, int count) {
  constexpr std::size_t N = voigt_size(D);
  ExportMesh<D> m = cell_mesh_of<D>(plan);
  std::vector<FeHomogenised<N>> solved;
  Json out = Json::array();
  for (int level = 0; level < count; ++level) {
    if (level > 0) m = split_nested(m);
    if constexpr (D == 2) solved.push_back(fe_homogenise(m, false, false));
    else solved.push_back(fe_homogenise(m, false));
    std::fprintf(stderr, "  level %d: %zu unknowns, %.2f s\n", level, solved.back().unknowns, solved.back().seconds);
  }
  for (int level = 0; level < count; ++level) {
    const auto& s = solved[static_cast<std::size_t>(level)];
    Json j{{"level", level}, {"unknowns", s.unknowns}, {"seconds", s.seconds},
           {"bulk_modulus", bulk_modulus(s.stiffness)}, {"shear_modulus", shear_modulus(s.stiffness)},
           {"C11", s.stiffness[0][0]}, {"from_finest", difference<N>(s.stiffness, solved.back().stiffness)}};
    if (level + 1 < count) j["from_next"] = difference<N>(s.stiffness, solved[static_cast<std::size_t>(level) + 1].stiffness);
    out.push_back(j);
  }
  for (std::size_t k = 0; k + 2 < out.size(); ++k)
    out[k + 1]["factor"] = out[k]["from_next"].get<double>() / out[k + 1]["from_next"].get<double>();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  struct Cell {
    const char* name;
    std::string file;                     // empty: the default config
    std::vector<std::string> overrides;
    int levels;
  };
  const std::string three = (source / "data" / "examples" / "grains_3d_wc_co.ini").string();
  const std::vector<Cell> cells{
      {"2D default (contrast 2.7), 25 triangles per grain", "", {"mesh.triangles_per_grain=25"}, 4},
      {"2D default, matrix E = 40 GPa (contrast 20), 25 per grain", "",
       {"mesh.triangles_per_grain=25", "phase.matrix.E=40e9"}, 4},
      {"2D 60 grains, 30 % soft, contrast 20, 25 per grain", "",
       {"mesh.triangles_per_grain=25", "phase.matrix.E=40e9", "tessellation.grains=60", "phase.matrix.fraction=0.3",
        "tessellation.seed=7"}, 4},
      {"3D 20 grains WC-Co (contrast 3.3), 40 tetrahedra per grain", three,
       {"tessellation.grains=20", "mesh.tets_per_grain=40"}, 3},
      {"3D 20 grains, Co E = 35 GPa (contrast 20), 40 per grain", three,
       {"tessellation.grains=20", "mesh.tets_per_grain=40", "phase.Co.E=35e9"}, 3},
  };
  Json results = Json::array();
  for (const Cell& c : cells) {
    std::vector<std::string> overrides = c.overrides;
    overrides.push_back("homogenise.boundary=periodic");
    const Config config = c.file.empty() ? Config::from_text(default_run_config(), "default", overrides)
                                         : Config::from_file(c.file, overrides);
    const RunPlan plan = read_run_plan(config, false);
    std::fprintf(stderr, "%s\n", c.name);
    results.push_back({{"cell", c.name},
                       {"levels", plan.dimensions() == 2 ? levels<2>(plan, c.levels) : levels<3>(plan, c.levels)}});
  }
  std::printf("%s\n", results.dump(1).c_str());
  write_results(source / "bench" / "results.json", "fe_nested",
                "one solve per level in one process (CHOLMOD's factorisation; seconds the solve's own timer)", results);
}
