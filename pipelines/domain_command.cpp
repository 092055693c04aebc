#include "pipelines/domain_command.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "mesh/quality.hpp"
#include "pipelines/mesh_outputs.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "view/mesh_description.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

namespace {

Json run_and_write(const Config& c, const std::filesystem::path& out) {
  claim_output(out, "domain");
  const DomainJob job = read_domain_job(c);
  const DistMeshResult result = mesh_domain(job);
  const TriMesh& mesh = result.mesh;

  const MeshQuality quality = measure_quality(mesh);
  const auto edges = mesh_edges(mesh);
  double boundary_distance = 0.0;
  for (int v : boundary_points(mesh, edges))
    boundary_distance = std::max(boundary_distance, std::abs(job.problem.domain(mesh.points[v])));
  std::vector<double> region_area;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto r = static_cast<std::size_t>(result.phase[t]);
    if (region_area.size() <= r) region_area.resize(r + 1, 0.0);
    region_area[r] += triangle_area(mesh, static_cast<int>(t));
  }
  const double area = mesh_area(mesh);
  std::vector<double> region_fraction;
  for (double a : region_area) region_fraction.push_back(a / area);

  Warnings warnings;
  if (const auto w = poor_quality_warning(quality, mesh.triangles.size(),
                                          "a size function that jumps (size.gradient) or sharp corners"))
    warnings.add(*w);
  if (!result.stats.converged)
    warnings.add("mesh: the force iterations stopped (" + result.stats.stop_reason +
                 ") before the points settled (the mesh is valid; see distmesh.max_iterations)");
  StagedOutput staged(out, "domain");
  // The file calls the interface's sides "region" (0 outside, 1 inside); the export reads them as phases.
  write_vtu(staged.dir() / "mesh.vtu", mesh, {{"region", result.phase}, {"quality", triangle_quality(mesh)}});
  write_mesh_png(staged.dir() / "mesh.png", mesh, {.width_px = job.picture_width, .fill_by = result.phase, .scale_bar = true});
  // For the export: the bounding box is the cell; inside the interface is the second phase.
  MeshDescription description;
  for (const Vec2 p : mesh.points) description.cell.extend(p);
  description.phases.push_back({job.problem.interface ? "matrix" : "solid", {}, {}});
  if (job.problem.interface) description.phases.push_back({"inclusion", {}, {}});
  write_mesh_description(staged.dir() / "mesh.json", description);

  const DistMeshStats& s = result.stats;
  Json report;
  report["config"] = c.source();
  report["points"] = mesh.points.size();
  report["triangles"] = mesh.triangles.size();
  report["area"] = area;
  report["region_area"] = region_area;
  report["region_fraction"] = region_fraction;
  add_quality(report, quality);
  report["max_boundary_distance"] = boundary_distance;
  report["max_boundary_distance_over_h0"] = boundary_distance / job.problem.h0;
  report["interface_straddling_triangles"] = s.interface_straddling;
  report["h0"] = job.problem.h0;
  report["seed"] = job.seed;
  report["size_graded"] = s.size_graded;
  report["initial_points"] = s.initial_points;
  report["fixed_points"] = job.problem.fixed.size();
  report["iterations"] = s.iterations;
  report["retriangulations"] = s.retriangulations;
  report["triangulations_built_anew"] = s.rebuilds;
  report["edge_flips"] = s.flips;
  report["density_removed"] = s.density_removed;
  report["density_added"] = s.density_added;
  report["interface_repairs"] = s.interface_repairs;
  report["converged"] = s.converged;
  report["stop_reason"] = s.stop_reason;
  report["seconds"] = s.seconds;
  report["seeding_seconds"] = s.seeding_seconds;
  report["triangulation_seconds"] = s.triangulation_seconds;
  report["finish_seconds"] = s.finish_seconds;
  add_time_limit(report, job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();
  return report;
}

}  // namespace

void run_domain_command(const Config& c, const std::filesystem::path& out) {
  const Json report = run_and_write(c, out);
  std::printf("grainmesh domain: %zu points, %zu triangles, q_min %.3f, q_mean %.3f, %s after %d iterations "
              "(%.3f s)\n  wrote %s/{mesh.vtu, mesh.png, report.json}\n",
              report["points"].get<std::size_t>(), report["triangles"].get<std::size_t>(),
              report["q_min"].get<double>(), report["q_mean"].get<double>(),
              report["converged"].get<bool>() ? "converged" : "NOT converged", report["iterations"].get<int>(),
              report["seconds"].get<double>(), out.string().c_str());
}

}  // namespace grainmesh
