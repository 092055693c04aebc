#include "mesh/distmesh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "mesh/delaunay.hpp"
#include "mesh/quality.hpp"
#include "domain/size_grading.hpp"

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

// Points in a uniform hash grid, for "is there a point within r of p" with r up to the
// cell size. Linear in the number of points for evenly spread inputs.
class PointGrid {
 public:
  explicit PointGrid(double cell) : cell_(cell) {}
  void insert(Vec2 p) { cells_[key(cell_of(p.x), cell_of(p.y))].push_back(p); }
  bool near(Vec2 p, double radius) const {
    const std::int64_t cx = cell_of(p.x), cy = cell_of(p.y);
    const std::int64_t reach = static_cast<std::int64_t>(std::ceil(radius / cell_));
    for (std::int64_t i = cx - reach; i <= cx + reach; ++i)
      for (std::int64_t j = cy - reach; j <= cy + reach; ++j) {
        const auto it = cells_.find(key(i, j));
        if (it == cells_.end()) continue;
        for (const Vec2 q : it->second)
          if (norm2(q - p) < radius * radius) return true;
      }
    return false;
  }

 private:
  std::int64_t cell_of(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::uint64_t key(std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint64_t>(j & 0xffffffff);
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Vec2>> cells_;
};

// The size field the engine works with: absolute edge lengths. The user's relative size
// h is scaled so that its least value over the domain maps to h0 (the thesis' meaning
// of h0), graded where it grows faster than the problem allows, then limited by the
// curvature of curved boundaries.
struct AbsoluteSize final : SizeFunction::Node {
  explicit AbsoluteSize(SizeFunction r) : relative(std::move(r)) {}
  SizeFunction relative;
  double scale = 1.0;  // h0 / min h
  std::optional<SizeGrading> grading;
  std::vector<DistanceFunction> curved;
  double angle = 0.0, gradient = 0.0;

  void eval(std::span<const Vec2> p, std::span<double> out) const override {
    relative.eval(p, out);
    for (std::size_t i = 0; i < p.size(); ++i) {
      out[i] *= scale;
      if (grading) out[i] = grading->at(p[i], out[i]);
      for (const auto& c : curved) out[i] = std::min(out[i], c.curvature_size(p[i], angle, gradient));
    }
  }
  std::string describe() const override { return relative.describe(); }
};

// One run of Algorithm 1. Points 0 .. nfix-1 are the fixed points.
class Engine {
 public:
  Engine(const DistMeshProblem& pb, const DistMeshOptions& opt)
      : pb_(pb),
        opt_(opt),
        h0_(pb.h0),
        geps_(opt.geps * pb.h0),
        deps_(std::sqrt(std::numeric_limits<double>::epsilon()) * pb.h0),
        proj_tol_(1e-10 * pb.h0),
        on_interface_tol_(1e-8 * pb.h0) {}

  DistMeshResult run(Rng& rng);

 private:
  bool fixed_boundary() const { return !pb_.constraints.empty(); }
  std::vector<Vec2> lattice(double spacing) const;
  std::vector<Vec2> graded_points() const;
  void seed_points(Rng& rng);
  std::vector<double> checked_size(const std::vector<Vec2>& pts) const;
  int interface_mover(int a, int b, const std::vector<double>& di) const;
  void triangulate(bool from_scratch = false);
  void points_changed();
  void points_appended(std::size_t first, const std::vector<int>& near);
  void bar_forces();
  bool density_control();
  void move_points();
  void follow_interface();
  void project_boundary();
  double max_move_since_triangulation() const;
  std::size_t repair_interface();
  void optimize_stars(std::size_t first = 0);
  std::size_t insert_steiner_points();
  std::size_t remove_crowding_points();
  std::size_t try_steiner_points();
  std::pair<double, double> shortfall(double target) const;
  TriMesh compact() const;

  const DistMeshProblem& pb_;
  const DistMeshOptions& opt_;
  const double h0_, geps_, deps_, proj_tol_, on_interface_tol_;
  std::optional<SizeFunction> size_;  // absolute, set by seed_points

  std::size_t nfix_ = 0;
  std::vector<Vec2> p_;                      // #N positions, fixed first
  std::vector<Vec2> pold_;                   // positions at the last triangulation
  std::vector<Vec2> before_;                 // positions at the start of the iteration
  Triangulation live_;                       // kept Delaunay by flips while points move
  bool live_valid_ = false;                  // false: the points changed, build anew
  std::vector<int> orphans_;                 // points in no triangle of live_
  std::vector<std::array<int, 3>> tris_;     // triangles with centroid inside
  std::vector<std::array<int, 2>> bars_;     // unique edges of tris_
  std::vector<char> on_boundary_;            // #N: on an edge of one triangle
  std::vector<char> bar_on_boundary_;        // #bars: an edge of one triangle
  std::vector<char> on_interface_;           // #N: held on dI = 0 (kept aligned with p_)
  std::vector<Vec2> force_, mid_;            // #N total force; #bars midpoints (at triangulation)
  std::vector<double> len_, d_, di_;         // #bars lengths; #N d, dI
  std::vector<double> bar_size_;             // #bars size field at the midpoints
  std::vector<double> point_size_;           // #N size at the points (absolute sizes only)
  std::vector<char> kept_;                   // #live triangles: inside the domain
  double sum_size2_ = 0.0;                   // sum of bar_size_ squared
  double len0_scale_ = 0.0;                  // wanted length / bar size, this iteration
  std::vector<double> dval_;                 // #N d at dpos_, the last exact evaluation
  std::vector<Vec2> dpos_;
  DistMeshStats stats_;
};

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

// Above this many lattice points at the finest spacing, seeding starts from a quadtree.
constexpr double kMaxLatticePoints = 20000.0;
// Initial points keep this many sizes clear of a seeded boundary.
constexpr double kClear = 0.4;
// Optimisation keeps free points at least this x the local size inside a seeded boundary.
constexpr double kStarClearance = 0.05;

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
void Engine::seed_points(Rng& rng) {
  std::vector<Vec2> fixed;  // each once: points closer than geps are the same point
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

  // A graded start only where a lattice at the finest spacing would be large.
  const double lattice_points = pb_.bbox.width() * pb_.bbox.height() / (h0_ * h0_);
  const bool graded = pb_.absolute_size && lattice_points > kMaxLatticePoints;
  std::vector<Vec2> pts = graded ? graded_points() : lattice(h0_);
  if (pts.empty() && !fixed_boundary())  // a seeded boundary alone still makes a mesh
    throw GeometryError("domain is empty inside its bounding box " + to_text(pb_.bbox.lo) + " - " + to_text(pb_.bbox.hi) +
                        ": no lattice point of spacing h0 = " + to_text(h0_) + " lies inside");
  const std::vector<double> h = checked_size(pts.empty() ? fixed : pts);
  checked_size(fixed);

  // The absolute size field and the lattice spacing it needs.
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
  stats_.lattice_spacing = spacing;
  if (spacing < h0_) pts = lattice(spacing);

  std::vector<double> s;
  if (pb_.absolute_size && spacing == h0_ && !pts.empty()) {
    s = h;  // the same field, already evaluated
  } else {
    s.resize(pts.size());
    size_->eval(pts, s);
  }
  p_ = fixed;
  nfix_ = fixed.size();
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
      p_.push_back(q);
      on_interface_.push_back(interface);
    }
  };
  auto clear_of = [&](const DistanceFunction& curve, std::size_t i) { return std::abs(curve(pts[i])) > 0.7 * s[i]; };
  on_interface_.assign(p_.size(), 0);
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
    p_.push_back(pts[i]);
    on_interface_.push_back(0);
  }
  stats_.initial_points = p_.size();
}

