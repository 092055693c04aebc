#include "mesh/distmesh.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "mesh/distmesh_engine.hpp"

namespace grainmesh {
namespace {

void check_parameters(const DistMeshProblem& pb, const DistMeshOptions& opt) {
  auto positive = [](double v, const std::string& name) {
    if (!(v > 0.0) || !std::isfinite(v)) throw ConfigError(name + " must be positive, got " + to_text(v));
  };
  positive(pb.h0, "h0");
  if (pb.bbox.empty() || !is_finite(pb.bbox.lo) || !is_finite(pb.bbox.hi))
    throw ConfigError("bounding box " + to_text(pb.bbox.lo) + " - " + to_text(pb.bbox.hi) + " is empty or not finite");
  if (!(pb.curvature_angle >= 0.0) || !std::isfinite(pb.curvature_angle))
    throw ConfigError("curvature angle must be >= 0, got " + to_text(pb.curvature_angle));
  if (pb.curvature_angle > 0.0) positive(pb.curvature_gradient, "curvature gradient");
  positive(opt.fscale, "fscale");
  positive(opt.dt, "dt");
  positive(opt.ttol, "ttol");
  positive(opt.dptol, "dptol");
  positive(opt.geps, "geps");
  if (opt.max_iterations < 1) throw ConfigError("max_iterations must be at least 1");
  if (opt.density_control_every < 0) throw ConfigError("density_control_every must be >= 0");
  if (opt.optimize_sweeps < 0) throw ConfigError("optimize_sweeps must be >= 0");
}

}  // namespace

namespace distmesh_detail {

DistMeshResult Engine::run(Rng& rng) {
  const auto start = std::chrono::steady_clock::now();
  auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  seed_points(rng);
  stats_.seeding_seconds = since(start);

  bool retriangulate = true;
  for (int it = 1;; ++it) {
    stats_.iterations = it;
    if (opt_.deadline.passed())
      opt_.deadline.check("after " + std::to_string(it - 1) + " force iterations (" + std::to_string(p_.size()) + " points)");
    if (retriangulate || max_move_since_triangulation() > opt_.ttol * h0_) {
      triangulate();
      retriangulate = false;
      if (tris_.empty())
        throw GeometryError("domain is too small for h0 = " + to_text(h0_) + ": no triangle fits inside it");
    }
    bar_forces();
    if (opt_.density_control_every > 0 && it % opt_.density_control_every == 0 && density_control()) {
      retriangulate = true;
      continue;
    }
    before_ = p_.positions();
    move_points();
    if (pb_.interface) follow_interface();
    project_boundary();

    // Points on the boundary feel the boundary's reaction and never come to rest; the
    // others (interface points included) are judged by how far they actually moved.
    // With a graded absolute size, each point is judged against its own size.
    double max_move2 = 0.0;
    for (std::size_t i = p_.fixed(); i < p_.size(); ++i) {
      if (!(d_[i] < -geps_)) continue;
      const double scale = pb_.absolute_size && i < point_size_.size() ? point_size_[i] / h0_ : 1.0;
      max_move2 = std::max(max_move2, norm2(p_[i] - before_[i]) / (scale * scale));
    }
    if (std::sqrt(max_move2) < opt_.dptol * h0_) {
      stats_.converged = true;
      stats_.stop_reason = "converged: every interior point moved less than dptol h0";
      break;
    }
    if (it >= opt_.max_iterations) {
      stats_.stop_reason = "iteration limit " + std::to_string(opt_.max_iterations) + " reached before convergence";
      break;
    }
  }

  // A domain's hull can fold without turning a triangle over: start the finish afresh.
  const auto finish = std::chrono::steady_clock::now();
  triangulate(!fixed_boundary());
  if (pb_.interface) stats_.interface_straddling = repair_interface();
  optimize_stars();
  for (int round = 0; fixed_boundary() && round < 6 && insert_steiner_points() > 0; ++round) {
    opt_.deadline.check("while inserting Steiner points");
    triangulate();
    optimize_stars();
  }
  if (fixed_boundary() && remove_crowding_points() > 0) optimize_stars();
  if (fixed_boundary() && try_steiner_points() > 0) optimize_stars();

  DistMeshResult result{compact(), {}, stats_};
  result.phase = interface_phase(result.mesh);
  validate(result.mesh);
  result.stats.finish_seconds = since(finish);
  result.stats.seconds = since(start);
  return result;
}


}  // namespace distmesh_detail


DistMeshResult distmesh(const DistMeshProblem& problem, const DistMeshOptions& options, Rng& rng) {
  check_parameters(problem, options);
  distmesh_detail::Engine engine(problem, options);
  return engine.run(rng);
}


}  // namespace grainmesh
