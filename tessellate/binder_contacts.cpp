#include "tessellate/binder_contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "common/ring.hpp"
#include "tessellate/regularise.hpp"
#include "tessellate/window.hpp"

namespace grainmesh {

std::vector<TaggedCorner> shrink_tagged(const std::vector<Vec2>& ring, double t) {
  std::vector<TaggedCorner> poly;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) poly.push_back({ring[k], static_cast<int>(k)});
  for (std::size_t k = 0; k < n && poly.size() >= 3; ++k) {
    const Vec2 a = ring[k], b = ring[(k + 1) % n];
    const Vec2 dir = b - a;
    const double len = norm(dir);
    if (len == 0.0) continue;
    const Vec2 inward = perp(dir) / len;  // left of a counter-clockwise edge
    const double offset = dot(inward, a) + t;
    std::vector<TaggedCorner> out;
    for (std::size_t m = 0; m < poly.size(); ++m) {
      const TaggedCorner& p = poly[m];
      const Vec2 q = poly[(m + 1) % poly.size()].p;
      const double dp = dot(inward, p.p) - offset, dq = dot(inward, q) - offset;
      if (dp >= 0.0) out.push_back(p);
      // Leaving: the side goes on along the offset line k; entering: along p's own.
      if ((dp >= 0.0) != (dq >= 0.0))
        out.push_back({p.p + (dp / (dp - dq)) * (q - p.p), dp >= 0.0 ? static_cast<int>(k) : p.edge});
    }
    poly = std::move(out);
  }
  std::vector<Vec2> pts;
  for (const auto& c : poly) pts.push_back(c.p);
  if (poly.size() < 3 || !(polygon_area(pts) > 0.0)) return {};
  return poly;
}

std::vector<Vec2> points_of(const std::vector<BinderCorner>& poly) {
  std::vector<Vec2> pts;
  for (const BinderCorner& c : poly) pts.push_back(c.p);
  return pts;
}

std::vector<Contact> contact_candidates(const TorusGraph& g, const std::vector<int>& cells, Rng& rng) {
  std::vector<int> index(g.rings.size(), -1);
  for (std::size_t k = 0; k < cells.size(); ++k) index[static_cast<std::size_t>(cells[k])] = static_cast<int>(k);
  const auto vc = vertex_cells(g);
  std::vector<Contact> out;
  for (const EdgeRef& e : unique_edges(g)) {
    const EdgeRef twin = twin_edge(g, vc, e);
    if (twin.cell < 0 || twin.cell == e.cell) continue;
    const int a = index[static_cast<std::size_t>(e.cell)], b = index[static_cast<std::size_t>(twin.cell)];
    if (a < 0 || b < 0) continue;
    // The twin runs the other way: its end is this edge's start.
    const auto& ra = g.rings[static_cast<std::size_t>(e.cell)];
    const auto& rb = g.rings[static_cast<std::size_t>(twin.cell)];
    const Corner ca = ra[static_cast<std::size_t>(e.at)];
    const Corner cb = rb[(static_cast<std::size_t>(twin.at) + 1) % rb.size()];
    if (ca.v != cb.v) continue;
    out.push_back({a, e.at, b, twin.at, ca.i - cb.i, ca.j - cb.j});
  }
  for (std::size_t k = out.size(); k > 1; --k)  // Fisher-Yates with our own draws
    std::swap(out[k - 1], out[static_cast<std::size_t>(uniform01(rng) * static_cast<double>(k))]);
  return out;
}