// After points were added, removed or renumbered: the next triangulation starts afresh.
void Engine::points_changed() {
  live_valid_ = false;
  dval_.clear();
}

// Step 2: Delaunay triangulation, keeping triangles whose centroid is inside; the bars
// are the unique edges, and an edge of one triangle only lies on the mesh boundary.
// Beyond the thesis, the triangulation is not built anew each time: while the points
// only moved, edge flips make the last one Delaunay again (the same triangles a new one
// would have, but for ties), unless a move turned a triangle over.
void Engine::triangulate(bool from_scratch) {
  const auto started = std::chrono::steady_clock::now();
  bool repaired = live_valid_ && !from_scratch;
  for (std::size_t k = 0; repaired && k < orphans_.size(); ++k)  // a point outside it moved in
    repaired = p_[orphans_[k]] == pold_[orphans_[k]];
  // A domain's triangulation covers the points' hull, whose outer slivers (between
  // points on a straight side) may turn over; they are no part of the mesh and go.
  const std::size_t before = live_.triangles.size();
  repaired = repaired && restore_delaunay(live_, p_, &stats_.flips, !fixed_boundary());
  if (!repaired) {
    live_ = fixed_boundary() ? constrained_delaunay_triangulation(p_, pb_.constraints) : delaunay_triangulation(p_);
    live_valid_ = true;
    ++stats_.rebuilds;
  }
  if (!repaired || live_.triangles.size() < before) {
    std::vector<char> used(p_.size(), 0);
    for (const auto& t : live_.triangles)
      for (int v : t) used[v] = 1;
    orphans_.clear();
    for (std::size_t i = 0; i < p_.size(); ++i)
      if (!used[i]) orphans_.push_back(static_cast<int>(i));
  }
  // The kept triangles, and their edges as bars: each edge once, from the lower of its
  // two kept triangles, or the only one (then on the mesh boundary). Linear, no sorting.
  const auto& tri = live_.triangles;
  const auto& nb = live_.neighbours;
  kept_.assign(tri.size(), 1);
  if (!fixed_boundary())  // the seeded rings say what is inside; else the centroid does
    for (std::size_t t = 0; t < tri.size(); ++t)
      kept_[t] = pb_.domain((p_[tri[t][0]] + p_[tri[t][1]] + p_[tri[t][2]]) / 3.0) < -geps_;
  tris_.clear();
  bars_.clear();
  bar_on_boundary_.clear();
  on_boundary_.assign(p_.size(), 0);
  for (std::size_t t = 0; t < tri.size(); ++t) {
    if (!kept_[t]) continue;
    tris_.push_back(tri[t]);
    for (int k = 0; k < 3; ++k) {
      const int u = nb[t][k];
      const bool boundary = u < 0 || !kept_[u];
      if (!boundary && u < static_cast<int>(t)) continue;
      const int a = tri[t][(k + 1) % 3], b = tri[t][(k + 2) % 3];
      bars_.push_back({a, b});
      bar_on_boundary_.push_back(boundary);
      if (boundary) on_boundary_[a] = on_boundary_[b] = 1;
    }
  }
  // The size at each bar's midpoint. Evaluated here rather than every iteration: until
  // the next triangulation no point moves more than ttol h0, which changes a size by a
  // fraction ttol x (size gradient) of itself, about 1 %, and the size field (many
  // curved fibres, user expressions) is the costliest part of an iteration.
  // With absolute sizes (the mesh stage's graded fields, many bars per point), a bar
  // takes the mean of its ends' sizes, and the fixed points' sizes are kept.
  bar_size_.resize(bars_.size());
  if (pb_.absolute_size) {
    const std::size_t known = point_size_.size() >= nfix_ ? nfix_ : 0;
    point_size_.resize(p_.size());
    size_->eval(std::span<const Vec2>(p_).subspan(known), std::span<double>(point_size_).subspan(known));
    for (std::size_t e = 0; e < bars_.size(); ++e)
      bar_size_[e] = 0.5 * (point_size_[bars_[e][0]] + point_size_[bars_[e][1]]);
  } else {
    mid_.resize(bars_.size());
    for (std::size_t e = 0; e < bars_.size(); ++e) mid_[e] = 0.5 * (p_[bars_[e][0]] + p_[bars_[e][1]]);
    size_->eval(mid_, bar_size_);
  }
  sum_size2_ = 0.0;
  for (double h : bar_size_) sum_size2_ += h * h;
  pold_ = p_;
  ++stats_.retriangulations;
  stats_.triangulation_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

// Step 3: bar lengths and the lengths they want (eq. 2.9), and the repulsive forces (eq. 2.6).
void Engine::bar_forces() {
  const std::size_t nb = bars_.size();
  len_.resize(nb);
  auto length2 = [&](std::size_t e) { return norm2(p_[bars_[e][0]] - p_[bars_[e][1]]); };
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;  // four chains, so the additions overlap
  std::size_t e = 0;
  for (; e + 4 <= nb; e += 4) {
    const double a = length2(e), b = length2(e + 1), c = length2(e + 2), d = length2(e + 3);
    s0 += a, s1 += b, s2 += c, s3 += d;
    len_[e] = std::sqrt(a), len_[e + 1] = std::sqrt(b), len_[e + 2] = std::sqrt(c), len_[e + 3] = std::sqrt(d);
  }
  for (; e < nb; ++e) {
    const double a = length2(e);
    s0 += a;
    len_[e] = std::sqrt(a);
  }
  const double sum_l2 = (s0 + s1) + (s2 + s3);
  len0_scale_ = sum_size2_ > 0.0 ? opt_.fscale * std::sqrt(sum_l2 / sum_size2_) : 0.0;

  force_.assign(p_.size(), Vec2{});
  for (std::size_t e = 0; e < nb; ++e) {
    const double l = len_[e], l0 = len0_scale_ * bar_size_[e];
    if (l >= l0 || l == 0.0) continue;
    const int i = bars_[e][0], j = bars_[e][1];
    const Vec2 f = ((l0 - l) / l) * (p_[i] - p_[j]);
    force_[i] += f;
    force_[j] -= f;
  }
}

// Density control. Removes the free end points of bars shorter than half their wanted
// length (as DistMesh does), and, beyond the thesis, splits boundary and interface edges
// longer than 1.5 times their wanted length at their midpoint projected onto the curve:
// points cannot migrate along a curve past each other, so a gap there never closes.
bool Engine::density_control() {
  std::vector<char> drop(p_.size(), 0);
  std::vector<Vec2> added_boundary, added_interface;
  std::vector<int> near, near_interface;  // a point near each added one
  bool any = false;
  for (std::size_t e = 0; e < bars_.size(); ++e) {
    const int a = bars_[e][0], b = bars_[e][1];
    const double len0 = len0_scale_ * bar_size_[e];
    if (len0 > 2.0 * len_[e]) {
      for (int v : bars_[e])
        if (static_cast<std::size_t>(v) >= nfix_) drop[v] = any = true;
    } else if (opt_.split_long_edges && !fixed_boundary() && len_[e] > 1.5 * len0 / opt_.fscale) {
      const Vec2 mid = 0.5 * (p_[a] + p_[b]);
      if (bar_on_boundary_[e]) {
        added_boundary.push_back(project_to_zero(pb_.domain, mid, deps_, proj_tol_));
        near.push_back(a);
      } else if (on_interface_[a] && on_interface_[b] && pb_.interface) {
        added_interface.push_back(project_to_zero(*pb_.interface, mid, deps_, proj_tol_));
        near_interface.push_back(a);
      }
    }
  }
  any = any || !added_boundary.empty() || !added_interface.empty();
  if (!any) return false;
  const bool dropping = std::find(drop.begin(), drop.end(), 1) != drop.end();
  if (dropping) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < p_.size(); ++i)
      if (!drop[i]) {
        p_[out] = p_[i];
        on_interface_[out++] = on_interface_[i];
      }
    stats_.density_removed += p_.size() - out;
    points_changed();
    p_.resize(out);
    on_interface_.resize(out);
  }
  const std::size_t first = p_.size();
  for (const Vec2 q : added_boundary) p_.push_back(q), on_interface_.push_back(0);
  for (const Vec2 q : added_interface) p_.push_back(q), on_interface_.push_back(1);
  stats_.density_added += added_boundary.size() + added_interface.size();
  if (!dropping) {
    near.insert(near.end(), near_interface.begin(), near_interface.end());
    points_appended(first, near);
  }
  return true;
}

