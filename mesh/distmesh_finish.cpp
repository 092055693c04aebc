#include "mesh/distmesh_engine.hpp"

#include <algorithm>
#include <unordered_map>

#include "mesh/quality.hpp"

namespace grainmesh::distmesh_detail {

namespace {

// radius_ratio(), or -1 for an inverted or flat triangle.
double signed_quality(Vec2 a, Vec2 b, Vec2 c) { return signed_area2(a, b, c) <= 0.0 ? -1.0 : radius_ratio(a, b, c); }

}  // namespace

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
    for (std::size_t i = std::max(first, p_.fixed()); i < p_.size(); ++i) {
      if (!dirty[i] || start[i] == start[i + 1]) continue;
      dirty[i] = 0;
      if (on_boundary_[i] && p_.on_interface(i)) continue;  // where the two curves meet
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
      const DistanceFunction* curve = on_boundary_[i] ? &pb_.domain : (p_.on_interface(i) ? &*pb_.interface : nullptr);
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
        if (pb_.interface && !p_.on_interface(i) && ((*pb_.interface)(x) < 0.0) != ((*pb_.interface)(p_[i]) < 0.0))
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
  for (const Vec2 q : added) p_.add(q);
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
      if (static_cast<std::size_t>(v) >= p_.fixed()) {
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
    p_.erase(v);
    points_changed();
    triangulate();
    const auto now = shortfall(kMendBelow);
    if (now.first >= best.first && now.second < best.second) {
      best = now;
      ++removed;
      continue;
    }
    p_.insert(v, kept);
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
    p_.add(x);
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
  return mesh;
}

std::vector<int> Engine::interface_phase(const TriMesh& mesh) const {
  std::vector<int> phase(mesh.triangles.size(), 0);
  if (pb_.interface)
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      phase[t] = (*pb_.interface)(triangle_centroid(mesh, static_cast<int>(t))) < 0.0 ? 1 : 0;
  return phase;
}


}  // namespace grainmesh::distmesh_detail
