#include "mesh/grain_mesh.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/point_key.hpp"
#include "common/random.hpp"
#include "mesh/polygon.hpp"

namespace grainmesh {

double region_size(const GrainMeshOptions& o, int phase) {
  if (phase >= 0 && static_cast<std::size_t>(phase) < o.phase_size.size() && o.phase_size[phase] > 0.0)
    return o.phase_size[phase];
  return o.size;
}

namespace {

std::int64_t edge_key(int a, int b) { return static_cast<std::int64_t>(std::min(a, b)) << 32 | std::max(a, b); }

// Edge id by its two end vertices, either order.
std::unordered_map<std::int64_t, int> edge_index(const Tessellation& t) {
  std::unordered_map<std::int64_t, int> index;
  for (std::size_t e = 0; e < t.edges.size(); ++e) index[edge_key(t.edges[e].v0, t.edges[e].v1)] = static_cast<int>(e);
  return index;
}

CellSide edge_side(const Tessellation& t, const TessEdge& e) { return cell_side(t, t.vertices[e.v0], t.vertices[e.v1]); }

struct RegionResult {
  std::vector<Vec2> interior;                  // new points, in the engine's order
  std::vector<std::array<int, 3>> triangles;   // ids: >= 0 global, < 0 -(1 + interior index)
  int iterations = 0;
  bool converged = true;
};

// Points strictly between a and b, evenly in the integral of 1/h.
std::vector<Vec2> seed_segment(Vec2 a, Vec2 b, const FeatureSize& size, double cap) {
  const auto h = [&](Vec2 x) { return size.at(x, cap); };
  const double len = norm(b - a);
  double finest = cap;
  constexpr int kProbe = 32;
  for (int k = 0; k <= kProbe; ++k) finest = std::min(finest, h(a + (static_cast<double>(k) / kProbe) * (b - a)));
  const int m = std::clamp(static_cast<int>(std::ceil(4.0 * len / finest)), 16, 1 << 20);
  std::vector<double> cum(m + 1, 0.0);  // integral of 1/h up to sample k
  double prev = 1.0 / h(a);
  for (int k = 1; k <= m; ++k) {
    const double next = 1.0 / h(a + (static_cast<double>(k) / m) * (b - a));
    cum[k] = cum[k - 1] + 0.5 * (prev + next) * len / m;
    prev = next;
  }
  if (!(cum[m] < kMaxMeshPoints))
    throw ConfigError("mesh: a grain boundary " + to_text(len) + " long would get " + to_text(cum[m]) +
                      " nodes (size down to " + to_text(finest) + "): raise the element size");
  const int n = std::max(1, static_cast<int>(std::lround(cum[m])));
  std::vector<Vec2> out;
  int k = 0;
  for (int q = 1; q < n; ++q) {
    const double target = cum[m] * q / n;
    while (cum[k + 1] < target) ++k;
    const double s = (k + (target - cum[k]) / (cum[k + 1] - cum[k])) / m;
    out.push_back(a + s * (b - a));
  }
  return out;
}

// A region corner sharper than this gets its first seeds on both edges at the same
// distance: the triangle in the corner is then isosceles, the best it can be.
constexpr double kSharpCorner = 60.0 * std::numbers::pi / 180.0;

// Of a sharp corner's two edges, the one whose first seed lies farther from the corner
// gets its seeds drawn in until that one lies at the other's distance. Edges on the
// cell's sides keep their seeds (periodic partners copy them); sharp corners never lie
// there (the window keeps side crossings wide), nor on holes (a region's corners at a
// hole are reflex or wide).
void equal_legs_at_sharp_corners(const Tessellation& t, const std::unordered_map<std::int64_t, int>& index,
                                 const std::vector<int>& partner, std::vector<std::vector<Vec2>>& seeds) {
  std::vector<char> on_side(seeds.size(), 0);
  for (std::size_t e = 0; e < seeds.size(); ++e)
    if (partner[e] >= 0) on_side[e] = on_side[partner[e]] = 1;
  auto usable = [&](int e) { return !seeds[e].empty() && !on_side[e]; };
  // Distance of edge e's seed nearest to its end v.
  auto first_distance = [&](int e, int v) {
    return norm((t.edges[e].v0 == v ? seeds[e].front() : seeds[e].back()) - t.vertices[v]);
  };
  // Moves edge e's seeds so that the one nearest v lies `d` from it, the others stretched
  // along (each keeps its share of the rest of the edge): no one gap takes the change.
  auto pull_in = [&](int e, int v, double d) {
    const Vec2 at = t.vertices[v], far = t.vertices[t.edges[e].v0 == v ? t.edges[e].v1 : t.edges[e].v0];
    const double len = norm(far - at), d0 = first_distance(e, v);
    for (Vec2& p : seeds[e]) {
      const double u = norm(p - at);
      p = at + ((d + (u - d0) * (len - d) / (len - d0)) / len) * (far - at);
    }
  };
  for (const Region& region : t.regions) {
    const auto& ring = region.rings.front();
    for (std::size_t k = 0, n = ring.size(); k < n; ++k) {
      const int prev = ring[(k + n - 1) % n], v = ring[k], next = ring[(k + 1) % n];
      const Vec2 at = t.vertices[v], a = t.vertices[prev] - at, b = t.vertices[next] - at;
      const double angle = std::atan2(std::abs(cross(a, b)), dot(a, b));
      if (!(angle < kSharpCorner) || cross(b, a) <= 0.0) continue;  // not a sharp convex corner
      const auto ea = index.find(edge_key(prev, v)), eb = index.find(edge_key(v, next));
      if (ea == index.end() || eb == index.end()) continue;
      if (!usable(ea->second) || !usable(eb->second)) continue;
      const double da = first_distance(ea->second, v), db = first_distance(eb->second, v);
      if (da > db) pull_in(ea->second, v, db);
      else if (db > da) pull_in(eb->second, v, da);
    }
  }
}

}  // namespace

FeatureSize tessellation_size(const Tessellation& t, const GrainMeshOptions& o) {
  double largest = o.size, finest = o.size;
  std::vector<double> phase_size;
  for (std::size_t p = 0; p < t.phases.size(); ++p) {
    phase_size.push_back(region_size(o, static_cast<int>(p)));
    largest = std::max(largest, phase_size.back());
    finest = std::min(finest, phase_size.back());
  }
  std::vector<SizeSource> sources;
  if (o.feature_size) sources = feature_sources(t, 0.5 * finest, largest, o.feature_fraction, o.gradient);
  const auto graded = grading_sources(t, o.boundary_size, o.junction_size, phase_size, largest, o.gradient);
  sources.insert(sources.end(), graded.begin(), graded.end());
  return FeatureSize(std::move(sources), largest, o.gradient);
}

std::vector<std::vector<Vec2>> seed_edges(const Tessellation& t, const GrainMeshOptions& o, const FeatureSize& size) {
  const std::size_t ne = t.edges.size();
  std::vector<double> h(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    double s = 1e300;
    for (int r : {t.edges[e].left, t.edges[e].right})
      if (r >= 0) s = std::min(s, region_size(o, t.regions[r].phase));
    h[e] = s;
  }
  const auto index = edge_index(t);
  // Periodic sides: right/top edge -> its partner on the left/bottom, sharing one size.
  std::vector<int> partner(ne, -1);
  if (t.periodic) {
    std::unordered_map<int, int> to_left, to_bottom;  // right -> left, top -> bottom vertex
    for (const auto& [l, r] : t.partners_x) to_left[r] = l;
    for (const auto& [b, u] : t.partners_y) to_bottom[u] = b;
    for (std::size_t e = 0; e < ne; ++e) {
      const CellSide side = edge_side(t, t.edges[e]);
      if (side != kRight && side != kTop) continue;
      const auto& to_low = side == kRight ? to_left : to_bottom;
      const auto a = to_low.find(t.edges[e].v0), b = to_low.find(t.edges[e].v1);
      const auto it = (a != to_low.end() && b != to_low.end()) ? index.find(edge_key(a->second, b->second)) : index.end();
      if (it == index.end()) throw GeometryError("mesh: a side edge of the periodic cell has no partner edge");
      partner[e] = it->second;
      h[it->second] = h[e] = std::min(h[e], h[it->second]);
    }
  }
  std::vector<std::vector<Vec2>> seeds(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    if (partner[e] >= 0) continue;
    const Vec2 a = t.vertices[t.edges[e].v0], b = t.vertices[t.edges[e].v1];
    if (e % 256 == 0) o.distmesh.deadline.check("while seeding grain boundaries");
    seeds[e] = seed_segment(a, b, size, h[e]);
  }
  equal_legs_at_sharp_corners(t, index, partner, seeds);
  for (std::size_t e = 0; e < ne; ++e) {
    if (partner[e] < 0) continue;
    const TessEdge& low = t.edges[partner[e]];
    const bool right = edge_side(t, t.edges[e]) == kRight;
    std::vector<Vec2> s = seeds[partner[e]];
    for (Vec2& p : s) (right ? p.x : p.y) = right ? t.width : t.height;
    // Same direction when v0 of this edge is the partner of low.v0.
    const Vec2 v0 = t.vertices[t.edges[e].v0], l0 = t.vertices[low.v0];
    if ((right ? v0.y != l0.y : v0.x != l0.x)) std::reverse(s.begin(), s.end());
    seeds[e] = std::move(s);
  }
  return seeds;
}

GrainMesh mesh_tessellation(const Tessellation& t, const GrainMeshOptions& o) {
  if (!(o.size > 0.0) || !std::isfinite(o.size)) throw ConfigError("mesh: the element size must be positive");
  for (const auto& [value, name] : {std::pair{o.boundary_size, "boundary size"}, {o.junction_size, "junction size"}})
    if (!(value >= 0.0) || !std::isfinite(value)) throw ConfigError(std::string("mesh: the ") + name + " must be >= 0");
  if (!(o.gradient > 0.0) || !std::isfinite(o.gradient)) throw ConfigError("mesh: the size gradient must be positive");
  const auto start = std::chrono::steady_clock::now();
  const auto size = std::make_shared<const FeatureSize>(tessellation_size(t, o));
  const auto seeds = seed_edges(t, o, *size);
  GrainMesh out;
  auto since = [](auto t0) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  out.sizing_seconds = since(start);
  // Global nodes: tessellation vertices, then edge seeds, then each region's interior.
  std::vector<Vec2>& pts = out.mesh.points;
  pts = t.vertices;
  std::vector<int> first_seed(t.edges.size());
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    first_seed[e] = static_cast<int>(pts.size());
    pts.insert(pts.end(), seeds[e].begin(), seeds[e].end());
  }
  const auto index = edge_index(t);

