#include "mesh/distmesh_engine.hpp"

#include <algorithm>
#include <memory>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace grainmesh::distmesh_detail {

// The user's size function at the points; throws where it is not finite and positive.
std::vector<double> Engine::checked_size(const std::vector<Vec2>& pts) const {
  std::vector<double> h(pts.size());
  pb_.size.eval(pts, h);
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!(h[i] > 0.0) || !std::isfinite(h[i]))
      throw ConfigError("size function '" + pb_.size.describe() + "' is " + to_text(h[i]) + " at " + to_text(pts[i]) +
                        " inside the domain; it must be finite and positive there");
  return h;
}

// Equilateral lattice of the given spacing over the bounding box (every other row shifted
// by half a spacing), restricted to d < geps.
std::vector<Vec2> Engine::lattice(double spacing) const {
  const Box& bb = pb_.bbox;
  const double dy = spacing * std::sqrt(3.0) / 2.0;
  const double nx = std::floor(bb.width() / spacing) + 1.0, ny = std::floor(bb.height() / dy) + 1.0;
  if (nx * ny > 2e8)
    throw ConfigError("the initial lattice of spacing " + to_text(spacing) + " would have " + to_text(nx * ny) +
                      " points over the bounding box: raise h0" +
                      (spacing < h0_ ? std::string(" or lower the curvature refinement") : std::string()));
  std::vector<Vec2> pts;
  for (std::int64_t j = 0; j < static_cast<std::int64_t>(ny); ++j) {
    const double y = bb.lo.y + static_cast<double>(j) * dy;
    const double shift = (j % 2) ? 0.5 * spacing : 0.0;
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(nx); ++i) {
      const Vec2 q{bb.lo.x + shift + static_cast<double>(i) * spacing, y};
      if (pb_.domain(q) < geps_) pts.push_back(q);
    }
  }
  return pts;
}


// With an absolute size field: the centres of a quadtree's leaves over the bounding box,
// each leaf split until it is about the size at its centre (or h0), kept where
// d < geps. Costs in proportion to the points made, however fine the finest size.
// (Leaves are split until no wider than 1.25 x the size at their centre.)
std::vector<Vec2> Engine::graded_points() const {
  std::vector<Vec2> out;
  const double w0 = std::max(pb_.bbox.width(), pb_.bbox.height());
  std::vector<std::pair<Vec2, double>> stack{{pb_.bbox.centre(), w0}};
  while (!stack.empty()) {
    const auto [c, w] = stack.back();
    stack.pop_back();
    if (pb_.domain(c) > 0.75 * w) continue;  // the cell lies wholly outside
    // Leaves end between 0.625 and 1.25 times the size: one point per leaf then has about
    // the density of an equilateral lattice of that spacing.
    if (w > h0_ && w > 1.25 * pb_.size(c)) {
      const double q = 0.25 * w;
      for (const Vec2 d : {Vec2{-q, -q}, Vec2{q, -q}, Vec2{-q, q}, Vec2{q, q}}) stack.push_back({c + d, 0.5 * w});
      continue;
    }
    if (pb_.domain(c) < geps_) out.push_back(c);
    if (out.size() % 65536 == 0 && !out.empty()) {
      if (static_cast<double>(out.size()) > kMaxMeshPoints)
        throw ConfigError("the size field asks for more than " + to_text(kMaxMeshPoints) +
                          " points (its least value is " + to_text(h0_) + "): raise the smallest size");
      if (opt_.deadline.passed()) opt_.deadline.check("while seeding points");
    }
  }
  return out;
}

// Step 1: equilateral lattice, keep d < geps, then keep each point with probability
// (s_min / s)^2 so that density follows the size field. With boundary seeding, points
// near the boundary are first projected onto it and thinned to the local size, and the
// lattice keeps clear of them.
// The problem's fixed points, checked; with a projected boundary each once (points
// closer than geps are the same point).
std::vector<Vec2> Engine::unique_fixed_points() const {
  std::vector<Vec2> fixed;
  PointGrid seen(h0_);
  for (const Vec2 f : pb_.fixed) {
    if (!is_finite(f)) throw GeometryError("fixed point " + to_text(f) + " is not finite");
    const double d = pb_.domain(f);
    if (d > geps_)
      throw GeometryError("fixed point " + to_text(f) + " lies outside the domain (distance " + to_text(d) + ")");
    if (!fixed_boundary() && seen.near(f, geps_)) continue;
    seen.insert(f);
    fixed.push_back(f);
  }
  return fixed;
}

