// Where the cell's sides go on the torus, and what is done where they cross boundaries
// too shallowly.
#include "tessellate/window.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "tessellate/regularise.hpp"

namespace grainmesh {

namespace {

constexpr int kCandidates = 1024;                      // offsets tried per axis
constexpr double kGoodAngle = 40.0 * std::numbers::pi / 180.0;  // steeper crossings score 1

double coord(Vec2 p, int axis) { return axis == 0 ? p.x : p.y; }
Vec2 make(int axis, double u, double w) { return axis == 0 ? Vec2{u, w} : Vec2{w, u}; }

double wrap(double x, double period) {
  double r = std::fmod(x, period);
  if (r < 0.0) r += period;
  return r;
}

}  // namespace

std::vector<double> best_line_offsets(const std::vector<Segment>& segments, const std::vector<Vec2>& points, int axis,
                                      double period, double other_period, bool other_periodic, double scale,
                                      const std::vector<double>& fixed_along, int count) {
  const double h = period / kCandidates;
  std::vector<double> worst(kCandidates, 1.0);  // the weakest feature near each line
  std::vector<double> sum(kCandidates, 0.0);    // for ties: the total margin
  std::vector<std::vector<double>> along(kCandidates);
  auto lines_in = [&](double lo, double hi, auto&& f) {
    for (long long G = static_cast<long long>(std::ceil(lo / h - 0.5)); (G + 0.5) * h < hi; ++G) {
      const double c = (G + 0.5) * h;
      if (c <= lo) continue;
      f(static_cast<int>(((G % kCandidates) + kCandidates) % kCandidates), c);
    }
  };
  for (const Vec2& p : points) {
    const double u = coord(p, axis);
    lines_in(u - scale, u + scale, [&](int g, double c) {
      const double term = std::abs(c - u) / scale;
      worst[g] = std::min(worst[g], term);
      sum[g] += term - 1.0;
    });
  }
  for (const Segment& s : segments) {
    const double ua = coord(s.a, axis), ub = coord(s.b, axis);
    const double wa = coord(s.a, 1 - axis), wb = coord(s.b, 1 - axis);
    const double angle = std::atan2(std::abs(ub - ua), std::abs(wb - wa));
    const double term = std::min(1.0, angle / kGoodAngle);
    lines_in(std::min(ua, ub), std::max(ua, ub), [&](int g, double c) {
      worst[g] = std::min(worst[g], term);
      sum[g] += term - 1.0;
      const double w = wa + (c - ua) / (ub - ua) * (wb - wa);
      along[g].push_back(other_periodic ? wrap(w, other_period) : w);
    });
  }
  std::vector<std::pair<double, int>> ranked;  // (-score, candidate): best first, ties by position
  for (int g = 0; g < kCandidates; ++g) {
    auto& w = along[g];
    w.insert(w.end(), fixed_along.begin(), fixed_along.end());
    std::sort(w.begin(), w.end());
    for (std::size_t k = 0; k + 1 < w.size(); ++k) worst[g] = std::min(worst[g], (w[k + 1] - w[k]) / scale);
    if (other_periodic && w.size() > 1) worst[g] = std::min(worst[g], (w.front() + other_period - w.back()) / scale);
    ranked.emplace_back(-(std::min(worst[g], 1.0) + 1e-6 * sum[g]), g);
  }
  std::sort(ranked.begin(), ranked.end());
  // The best candidates at least a few grid steps apart, so they differ in substance.
  std::vector<double> out;
  std::vector<int> taken;
  for (const auto& [score, g] : ranked) {
    if (static_cast<int>(out.size()) == count) break;
    bool near = false;
    for (int t : taken) {
      const int d = std::abs(t - g);
      near = near || std::min(d, kCandidates - d) < 8;
    }
    if (near) continue;
    taken.push_back(g);
    out.push_back((g + 0.5) * h);
  }
  return out;
}

std::vector<Vec2> line_crossings(const std::vector<Segment>& segments, int axis, double c, double width,
                                 double height) {
  const double period = axis == 0 ? width : height;
  std::vector<Vec2> out;
  for (const Segment& s : segments) {
    const double ua = coord(s.a, axis), ub = coord(s.b, axis);
    const double wa = coord(s.a, 1 - axis), wb = coord(s.b, 1 - axis);
    for (long long k = static_cast<long long>(std::ceil((std::min(ua, ub) - c) / period));
         c + k * period < std::max(ua, ub); ++k) {
      const double x = c + k * period;
      if (x <= std::min(ua, ub)) continue;
      const double w = wa + (x - ua) / (ub - ua) * (wb - wa);
      out.push_back(reduce_periodic(make(axis, c, w), width, height));
    }
  }
  return out;
}

int push_vertices_off_lines(TorusGraph& g, double distance, double min_angle, double min_edge) {
  const auto vc = vertex_cells(g);
  // The sharpest corner and the shortest edge at v of the cells around v; -1 when one
  // of them is not a simple counter-clockwise polygon.
  auto worst = [&](int v, double* shortest) {
    double sharpest = 2.0 * std::numbers::pi;
    *shortest = 1e300;
    for (int c : vc[v]) {
      const auto poly = g.polygon(c);
      if (!(polygon_area(poly) > 0.0) || !ring_is_simple(poly)) return -1.0;
      sharpest = std::min(sharpest, sharpest_corner(poly));
      const std::size_t n = poly.size();
      for (std::size_t k = 0; k < n; ++k)
        if (g.rings[c][k].v == v || g.rings[c][(k + 1) % n].v == v)
          *shortest = std::min(*shortest, norm(poly[(k + 1) % n] - poly[k]));
    }
    return sharpest;
  };
  int moved = 0;
  for (int v = 0; v < static_cast<int>(g.vertices.size()); ++v) {
    if (vc[v].empty()) continue;
    const Vec2 old = g.vertices[v];
    Vec2 p = old;
    for (int axis = 0; axis < 2; ++axis) {
      const double period = axis == 0 ? g.width : g.height;
      const double u = coord(p, axis);
      const double line = g.periodic ? std::round(u / period) * period : (u < 0.5 * period ? 0.0 : period);
      const double d = u - line;
      if (std::abs(d) >= distance) continue;
      double target = line + (d < 0.0 ? -distance : distance);
      if (g.periodic && (target < 0.0 || target >= period)) target = line == 0.0 ? distance : period - distance;
      p = make(axis, target, coord(p, 1 - axis));
    }
    if (p == old) continue;
    double short_before = 0.0, short_after = 0.0;
    const double before = worst(v, &short_before);
    g.vertices[v] = p;
    const double after = worst(v, &short_after);
    if (after < 0.0 || after < std::min(before, min_angle) || short_after < std::min(short_before, min_edge)) {
      g.vertices[v] = old;
      continue;
    }
    ++moved;
  }
  return moved;
}

void translate_graph(TorusGraph& g, Vec2 origin) {
  std::vector<Corner> shift(g.vertices.size());
  for (std::size_t v = 0; v < g.vertices.size(); ++v)
    g.vertices[v] = reduce_periodic(g.vertices[v] - origin, g.width, g.height, &shift[v]);
  for (auto& ring : g.rings)
    for (Corner& c : ring) {
      c.i += shift[c.v].i;
      c.j += shift[c.v].j;
    }
  for (Vec2& s : g.seeds) s = reduce_periodic(s - origin, g.width, g.height);
}

namespace {

// The corners of a square step that replaces the crossing of segment pa -> pb with the
// line coord(axis) = c: q1 before the line, q2 after it, both at the crossing's height
// and at most `step` from the line. False when the segment's ends leave no room.
bool step_points(Vec2 pa, Vec2 pb, int axis, double c, double step, Vec2* q1, Vec2* q2) {
  const double ua = coord(pa, axis), ub = coord(pb, axis);
  const double wa = coord(pa, 1 - axis), wb = coord(pb, 1 - axis);
  const double w = wa + (c - ua) / (ub - ua) * (wb - wa);
  // Corners at q1 and q2 stay >= 90 degrees as long as the ends lie beyond them.
  const double d = std::min({step, 0.8 * std::abs(ua - c), 0.8 * std::abs(ub - c), 0.45 * std::abs(w - wa),
                             0.45 * std::abs(wb - w)});
  if (!(d > 0.0)) return false;
  const double sign = ua < c ? 1.0 : -1.0;
  *q1 = make(axis, c - sign * d, w);
  *q2 = make(axis, c + sign * d, w);
  return true;
}

// The first line coord(axis) = k x period crossed by pa -> pb at less than min_angle, or
// false. Only k = 0, 1 when not periodic.
bool shallow_crossing(Vec2 pa, Vec2 pb, int axis, double period, bool periodic, double min_angle, long long* line) {
  const double ua = coord(pa, axis), ub = coord(pb, axis);
  const double angle = std::atan2(std::abs(ub - ua), std::abs(coord(pb, 1 - axis) - coord(pa, 1 - axis)));
  if (angle >= min_angle) return false;
  for (long long k = static_cast<long long>(std::floor(std::min(ua, ub) / period)) + 1; k * period < std::max(ua, ub);
       ++k)
    if (periodic || k == 0 || k == 1) {
      *line = k;
      return true;
    }
  return false;
}

struct Shallow {
  int u, v, di, dj;  // the edge, by its ends and their relative shift
  int axis;
  long long line;    // the line coordinate is line x period
};

// Inserts the step into edge e of cell c and its twin; false (and no change) when a ring
// would stop being simple.
bool insert_step(TorusGraph& g, std::vector<std::vector<int>>& vc, EdgeRef e, const Shallow& s, double step) {
  auto& ring = g.rings[e.cell];
  const Corner a = ring[e.at];
  const Corner b = ring[(e.at + 1) % ring.size()];
  const EdgeRef twin = twin_edge(g, vc, e);
  if (twin.cell < 0) return false;
  const double period = s.axis == 0 ? g.width : g.height;
  Vec2 q1, q2;
  if (!step_points(g.point(a), g.point(b), s.axis, static_cast<double>(s.line) * period, step, &q1, &q2)) return false;
  const int n1 = static_cast<int>(g.vertices.size());
  const int n2 = n1 + 1;
  Corner k1{}, k2{};
  g.vertices.push_back(g.periodic ? reduce_periodic(q1, g.width, g.height, &k1) : q1);
  g.vertices.push_back(g.periodic ? reduce_periodic(q2, g.width, g.height, &k2) : q2);
  const Corner twin_a = g.rings[twin.cell][(twin.at + 1) % g.rings[twin.cell].size()];  // u in the twin's frame
  const int Di = twin_a.i - a.i, Dj = twin_a.j - a.j;

  const auto saved_c = g.rings[e.cell];
  const auto saved_t = g.rings[twin.cell];
  ring.insert(ring.begin() + e.at + 1, {Corner{n1, k1.i, k1.j}, Corner{n2, k2.i, k2.j}});
  auto& tring = g.rings[twin.cell];
  // When both occurrences are in one cell, the first insertion moved the second.
  int tat = twin.at;
  if (twin.cell == e.cell && twin.at > e.at) tat += 2;
  tring.insert(tring.begin() + tat + 1, {Corner{n2, k2.i + Di, k2.j + Dj}, Corner{n1, k1.i + Di, k1.j + Dj}});
  for (int cell : {e.cell, twin.cell}) {
    const auto poly = g.polygon(cell);
    if (!(polygon_area(poly) > 0.0) || !ring_is_simple(poly)) {
      g.rings[e.cell] = saved_c;
      g.rings[twin.cell] = saved_t;
      g.vertices.resize(n1);
      return false;
    }
  }
  vc.push_back({std::min(e.cell, twin.cell), std::max(e.cell, twin.cell)});
  if (vc.back()[0] == vc.back()[1]) vc.back().pop_back();
  vc.push_back(vc.back());
  return true;
}

}  // namespace

int square_shallow_crossings(TorusGraph& g, double min_angle, double step) {
  auto vc = vertex_cells(g);
  int made = 0;
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<Shallow> found;
    for (const EdgeRef& e : unique_edges(g)) {
      const auto& ring = g.rings[e.cell];
      const Corner& a = ring[e.at];
      const Corner& b = ring[(e.at + 1) % ring.size()];
      const Vec2 pa = g.point(a), pb = g.point(b);
      for (int axis = 0; axis < 2; ++axis) {  // one step per edge and pass
        long long k = 0;
        if (!shallow_crossing(pa, pb, axis, axis == 0 ? g.width : g.height, g.periodic, min_angle, &k)) continue;
        found.push_back({a.v, b.v, b.i - a.i, b.j - a.j, axis, k});
        break;
      }
    }
    if (found.empty()) break;
    int done = 0;
    for (const Shallow& s : found) {
      for (int c : vc[s.u]) {
        const auto& ring = g.rings[c];
        int at = -1;
        for (int k = 0; k < static_cast<int>(ring.size()); ++k) {
          const Corner& p = ring[k];
          const Corner& q = ring[(k + 1) % ring.size()];
          if (p.v == s.u && q.v == s.v && q.i - p.i == s.di && q.j - p.j == s.dj) at = k;
        }
        if (at < 0) continue;
        if (insert_step(g, vc, {c, at}, s, step)) ++done;
        break;
      }
    }
    made += done;
    if (done == 0) break;
  }
  return made;
}