  const int nr = static_cast<int>(t.regions.size());
  std::vector<RegionResult> results(nr);
  auto mesh_region = [&](int r) {
    const Region& region = t.regions[r];
    const double h = region_size(o, region.phase);
    std::vector<std::vector<Vec2>> rings;
    std::vector<int> ids;  // global id of each fixed point
    std::vector<Vec2> fixed;
    std::vector<std::array<int, 2>> constraints;
    for (const auto& ring : region.rings) {
      std::vector<Vec2> loop;
      const int base = static_cast<int>(ids.size());
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const int a = ring[k], b = ring[(k + 1) % ring.size()];
        loop.push_back(t.vertices[a]);
        ids.push_back(a);
        const auto it = index.find(edge_key(a, b));
        if (it == index.end()) throw GeometryError("mesh: region " + std::to_string(r) + " has a side that is no edge");
        const int e = it->second;
        const int n = static_cast<int>(seeds[e].size());
        const bool forward = t.edges[e].v0 == a;
        for (int q = 0; q < n; ++q) {
          const int s = forward ? q : n - 1 - q;
          loop.push_back(seeds[e][s]);
          ids.push_back(first_seed[e] + s);
        }
      }
      const int count = static_cast<int>(loop.size());
      for (int k = 0; k < count; ++k) constraints.push_back({base + k, base + (k + 1) % count});
      fixed.insert(fixed.end(), loop.begin(), loop.end());
      rings.push_back(std::move(loop));
    }
    const DistanceFunction domain = polygon(rings);
    // The finest size is on the boundary, where the features are; a margin for the
    // stretches between seeds.
    double h0 = h;
    for (const Vec2 p : fixed) h0 = std::min(h0, 0.9 * size->at(p, h));
    const DistMeshProblem pb{.domain = domain, .size = capped_size(size, h), .h0 = h0, .bbox = domain.bounds(),
                             .fixed = std::move(fixed), .interface = {}, .constraints = std::move(constraints),
                             .absolute_size = true};
    // Fixed points come back with their bits: that is how the engine's output finds them.
    PointMap<int> fixed_id;
    for (std::size_t k = 0; k < pb.fixed.size(); ++k) fixed_id.emplace(point_key(pb.fixed[k]), ids[k]);
    Rng rng(derived_seed(o.seed, static_cast<std::uint64_t>(r)));  // whichever thread meshes it
    const DistMeshResult res = distmesh(pb, o.distmesh, rng);
    RegionResult& rr = results[r];
    std::vector<int> local(res.mesh.points.size());
    for (std::size_t i = 0; i < res.mesh.points.size(); ++i) {
      const auto it = fixed_id.find(point_key(res.mesh.points[i]));
      if (it != fixed_id.end()) {
        local[i] = it->second;
      } else {
        local[i] = -1 - static_cast<int>(rr.interior.size());
        rr.interior.push_back(res.mesh.points[i]);
      }
    }
    for (const auto& tri : res.mesh.triangles) rr.triangles.push_back({local[tri[0]], local[tri[1]], local[tri[2]]});
    rr.iterations = res.stats.iterations;
    rr.converged = res.stats.converged;
  };
  const auto regions_start = std::chrono::steady_clock::now();
  tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
  std::mutex progress_mutex;
  int regions_done = 0;
  arena.execute([&] {
    tbb::parallel_for(0, nr, [&](int r) {
      // The engine's errors, with the grain they happened in.
      const std::string where = "mesh: grain " + std::to_string(t.regions[r].grain) + ": ";
      try {
        mesh_region(r);
      } catch (const TimeLimitError& e) {
        throw TimeLimitError(where + e.what());
      } catch (const ConfigError& e) {
        throw ConfigError(where + e.what());
      } catch (const GeometryError& e) {
        throw GeometryError(where + e.what());
      }
      if (!o.progress) return;
      const std::lock_guard<std::mutex> lock(progress_mutex);
      o.progress(++regions_done, nr);
    });
  });

  out.regions_seconds = since(regions_start);
  const auto merge_start = std::chrono::steady_clock::now();
  for (int r = 0; r < nr; ++r) {
    const int base = static_cast<int>(pts.size());
    pts.insert(pts.end(), results[r].interior.begin(), results[r].interior.end());
    for (auto tri : results[r].triangles) {
      for (int& v : tri)
        if (v < 0) v = base + (-1 - v);
      out.mesh.triangles.push_back(tri);
      out.mesh.region.push_back(t.regions[r].grain);
      out.phase.push_back(t.regions[r].phase);
    }
    out.iterations_max = std::max(out.iterations_max, results[r].iterations);
    out.unconverged_regions += results[r].converged ? 0 : 1;
  }
  out.regions = nr;
  pair_periodic_nodes(t, out);
  validate(out.mesh);
  out.merge_seconds = since(merge_start);
  out.seconds = since(start);
  return out;
}