// Points `first` on were appended, each near the point `near` names: they are inserted
// into the live triangulation (brought up to the points' moves first), or the next
// triangulation starts afresh.
void Engine::points_appended(std::size_t first, const std::vector<int>& near) {
  dval_.resize(p_.size(), std::numeric_limits<double>::infinity());  // nothing known of the new ones
  dpos_.resize(p_.size());
  if (!live_valid_ || !restore_delaunay(live_, p_, &stats_.flips)) {  // (its hull kept whole)
    live_valid_ = false;
    return;
  }
  std::vector<int> triangle_at(first, -1);
  for (std::size_t t = 0; t < live_.triangles.size(); ++t)
    for (int v : live_.triangles[t]) triangle_at[v] = static_cast<int>(t);
  for (std::size_t k = first; k < p_.size(); ++k) {
    const int hint = triangle_at[near[k - first]];
    if (hint < 0 || !insert_point(live_, p_, static_cast<int>(k), hint)) {
      live_valid_ = false;
      return;
    }
    ++stats_.inserted;
  }
}

// Step 4: forward Euler (eq. 2.12); fixed points do not move.
void Engine::move_points() {
  for (std::size_t i = nfix_; i < p_.size(); ++i) p_[i] += opt_.dt * force_[i];
}

// Algorithm 3's choice for a bar crossing the interface: the end nearer to it, unless
// that end is fixed; -1 when both are.
int Engine::interface_mover(int a, int b, const std::vector<double>& di) const {
  const int k = std::abs(di[a]) <= std::abs(di[b]) ? a : b;
  if (static_cast<std::size_t>(k) >= nfix_) return k;
  const int other = k == a ? b : a;
  return static_cast<std::size_t>(other) >= nfix_ ? other : -1;
}

