#include "grains/edge_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "grains/edge_index.hpp"

namespace grainmesh {
namespace {

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
void equal_legs_at_sharp_corners(const Tessellation& t, const EdgeIndex& index,
                                 const std::vector<SidePartner>& partner, std::vector<std::vector<Vec2>>& seeds) {
  std::vector<char> on_side(seeds.size(), 0);
  for (std::size_t e = 0; e < seeds.size(); ++e)
    if (partner[e].low >= 0) on_side[e] = on_side[partner[e].low] = 1;
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
      const int ea = index.find(prev, v), eb = index.find(v, next);
      if (ea < 0 || eb < 0) continue;
      if (!usable(ea) || !usable(eb)) continue;
      const double da = first_distance(ea, v), db = first_distance(eb, v);
      if (da > db) pull_in(ea, v, db);
      else if (db > da) pull_in(eb, v, da);
    }
  }
}

}  // namespace

std::vector<std::vector<Vec2>> seed_edges(const Tessellation& t, const GrainMeshOptions& o, const FeatureSize& size) {
  const EdgeIndex index(t);
  return seed_edges(t, o, size, index, side_partners(t, index));
}

std::vector<std::vector<Vec2>> seed_edges(const Tessellation& t, const GrainMeshOptions& o, const FeatureSize& size,
                                          const EdgeIndex& index, const std::vector<SidePartner>& partner) {
  const std::size_t ne = t.edges.size();
  std::vector<double> h(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    double s = 1e300;
    for (int r : {t.edges[e].left, t.edges[e].right})
      if (r >= 0) s = std::min(s, region_size(o, t.regions[r].phase));
    h[e] = s;
  }
  // Periodic sides: right/top edge and its partner on the left/bottom share one size.
  for (std::size_t e = 0; e < ne; ++e)
    if (partner[e].low >= 0) h[partner[e].low] = h[e] = std::min(h[e], h[partner[e].low]);
  std::vector<std::vector<Vec2>> seeds(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    if (partner[e].low >= 0) continue;
    const Vec2 a = t.vertices[t.edges[e].v0], b = t.vertices[t.edges[e].v1];
    if (e % 256 == 0) o.distmesh.deadline.check("while seeding grain boundaries");
    seeds[e] = seed_segment(a, b, size, h[e]);
  }
  equal_legs_at_sharp_corners(t, index, partner, seeds);
  for (std::size_t e = 0; e < ne; ++e) {
    if (partner[e].low < 0) continue;
    const bool right = edge_side(t, t.edges[e]) == kRight;
    std::vector<Vec2> s = seeds[partner[e].low];
    for (Vec2& p : s) (right ? p.x : p.y) = right ? t.width : t.height;
    if (partner[e].reversed) std::reverse(s.begin(), s.end());
    seeds[e] = std::move(s);
  }
  return seeds;
}

std::vector<SidePartner> side_partners(const Tessellation& t, const EdgeIndex& index) {
  std::vector<SidePartner> partner(t.edges.size());
  if (!t.periodic) return partner;
  std::unordered_map<int, int> to_left, to_bottom;  // right -> left, top -> bottom vertex
  for (const auto& [l, r] : t.partners.axis[0]) to_left[r] = l;
  for (const auto& [b, u] : t.partners.axis[1]) to_bottom[u] = b;
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const CellSide side = edge_side(t, t.edges[e]);
    if (side != kRight && side != kTop) continue;
    const auto& to_low = side == kRight ? to_left : to_bottom;
    const auto a = to_low.find(t.edges[e].v0), b = to_low.find(t.edges[e].v1);
    const int low = (a != to_low.end() && b != to_low.end()) ? index.find(a->second, b->second) : -1;
    if (low < 0) throw GeometryError("mesh: a side edge of the periodic cell has no partner edge");
    // The same direction when v0 of this edge is the partner of the low edge's v0.
    partner[e] = {low, a->second != t.edges[low].v0};
  }
  return partner;
}

PeriodicPairs node_pairs(const Tessellation& t, const std::vector<SidePartner>& partner,
                         const std::vector<int>& first_id, const std::vector<std::vector<Vec2>>& seeds) {
  PeriodicPairs pairs = t.partners;  // the vertices: mesh node v is vertex v
  for (std::size_t e = 0; e < partner.size(); ++e) {
    if (partner[e].low < 0) continue;
    auto& out = edge_side(t, t.edges[e]) == kRight ? pairs.axis[0] : pairs.axis[1];
    const int n = static_cast<int>(seeds[e].size());
    for (int k = 0; k < n; ++k)
      out.emplace_back(first_id[partner[e].low] + (partner[e].reversed ? n - 1 - k : k), first_id[e] + k);
  }
  for (auto* side : {&pairs.axis[0], &pairs.axis[1]}) std::sort(side->begin(), side->end());
  return pairs;
}

}  // namespace grainmesh
