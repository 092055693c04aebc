#include "pipelines/domain_job.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "domain/shape_parser.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/config_values.hpp"

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

}  // namespace grainmesh