namespace {

// Whether p stays at least `step` from every cell line (x = k W, y = k H; only the sides
// when not periodic) and in lattice cell `cell` (found from the first point when unset).
bool clear_of_lines(Vec2 p, double W, double H, bool periodic, double step, long long* cx, long long* cy, bool first) {
  const long long x0 = static_cast<long long>(std::floor((p.x - step) / W)),
                  x1 = static_cast<long long>(std::floor((p.x + step) / W));
  const long long y0 = static_cast<long long>(std::floor((p.y - step) / H)),
                  y1 = static_cast<long long>(std::floor((p.y + step) / H));
  if (x0 != x1 || y0 != y1) return false;
  if (!periodic && (x0 != 0 || y0 != 0)) return false;
  if (first) *cx = x0, *cy = y0;
  return x0 == *cx && y0 == *cy;
}

// The interior angle of a counter-clockwise ring at its corner k.
double interior_angle(const std::vector<Vec2>& ring, std::size_t k) {
  const std::size_t n = ring.size();
  const Vec2 v = ring[k], next = ring[(k + 1) % n] - v, prev = ring[(k + n - 1) % n] - v;
  const double a = std::atan2(cross(next, prev), dot(next, prev));
  return a < 0.0 ? a + 2.0 * std::numbers::pi : a;
}

// The interior angle of a ring at the corner with exactly the coordinates p (-1 if none).
double angle_at(const std::vector<Vec2>& ring, Vec2 p) {
  for (std::size_t k = 0; k < ring.size(); ++k)
    if (ring[k] == p) return interior_angle(ring, k);
  return -1.0;
}

// Corners sharper than this, of a grain or of the binder, where a bridge is made: they
// would mesh into slivers.
constexpr double kMinBridgeAngle = 20.0 * std::numbers::pi / 180.0;

// Whether the grown grain's four bridge corners `own` (a0, b1, b0, a1 in its frame), the
// binder beside them (at a0 and a1 the rest of the turn; at b1 and b0, `borrowed` in the
// neighbour's frame, the rest after both grains) all stay at or above kMinBridgeAngle.
bool bridge_corners_open(const std::vector<Vec2>& grown, const std::vector<Vec2>& neighbour, std::array<Vec2, 4> own,
                         std::array<Vec2, 2> borrowed) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  for (int k = 0; k < 4; ++k) {
    const double mine = angle_at(grown, own[static_cast<std::size_t>(k)]);
    if (mine < kMinBridgeAngle) return false;
    double binder = kTurn - mine;
    if (k == 1 || k == 2) {
      const double theirs = angle_at(neighbour, borrowed[static_cast<std::size_t>(k - 1)]);
      if (theirs < 0.0) return false;
      binder -= theirs;
    }
    if (binder < kMinBridgeAngle) return false;
  }
  return true;
}

// The boundary length of a grain that counts for contiguity: all of it on the torus; in
// a bounded cell the part inside, not along the sides.
double counted_perimeter(const std::vector<Vec2>& poly, double W, double H, bool periodic) {
  const std::vector<Vec2> inside = periodic ? poly : clip_to_cell(poly, W, H);
  double length = 0.0;
  for (std::size_t k = 0; k < inside.size(); ++k) {
    const Vec2 a = inside[k], b = inside[(k + 1) % inside.size()];
    const bool along_side =
        !periodic && ((a.x == b.x && (a.x == 0.0 || a.x == W)) || (a.y == b.y && (a.y == 0.0 || a.y == H)));
    if (!along_side) length += norm(b - a);
  }
  return length;
}

}  // namespace

