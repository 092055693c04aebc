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

MeshJob read_mesh_job(const Config& c) {
  c.check_keys(mesh_config_keys());
  for (const char* key : {"mesh.tets_per_grain", "output.section"})
    if (c.has(key)) c.fail(key, "only for 3D tessellations (tessellation.json version 2)");
  MeshJob job;
  job.origin = c.origin();
  GrainMeshOptions& o = job.options;
  // mesh.h and mesh.grading are the run config's names of mesh.size and mesh.gradient.
  const std::string size_key = one_of_keys(c, "mesh.size", "mesh.h");
  const std::string gradient_key = one_of_keys(c, "mesh.gradient", "mesh.grading");
  if (c.has(size_key) && c.has("mesh.triangles_per_grain"))
    c.fail("mesh.triangles_per_grain", "give either " + size_key + " or mesh.triangles_per_grain, not both");
  if (c.has(size_key)) {
    o.size = c.number(size_key);
    if (!(o.size > 0.0) || !std::isfinite(o.size)) c.fail(size_key, "must be positive, got " + c.text(size_key));
    job.size_key = size_key;
  } else {
    job.per_grain = c.number("mesh.triangles_per_grain", 100.0);
    if (!(*job.per_grain >= 2.0 && *job.per_grain <= 1e6)) c.fail("mesh.triangles_per_grain", "must lie between 2 and 1e6");
  }
  for (const std::string& name : c.names_in("phase")) {
    const std::string key = "phase." + name + ".size";
    if (!c.has(key)) continue;
    job.phase_sizes.emplace_back(name, c.number(key));
    if (!(job.phase_sizes.back().second > 0.0) || !std::isfinite(job.phase_sizes.back().second))
      c.fail(key, "must be positive, got " + c.text(key));
  }
  for (const auto& [key, value] : {std::pair{"mesh.boundary_size", &o.boundary_size}, {"mesh.junction_size", &o.junction_size}}) {
    *value = c.number(key, 0.0);
    if (!(*value >= 0.0) || !std::isfinite(*value)) c.fail(key, "must be positive (or 0 for none), got " + c.text(key));
  }
  o.gradient = c.number(gradient_key, o.gradient);
  if (!(o.gradient >= 0.05 && o.gradient <= 10.0)) c.fail(gradient_key, "must lie between 0.05 and 10");
  const long long threads = c.integer("mesh.threads", 0);
  if (threads < 0 || threads > 1024) c.fail("mesh.threads", "must be between 0 (all cores) and 1024");
  o.threads = static_cast<int>(threads);
  o.seed = c.unsigned_integer("mesh.seed", 1);
  const long long iterations = c.integer("mesh.max_iterations", o.distmesh.max_iterations);
  if (iterations < 1 || iterations > 100'000'000) c.fail("mesh.max_iterations", "must be at least 1");
  o.distmesh.max_iterations = static_cast<int>(iterations);
  const long long width = c.integer("output.picture_width", job.picture_width);
  if (width < 100 || width > 20000) c.fail("output.picture_width", "must be between 100 and 20000");
  o.distmesh.deadline = Deadline::after(read_time_limit(c), kTimeLimitKey);
  job.picture_width = static_cast<int>(width);
  return job;
}

MeshJob resolve_mesh_job(MeshJob job, const Tessellation& t) {
  GrainMeshOptions& o = job.options;
  if (job.per_grain) {
    // Equilateral triangles of side h have area h^2 sqrt(3) / 4.
    const double grain_area = t.width * t.height / std::max(1, t.stats.grains);
    o.size = std::sqrt(4.0 * grain_area / (*job.per_grain * std::sqrt(3.0)));
  }
  o.phase_size.assign(t.phases.size(), 0.0);
  for (const auto& [name, size] : job.phase_sizes) {
    std::size_t p = 0;
    while (p < t.phases.size() && t.phases[p].name != name) ++p;
    if (p == t.phases.size()) {
      std::string names;
      for (const Phase& ph : t.phases) names += (names.empty() ? "" : ", ") + ph.name;
      job.origin.fail("phase." + name + ".size", "unknown phase '" + name + "' (the tessellation's phases: " + names + ")");
    }
    o.phase_size[p] = size;
  }
  // Far too fine a size is a slip (a unit, a digit): refused before any work is done.
  double finest = o.size;
  std::string finest_key = job.per_grain ? "mesh.triangles_per_grain" : job.size_key;
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    if (o.phase_size[p] > 0.0 && o.phase_size[p] < finest) {
      finest = o.phase_size[p];
      finest_key = "phase." + t.phases[p].name + ".size";
    }
  const double triangles = t.width * t.height / (0.25 * std::sqrt(3.0) * finest * finest);
  if (triangles > 2.0 * kMaxMeshPoints) {
    job.origin.fail(finest_key, "asks for about " + to_text(triangles) + " triangles (size " + to_text(finest) + " over a " +
                                    to_text(t.width) + " x " + to_text(t.height) + " cell), more than " +
                                    to_text(2.0 * kMaxMeshPoints) + ": coarsen it");
  }
  return job;
}

MeshJob read_mesh_job(const Config& config, const Tessellation& t) { return resolve_mesh_job(read_mesh_job(config), t); }

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