// Algorithm 3: for each bar whose ends lie on opposite sides of dI = 0, the end nearer
// to the interface is projected onto it. Beyond the thesis, a point once on the
// interface stays there: it is projected back after every move, so it slides along the
// interface instead of leaving it and being caught again.
void Engine::follow_interface() {
  const DistanceFunction& di = *pb_.interface;
  di_.resize(p_.size());
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (on_interface_[i] && i >= nfix_) p_[i] = project_to_zero(di, p_[i], deps_, proj_tol_);
    di_[i] = on_interface_[i] ? 0.0 : di(p_[i]);
  }
  for (const auto& bar : bars_) {
    const int a = bar[0], b = bar[1];
    if (!((di_[a] > 0.0 && di_[b] < 0.0) || (di_[a] < 0.0 && di_[b] > 0.0))) continue;
    const int k = interface_mover(a, b, di_);
    if (k < 0) continue;
    p_[k] = project_to_zero(di, p_[k], deps_, proj_tol_);
    di_[k] = 0.0;
    on_interface_[k] = 1;
  }
}

// Step 5: points that left the domain are projected back onto its boundary (eq. 2.13).
void Engine::project_boundary() {
  d_.resize(p_.size());
  if (dval_.size() != p_.size()) {  // points were added or removed: nothing cached
    dval_.assign(p_.size(), std::numeric_limits<double>::infinity());
    dpos_ = p_;
  }
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (i < nfix_ && std::isfinite(dval_[i])) {  // fixed points never move
      d_[i] = dval_[i];
      continue;
    }
    // d is 1-Lipschitz: a point that was deep inside and moved little since is still
    // inside, and its bound is enough for everything below.
    const double deep = geps_ + (fixed_boundary() ? (i < point_size_.size() ? point_size_[i] : h0_) / 3.0 : 0.0);
    const double bound = dval_[i] + norm(p_[i] - dpos_[i]);
    if (bound < -deep) {
      d_[i] = bound;
      continue;
    }
    d_[i] = pb_.domain(p_[i]);
    dval_[i] = d_[i];
    dpos_[i] = p_[i];
    if (i < nfix_) continue;
    if (!fixed_boundary()) {
      if (d_[i] > 0.0) {
        p_[i] = project_to_zero(pb_.domain, p_[i], deps_, proj_tol_);
        dval_[i] = std::numeric_limits<double>::infinity();  // on the boundary now: check again
      }
      continue;
    }
    // Never onto the boundary between two fixed seeds: back inside, half the local size
    // from it, along the distance gradient.
    const double margin = 0.5 * (i < point_size_.size() ? point_size_[i] : (*size_)(p_[i]));
    const bool pulled = d_[i] > -margin;
    for (int step = 0; step < 4 && d_[i] > -margin; ++step) {
      const Vec2 g = numerical_gradient(pb_.domain, p_[i], d_[i], deps_);
      const double g2 = norm2(g);
      if (!(g2 > 0.0)) break;
      p_[i] -= ((d_[i] + margin) / g2) * g;
      d_[i] = pb_.domain(p_[i]);
    }
    dval_[i] = d_[i];
    dpos_[i] = p_[i];
    // Held off the boundary, it feels the boundary's reaction like a projected point
    // and is not judged for convergence (d = 0 marks it, as on the boundary).
    if (pulled) d_[i] = 0.0;
  }
}

