#include "pipelines/tessellate_3d_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string_view>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "domain/shape_parser.hpp"
#include "pipelines/cell_config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"
#include "view/vtu.hpp"
#include "tessellate/tessellate_3d.hpp"

namespace grainmesh {

Json write_tessellation_3d_files(const std::filesystem::path& dir, const Tessellation3& t, const Tessellate3Job& job,
                                 bool pictures, const std::string& length_unit, Warnings& warnings) {
  write_text_file(dir / "tessellation.json", tessellation_to_json(t));
  write_tessellation_vtu(dir / "tessellation.vtu", t);
  const double z = section_height(t, job.section * t.depth);
  if (pictures) {
    try {
      const Section section = tessellation_section(t, z);
      PictureOptions picture{.width_px = job.picture_width, .fill_by = section.phase, .outline_by = section.grain,
                             .scale_bar = true, .length_unit = length_unit};
      for (const Phase& p : t.phases) picture.legend.push_back(p.name);
      write_mesh_png(dir / "tessellation.png", section.cells, picture);
    } catch (const GeometryError& e) {
      // A picture is no reason to fail a run.
      warnings.add("tessellation.png not drawn: the section z = " + to_text(z) + " could not be drawn (" + e.what() +
                   "); another output.section may be");
    }
  }
  // The phases at the top, as in 2D; the rest of tessellation.json's statistics beside them.
  Json statistics = statistics_json(t.stats, t.phases);
  Json phases = std::move(statistics["phases"]);
  statistics.erase("phases");
  return {{"dimensions", 3},
          {"seed", job.seed},
          {"width", t.width},
          {"height", t.height},
          {"depth", t.depth},
          {"periodic", t.periodic},
          {"grains", t.stats.grains},
          {"phases", phases},
          {"statistics", statistics},
          {"section_z", z},
          {"vertices", t.vertices.size()},
          {"faces", t.faces.size()},
          {"regions", t.regions.size()}};
}

void print_tessellation_3d_summary(const Tessellation3& t, double seconds) {
  const Tessellation3Stats& s = t.stats;
  std::printf("grainmesh tessellate: %d grains in 3D, %zu regions, %zu faces, sharpest dihedral %.1f deg, shortest edge %.3g (%.3f s)\n",
              s.grains, t.regions.size(), t.faces.size(), s.sharpest_dihedral_deg, s.shortest_edge, seconds);
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    std::printf("  phase %-10s target %.4f achieved %.4f (%d grains)\n", t.phases[p].name.c_str(), s.phases[p].target_fraction,
                s.phases[p].achieved_fraction, s.phases[p].grains);
}

void run_tessellate_3d_command(const Config& c, const std::filesystem::path& out) {
  claim_output(out, "tessellate");
  const Tessellate3Job job = read_tessellate_3d_job(c);
  const auto start = std::chrono::steady_clock::now();
  Warnings warnings;
  const Tessellation3 t = run_tessellate_job(job, warnings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  StagedOutput staged(out, "tessellate");
  Json report{{"config", c.source()}};
  report.update(write_tessellation_3d_files(staged.dir(), t, job, true, {}, warnings));
  report["seconds"] = seconds;
  add_time_limit(report, job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();

  print_tessellation_3d_summary(t, seconds);
  std::printf("  wrote %s/{tessellation.json, tessellation.vtu, tessellation.png (section z = %g), report.json}\n",
              out.string().c_str(), report["section_z"].get<double>());
}

}  // namespace grainmesh
