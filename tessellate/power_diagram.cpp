// The power diagram through CGAL's regular triangulation: the only file of this stage
// that includes CGAL. Periodicity comes from image copies of the seeds in a margin around
// the cell, which works for any W x H (CGAL's periodic triangulations want a square).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/spatial_grid.hpp"
#include "tessellate/torus.hpp"

namespace grainmesh {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb0 = CGAL::Regular_triangulation_vertex_base_2<K>;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<Corner, K, Vb0>;  // seed, image shift
using Fb = CGAL::Regular_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Regular = CGAL::Regular_triangulation_2<K, Tds>;
using WPoint = Regular::Weighted_point;

// A triangle of seeds on the torus: (seed, di, dj) of each corner relative to the first,
// rotated to the smallest such tuple, so every image of the triangle has one key.
using FaceKey = std::array<int, 7>;

struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::size_t h = 1469598103934665603ull;
    for (int x : k) h = (h ^ static_cast<std::size_t>(static_cast<unsigned>(x))) * 1099511628211ull;
    return h;
  }
};

FaceKey face_key(const std::array<Corner, 3>& c, int* first) {
  FaceKey best{};
  for (int r = 0; r < 3; ++r) {
    const Corner& a = c[r];
    const Corner& b = c[(r + 1) % 3];
    const Corner& d = c[(r + 2) % 3];
    const FaceKey key{a.v, b.v, b.i - a.i, b.j - a.j, d.v, d.i - a.i, d.j - a.j};
    if (r == 0 || key < best) {
      best = key;
      *first = r;
    }
  }
  return best;
}

// The point of equal power distance |x - p|^2 - w to three weighted points.
Vec2 power_centre(Vec2 p0, double w0, Vec2 p1, double w1, Vec2 p2, double w2) {
  const Vec2 a = p1 - p0;
  const Vec2 b = p2 - p0;
  const double ra = 0.5 * (norm2(a) - (w1 - w0));
  const double rb = 0.5 * (norm2(b) - (w2 - w0));
  const double det = cross(a, b);
  return p0 + Vec2{(ra * b.y - rb * a.y) / det, (a.x * rb - b.x * ra) / det};
}

struct Built {
  TorusGraph graph;
  bool margin_ok = true;
};

// The weighted points to triangulate: on a torus each seed's images within `margin` of
// the cell (Corner{seed, i, j}: shifted by (i W, j H)); in the plane the seeds and eight
// far points (Corner{n + k, 0, 0}, positions in `far`) with nothing to say inside the
// cell, so that every seed's cell is bounded.
std::vector<std::pair<WPoint, Corner>> weighted_points(const std::vector<Vec2>& seeds, const std::vector<double>& weights,
                                                       double W, double H, bool periodic, double margin,
                                                       std::vector<Vec2>& far) {
  const int n = static_cast<int>(seeds.size());
  std::vector<std::pair<WPoint, Corner>> points;
  const int ki = periodic ? static_cast<int>(std::ceil(margin / W)) : 0;
  const int kj = periodic ? static_cast<int>(std::ceil(margin / H)) : 0;
  for (int j = -kj; j <= kj; ++j)
    for (int i = -ki; i <= ki; ++i)
      for (int s = 0; s < n; ++s) {
        const Vec2 p{seeds[s].x + i * W, seeds[s].y + j * H};
        if (p.x < -margin || p.x > W + margin || p.y < -margin || p.y > H + margin) continue;
        points.push_back({WPoint(K::Point_2(p.x, p.y), weights[s]), Corner{s, i, j}});
      }
  if (!periodic) {
    const double r = 4.0 * std::hypot(W, H);
    for (int k = 0; k < 8; ++k) {
      const double a = 2.0 * M_PI * k / 8.0;
      const Vec2 p{0.5 * W + r * std::cos(a), 0.5 * H + r * std::sin(a)};
      far.push_back(p);
      points.push_back({WPoint(K::Point_2(p.x, p.y), 0.0), Corner{n + k, 0, 0}});
    }
  }
  return points;
}