BridgedGrains bridged_grains(const std::vector<std::vector<Vec2>>& cell_poly, const std::vector<Contact>& contacts,
                             int count, double t, Vec2 origin, double W, double H, bool periodic, double step) {
  BridgedGrains out;
  std::vector<std::vector<TaggedCorner>> shrunk;
  for (const auto& ring : cell_poly) {
    shrunk.push_back(shrink_tagged(ring, t));
    for (TaggedCorner& c : shrunk.back()) c.p -= origin;
  }
  // Each grain's corner at which a bridge starts: its two borrowed corners and the edge.
  struct Bridge {
    std::size_t after;
    BinderCorner b1, b0;
  };
  std::vector<std::vector<Bridge>> bridges(shrunk.size());
  std::vector<std::vector<int>> shared_from(shrunk.size());  // per corner of a grain: its outgoing edge's shared id
  for (std::size_t g = 0; g < shrunk.size(); ++g) shared_from[g].assign(shrunk[g].size(), -1);
  // Grain g's corners with its bridges: after each corner a bridge starts at, the
  // neighbour's two corners it borrows.
  auto assemble = [&](std::size_t g) {
    std::vector<BinderCorner> poly;
    for (std::size_t k = 0; k < shrunk[g].size(); ++k) {
      poly.push_back({shrunk[g][k].p, shrunk[g][k].p, 0, 0, shared_from[g][k]});
      for (const Bridge& b : bridges[g])
        if (b.after == k) poly.insert(poly.end(), {b.b1, b.b0});
    }
    return poly;
  };
  auto find = [](const std::vector<TaggedCorner>& poly, int edge) {
    for (std::size_t k = 0; k < poly.size(); ++k)
      if (poly[k].edge == edge) return static_cast<int>(k);
    return -1;
  };
  for (int c = 0; c < std::min<int>(count, static_cast<int>(contacts.size())); ++c) {
    const Contact& k = contacts[static_cast<std::size_t>(c)];
    const auto& A = shrunk[static_cast<std::size_t>(k.a)];
    const auto& B = shrunk[static_cast<std::size_t>(k.b)];
    const int ia = find(A, k.edge_a), ib = find(B, k.edge_b);
    if (ia < 0 || ib < 0 || shared_from[static_cast<std::size_t>(k.b)][static_cast<std::size_t>(ib)] >= 0) continue;
    const Vec2 shift{k.di * W, k.dj * H};
    const Vec2 a0 = A[static_cast<std::size_t>(ia)].p, a1 = A[(static_cast<std::size_t>(ia) + 1) % A.size()].p;
    const Vec2 b0 = B[static_cast<std::size_t>(ib)].p, b1 = B[(static_cast<std::size_t>(ib) + 1) % B.size()].p;
    long long cx = 0, cy = 0;
    bool clear = true, first = true;
    for (const Vec2 p : {a0, b1 + shift, b0 + shift, a1}) {
      clear = clear && clear_of_lines(p, W, H, periodic, step, &cx, &cy, first);
      first = false;
    }
    if (!clear) continue;
    const int id = static_cast<int>(out.shared_edge.size());
    auto& mine = bridges[static_cast<std::size_t>(k.a)];
    mine.push_back({static_cast<std::size_t>(ia), {b1 + shift, b1, k.di, k.dj, id}, {b0 + shift, b0, k.di, k.dj, -1}});
    // A bridge that would fold the grain onto itself (a short face beside a long one), or
    // leave a corner of a grain or of the binder sharper than kMinBridgeAngle, is not made.
    const std::vector<Vec2> grown = points_of(assemble(static_cast<std::size_t>(k.a)));
    if (!ring_is_simple(grown) || !bridge_corners_open(grown, points_of(assemble(static_cast<std::size_t>(k.b))),
                                                       {a0, b1 + shift, b0 + shift, a1}, {b1, b0})) {
      mine.pop_back();
      continue;
    }
    out.shared_edge.push_back({b0, b1, 0, 0});
    shared_from[static_cast<std::size_t>(k.b)][static_cast<std::size_t>(ib)] = id;
    out.contact += norm(b1 - b0);
    ++out.contacts;
  }
  out.grains.resize(shrunk.size());
  for (std::size_t g = 0; g < shrunk.size(); ++g) {
    out.grains[g] = assemble(g);
    if (out.grains[g].empty()) continue;
    const std::vector<Vec2> pts = points_of(out.grains[g]);
    out.area += polygon_area(periodic ? pts : clip_to_cell(pts, W, H));
    out.perimeter += counted_perimeter(pts, W, H, periodic);
  }
  return out;
}

}  // namespace grainmesh
