#include "pipelines/mesh_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "grains/conformity.hpp"
#include "grains3d/conformity_3d.hpp"
#include "pipelines/result_pictures.hpp"
#include "view/mesh_description.hpp"
#include "view/box_view.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

GrainMesh run_mesh_job(const Tessellation& t, const MeshJob<2>& job, Warnings& warnings) {
  GrainMesh m = mesh_tessellation(t, job.options);
  check_conformity(t, m);
  if (m.unconverged_regions > 0)
    warnings.add("mesh: " + std::to_string(m.unconverged_regions) + (m.unconverged_regions == 1 ? " region" : " regions") +
                 " stopped at mesh.max_iterations = " + std::to_string(job.options.distmesh.max_iterations) +
                 " before their points settled (the mesh is valid)");
  return m;
}

GrainMesh3 run_mesh_job(const Tessellation3& t, const MeshJob<3>& job, Warnings&) {
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

namespace {

std::size_t element_count(const GrainMesh& m) { return m.mesh.triangles.size(); }
std::size_t element_count(const GrainMesh3& m) { return m.mesh.tets.size(); }

template <int D, class Cell>
auto coarse_mesh(const Cell& t, MeshJob<D> job, std::size_t cells) {
  if constexpr (D == 2) job.options.progress = nullptr;
  Warnings quiet(false);
  auto coarse = run_mesh_job(t, scaled_mesh_job(job, 2.0), quiet);
  const double fine = std::pow(2.0, D) * static_cast<double>(element_count(coarse));
  if (fine > 1.25 * static_cast<double>(cells))
    coarse = run_mesh_job(t, scaled_mesh_job(job, 2.0 * std::pow(fine / static_cast<double>(cells), 1.0 / D)), quiet);
  return coarse;
}

}  // namespace

GrainMesh fe_coarse_mesh(const Tessellation& t, const MeshJob<2>& job, std::size_t cells) {
  return coarse_mesh<2>(t, job, cells);
}

GrainMesh3 fe_coarse_mesh(const Tessellation3& t, const MeshJob<3>& job, std::size_t cells) {
  return coarse_mesh<3>(t, job, cells);
}

Json write_mesh_files(const std::filesystem::path& dir, const Tessellation& t, const GrainMesh& m,
                      const MeshJob<2>& job, const Drawing& drawing, Warnings& warnings) {
  const MeshQuality q = measure_quality(m.mesh);
  if (const auto w = poor_quality_warning(q, m.mesh.triangles.size(),
                                          "sharp grain corners (tessellation.lloyd_iterations >= 3) or size jumps "
                                          "(mesh.gradient)"))
    warnings.add(*w);
  MeshDescription description{.cell = Box{{0.0, 0.0}, {t.width, t.height}}, .periodic = t.periodic, .phases = {}};
  for (const Phase& p : t.phases) description.phases.push_back({p.name, p.youngs_modulus, p.poisson_ratio});
  const std::vector<std::string> names = phase_names(t.phases);
  write_vtu(dir / "mesh.vtu", m.mesh, {{"grain", m.grain}, {"phase", m.phase}, {"quality", triangle_quality(m.mesh)}},
            {{"phase_names", names}});
  write_mesh_description(dir / "mesh.json", description);
  if (drawing.pictures) {
    PictureOptions picture{.width_px = job.picture_width, .fill_by = m.phase, .outline_by = m.grain, .legend = names,
                           .scale_bar = true, .length_unit = drawing.unit};
    write_mesh_png(dir / "mesh.png", m.mesh, picture);
    if (drawing.detail) {
      picture.view = detail_view(t);
      write_mesh_png(dir / "mesh_detail.png", m.mesh, picture);
    }
  }
  Json mesh{{"points", m.mesh.points.size()}, {"cells", m.mesh.triangles.size()}};
  add_quality(mesh, q);
  mesh["cells_per_grain_mean"] = static_cast<double>(m.mesh.triangles.size()) / std::max(1, t.stats.grains);
  mesh["iterations_max"] = m.iterations_max;
  mesh["unconverged_regions"] = m.unconverged_regions;
  mesh["seed"] = job.options.seed;
  return {{"mesh", mesh},
          {"size", job.options.size},
          {"pairs", {{"x", m.pairs.axis[0].size()}, {"y", m.pairs.axis[1].size()}}},
          {"conforming", true},  // run_mesh_job's check passed
          {"threads", job.options.threads}};
}

Json write_mesh_files(const std::filesystem::path& dir, const Tessellation3& t, const GrainMesh3& m,
                      const MeshJob<3>& job, const Drawing& drawing, Warnings& warnings) {
  const TetQuality q = measure_quality(m.mesh);
  std::vector<double> quality;
  for (const auto& tet : m.mesh.tets)
    quality.push_back(radius_ratio(m.mesh.points[tet[0]], m.mesh.points[tet[1]], m.mesh.points[tet[2]], m.mesh.points[tet[3]]));
  if (q.min_dihedral_deg < 5.0)
    warnings.add("mesh: the smallest dihedral angle is " + to_text(q.min_dihedral_deg, 3) + " degrees (" +
                 to_text(100.0 * q.share_dihedral_below_10, 2) +
                 " % of the tetrahedra have one below 10): sharp corners of the tessellation's faces cause it");
  const std::vector<std::string> names = phase_names(t.phases);
  write_tet_vtu(dir / "mesh.vtu", m.mesh, {{"grain", &m.grain}, {"phase", &m.phase}, {"region", &m.region}},
                {{"quality", &quality}}, {{"phase_names", names}});
  const double z = section_height(t, job.section * t.depth);
  if (drawing.pictures) {
    try {
      const Section section = mesh_section(m.mesh, m.grain, m.phase, z);
      write_mesh_png(dir / "mesh.png", section.cells,
                     {.width_px = job.picture_width, .fill_by = section.phase, .outline_by = section.grain,
                      .legend = names, .scale_bar = true, .length_unit = drawing.unit});
    } catch (const GeometryError& e) {
      warnings.add("mesh.png not drawn: the section z = " + to_text(z) + " could not be drawn (" + e.what() +
                   "); another output.section may be");
    }
    try {
      const BoxView view = box_view(m.mesh);
      std::vector<int> phase;
      for (const int t : view.tet) phase.push_back(m.phase[t]);
      write_mesh_png(dir / "mesh_view.png", view.mesh,
                     {.width_px = job.picture_width, .fill_by = phase, .outline_by = view.outline(m.grain), .shade = view.shade,
                      .legend = names, .scale_bar = true, .length_unit = drawing.unit});
    } catch (const GeometryError& e) {
      warnings.add(std::string("mesh_view.png not drawn: ") + e.what());
    }
  }
  return {{"mesh",
           {{"points", m.mesh.points.size()},
            {"cells", m.mesh.tets.size()},
            {"q_min", q.q_min},
            {"q_mean", q.q_mean},
            {"min_dihedral_deg", q.min_dihedral_deg},
            {"max_dihedral_deg", q.max_dihedral_deg},
            {"share_dihedral_below_10", q.share_dihedral_below_10},
            {"cells_per_grain_mean", static_cast<double>(m.mesh.tets.size()) / std::max(1, t.stats.grains)},
            // bent faces meshed as one surface move the grains' volumes a little (surface_mesh.hpp)
            {"grain_volume_change_max", grain_volume_change_max(t, m)}}},
          {"size", job.options.size},
          {"pairs", {{"x", m.pairs.axis[0].size()}, {"y", m.pairs.axis[1].size()}, {"z", m.pairs.axis[2].size()}}},
          {"conforming", true},  // run_mesh_job's check passed
          {"threads", job.options.threads},
          {"section_z", z},
          {"surface_points", m.surface_points},
          {"surface_triangles", m.surface_triangles},
          {"surface_seconds", m.surface_seconds},
          {"fill_seconds", m.fill_seconds}};
}

void print_mesh_summary(const GrainMesh& m, const Json& mesh) {
  std::printf("grainmesh mesh: %zu points, %zu triangles (%.0f per grain), q_min %.3f, q_mean %.3f, conforming (%.3f s)\n",
              mesh["points"].get<std::size_t>(), mesh["cells"].get<std::size_t>(),
              mesh["cells_per_grain_mean"].get<double>(), mesh["q_min"].get<double>(), mesh["q_mean"].get<double>(),
              m.seconds);
}

void print_mesh_summary(const GrainMesh3& m, const Json& mesh) {
  std::printf("grainmesh mesh: 3D, %zu points, %zu tetrahedra (%.0f per grain), q_min %.3f, q_mean %.3f, smallest "
              "dihedral %.1f deg, conforming (%.2f s)\n",
              mesh["points"].get<std::size_t>(), mesh["cells"].get<std::size_t>(), mesh["cells_per_grain_mean"].get<double>(),
              mesh["q_min"].get<double>(), mesh["q_mean"].get<double>(), mesh["min_dihedral_deg"].get<double>(), m.seconds);
}

std::optional<std::string> poor_quality_warning(const MeshQuality& q, std::size_t triangles, const std::string& causes) {
  if (!(q.q_min < kPoorQuality)) return std::nullopt;
  return "mesh: q_min " + to_text(q.q_min, 3) + " is below " + to_text(kPoorQuality) + " (" +
         std::to_string(std::lround(q.q_below_half * static_cast<double>(triangles))) +
         " triangles below 0.5): look at mesh.png; " + causes + " cause it";
}

Box detail_view(const Tessellation& t) {
  const double side = std::min({3.0 * std::sqrt(t.width * t.height / std::max(1, t.stats.grains)), t.width, t.height});
  const Vec2 centre{0.5 * t.width, 0.5 * t.height}, half{0.5 * side, 0.5 * side};
  return Box{centre - half, centre + half};
}

}  // namespace grainmesh