Built build(const std::vector<Vec2>& seeds, const std::vector<double>& weights, double W, double H, bool periodic,
            double margin) {
  const int n = static_cast<int>(seeds.size());
  const double w_max = *std::max_element(weights.begin(), weights.end());
  std::vector<Vec2> dummies;
  const auto points = weighted_points(seeds, weights, W, H, periodic, margin, dummies);
  Regular rt;
  rt.insert(points.begin(), points.end());

  Built out;
  // Seeds along a line: no image in the margin closes some cell yet (the triangulation is
  // flat, or a cell unbounded). A periodic cell widens its margin; a plane one has far
  // points all around, so this cannot happen there.
  auto too_narrow = [&](const char* what) {
    if (!periodic) throw GeometryError(std::string("power diagram: ") + what + " (internal error)");
    out.margin_ok = false;
    return out;
  };
  if (rt.dimension() < 2) return too_narrow("the seeds and their far points are collinear");

  std::vector<Regular::Vertex_handle> central(n);
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v)
    if (v->info().i == 0 && v->info().j == 0 && v->info().v < n) central[v->info().v] = v;

  TorusGraph& g = out.graph;
  g.width = W;
  g.height = H;
  g.periodic = periodic;
  g.seeds = seeds;
  g.weights = weights;
  g.rings.assign(n, {});
  std::unordered_map<FaceKey, int, FaceKeyHash> ids;
  auto seed_point = [&](int s) { return s < n ? seeds[s] : dummies[s - n]; };
  auto seed_weight = [&](int s) { return s < n ? weights[s] : 0.0; };
  for (int s = 0; s < n; ++s) {
    if (central[s] == Regular::Vertex_handle()) continue;  // hidden by heavier neighbours
    auto fc = rt.incident_faces(central[s]);
    const auto done = fc;
    do {
      if (rt.is_infinite(fc)) return too_narrow("a seed's cell is unbounded");
      const std::array<Corner, 3> c{fc->vertex(0)->info(), fc->vertex(1)->info(), fc->vertex(2)->info()};
      int r = 0;
      const FaceKey key = face_key(c, &r);
      const Corner& f = c[r];
      auto [it, fresh] = ids.try_emplace(key, static_cast<int>(g.vertices.size()));
      // The centre from the canonical triangle, so every image computes the same bits.
      const Vec2 q1{key[2] * W, key[3] * H};
      const Vec2 q2{key[5] * W, key[6] * H};
      const Vec2 centre = power_centre(seed_point(key[0]), seed_weight(key[0]), seed_point(key[1]) + q1,
                                       seed_weight(key[1]), seed_point(key[4]) + q2, seed_weight(key[4]));
      if (!is_finite(centre)) throw GeometryError("power diagram: degenerate seed triangle (coincident seeds?)");
      Corner k{};
      const Vec2 reduced = periodic ? reduce_periodic(centre, W, H, &k) : centre;
      if (fresh) g.vertices.push_back(reduced);
      g.rings[s].push_back(Corner{it->second, k.i + f.i, k.j + f.j});
      if (periodic) {
        // Would a seed beyond the margin cut this corner off? Its power distance from the
        // centre is at least dist^2 - w_max, the face's own is |c - p|^2 - w.
        const Vec2 at = centre + Vec2{f.i * W, f.j * H};
        const double rho2 = norm2(at - seeds[s]) - weights[s];
        const double dist = std::min({at.x + margin, W + margin - at.x, at.y + margin, H + margin - at.y});
        if (dist <= 0.0 || dist * dist < rho2 + w_max) out.margin_ok = false;
      }
    } while (++fc != done);
  }
  return out;
}

// Merges vertices closer than d (images of one power centre computed from different
// triangles of cocircular seeds) and drops the repeated corners this leaves.
void merge_close_vertices(TorusGraph& g, double d) {
  const int nv = static_cast<int>(g.vertices.size());
  std::vector<int> rep(nv);
  std::iota(rep.begin(), rep.end(), 0);
  std::vector<Corner> delta(nv);
  // On a torus the cells wrap: nx x ny of them, at least d wide.
  const std::int64_t nx = g.periodic ? std::max<std::int64_t>(1, static_cast<std::int64_t>(g.width / d)) : 0;
  const std::int64_t ny = g.periodic ? std::max<std::int64_t>(1, static_cast<std::int64_t>(g.height / d)) : 0;
  auto wrap = [](std::int64_t a, std::int64_t m) { return m > 0 ? ((a % m) + m) % m : a; };
  HashGrid<int> grid(d);
  for (int v = 0; v < nv; ++v) {
    const std::int64_t cx = grid.cell_of(g.vertices[v].x), cy = grid.cell_of(g.vertices[v].y);
    for (std::int64_t dy = -1; dy <= 1 && rep[v] == v; ++dy)
      for (std::int64_t dx = -1; dx <= 1 && rep[v] == v; ++dx) {
        const std::vector<int>* cell = grid.at(wrap(cx + dx, nx), wrap(cy + dy, ny));
        if (!cell) continue;
        for (int u : *cell) {
          Vec2 e = g.vertices[v] - g.vertices[u];
          Corner k{};
          if (g.periodic) {
            k.i = static_cast<int>(std::lround(e.x / g.width));
            k.j = static_cast<int>(std::lround(e.y / g.height));
            e -= Vec2{k.i * g.width, k.j * g.height};
          }
          if (norm(e) < d) {
            rep[v] = u;
            delta[v] = k;
            break;
          }
        }
      }
    if (rep[v] == v) grid.add(wrap(cx, nx), wrap(cy, ny), v);
  }
  std::vector<int> new_id(nv, -1);
  std::vector<Vec2> kept;
  for (auto& ring : g.rings) {
    std::vector<Corner> out;
    for (Corner c : ring) {
      if (rep[c.v] != c.v) c = Corner{rep[c.v], c.i + delta[c.v].i, c.j + delta[c.v].j};
      if (!out.empty() && out.back() == c) continue;
      out.push_back(c);
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    if (out.size() < 3) out.clear();
    for (Corner& c : out) {
      if (new_id[c.v] < 0) {
        new_id[c.v] = static_cast<int>(kept.size());
        kept.push_back(g.vertices[c.v]);
      }
      c.v = new_id[c.v];
    }
    ring = std::move(out);
  }
  g.vertices = std::move(kept);
}

}  // namespace

TorusGraph power_diagram(const std::vector<Vec2>& seeds, const std::vector<double>& weights, double width,
                         double height, bool periodic, double merge_distance) {
  if (seeds.empty()) throw GeometryError("power diagram: no seeds");
  const double spacing = std::sqrt(width * height / static_cast<double>(seeds.size()));
  const double w_max = *std::max_element(weights.begin(), weights.end());
  double margin = 2.5 * spacing + std::sqrt(std::max(0.0, w_max));
  try {
    for (int attempt = 0; attempt < 12; ++attempt, margin *= 2.0) {
      Built b = build(seeds, weights, width, height, periodic, margin);
      if (!b.margin_ok) continue;
      merge_close_vertices(b.graph, merge_distance);
      return std::move(b.graph);
    }
  } catch (const CGAL::Failure_exception& e) {
    throw GeometryError(std::string("power diagram: CGAL failed: ") + e.what());
  }
  throw GeometryError("power diagram: the periodic images never sufficed (internal error)");
}

}  // namespace grainmesh