// Sets size_, the absolute size field (the user's scaled so that its least value `h`
// over `pts` is h0, graded and limited by curvature as asked); returns the lattice
// spacing it needs (below h0 where curvature asks for finer).
double Engine::make_size_field(const std::vector<Vec2>& pts, const std::vector<double>& h) {
  auto size = std::make_shared<AbsoluteSize>(pb_.size);
  size->scale = pb_.absolute_size ? 1.0 : h0_ / *std::min_element(h.begin(), h.end());
  if (pb_.size_gradient > 0.0 && !pb_.absolute_size) {
    // Sizes asked inside the domain (and a lattice step beyond), scaled like the field.
    auto sample = [&](std::span<const Vec2> nodes, std::span<double> out) {
      pb_.size.eval(nodes, out);
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const bool asked = pb_.domain(nodes[i]) < h0_ && std::isfinite(out[i]) && out[i] > 0.0;
        out[i] = asked ? out[i] * size->scale : std::numeric_limits<double>::infinity();
      }
    };
    SizeGrading grading(pb_.bbox, h0_, pb_.size_gradient, sample);
    stats_.size_graded = grading.limits();
    if (grading.limits()) size->grading = std::move(grading);
  }
  double spacing = h0_;
  if (pb_.curvature_angle > 0.0) {
    size->angle = pb_.curvature_angle;
    size->gradient = pb_.curvature_gradient;
    size->curved.push_back(pb_.domain);
    if (pb_.interface) size->curved.push_back(*pb_.interface);
    for (const Vec2 q : pts)
      for (const auto& c : size->curved) spacing = std::min(spacing, c.curvature_size(q, pb_.curvature_angle, 0.0));
  }
  size_ = SizeFunction(size);
  return spacing;
}

void Engine::seed_points(Rng& rng) {
  const std::vector<Vec2> fixed = unique_fixed_points();

  // A graded start only where a lattice at the finest spacing would be large.
  const double lattice_points = pb_.bbox.width() * pb_.bbox.height() / (h0_ * h0_);
  const bool graded = pb_.absolute_size && lattice_points > kMaxLatticePoints;
  std::vector<Vec2> pts = graded ? graded_points() : lattice(h0_);
  if (pts.empty() && !fixed_boundary())  // a seeded boundary alone still makes a mesh
    throw GeometryError("domain is empty inside its bounding box " + to_text(pb_.bbox.lo) + " - " + to_text(pb_.bbox.hi) +
                        ": no lattice point of spacing h0 = " + to_text(h0_) + " lies inside");
  const std::vector<double> h = checked_size(pts.empty() ? fixed : pts);
  checked_size(fixed);

  const double spacing = make_size_field(pts, h);
  stats_.lattice_spacing = spacing;
  if (spacing < h0_) pts = lattice(spacing);

  std::vector<double> s;
  if (pb_.absolute_size && spacing == h0_ && !pts.empty()) {
    s = h;  // the same field, already evaluated
  } else {
    s.resize(pts.size());
    size_->eval(pts, s);
  }
  p_.start(fixed);
  // Graded points ask "near" within half their own size, so the grid's cells must be as
  // large as the largest size.
  PointGrid taken(pb_.absolute_size && !s.empty() ? *std::max_element(s.begin(), s.end()) : spacing);
  for (const Vec2 f : fixed) taken.insert(f);

  // Seeds on a curve: lattice points within one local size of it, projected onto it,
  // each kept unless an earlier seed lies closer than 0.85 of the local size.
  auto seed_curve = [&](const DistanceFunction& curve, bool interface) {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (std::abs(curve(pts[i])) > s[i]) continue;
      const Vec2 q = project_to_zero(curve, pts[i], deps_, proj_tol_);
      if (interface && pb_.domain(q) > -0.5 * s[i]) continue;  // leave where the curves meet to the fixed points
      if (taken.near(q, 0.85 * s[i])) continue;
      taken.insert(q);
      p_.add(q, interface);
    }
  };
  auto clear_of = [&](const DistanceFunction& curve, std::size_t i) { return std::abs(curve(pts[i])) > 0.7 * s[i]; };
  const bool seed_boundary = opt_.boundary_seeding && !fixed_boundary();
  if (seed_boundary) {
    seed_curve(pb_.domain, false);
    if (pb_.interface) seed_curve(*pb_.interface, true);
  }
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double keep = graded ? 1.0 : (spacing / s[i]) * (spacing / s[i]);  // graded points are sized
    const double u = uniform01(rng);  // one draw per lattice point: the stream never depends on the grid
    if (u >= keep) continue;
    if (fixed_boundary()) {
      // Clear of the seeded boundary by kClear of a size, so no sliver forms against it.
      if (pb_.domain(pts[i]) > -kClear * s[i] || taken.near(pts[i], kClear * s[i])) continue;
    } else if (seed_boundary) {
      if (!clear_of(pb_.domain, i) || (pb_.interface && !clear_of(*pb_.interface, i)) || taken.near(pts[i], 0.5 * s[i]))
        continue;
    } else if (taken.near(pts[i], 0.5 * spacing)) {
      continue;
    }
    p_.add(pts[i]);
  }
  stats_.initial_points = p_.size();
}


}  // namespace grainmesh::distmesh_detail
