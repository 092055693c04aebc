#include "pipelines/domain_command.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "domain/shape_parser.hpp"
#include "mesh/quality.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/config_values.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "view/mesh_description.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

const std::vector<std::string>& domain_config_keys() {
  static const std::vector<std::string> keys = keys_of(kDomainKey);
  return keys;
}

namespace {

// Curved boundaries get at least this many edges per full turn: the chord error of a
// circle's area is then (2 pi / 48)^2 / 6 = 0.29 %.
constexpr double kDefaultCurvatureSegments = 48.0;
// How fast the size may grow per unit distance before a size function is graded (the
// mesh stage's mesh.gradient default); the thesis' graded examples stay below it.
constexpr double kDefaultSizeGradient = 0.3;

// Several values of a shape key are united.
std::optional<DistanceFunction> read_shapes(const Config& c, const std::string& key) {
  std::vector<DistanceFunction> parts;
  for (const auto& text : c.all(key)) parts.push_back(parse_shape(text, c.source() + ": " + key));
  if (parts.empty()) return std::nullopt;
  return unite(std::move(parts));
}

// A plain positive number is a constant size; anything else a muparser expression.
// Several values are combined by their minimum.
SizeFunction read_size(const Config& c) {
  std::vector<SizeFunction> parts;
  for (const auto& text : c.all("size.function")) {
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec == std::errc() && ptr == text.data() + text.size()) {
      if (!(v > 0.0) || !std::isfinite(v)) c.fail("size.function", "constant " + text + " must be positive");
      parts.push_back(constant_size(v));
    } else {
      parts.push_back(expression_size(text, c.source() + ": size.function"));
    }
  }
  if (parts.empty()) return constant_size(1.0);
  return minimum_size(std::move(parts));
}

int bounded_int(const Config& c, const std::string& key, int fallback, int lo, int hi) {
  const long long v = c.integer(key, fallback);
  if (v < lo || v > hi) c.fail(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return static_cast<int>(v);
}


}  // namespace

DomainJob read_domain_job(const Config& c) {
  c.check_keys(domain_config_keys());
  std::optional<DistanceFunction> domain = read_shapes(c, "domain.shape");
  if (!domain) c.fail("domain.shape", "missing (required)");
  const std::optional<DistanceFunction> interface = read_shapes(c, "interface.shape");

  DistMeshOptions opt;
  opt.fscale = positive(c, "distmesh.fscale", opt.fscale);
  opt.dt = positive(c, "distmesh.dt", opt.dt);
  opt.ttol = positive(c, "distmesh.ttol", opt.ttol);
  opt.dptol = positive(c, "distmesh.dptol", opt.dptol);
  opt.geps = positive(c, "distmesh.geps", opt.geps);
  opt.max_iterations = bounded_int(c, "distmesh.max_iterations", opt.max_iterations, 1, 100'000'000);
  opt.density_control_every = bounded_int(c, "distmesh.density_control_every", opt.density_control_every, 0, 1'000'000);
  opt.boundary_seeding = c.flag("distmesh.boundary_seeding", opt.boundary_seeding);
  opt.split_long_edges = c.flag("distmesh.split_long_edges", opt.split_long_edges);
  opt.optimize_sweeps = bounded_int(c, "distmesh.optimize_sweeps", opt.optimize_sweeps, 0, 1'000'000);
  opt.optimize_below = c.number("distmesh.optimize_below", opt.optimize_below);

  DomainJob job{.problem = {.domain = *domain, .size = read_size(c), .h0 = c.number("size.h0"), .bbox = {}, .fixed = {}, .interface = interface},
                .options = opt,
                .seed = c.unsigned_integer("distmesh.seed", 1)};
  job.picture_width = bounded_int(c, "output.picture_width", job.picture_width, 100, 20000);
  job.options.deadline = Deadline::after(read_time_limit(c), kTimeLimitKey);
  DistMeshProblem& pb = job.problem;
  if (!(pb.h0 > 0.0)) c.fail("size.h0", "must be positive, got " + c.text("size.h0"));
  const double segments = c.number("size.curvature_segments", kDefaultCurvatureSegments);
  if (segments != 0.0 && !(segments >= 3.0)) c.fail("size.curvature_segments", "must be 0 (off) or at least 3");
  pb.curvature_angle = segments == 0.0 ? 0.0 : 2.0 * std::numbers::pi / segments;
  pb.curvature_gradient = positive(c, "size.curvature_gradient", pb.curvature_gradient);
  pb.size_gradient = c.number("size.gradient", kDefaultSizeGradient);
  if (!(pb.size_gradient == 0.0 || (pb.size_gradient >= 0.05 && pb.size_gradient <= 10.0)))
    c.fail("size.gradient", "must be 0 (the size function as given) or lie between 0.05 and 10, got " + c.text("size.gradient"));

  if (const auto bbox = c.optional_text("domain.bbox")) {
    const auto v = parse_numbers(*bbox, 4, c.source() + ": domain.bbox");
    if (!(v[0] < v[2] && v[1] < v[3])) c.fail("domain.bbox", "expected x1 y1 x2 y2 with x1 < x2 and y1 < y2");
    pb.bbox = {{v[0], v[1]}, {v[2], v[3]}};
  } else {
    pb.bbox = pb.domain.bounds();
    if (pb.bbox.empty() || !is_finite(pb.bbox.lo) || !is_finite(pb.bbox.hi))
      c.fail("domain.bbox", "the shape has no finite extent; give the bounding box");
  }

  for (const auto& text : c.all("fixed.points"))
    for (const Vec2 p : parse_point_list(text, c.source() + ": fixed.points")) pb.fixed.push_back(p);
  if (c.flag("fixed.polygon_vertices", true)) {
    // Polygon corners that lie on the final boundary, or on the interface inside the
    // domain, are where DistMesh needs fixed points to keep sharp corners sharp.
    const double tol = opt.geps * pb.h0;
    for (const Vec2 v : pb.domain.vertices())
      if (std::abs(pb.domain(v)) <= tol) pb.fixed.push_back(v);
    if (pb.interface)
      for (const Vec2 v : pb.interface->vertices())
        if (pb.domain(v) <= tol && std::abs((*pb.interface)(v)) <= tol) pb.fixed.push_back(v);
  }
  return job;
}

DistMeshResult mesh_domain(const DomainJob& job) {
  Rng rng(job.seed);
  return distmesh(job.problem, job.options, rng);
}

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