void pair_periodic_nodes(const Tessellation& t, GrainMesh& m) {
  m.pairs_x.clear();
  m.pairs_y.clear();
  if (!t.periodic) return;
  const std::vector<Vec2>& pts = m.mesh.points;
  for (int axis = 0; axis < 2; ++axis) {
    const double far = axis == 0 ? t.width : t.height;
    auto along = [axis](Vec2 p) { return axis == 0 ? p.y : p.x; };
    auto across = [axis](Vec2 p) { return axis == 0 ? p.x : p.y; };
    std::map<double, int> high;
    for (int v = 0; v < static_cast<int>(pts.size()); ++v)
      if (across(pts[v]) == far) high[along(pts[v])] = v;
    auto& pairs = axis == 0 ? m.pairs_x : m.pairs_y;
    for (int v = 0; v < static_cast<int>(pts.size()); ++v) {
      if (across(pts[v]) != 0.0) continue;
      const auto it = high.find(along(pts[v]));
      if (it == high.end())
        throw GeometryError("mesh: the node at " + to_text(pts[v]) + " on a cell side has no periodic partner");
      pairs.emplace_back(v, it->second);
    }
  }
}

Conformity check_conformity(const Tessellation& t, const GrainMesh& m, double area_tolerance) {
  const TriMesh& mesh = m.mesh;
  const double W = t.width, H = t.height;
  Conformity c;
  if (m.phase.size() != mesh.triangles.size() || mesh.region.size() != mesh.triangles.size())
    throw GeometryError("conformity: the mesh needs a grain and a phase for each of its triangles");
  // Nodes: no two at one place, and every tessellation vertex among them.
  PointMap<int> node;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (!node.emplace(point_key(mesh.points[v]), static_cast<int>(v)).second)
      throw GeometryError("conformity: two nodes at " + to_text(mesh.points[v]));
  for (const Vec2 v : t.vertices)
    if (!node.count(point_key(v))) throw GeometryError("conformity: the tessellation vertex " + to_text(v) + " is no mesh node");
  const auto edges = mesh_edges(mesh);  // throws for an edge of three triangles
  for (const MeshEdge& e : edges) {
    if (e.right >= 0) continue;
    ++c.boundary_edges;
    const Vec2 a = mesh.points[e.a], b = mesh.points[e.b];
    if (cell_side(t, a, b) == kNoSide)
      throw GeometryError("conformity: edge " + to_text(a) + " - " + to_text(b) + " has one triangle but lies inside the cell");
  }
  // Each triangle inside the region of its grain: its centroid strictly inside one of the
  // grain's regions and its corners no farther than rounding from it.
  std::vector<std::vector<int>> regions_of(t.grains.size());
  std::vector<PolygonDistance> dist;
  dist.reserve(t.regions.size());
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    PolygonRings rings;
    for (const auto& ring : t.regions[r].rings) {
      rings.emplace_back();
      for (int v : ring) rings.back().push_back(t.vertices[v]);
    }
    dist.emplace_back(rings);
    regions_of[t.regions[r].grain].push_back(static_cast<int>(r));
  }
  const double tol = 1e-12 * std::max(W, H);
  std::vector<double> area(t.grains.size(), 0.0);
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const int g = mesh.region[k];
    if (g < 0 || static_cast<std::size_t>(g) >= t.grains.size())
      throw GeometryError("conformity: triangle " + std::to_string(k) + " names grain " + std::to_string(g));
    const Vec2 centre = triangle_centroid(mesh, static_cast<int>(k));
    bool inside = false;
    for (int r : regions_of[g]) {
      if (!dist[r].contains(centre)) continue;
      inside = true;
      for (int v : mesh.triangles[k])
        if (dist[r](mesh.points[v]) > tol)
          throw GeometryError("conformity: triangle " + std::to_string(k) + " reaches out of its grain " + std::to_string(g));
    }
    if (!inside) throw GeometryError("conformity: triangle " + std::to_string(k) + " lies outside its grain " + std::to_string(g));
    if (m.phase[k] != t.grains[g].phase)
      throw GeometryError("conformity: triangle " + std::to_string(k) + " has phase " + std::to_string(m.phase[k]) +
                          ", its grain " + std::to_string(g) + " phase " + std::to_string(t.grains[g].phase));
    area[g] += triangle_area(mesh, static_cast<int>(k));
  }
  for (const Grain& g : t.grains) {
    const double err = std::abs(area[g.id] - g.area) / g.area;
    c.max_area_error = std::max(c.max_area_error, err);
    if (err > area_tolerance)
      throw GeometryError("conformity: grain " + std::to_string(g.id) + " has mesh area " + to_text(area[g.id], 12) +
                          " for polygon area " + to_text(g.area, 12));
  }
  if (t.periodic) {
    std::size_t left = 0, bottom = 0;
    for (const Vec2 p : mesh.points) {
      left += p.x == 0.0 ? 1 : 0;
      bottom += p.y == 0.0 ? 1 : 0;
    }
    if (m.pairs_x.size() != left || m.pairs_y.size() != bottom)
      throw GeometryError("conformity: not every node on the left or bottom side is paired");
    for (const auto& [a, b] : m.pairs_x)
      c.max_pair_mismatch = std::max(c.max_pair_mismatch, norm(mesh.points[b] - mesh.points[a] - Vec2{W, 0.0}));
    for (const auto& [a, b] : m.pairs_y)
      c.max_pair_mismatch = std::max(c.max_pair_mismatch, norm(mesh.points[b] - mesh.points[a] - Vec2{0.0, H}));
    if (c.max_pair_mismatch > tol) throw GeometryError("conformity: periodic node pairs do not match");
  }
  return c;
}

}  // namespace grainmesh
