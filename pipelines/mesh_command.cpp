#include "pipelines/mesh_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "grains/conformity.hpp"
#include "mesh/quality.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/mesh_3d_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/result_pictures.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/mesh_description.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"

namespace grainmesh {



Tessellation read_tessellation_file(const std::filesystem::path& file) {
  return tessellation_from_json(read_text_file(file, "tessellation file"), file.string());
}

std::optional<std::string> poor_quality_warning(const MeshQuality& q, std::size_t triangles, const std::string& causes) {
  if (!(q.q_min < kPoorQuality)) return std::nullopt;
  return "mesh: q_min " + to_text(q.q_min, 3) + " is below " + to_text(kPoorQuality) + " (" +
         std::to_string(std::lround(q.q_below_half * static_cast<double>(triangles))) +
         " triangles below 0.5): look at mesh.png; " + causes + " cause it";
}

std::vector<std::string> mesh_warnings(const GrainMesh& m, const MeshQuality& q, const GrainMeshOptions& o) {
  std::vector<std::string> warnings;
  if (const auto w = poor_quality_warning(q, m.mesh.triangles.size(),
                                          "sharp grain corners (tessellation.lloyd_iterations >= 3) or size jumps "
                                          "(mesh.gradient)"))
    warnings.push_back(*w);
  if (m.unconverged_regions > 0)
    warnings.push_back("mesh: " + std::to_string(m.unconverged_regions) +
                       (m.unconverged_regions == 1 ? " region" : " regions") + " stopped at mesh.max_iterations = " +
                       std::to_string(o.distmesh.max_iterations) + " before their points settled (the mesh is valid)");
  return warnings;
}

void write_mesh_files(const std::filesystem::path& dir, const Tessellation& t, const GrainMesh& m, int picture_width,
                      bool detail, const std::string& length_unit) {
  MeshDescription description{.cell = Box{{0.0, 0.0}, {t.width, t.height}}, .periodic = t.periodic, .phases = {}};
  for (const Phase& p : t.phases) description.phases.push_back({p.name, p.youngs_modulus, p.poisson_ratio});
  const std::vector<std::string> names = phase_names(t);  // the phase array's labels, as the 3D mesh.vtu has them
  write_vtu(dir / "mesh.vtu", m.mesh, {{"grain", m.grain}, {"phase", m.phase}, {"quality", triangle_quality(m.mesh)}},
            {{"phase_names", names}});
  write_mesh_description(dir / "mesh.json", description);
  if (picture_width == 0) return;
  write_mesh_png(dir / "mesh.png", m.mesh,
                 {.width_px = picture_width, .fill_by = m.phase, .outline_by = m.grain, .legend = names, .scale_bar = true,
                  .length_unit = length_unit});
  if (!detail) return;
  write_mesh_png(dir / "mesh_detail.png", m.mesh,
                 {.width_px = picture_width, .fill_by = m.phase, .outline_by = m.grain, .view = detail_view(t),
                  .legend = names, .scale_bar = true, .length_unit = length_unit});
}

Box detail_view(const Tessellation& t) {
  const double side = std::min({3.0 * std::sqrt(t.width * t.height / std::max(1, t.stats.grains)), t.width, t.height});
  const Vec2 centre{0.5 * t.width, 0.5 * t.height}, half{0.5 * side, 0.5 * side};
  return Box{centre - half, centre + half};
}

void run_mesh_command(const std::filesystem::path& tessellation, const Config& c, const std::filesystem::path& out) {
  claim_output(out, "mesh");
  const std::string text = read_text_file(tessellation, "tessellation file");
  if (tessellation_version(text) == 2)
    return run_mesh_3d_command(tessellation_3d_from_json(text, tessellation.string()), tessellation, c, out);
  const Tessellation t = tessellation_from_json(text, tessellation.string());
  const MeshJob job = read_mesh_job(c, t);
  const GrainMesh m = mesh_tessellation(t, job.options);
  const Conformity conformity = check_conformity(t, m);
  const MeshQuality q = measure_quality(m.mesh);
  Warnings warnings;
  for (const std::string& w : mesh_warnings(m, q, job.options)) warnings.add(w);

  StagedOutput staged(out, "mesh");
  write_mesh_files(staged.dir(), t, m, job.picture_width);
  Json report;
  report["dimensions"] = 2;
  report["tessellation"] = tessellation.string();
  report["points"] = m.mesh.points.size();
  report["triangles"] = m.mesh.triangles.size();
  report["grains"] = t.grains.size();
  report["regions"] = m.regions;
  report["cells_per_grain_mean"] = static_cast<double>(m.mesh.triangles.size()) / static_cast<double>(t.grains.size());
  report["size"] = job.options.size;
  add_quality(report, q);
  report["max_grain_area_error"] = conformity.max_area_error;
  report["max_pair_mismatch"] = conformity.max_pair_mismatch;
  report["pairs_x"] = m.pairs.axis[0].size();
  report["pairs_y"] = m.pairs.axis[1].size();
  report["boundary_edges"] = conformity.boundary_edges;
  report["iterations_max"] = m.iterations_max;
  report["unconverged_regions"] = m.unconverged_regions;
  report["threads"] = job.options.threads;
  report["seed"] = job.options.seed;
  report["seconds"] = m.seconds;
  add_time_limit(report, job.options.distmesh.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();
  std::printf("grainmesh mesh: %zu points, %zu triangles (%.0f per grain), q_min %.3f, q_mean %.3f, conforming "
              "(%.3f s)\n  wrote %s/{mesh.vtu, mesh.json, mesh.png, mesh_detail.png, report.json}\n",
              m.mesh.points.size(), m.mesh.triangles.size(), report["cells_per_grain_mean"].get<double>(), q.q_min,
              q.q_mean, m.seconds, out.string().c_str());
}

void run_check_command(const std::filesystem::path& tessellation, const std::filesystem::path& mesh_file) {
  const Tessellation t = read_tessellation_file(tessellation);
  VtuContents vtu = read_vtu(mesh_file);
  auto cell_ints = [&](const std::string& name) {
    if (const std::vector<int>* v = vtu.ints(name)) return *v;
    throw IoError(mesh_file.string() + ": no integer cell array '" + name + "' (is it a grainmesh mesh.vtu?)");
  };
  LabelledCells m{std::move(vtu.mesh), cell_ints("grain"), cell_ints("phase"), {}};
  Conformity c;
  try {
    validate(m.mesh);
    m.pairs = pair_periodic_nodes(t, m.mesh.points);
    c = check_conformity(t, m);
  } catch (const GeometryError& e) {
    throw GeometryError(mesh_file.string() + ": " + e.what());
  }
  const bool triangles = as_triangles(m.mesh).has_value();
  std::printf("grainmesh check: %s conforms to %s: %zu %s, grain areas within %.1e, %zu + %zu periodic node "
              "pairs within %.1e, %zu edges on the cell's sides\n",
              mesh_file.string().c_str(), tessellation.string().c_str(), m.mesh.cells(),
              triangles ? "triangles" : "polygonal cells", c.max_area_error,
              m.pairs.axis[0].size(), m.pairs.axis[1].size(), c.max_pair_mismatch, c.boundary_edges);
}

}  // namespace grainmesh