// In units of h0; with a graded absolute size, each point's move relative to its own size.
double Engine::max_move_since_triangulation() const {
  double moved2 = 0.0;
  const bool graded = pb_.absolute_size && point_size_.size() == p_.size();
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const double scale = graded ? point_size_[i] / h0_ : 1.0;
    moved2 = std::max(moved2, norm2(p_[i] - pold_[i]) / (scale * scale));
  }
  return std::sqrt(moved2);
}

// After the last triangulation: triangles whose corners lie on opposite sides of the
// interface get the Algorithm 3 treatment on their crossing edges, and the mesh is
// triangulated again, until none is left (or the pass limit). Returns how many remain.
std::size_t Engine::repair_interface() {
  const DistanceFunction& di = *pb_.interface;
  for (int pass = 0;; ++pass) {
    di_.resize(p_.size());
    for (std::size_t i = 0; i < p_.size(); ++i) di_[i] = di(p_[i]);
    auto side = [&](int v) { return di_[v] > on_interface_tol_ ? 1 : (di_[v] < -on_interface_tol_ ? -1 : 0); };
    std::vector<int> movers;
    std::size_t straddling = 0;
    for (const auto& t : tris_) {
      int lo = 1, hi = -1;
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        lo = std::min(lo, side(a));
        hi = std::max(hi, side(a));
        if (side(a) * side(b) >= 0) continue;
        if (const int m = interface_mover(a, b, di_); m >= 0) movers.push_back(m);
      }
      straddling += (lo < 0 && hi > 0);
    }
    if (straddling == 0 || movers.empty() || pass == 20) return straddling;
    std::sort(movers.begin(), movers.end());
    movers.erase(std::unique(movers.begin(), movers.end()), movers.end());
    for (int m : movers) {
      p_[m] = project_to_zero(di, p_[m], deps_, proj_tol_);
      on_interface_[m] = 1;
    }
    ++stats_.interface_repairs;
    triangulate();
  }
}

