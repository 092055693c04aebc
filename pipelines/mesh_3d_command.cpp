#include "pipelines/mesh_3d_command.hpp"

#include <cmath>
#include <cstdio>

#include "common/format.hpp"
#include "grains3d/conformity_3d.hpp"
#include "pipelines/config.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

GrainMesh3 run_mesh_3d_job(const Tessellation3& t, const Mesh3Job& job) {
  GrainMesh3 m = mesh_tessellation_3d(t, job.options);
  try {
    check_conformity(t, m);
  } catch (const GeometryError& e) {
    // Every region meshed, but the pieces do not fit: an inconsistency no config should make.
    throw GeometryError(std::string("the 3D mesh failed its conformity check (") + e.what() +
                        "): a grainmesh bug, please report it with this config; another mesh.tets_per_grain (or "
                        "mesh.size) avoids it");
  }
  return m;
}

Json write_mesh_3d_files(const std::filesystem::path& dir, const Tessellation3& t, const GrainMesh3& m, const Mesh3Job& job,
                         Warnings& warnings, bool pictures, const std::string& length_unit) {
  const TetQuality q = measure_quality(m.mesh);
  std::vector<double> quality;
  for (const auto& tet : m.mesh.tets)
    quality.push_back(radius_ratio(m.mesh.points[tet[0]], m.mesh.points[tet[1]], m.mesh.points[tet[2]], m.mesh.points[tet[3]]));
  if (q.min_dihedral_deg < 5.0)
    warnings.add("mesh: the smallest dihedral angle is " + to_text(q.min_dihedral_deg, 3) + " degrees (" +
                 to_text(100.0 * q.share_dihedral_below_10, 2) +
                 " % of the tetrahedra have one below 10): sharp corners of the tessellation's faces cause it");
  std::vector<std::string> names;
  for (const Phase& p : t.phases) names.push_back(p.name);
  write_tet_vtu(dir / "mesh.vtu", m.mesh, {{"grain", &m.grain}, {"phase", &m.phase}, {"region", &m.region}},
                {{"quality", &quality}}, {{"phase_names", names}});
  const double z = section_height(t, job.section * t.depth);
  if (pictures) {
    try {
      const Section section = mesh_section(m.mesh, m.grain, m.phase, z);
      write_mesh_png(dir / "mesh.png", section.cells,
                     {.width_px = job.picture_width, .fill_by = section.phase, .outline_by = section.grain,
                      .legend = names, .scale_bar = true, .length_unit = length_unit});
    } catch (const GeometryError& e) {
      warnings.add("mesh.png not drawn: the section z = " + to_text(z) + " could not be drawn (" + e.what() +
                   "); another output.section may be");
    }
  }
  const double per_grain = static_cast<double>(m.mesh.tets.size()) / static_cast<double>(t.grains.size());
  return {{"mesh",
           {{"points", m.mesh.points.size()},
            {"cells", m.mesh.tets.size()},
            {"q_min", q.q_min},
            {"q_mean", q.q_mean},
            {"min_dihedral_deg", q.min_dihedral_deg},
            {"max_dihedral_deg", q.max_dihedral_deg},
            {"share_dihedral_below_10", q.share_dihedral_below_10},
            {"cells_per_grain_mean", per_grain}}},
          {"grains", t.grains.size()},
          {"regions", t.regions.size()},
          {"size", job.options.size},
          {"surface_points", m.surface_points},
          {"surface_triangles", m.surface_triangles},
          {"pairs", {{"x", m.pairs.axis[0].size()}, {"y", m.pairs.axis[1].size()}, {"z", m.pairs.axis[2].size()}}},
          {"conforming", true},  // check_conformity passed, or nothing was written
          {"threads", job.options.threads},
          {"section_z", z},
          {"surface_seconds", m.surface_seconds},
          {"fill_seconds", m.fill_seconds}};
}

void print_mesh_3d_summary(const Json& mesh, double seconds) {
  std::printf("grainmesh mesh: 3D, %zu points, %zu tetrahedra (%.0f per grain), q_min %.3f, q_mean %.3f, smallest "
              "dihedral %.1f deg, conforming (%.2f s)\n",
              mesh["points"].get<std::size_t>(), mesh["cells"].get<std::size_t>(), mesh["cells_per_grain_mean"].get<double>(),
              mesh["q_min"].get<double>(), mesh["q_mean"].get<double>(), mesh["min_dihedral_deg"].get<double>(), seconds);
}

void run_mesh_3d_command(const Tessellation3& t, const std::filesystem::path& tessellation, const Config& c,
                         const std::filesystem::path& out) {
  const Mesh3Job job = resolve_mesh_job(read_mesh_3d_job(c), t);
  const GrainMesh3 m = run_mesh_3d_job(t, job);
  Warnings warnings;
  StagedOutput staged(out, "mesh");
  Json report{{"dimensions", 3}, {"tessellation", tessellation.string()}};
  report.update(write_mesh_3d_files(staged.dir(), t, m, job, warnings, true, {}));
  report["seconds"] = m.seconds;
  add_time_limit(report, job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();
  print_mesh_3d_summary(report["mesh"], m.seconds);
  std::printf("  wrote %s/{mesh.vtu, mesh.png (section z = %g), report.json}\n", out.string().c_str(),
              report["section_z"].get<double>());
}

}  // namespace grainmesh
