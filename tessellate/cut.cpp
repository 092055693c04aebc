// Cutting grains by the cell's sides. Every cut point is computed from the canonical
// endpoints of its edge, in the frame of that edge, so a point on a shared edge and its
// periodic partner on the opposite side come out with the same bits.
#include "tessellate/cut.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/point_key.hpp"
#include "tessellate/regularise.hpp"

namespace grainmesh {

std::vector<CutPolygon> cell_polygons(const TorusGraph& g, const std::vector<int>& cells) {
  std::vector<CutPolygon> out;
  out.reserve(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const auto& ring = g.rings[cells[k]];
    CutPolygon poly;
    poly.grain = static_cast<int>(k);
    for (std::size_t n = 0; n < ring.size(); ++n) {
      const Corner& a = ring[n];
      const Corner& b = ring[(n + 1) % ring.size()];
      poly.corners.push_back({g.vertices[a.v], a.i, a.j});
      const bool forward = canonical_direction(a, b);
      const Corner& from = forward ? a : b;
      const Corner& to = forward ? b : a;
      const Vec2 p = g.vertices[from.v];
      const Vec2 q{g.vertices[to.v].x + (to.i - from.i) * g.width, g.vertices[to.v].y + (to.j - from.j) * g.height};
      poly.edges.push_back({p, q, from.i, from.j});
    }
    out.push_back(std::move(poly));
  }
  return out;
}

namespace {

// A point of a polygon being clipped; `tag` is the edge the outgoing segment lies on, or
// -1 when it runs along a side of the cell.
struct ClipPoint {
  Vec2 p;
  int tag = -1;
};

constexpr double kCornerSnap = 1e-9;  // x the cell side

struct Clipper {
  double W, H;
  const CutPolygon* poly;
  int a, b;  // lattice translate of the polygon

  // The crossing of the segment from `from` with the line coord(axis) = k x period. A
  // crossing within kCornerSnap of a cell corner is the corner: a boundary through (or
  // next to) a corner must not leave a side edge a rounding error long.
  Vec2 crossing(const ClipPoint& from, int axis, int k) const {
    if (from.tag < 0) return axis == 0 ? Vec2{k * W, from.p.y} : Vec2{from.p.x, k * H};
    const CutEdge& e = poly->edges[from.tag];
    const int fi = e.i + a, fj = e.j + b;
    if (axis == 0) {
      const double x = static_cast<double>(k - fi) * W;
      const double t = (x - e.p.x) / (e.q.x - e.p.x);
      return {k * W, snap(e.p.y + t * (e.q.y - e.p.y) + fj * H, H)};
    }
    const double y = static_cast<double>(k - fj) * H;
    const double t = (y - e.p.y) / (e.q.y - e.p.y);
    return {snap(e.p.x + t * (e.q.x - e.p.x) + fi * W, W), k * H};
  }
  static double snap(double u, double period) {
    const double corner = std::round(u / period) * period;
    return std::abs(u - corner) <= kCornerSnap * period ? corner : u;
  }

  // Keeps the part with coord >= k x period (upper = false) or <= (upper = true).
  std::vector<ClipPoint> clip(const std::vector<ClipPoint>& in, int axis, int k, bool upper) const {
    std::vector<ClipPoint> out;
    const double c = axis == 0 ? k * W : k * H;
    auto inside = [&](const ClipPoint& q) {
      const double u = axis == 0 ? q.p.x : q.p.y;
      return upper ? u <= c : u >= c;
    };
    for (std::size_t n = 0; n < in.size(); ++n) {
      const ClipPoint& cur = in[n];
      const ClipPoint& next = in[(n + 1) % in.size()];
      const bool ci = inside(cur), ni = inside(next);
      if (ci) out.push_back(cur);
      if (ci != ni) out.push_back({crossing(cur, axis, k), ci ? -1 : cur.tag});
    }
    return out;
  }
};

// Vertices by their exact coordinates: a point reached from two pieces is one vertex.
class VertexTable {
 public:
  explicit VertexTable(std::vector<Vec2>& v) : vertices_(v) {}
  int id(Vec2 p) {
    auto [it, fresh] = ids_.try_emplace(point_key(p), static_cast<int>(vertices_.size()));
    if (fresh) vertices_.push_back({p.x + 0.0, p.y + 0.0});
    return it->second;
  }

