#include "pipelines/tessellate_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "domain/shape_parser.hpp"
#include "pipelines/cell_config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/material_units.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/tessellate_3d_command.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"
#include "tessellate/tessellate.hpp"

namespace grainmesh {





PictureOptions tessellation_picture(const Tessellation& t, int width, const std::string& length_unit) {
  PictureOptions o{.width_px = width, .scale_bar = true, .length_unit = length_unit};
  for (const Phase& p : t.phases) o.legend.push_back(p.name);
  return o;
}

void run_tessellate_command(const Config& c, const std::filesystem::path& out) {
  if (cell_dimensions(c) == 3) return run_tessellate_3d_command(c, out);
  claim_output(out, "tessellate");
  const TessellateJob job = read_tessellate_job(c);
  const auto start = std::chrono::steady_clock::now();
  const Tessellation t = run_tessellate_job(job);
  check_phases_have_grains(t.phases, t.stats.phases, t.stats.grains, job.origin, job.options.matrix_phase);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Warnings warnings;
  for (const std::string& w : phase_fraction_warnings(t.phases, t.stats.phases, t.stats.grains)) warnings.add(w);

  StagedOutput staged(out, "tessellate");
  write_text_file(staged.dir() / "tessellation.json", tessellation_to_json(t));
  write_tessellation_vtp(staged.dir() / "tessellation.vtp", t);
  write_tessellation_png(staged.dir() / "tessellation.png", t, tessellation_picture(t, job.picture_width));
  const TessellationStats& s = t.stats;
  Json report;
  report["config"] = c.source();
  report["dimensions"] = 2;
  report["seed"] = job.seed;
  report["width"] = t.width;
  report["height"] = t.height;
  report["periodic"] = t.periodic;
  report["grains"] = s.grains;
  report["phases"] = phases_json(t);
  report["statistics"] = descriptors_json(t);
  report["removed_grains"] = s.removed_grains;
  report["area_mean"] = s.area_mean;
  report["area_std"] = s.area_std;
  report["diameter_mean"] = s.diameter_mean;
  report["diameter_std"] = s.diameter_std;
  report["neighbours_mean"] = s.neighbours_mean;
  report["edges_per_grain_mean"] = s.edges_per_grain_mean;
  report["edge_threshold"] = s.edge_threshold;
  report["shortest_edge"] = s.shortest_edge;
  report["shortest_torus_edge"] = s.shortest_torus_edge;
  report["sharpest_corner_deg"] = s.sharpest_corner_deg;
  report["collapsed_edges"] = s.collapsed_edges;
  report["side_jogs"] = s.side_jogs;
  report["pushed_vertices"] = s.pushed_vertices;
  report["binder_offset"] = s.binder_offset;
  report["vertices"] = t.vertices.size();
  report["edges"] = t.edges.size();
  report["regions"] = t.regions.size();
  report["seconds"] = seconds;
  add_time_limit(report, job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();

  std::printf("grainmesh tessellate: %d grains, %zu regions, sharpest corner %.1f deg, shortest edge %.3g (%.3f s)\n",
              s.grains, t.regions.size(), s.sharpest_corner_deg, s.shortest_edge, seconds);
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    std::printf("  phase %-10s target %.4f achieved %.4f (%d grains)\n", t.phases[p].name.c_str(),
                s.phases[p].target_fraction, s.phases[p].achieved_fraction, s.phases[p].grains);
  std::printf("  wrote %s/{tessellation.json, tessellation.vtp, tessellation.png, report.json}\n", out.string().c_str());
}

}  // namespace grainmesh
