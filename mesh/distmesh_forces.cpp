#include "mesh/distmesh_engine.hpp"

#include <algorithm>

#include "common/errors.hpp"

namespace grainmesh::distmesh_detail {

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
  repaired = repaired && restore_delaunay(live_, p_.positions(), &stats_.flips, !fixed_boundary());
  if (!repaired) {
    live_ = fixed_boundary() ? constrained_delaunay_triangulation(p_.positions(), pb_.constraints) : delaunay_triangulation(p_.positions());
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
    const std::size_t known = point_size_.size() >= p_.fixed() ? p_.fixed() : 0;
    point_size_.resize(p_.size());
    size_->eval(std::span<const Vec2>(p_.positions()).subspan(known), std::span<double>(point_size_).subspan(known));
    for (std::size_t e = 0; e < bars_.size(); ++e)
      bar_size_[e] = 0.5 * (point_size_[bars_[e][0]] + point_size_[bars_[e][1]]);
  } else {
    mid_.resize(bars_.size());
    for (std::size_t e = 0; e < bars_.size(); ++e) mid_[e] = 0.5 * (p_[bars_[e][0]] + p_[bars_[e][1]]);
    size_->eval(mid_, bar_size_);
  }
  sum_size2_ = 0.0;
  for (double h : bar_size_) sum_size2_ += h * h;
  pold_ = p_.positions();
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
        if (static_cast<std::size_t>(v) >= p_.fixed()) drop[v] = any = true;
    } else if (opt_.split_long_edges && !fixed_boundary() && len_[e] > 1.5 * len0 / opt_.fscale) {
      const Vec2 mid = 0.5 * (p_[a] + p_[b]);
      if (bar_on_boundary_[e]) {
        added_boundary.push_back(project_to_zero(pb_.domain, mid, deps_, proj_tol_));
        near.push_back(a);
      } else if (p_.on_interface(a) && p_.on_interface(b) && pb_.interface) {
        added_interface.push_back(project_to_zero(*pb_.interface, mid, deps_, proj_tol_));
        near_interface.push_back(a);
      }
    }
  }
  any = any || !added_boundary.empty() || !added_interface.empty();
  if (!any) return false;
  const bool dropping = std::find(drop.begin(), drop.end(), 1) != drop.end();
  if (dropping) {
    stats_.density_removed += p_.remove(drop);
    points_changed();
  }
  const std::size_t first = p_.size();
  for (const Vec2 q : added_boundary) p_.add(q);
  for (const Vec2 q : added_interface) p_.add(q, true);
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
  if (!live_valid_ || !restore_delaunay(live_, p_.positions(), &stats_.flips)) {  // (its hull kept whole)
    live_valid_ = false;
    return;
  }
  std::vector<int> triangle_at(first, -1);
  for (std::size_t t = 0; t < live_.triangles.size(); ++t)
    for (int v : live_.triangles[t]) triangle_at[v] = static_cast<int>(t);
  for (std::size_t k = first; k < p_.size(); ++k) {
    const int hint = triangle_at[near[k - first]];
    if (hint < 0 || !insert_point(live_, p_.positions(), static_cast<int>(k), hint)) {
      live_valid_ = false;
      return;
    }
    ++stats_.inserted;
  }
}

// Step 4: forward Euler (eq. 2.12); fixed points do not move.
void Engine::move_points() {
  for (std::size_t i = p_.fixed(); i < p_.size(); ++i) p_[i] += opt_.dt * force_[i];
}

// Step 5: points that left the domain are projected back onto its boundary (eq. 2.13).
void Engine::project_boundary() {
  d_.resize(p_.size());
  if (dval_.size() != p_.size()) {  // points were added or removed: nothing cached
    dval_.assign(p_.size(), std::numeric_limits<double>::infinity());
    dpos_ = p_.positions();
  }
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (i < p_.fixed() && std::isfinite(dval_[i])) {  // fixed points never move
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
    if (i < p_.fixed()) continue;
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


}  // namespace grainmesh::distmesh_detail