 private:
  std::vector<Vec2>& vertices_;
  PointMap<int> ids_;
};

// Matrix regions in binder mode: the cell minus the grain pieces, traced as rings.
void add_matrix(Tessellation& t, VertexTable& table, int grain, int phase) {
  const double W = t.width, H = t.height;
  const std::size_t pieces = t.regions.size();
  for (Vec2 c : {Vec2{0, 0}, Vec2{W, 0}, Vec2{W, H}, Vec2{0, H}}) table.id(c);
  std::unordered_map<std::int64_t, char> covered;  // piece edges along a side, by (from, to)
  auto key = [](int a, int b) { return static_cast<std::int64_t>(a) << 32 | static_cast<std::uint32_t>(b); };
  std::unordered_map<int, int> next;
  auto link = [&](int from, int to) {
    if (!next.emplace(from, to).second) throw GeometryError("binder matrix: two grains touch at a vertex");
  };
  // Where two grains touch (binder mode's contacts) each has the edge, one each way: no
  // matrix there.
  std::unordered_map<std::int64_t, char> piece_edges;
  for (std::size_t r = 0; r < pieces; ++r) {
    const auto& ring = t.regions[r].rings[0];
    for (std::size_t n = 0; n < ring.size(); ++n) piece_edges[key(ring[n], ring[(n + 1) % ring.size()])] = 1;
  }
  for (std::size_t r = 0; r < pieces; ++r) {
    const auto& ring = t.regions[r].rings[0];
    for (std::size_t n = 0; n < ring.size(); ++n) {
      const int a = ring[n], b = ring[(n + 1) % ring.size()];
      if (cell_side(t, t.vertices[a], t.vertices[b]) != kNoSide) covered[key(a, b)] = 1;
      else if (!piece_edges.count(key(b, a))) link(b, a);
    }
  }
  // The cell's boundary, counter-clockwise, where no piece covers it.
  const Box cell{{0.0, 0.0}, {W, H}};
  for (CellSide s : kSidesCounterClockwise) {
    std::vector<int> on;
    for (int v = 0; v < static_cast<int>(t.vertices.size()); ++v)
      if (on_side(cell, t.vertices[v], s)) on.push_back(v);
    std::sort(on.begin(), on.end(), [&](int a, int b) {
      const Vec2 p = t.vertices[a], q = t.vertices[b];
      switch (s) {
        case kBottom: return p.x < q.x;
        case kRight: return p.y < q.y;
        case kTop: return p.x > q.x;
        default: return p.y > q.y;
      }
    });
    for (std::size_t n = 0; n + 1 < on.size(); ++n)
      if (!covered.count(key(on[n], on[n + 1]))) link(on[n], on[n + 1]);
  }
  std::vector<std::vector<int>> outers, holes;
  std::unordered_map<int, char> seen;
  std::vector<int> starts;
  for (const auto& [from, to] : next) starts.push_back(from);
  std::sort(starts.begin(), starts.end());
  for (int start : starts) {
    if (seen.count(start)) continue;
    std::vector<int> ring;
    int v = start;
    while (!seen.count(v)) {
      seen[v] = 1;
      ring.push_back(v);
      const auto it = next.find(v);
      if (it == next.end()) throw GeometryError("binder matrix: open boundary");
      v = it->second;
    }
    if (v != start) throw GeometryError("binder matrix: boundary rings cross");
    (polygon_area(ring_points(t.vertices, ring)) > 0.0 ? outers : holes).push_back(std::move(ring));
  }
  const std::size_t first = t.regions.size();
  for (auto& o : outers) t.regions.push_back(Region{grain, phase, {std::move(o)}});
  for (auto& h : holes) {
    int best = -1;
    double best_area = 0.0;
    for (std::size_t r = first; r < t.regions.size(); ++r) {
      const std::vector<Vec2> outer = ring_points(t.vertices, t.regions[r].rings[0]);
      const double a = polygon_area(outer);
      if (inside_ring(outer, t.vertices[h[0]]) && (best < 0 || a < best_area)) {
        best = static_cast<int>(r);
        best_area = a;
      }
    }
    if (best < 0) throw GeometryError("binder matrix: a grain lies outside the matrix");
    std::reverse(h.begin(), h.end());  // stored counter-clockwise, as the polygon it cuts out
    t.regions[best].rings.push_back(std::move(h));
  }
}

void build_edges(Tessellation& t) {
  std::unordered_map<std::int64_t, int> index;
  t.edges.clear();
  for (int r = 0; r < static_cast<int>(t.regions.size()); ++r) {
    const auto& rings = t.regions[r].rings;
    for (std::size_t q = 0; q < rings.size(); ++q) {
      const bool on_left = q == 0;  // holes are stored counter-clockwise: region on the right
      for (std::size_t n = 0; n < rings[q].size(); ++n) {
        const int a = rings[q][n], b = rings[q][(n + 1) % rings[q].size()];
        const std::int64_t k = static_cast<std::int64_t>(std::min(a, b)) << 32 | std::max(a, b);
        auto [it, fresh] = index.try_emplace(k, static_cast<int>(t.edges.size()));
        if (fresh) t.edges.push_back({a, b, -1, -1});
        TessEdge& e = t.edges[it->second];
        const bool left = (e.v0 == a) == on_left;
        int& slot = left ? e.left : e.right;
        if (slot >= 0) throw GeometryError("cut: an edge has the same side twice");
        slot = r;
      }
    }
  }
}

void build_partners(Tessellation& t) {
  try {
    t.partners = pair_by_position(t.vertices, Box{{0.0, 0.0}, {t.width, t.height}});
  } catch (const GeometryError& e) {
    throw GeometryError(std::string("cut: ") + e.what());
  }
}

}  // namespace

void cut_into_cell(const std::vector<CutPolygon>& polygons, Tessellation& t, int matrix_grain, int matrix_phase) {
  const double W = t.width, H = t.height;
  const double tiny = 1e-14 * W * H;
  t.vertices.clear();
  t.regions.clear();
  VertexTable table(t.vertices);
  for (const CutPolygon& poly : polygons) {
    Box box;
    for (const CutCorner& c : poly.corners) box.extend(Vec2{c.base.x + c.i * W, c.base.y + c.j * H});
    const int a0 = t.periodic ? static_cast<int>(std::ceil(-box.hi.x / W)) : 0;
    const int a1 = t.periodic ? static_cast<int>(std::floor((W - box.lo.x) / W)) : 0;
    const int b0 = t.periodic ? static_cast<int>(std::ceil(-box.hi.y / H)) : 0;
    const int b1 = t.periodic ? static_cast<int>(std::floor((H - box.lo.y) / H)) : 0;
    for (int b = b0; b <= b1; ++b)
      for (int a = a0; a <= a1; ++a) {
        const Clipper clipper{W, H, &poly, a, b};
        std::vector<ClipPoint> pts;
        for (std::size_t n = 0; n < poly.corners.size(); ++n) {
          const CutCorner& c = poly.corners[n];
          pts.push_back({{c.base.x + (c.i + a) * W, c.base.y + (c.j + b) * H}, static_cast<int>(n)});
        }
        pts = clipper.clip(pts, 0, 0, false);
        pts = clipper.clip(pts, 0, 1, true);
        pts = clipper.clip(pts, 1, 0, false);
        pts = clipper.clip(pts, 1, 1, true);
        std::vector<Vec2> ring;
        for (const ClipPoint& q : pts)
          if (ring.empty() || !(ring.back() == q.p)) ring.push_back(q.p);
        while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
        if (ring.size() < 3 || polygon_area(ring) <= tiny) continue;
        Region region{poly.grain, poly.phase, {{}}};
        for (const Vec2& p : ring) region.rings[0].push_back(table.id(p));
        t.regions.push_back(std::move(region));
      }
  }
  if (matrix_grain >= 0) add_matrix(t, table, matrix_grain, matrix_phase);
  build_edges(t);
  if (t.periodic) build_partners(t);
}

}  // namespace grainmesh