// radius_ratio(), or -1 for an inverted or flat triangle.
double signed_quality(Vec2 a, Vec2 b, Vec2 c) { return signed_area2(a, b, c) <= 0.0 ? -1.0 : radius_ratio(a, b, c); }

// Local optimisation of the worst regions (of points `first` on): a free point with a
// triangle of quality below optimize_below moves along the gradient of the sum of -1/q
// over its triangles (which weighs the worst most), by a backtracking line search that
// never lowers their least quality nor inverts one.
// Points on the boundary or the interface move along it. The connectivity is kept, so
// the mesh stays valid.
void Engine::optimize_stars(std::size_t first) {
  // Vertex -> triangles, compressed.
  std::vector<int> start(p_.size() + 1, 0), star;
  for (const auto& t : tris_)
    for (int v : t) ++start[v + 1];
  for (std::size_t i = 0; i < p_.size(); ++i) start[i + 1] += start[i];
  star.resize(start.back());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int t = 0; t < static_cast<int>(tris_.size()); ++t)
    for (int v : tris_[t]) star[fill[v]++] = t;

  const std::vector<char>& on_interface = on_interface_;
  const double min_gain = 1e-5;  // summed quality: smaller gains are not worth a sweep

  auto star_quality = [&](std::size_t i, Vec2 x, double& qmin) {
    double sum = 0.0;
    qmin = 1.0;
    for (int k = start[i]; k < start[i + 1]; ++k) {
      const auto& t = tris_[star[k]];
      auto at = [&](int v) { return v == static_cast<int>(i) ? x : p_[v]; };
      const double q = signed_quality(at(t[0]), at(t[1]), at(t[2]));
      sum += q > 0.0 ? -1.0 / q : -1e30;
      qmin = std::min(qmin, q);
    }
    return sum;
  };

  // A point is looked at again only once it or a neighbour has moved: otherwise it would
  // find what it found before (the same sweeps, in less time).
  std::vector<char> dirty(p_.size(), 1);
  for (int sweep = 0; sweep < opt_.optimize_sweeps; ++sweep) {
    opt_.deadline.check("while optimising the mesh");
    int moved = 0;
    for (std::size_t i = std::max(first, nfix_); i < p_.size(); ++i) {
      if (!dirty[i] || start[i] == start[i + 1]) continue;
      dirty[i] = 0;
      if (on_boundary_[i] && on_interface[i]) continue;  // where the two curves meet
      double qmin0;
      const double f0 = star_quality(i, p_[i], qmin0);
      if (qmin0 >= opt_.optimize_below) continue;
      double len = std::numeric_limits<double>::infinity();  // shortest edge at i
      for (int k = start[i]; k < start[i + 1]; ++k)
        for (int v : tris_[star[k]])
          if (v != static_cast<int>(i)) len = std::min(len, norm(p_[v] - p_[i]));
      const double step = 1e-4 * len;
      double unused;
      Vec2 g{(star_quality(i, p_[i] + Vec2{step, 0.0}, unused) - f0) / step,
             (star_quality(i, p_[i] + Vec2{0.0, step}, unused) - f0) / step};
      const DistanceFunction* curve = on_boundary_[i] ? &pb_.domain : (on_interface[i] ? &*pb_.interface : nullptr);
      if (curve) {  // keep the tangential part
        const Vec2 n = numerical_gradient(*curve, p_[i], (*curve)(p_[i]), deps_);
        if (norm2(n) > 0.0) g -= (dot(g, n) / norm2(n)) * n;
      }
      const double gn = norm(g);
      if (!(gn > 0.0)) continue;
      for (double alpha = 0.2 * len; alpha > 1e-3 * len; alpha *= 0.5) {
        Vec2 x = p_[i] + (alpha / gn) * g;
        if (curve) x = project_to_zero(*curve, x, deps_, proj_tol_);
        double qmin1;
        const double f1 = star_quality(i, x, qmin1);
        if (!(f1 > f0 + min_gain && qmin1 > 0.0 && qmin1 >= std::min(qmin0, opt_.optimize_below))) continue;
        // A free point stays inside (with a fixed seeded boundary, a star that is not
        // inverted says so), and on its side of the interface.
        if (!fixed_boundary() && !on_boundary_[i] && pb_.domain(x) >= -geps_) continue;
        // With a seeded boundary, a point its star lets onto (or next to) a boundary
        // segment would be split off into a sliver by the next triangulation.
        if (fixed_boundary() && !(pb_.domain(x) < -kStarClearance * (*size_)(x))) continue;
        if (pb_.interface && !on_interface[i] && ((*pb_.interface)(x) < 0.0) != ((*pb_.interface)(p_[i]) < 0.0))
          continue;
        p_[i] = x;
        ++moved;
        for (int k = start[i]; k < start[i + 1]; ++k)
          for (int v : tris_[star[k]]) dirty[v] = 1;
        break;
      }
    }
    if (moved == 0) break;
  }
}