int square_shallow_crossings(std::vector<Vec2>& poly, double width, double height, bool periodic, double min_angle,
                             double step) {
  int made = 0;
  for (std::size_t k = 0; k < poly.size() && made < 64; ++k) {
    const Vec2 pa = poly[k], pb = poly[(k + 1) % poly.size()];
    for (int axis = 0; axis < 2; ++axis) {
      const double period = axis == 0 ? width : height;
      long long line = 0;
      Vec2 q1, q2;
      if (!shallow_crossing(pa, pb, axis, period, periodic, min_angle, &line) ||
          !step_points(pa, pb, axis, static_cast<double>(line) * period, step, &q1, &q2))
        continue;
      std::vector<Vec2> trial = poly;
      trial.insert(trial.begin() + static_cast<std::ptrdiff_t>(k) + 1, {q1, q2});
      if (!(polygon_area(trial) > 0.0) || !ring_is_simple(trial)) continue;
      poly = std::move(trial);
      ++made;
      break;  // the new segments are checked as the loop goes on
    }
  }
  return made;
}

// The best `count` cell origins on the torus: x first, then y for each x, keeping clear
// of where the x side crosses boundaries and of the x side itself.
std::vector<Vec2> window_candidates(const std::vector<Segment>& segs, const std::vector<Vec2>& points, double W,
                                    double H, double scale, int count) {
  std::vector<Vec2> out;
  for (double ox : best_line_offsets(segs, points, 0, W, H, true, scale, {}, count)) {
    std::vector<Vec2> pts = points;
    for (const Vec2& p : line_crossings(segs, 0, ox, W, H)) pts.push_back(p);
    for (double oy : best_line_offsets(segs, pts, 1, H, W, true, scale, {ox}, count)) out.push_back({ox, oy});
  }
  return out;
}

// The part of a polygon inside [0, W] x [0, H] (Sutherland-Hodgman), for areas only.
std::vector<Vec2> clip_to_cell(std::vector<Vec2> poly, double W, double H) {
  poly = clip_half_plane(poly, {1.0, 0.0}, 0.0);
  poly = clip_half_plane(poly, {-1.0, 0.0}, -W);
  poly = clip_half_plane(poly, {0.0, 1.0}, 0.0);
  return clip_half_plane(poly, {0.0, -1.0}, -H);
}

}  // namespace grainmesh