// The finish after the force iterations (fixed seeded boundary only): triangles below
// kMendBelow get Steiner points or lose crowding points; those still below kTryBelow get
// one trial point each. Each trial retriangulates the region, so they are bounded.
constexpr double kMendBelow = 0.7;
constexpr double kTryBelow = 0.6;
constexpr std::size_t kMaxTrials = 200;
// A Steiner point closer than this x the local size to the corners of its triangle only
// splits a sliver into slivers: none is added there.
constexpr double kSteinerClearance = 0.1;

// The forces only push: where they left a gap (at a wide corner between seeds, across a
// thin place) a triangle stays poor that no move of its points can mend, often with all
// three corners fixed seeds. A poor triangle gets a free point at its circumcentre (which
// the Delaunay property keeps clear of every other point) when that lies inside the
// domain, half its radius clear of the boundary; the next triangulation and optimisation
// make the new star good. Returns how many points were added.
std::size_t Engine::insert_steiner_points() {
  std::vector<Vec2> added;
  std::vector<int> near;
  for (const auto& t : tris_) {
    const Vec2 a = p_[t[0]], b = p_[t[1]], c = p_[t[2]];
    if (radius_ratio(a, b, c) >= kMendBelow) continue;
    const Vec2 ab = b - a, ac = c - a;
    const double den = 2.0 * cross(ab, ac);
    if (!(std::abs(den) > 0.0)) continue;
    const Vec2 centre = a + Vec2{ac.y * norm2(ab) - ab.y * norm2(ac), ab.x * norm2(ac) - ac.x * norm2(ab)} / den;
    const double r = norm(centre - a);
    if (!(pb_.domain(centre) < -0.5 * r)) continue;
    if (r < kSteinerClearance * (*size_)(centre)) continue;  // a sliver far below the size: a point there makes more
    added.push_back(centre);
    near.push_back(t[0]);
  }
  const std::size_t first = p_.size();
  for (const Vec2 q : added) p_.push_back(q), on_interface_.push_back(0);
  points_appended(first, near);
  return added.size();
}

// The least quality, and how far the poor triangles fall short of `target` (summed squares).
std::pair<double, double> Engine::shortfall(double target) const {
  double least = 1.0, sum = 0.0;
  for (const auto& t : tris_) {
    const double q = signed_quality(p_[t[0]], p_[t[1]], p_[t[2]]);
    least = std::min(least, q);
    if (q < target) sum += (target - q) * (target - q);
  }
  return {least, sum};
}

// A free corner of a poor triangle that crowds a small place (a grain piece a few sizes
// wide) is removed when the mesh without it is better. Returns how many were removed.
std::size_t Engine::remove_crowding_points() {
  // The free corners of poor triangles, the worst first when there are more than can be
  // tried; then by index.
  std::unordered_map<int, double> worst;
  for (const auto& t : tris_) {
    const double q = radius_ratio(p_[t[0]], p_[t[1]], p_[t[2]]);
    if (q >= kMendBelow) continue;
    for (int v : t)
      if (static_cast<std::size_t>(v) >= nfix_) {
        auto [it, fresh] = worst.try_emplace(v, q);
        if (!fresh) it->second = std::min(it->second, q);
      }
  }
  std::vector<std::pair<double, int>> by_quality;
  for (const auto& [v, q] : worst) by_quality.push_back({q, v});
  std::sort(by_quality.begin(), by_quality.end());
  if (by_quality.size() > kMaxTrials) by_quality.resize(kMaxTrials);
  std::vector<int> candidates;
  for (const auto& [q, v] : by_quality) candidates.push_back(v);
  std::sort(candidates.begin(), candidates.end());
  std::size_t removed = 0;
  auto best = shortfall(kMendBelow);
  // From the highest index down, so the indices still to try stay valid.
  for (auto it = candidates.rbegin(); it != candidates.rend(); ++it) {
    opt_.deadline.check("while removing crowding points");
    const auto v = static_cast<std::size_t>(*it);
    const Vec2 kept = p_[v];
    p_.erase(p_.begin() + static_cast<std::ptrdiff_t>(v));
    on_interface_.erase(on_interface_.begin() + static_cast<std::ptrdiff_t>(v));
    points_changed();
    triangulate();
    const auto now = shortfall(kMendBelow);
    if (now.first >= best.first && now.second < best.second) {
      best = now;
      ++removed;
      continue;
    }
    p_.insert(p_.begin() + static_cast<std::ptrdiff_t>(v), kept);
    on_interface_.insert(on_interface_.begin() + static_cast<std::ptrdiff_t>(v), 0);
    points_changed();
  }
  triangulate();
  return removed;
}

// Poor triangles left after insertion and removal (in a grain piece a few sizes wide,
// where a circumcentre falls too near the boundary) are tried one by one: a free point
// at the middle of the triangle and its neighbours, optimised in its star, is kept when
// the mesh is better with it. Returns how many were kept.
std::size_t Engine::try_steiner_points() {
  std::vector<Vec2> candidates;
  {
    std::unordered_map<std::uint64_t, int> opposite;  // directed edge -> third vertex
    auto key = [](int a, int b) { return static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint32_t>(b); };
    for (const auto& t : tris_)
      for (int k = 0; k < 3; ++k) opposite[key(t[k], t[(k + 1) % 3])] = t[(k + 2) % 3];
    std::vector<std::pair<double, std::size_t>> poor;  // the worst first
    for (std::size_t k = 0; k < tris_.size(); ++k) {
      const auto& t = tris_[k];
      const double q = radius_ratio(p_[t[0]], p_[t[1]], p_[t[2]]);
      if (q < kTryBelow) poor.push_back({q, k});
    }
    std::sort(poor.begin(), poor.end());
    for (const auto& [q, k] : poor) {
      if (candidates.size() == kMaxTrials) break;
      const auto& t = tris_[k];
      Vec2 sum = p_[t[0]] + p_[t[1]] + p_[t[2]];
      int n = 3;
      for (int e = 0; e < 3; ++e) {
        const auto it = opposite.find(key(t[(e + 1) % 3], t[e]));
        if (it != opposite.end()) sum += p_[it->second], ++n;
      }
      const Vec2 x = sum / n;
      double nearest = std::numeric_limits<double>::infinity();
      for (int v : t) nearest = std::min(nearest, norm(p_[v] - x));
      if (pb_.domain(x) < -geps_ && nearest >= kSteinerClearance * (*size_)(x)) candidates.push_back(x);
    }
  }
  std::size_t kept = 0;
  auto best = shortfall(kMendBelow);
  for (const Vec2 x : candidates) {
    opt_.deadline.check("while trying Steiner points");
    p_.push_back(x);
    on_interface_.push_back(0);
    points_changed();
    triangulate();
    optimize_stars(p_.size() - 1);
    const auto now = shortfall(kMendBelow);
    if (now.first >= best.first && now.second < best.second) {
      best = now;
      ++kept;
      continue;
    }
    p_.pop_back();
    on_interface_.pop_back();
    points_changed();
  }
  triangulate();
  return kept;
}

// The final mesh: only points that some triangle uses, in their original order.
TriMesh Engine::compact() const {
  std::vector<int> new_id(p_.size(), -1);
  for (const auto& t : tris_)
    for (int v : t) new_id[v] = 0;
  TriMesh mesh;
  for (std::size_t i = 0; i < p_.size(); ++i)
    if (new_id[i] == 0) {
      new_id[i] = static_cast<int>(mesh.points.size());
      mesh.points.push_back(p_[i]);
    }
  mesh.triangles.reserve(tris_.size());
  for (const auto& t : tris_) mesh.triangles.push_back({new_id[t[0]], new_id[t[1]], new_id[t[2]]});
  mesh.region.assign(mesh.triangles.size(), 0);
  if (pb_.interface)
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      mesh.region[t] = (*pb_.interface)(triangle_centroid(mesh, static_cast<int>(t))) < 0.0 ? 1 : 0;
  return mesh;
}

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
    before_ = p_;
    move_points();
    if (pb_.interface) follow_interface();
    project_boundary();

    // Points on the boundary feel the boundary's reaction and never come to rest; the
    // others (interface points included) are judged by how far they actually moved.
    // With a graded absolute size, each point is judged against its own size.
    double max_move2 = 0.0;
    for (std::size_t i = nfix_; i < p_.size(); ++i) {
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

  DistMeshResult result{compact(), stats_};
  validate(result.mesh);
  result.stats.finish_seconds = since(finish);
  result.stats.seconds = since(start);
  return result;
}

}  // namespace

DistMeshResult distmesh(const DistMeshProblem& problem, const DistMeshOptions& options, Rng& rng) {
  check_parameters(problem, options);
  Engine engine(problem, options);
  return engine.run(rng);
}

}  // namespace grainmesh
