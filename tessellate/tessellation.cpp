// tessellate(): seeds -> power diagram -> Lloyd -> regularisation -> phases -> window ->
// cut, and the checks and statistics of the result.
#include "tessellate/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/descriptors.hpp"
#include "tessellate/steps.hpp"

namespace grainmesh {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Crossings of the cell's sides shallower than this are squared off.
constexpr double kMinSideAngle = 32.0 * kDegree;
// The corner angle that moving a vertex off a cell side may not go below.
constexpr double kMinCorner = 30.0 * kDegree;
// Vertices closer than this x the short-edge length to a cell side are moved off it, so
// a square step next to them still has legs of the full length.
constexpr double kPushDistance = 1.25;
// Cells up to this many grains try this many windows (x) as many (y) and keep the best.
constexpr std::size_t kTrialCells = 5000;
constexpr int kWindowTrials = 4;
// Binder layers (twice the shrink offset) thinner than this share of the grain spacing
// sqrt(W H / N) are refused: the pockets where they meet mesh into slivers.
constexpr double kMinBinderLayer = 2e-3;

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

// The polygon of a cell as it counts for areas and centroids: clipped when not periodic.
std::vector<Vec2> counted_polygon(const TorusGraph& g, int c) {
  auto poly = g.polygon(c);
  return g.periodic ? poly : clip_to_cell(std::move(poly), g.width, g.height);
}

double normal(Rng& rng) {
  const double u1 = 1.0 - uniform01(rng);  // (0, 1]
  const double u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

std::vector<int> live(const TorusGraph& g) {
  std::vector<int> cells;
  for (int c = 0; c < static_cast<int>(g.rings.size()); ++c)
    if (!g.rings[c].empty()) cells.push_back(c);
  return cells;
}

// Distinct neighbouring cells of each cell, as indices into `cells`.
std::vector<std::vector<int>> cell_neighbours(const TorusGraph& g, const std::vector<int>& cells) {
  std::vector<int> index(g.rings.size(), -1);
  for (std::size_t k = 0; k < cells.size(); ++k) index[cells[k]] = static_cast<int>(k);
  const auto vc = vertex_cells(g);
  std::vector<std::set<int>> sets(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k)
    for (int at = 0; at < static_cast<int>(g.rings[cells[k]].size()); ++at) {
      const EdgeRef twin = twin_edge(g, vc, {cells[k], at});
      if (twin.cell >= 0 && twin.cell != cells[k] && index[twin.cell] >= 0) sets[k].insert(index[twin.cell]);
    }
  std::vector<std::vector<int>> out;
  for (auto& s : sets) out.emplace_back(s.begin(), s.end());
  return out;
}

// Smallest interior angle of a region at any corner. A hole, stored counter-clockwise,
// is walked the other way so the region is on its left as for the outer ring.
double region_sharpest(const Tessellation& t, const Region& r) {
  double best = 2.0 * std::numbers::pi;
  for (std::size_t q = 0; q < r.rings.size(); ++q) {
    std::vector<Vec2> pts;
    for (int v : r.rings[q]) pts.push_back(t.vertices[v]);
    if (q > 0) std::reverse(pts.begin(), pts.end());
    best = std::min(best, sharpest_corner(pts));
  }
  return best;
}

void mean_std(const std::vector<double>& v, double* mean, double* sd) {
  double s = 0.0, s2 = 0.0;
  for (double x : v) s += x;
  *mean = v.empty() ? 0.0 : s / static_cast<double>(v.size());
  for (double x : v) s2 += (x - *mean) * (x - *mean);
  *sd = v.size() > 1 ? std::sqrt(s2 / static_cast<double>(v.size() - 1)) : 0.0;
}

void check_options(const TessellationOptions& o) {
  if (!(o.width > 0.0) || !(o.height > 0.0)) throw ConfigError("cell width and height must be positive");
  if (o.grains < 1) throw ConfigError("the number of grains must be at least 1");
  if (!o.seeds.empty() && static_cast<int>(o.seeds.size()) != o.grains)
    throw ConfigError("the number of grains must equal the number of given seeds");
  for (const Vec2 s : o.seeds)
    if (!(s.x >= 0.0 && s.x <= o.width && s.y >= 0.0 && s.y <= o.height))
      throw ConfigError("a given seed lies outside the cell");
  if (o.phases.empty()) throw ConfigError("at least one phase is needed");
  int rests = 0;
  double sum = 0.0;
  for (const Phase& p : o.phases) {
    rests += p.rest ? 1 : 0;
    sum += p.rest ? 0.0 : p.fraction;
  }
  if (rests > 1) throw ConfigError("only one phase may take the rest");
  if (rests == 0 && std::abs(sum - 1.0) > 1e-9) throw ConfigError("phase fractions must sum to 1");
  if (rests == 1 && sum > 1.0 + 1e-12) throw ConfigError("phase fractions exceed 1");
  if (o.phase_mode == PhaseMode::binder && (o.matrix_phase < 0 || o.matrix_phase >= static_cast<int>(o.phases.size())))
    throw ConfigError("binder mode needs a matrix phase");
  if (o.contiguity && (o.phase_mode != PhaseMode::grain || !(*o.contiguity > 0.0 && *o.contiguity < 1.0) ||
                       o.contiguity_phase < 0 || o.contiguity_phase >= static_cast<int>(o.phases.size())))
    throw ConfigError("a contiguity target lies in (0, 1), for a phase, in grain mode");
}

// The length of segment pq inside [0, W] x [0, H] (Liang-Barsky).
double length_inside(Vec2 p, Vec2 q, double W, double H) {
  const Vec2 d = q - p;
  double t0 = 0.0, t1 = 1.0;
  const double by[4][2] = {{-d.x, p.x}, {d.x, W - p.x}, {-d.y, p.y}, {d.y, H - p.y}};
  for (const auto& [a, b] : by) {
    if (a == 0.0) {
      if (b < 0.0) return 0.0;
      continue;
    }
    const double t = b / a;
    if (a < 0.0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  return t1 > t0 ? (t1 - t0) * norm(d) : 0.0;
}

// The boundary each of `cells` shares with each neighbour: the torus's edges, or in the
// plane their parts inside the cell (what the cut keeps).
SharedBoundaries shared_boundaries(const TorusGraph& g, const std::vector<int>& cells) {
  std::vector<int> index(g.rings.size(), -1);
  for (std::size_t k = 0; k < cells.size(); ++k) index[cells[k]] = static_cast<int>(k);
  const auto vc = vertex_cells(g);
  std::vector<std::map<int, double>> lengths(cells.size());
  for (const EdgeRef& e : unique_edges(g)) {
    const EdgeRef twin = twin_edge(g, vc, e);
    if (twin.cell < 0) continue;
    const int a = index[e.cell], b = index[twin.cell];
    if (a < 0 || b < 0 || a == b) continue;
    const auto& ring = g.rings[e.cell];
    const Vec2 p = g.point(ring[e.at]), q = g.point(ring[(e.at + 1) % ring.size()]);
    const double length = g.periodic ? norm(q - p) : length_inside(p, q, g.width, g.height);
    if (length <= 0.0) continue;
    lengths[a][b] += length;
    lengths[b][a] += length;
  }
  SharedBoundaries out;
  for (const auto& m : lengths) out.emplace_back(m.begin(), m.end());
  return out;
}

double target_fraction(const std::vector<Phase>& phases, int p) {
  if (!phases[p].rest) return phases[p].fraction;
  double sum = 0.0;
  for (const Phase& q : phases) sum += q.rest ? 0.0 : q.fraction;
  return 1.0 - sum;
}

std::vector<Segment> graph_segments(const TorusGraph& g);

// Places the cell on the torus (periodic) and clears its sides: junctions pushed off
// them, shallow crossings squared off. Small cells try the best few windows and keep
// the one whose cut has the mildest sharpest corner and shortest edge.
void place_window(TorusGraph& g, const std::vector<int>& cells, double scale, TessellationStats& st) {
  const int tries = g.periodic && cells.size() <= kTrialCells ? kWindowTrials : 1;
  const std::vector<Vec2> origins =
      g.periodic ? window_candidates(graph_segments(g), g.vertices, g.width, g.height, scale, tries)
                 : std::vector<Vec2>{Vec2{}};
  const double edge = st.edge_threshold > 0.0 ? st.edge_threshold : scale;
  double best_score = -1.0;
  TorusGraph best;
  for (const Vec2 origin : origins) {
    TorusGraph trial = g;
    if (trial.periodic) translate_graph(trial, origin);
    const int pushed = push_vertices_off_lines(trial, kPushDistance * scale, kMinCorner, st.edge_threshold);
    const int jogs = square_shallow_crossings(trial, kMinSideAngle, scale);
    double score = 0.0;
    if (origins.size() > 1) {
      Tessellation t;
      t.width = trial.width;
      t.height = trial.height;
      t.periodic = trial.periodic;
      cut_into_cell(cell_polygons(trial, cells), t, -1, -1);
      double sharpest = 2.0 * std::numbers::pi, shortest = 1e300;
      for (const Region& r : t.regions) sharpest = std::min(sharpest, region_sharpest(t, r));
      for (const TessEdge& e : t.edges) shortest = std::min(shortest, norm(t.vertices[e.v1] - t.vertices[e.v0]));
      score = std::min(1.0, sharpest / kMinCorner) + std::min(1.0, shortest / edge);
    }
    if (score > best_score) {
      best_score = score;
      best = std::move(trial);
      st.window_origin = origin;
      st.pushed_vertices = pushed;
      st.side_jogs = jogs;
    }
    if (score >= 2.0) break;  // nothing sharp, nothing short: no better window to find
  }
  g = std::move(best);
}

std::vector<Segment> graph_segments(const TorusGraph& g) {
  std::vector<Segment> out;
  for (const EdgeRef& e : unique_edges(g)) {
    const auto& ring = g.rings[e.cell];
    out.push_back({g.point(ring[e.at]), g.point(ring[(e.at + 1) % ring.size()])});
  }
  return out;
}

}  // namespace

CellSide cell_side(const Tessellation& t, Vec2 a, Vec2 b) { return side_along(Box{{0.0, 0.0}, {t.width, t.height}}, a, b); }

double region_area(const Tessellation& t, const Region& r) {
  double a = 0.0;
  for (std::size_t q = 0; q < r.rings.size(); ++q) {
    std::vector<Vec2> pts;
    for (int v : r.rings[q]) pts.push_back(t.vertices[v]);
    a += (q == 0 ? 1.0 : -1.0) * polygon_area(pts);
  }
  return a;
}

Tessellation tessellate(const TessellationOptions& o, Rng& rng) {
  check_options(o);
  const double W = o.width, H = o.height;
  const int n = o.grains;
  std::vector<Vec2> seeds = o.seeds;
  if (seeds.empty()) {
    seeds.resize(n);
    for (Vec2& s : seeds) {
      const double x = uniform01(rng), y = uniform01(rng);
      s = {x * W, y * H};
    }
  } else if (o.periodic) {
    for (Vec2& s : seeds) s = reduce_periodic(s, W, H);  // x = W is x = 0
  }
  std::vector<double> weights(n, 0.0);
  if (o.size_cv > 0.0) {
    // Lognormal radii with the asked coefficient of variation, scaled so their disks
    // would cover half the cell; weights are the radii squared.
    const double sigma = std::sqrt(std::log1p(o.size_cv * o.size_cv));
    double disks = 0.0;
    for (double& w : weights) {
      const double r = std::exp(sigma * normal(rng));
      w = r * r;
      disks += std::numbers::pi * w;
    }
    const double scale = 0.5 * W * H / disks;
    for (double& w : weights) w *= scale;
  }
  const double spacing = std::sqrt(W * H / n);
  const double merge = 1e-9 * spacing;
  TorusGraph g = power_diagram(seeds, weights, W, H, o.periodic, merge);
  for (int it = 0; it < o.lloyd_iterations; ++it) {
    if (o.deadline.passed()) o.deadline.check("after " + std::to_string(it) + " Lloyd iterations");
    for (int c = 0; c < n; ++c) {
      if (g.rings[c].empty()) continue;
      const auto poly = counted_polygon(g, c);
      if (poly.size() < 3) continue;
      const Vec2 centroid = polygon_centroid(poly);
      seeds[c] = o.periodic ? reduce_periodic(centroid, W, H) : centroid;
    }
    g = power_diagram(seeds, weights, W, H, o.periodic, merge);
  }

  Tessellation t;
  t.width = W;
  t.height = H;
  t.periodic = o.periodic;
  t.phases = o.phases;
  TessellationStats& st = t.stats;
  {
    std::vector<double> d;
    for (int c : live(g)) d.push_back(std::sqrt(4.0 * polygon_area(counted_polygon(g, c)) / std::numbers::pi));
    double sd = 0.0;
    mean_std(d, &st.diameter_mean, &sd);
  }
  st.removed_grains = n - g.live_cells();
  st.edge_threshold = o.min_edge * st.diameter_mean;
  if (st.edge_threshold > 0.0) {
    int vanished = 0;
    st.collapsed_edges = collapse_short_edges(g, st.edge_threshold, &vanished);
    st.removed_grains += vanished;
  }
  // Lengths below this count as short when placing the window.
  const double scale = st.edge_threshold > 0.0 ? st.edge_threshold : 0.1 * st.diameter_mean;

  const std::vector<int> cells = live(g);
  const auto neighbours = cell_neighbours(g, cells);
  {
    double edges = 0.0, nb = 0.0, shortest = 1e300;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      edges += static_cast<double>(g.rings[cells[k]].size());
      nb += static_cast<double>(neighbours[k].size());
    }
    for (const Segment& s : graph_segments(g)) shortest = std::min(shortest, norm(s.b - s.a));
    st.edges_per_grain_mean = edges / static_cast<double>(cells.size());
    st.neighbours_mean = nb / static_cast<double>(cells.size());
    st.shortest_torus_edge = shortest;
  }

  std::vector<int> hard;  // phases grains take
  for (int p = 0; p < static_cast<int>(o.phases.size()); ++p)
    if (o.phase_mode == PhaseMode::grain || p != o.matrix_phase) hard.push_back(p);

  std::vector<CutPolygon> polys;
  int matrix_grain = -1;
  std::vector<int> grain_cell;  // torus cell of each grain
  if (o.phase_mode == PhaseMode::grain) {
    place_window(g, cells, scale, st);
    std::vector<double> areas;
    for (int c : cells) areas.push_back(polygon_area(counted_polygon(g, c)));
    auto label = assign_phases(areas, neighbours, o.phases, hard, W * H, o.arrangement, rng);
    if (o.contiguity) {
      // Trades keep the phase's area within half a percent of the cell of its target.
      const SharedBoundaries shared = shared_boundaries(g, cells);
      const double target_area = target_fraction(o.phases, o.contiguity_phase) * W * H, slack = 0.005 * W * H;
      const std::vector<int> start = label;
      const double reached =
          arrange_contiguity(label, areas, shared, o.contiguity_phase, *o.contiguity, target_area, slack, rng);
      if (std::abs(reached - *o.contiguity) > kContiguityTolerance) {
        // Out of reach: how far the trades go either way, from the same start.
        std::pair<double, double> range;
        for (double* end : {&range.first, &range.second}) {
          std::vector<int> trial = start;
          *end = arrange_contiguity(trial, areas, shared, o.contiguity_phase, end == &range.first ? 0.0 : 1.0,
                                    target_area, slack, rng);
        }
        st.contiguity_range = range;
      }
    }
    polys = cell_polygons(g, cells);
    for (std::size_t k = 0; k < polys.size(); ++k) polys[k].phase = label[k];
    grain_cell = cells;
  } else {
    const double f_m = target_fraction(o.phases, o.matrix_phase);
    std::vector<std::vector<Vec2>> cell_poly;
    for (int c : cells) cell_poly.push_back(g.polygon(c));
    auto grain_area = [&](double off) {
      double a = 0.0;
      for (const auto& p : cell_poly) {
        auto s = shrink_polygon(p, off);
        if (!o.periodic && !s.empty()) s = clip_to_cell(std::move(s), W, H);
        if (s.size() >= 3) a += polygon_area(s);
      }
      return a;
    };
    const std::string what = "binder matrix fraction " + to_text(f_m);
    if (!(f_m > 0.0) || !(f_m < 1.0)) throw ConfigError(what + " cannot be reached: it must lie strictly between 0 and 1");
    const double target = (1.0 - f_m) * W * H;  // grain area left after shrinking
    double lo = 0.0, hi = spacing;
    while (grain_area(hi) > target) {
      lo = hi;
      hi *= 2.0;
      if (hi > 1e3 * std::max(W, H)) throw ConfigError(what + " cannot be reached by any offset");
    }
    for (int it = 0; it < 100 && hi - lo > 1e-13 * spacing; ++it) {
      const double mid = 0.5 * (lo + hi);
      (grain_area(mid) > target ? lo : hi) = mid;
    }
    st.binder_offset = 0.5 * (lo + hi);
    // Layers thinner than kMinBinderLayer of the grain spacing cannot be meshed well (the
    // pockets where they meet give slivers): say which fraction would do.
    const double layer = 2.0 * st.binder_offset;
    if (layer < kMinBinderLayer * spacing) {
      const double needed = f_m * kMinBinderLayer * spacing / layer;  // layers grow about linearly
      throw ConfigError(what + " makes layers " + to_text(layer, 3) + " thick, " + to_text(layer / spacing, 3) +
                        " of the grain spacing (at least " + to_text(kMinBinderLayer) +
                        " meshes well): raise it to at least " + to_text(std::ceil(needed * 1e4) / 1e4) +
                        " or use tessellation.phase_mode = grain");
    }
    std::vector<std::vector<Vec2>> shrunk;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      auto s = shrink_polygon(cell_poly[k], st.binder_offset);
      if (s.empty()) {
        ++st.removed_grains;  // swallowed by the matrix
        continue;
      }
      shrunk.push_back(std::move(s));
      grain_cell.push_back(cells[k]);
    }
    if (shrunk.empty()) throw ConfigError(what + " leaves no grain");
    if (o.periodic) {
      std::vector<Segment> segs;
      std::vector<Vec2> pts;
      for (const auto& s : shrunk)
        for (std::size_t k = 0; k < s.size(); ++k) {
          segs.push_back({s[k], s[(k + 1) % s.size()]});
          pts.push_back(s[k]);
        }
      st.window_origin = window_candidates(segs, pts, W, H, std::min(scale, st.binder_offset), 1).front();
    }
    // Square off shallow side crossings; each step costs the binder layer at most a
    // quarter of its thickness.
    for (auto& s : shrunk) {
      for (Vec2& p : s) p -= st.window_origin;
      st.side_jogs += square_shallow_crossings(s, W, H, o.periodic, kMinSideAngle, std::min(scale, 0.25 * st.binder_offset));
    }
    std::vector<double> areas;
    for (const auto& s : shrunk) {
      areas.push_back(polygon_area(o.periodic ? s : clip_to_cell(s, W, H)));
    }
    std::vector<std::vector<int>> none(shrunk.size());
    const auto label = assign_phases(areas, none, o.phases, hard, W * H, o.arrangement, rng);
    for (std::size_t k = 0; k < shrunk.size(); ++k) {
      CutPolygon poly{static_cast<int>(k), label[k], {}, {}};
      const std::size_t m = shrunk[k].size();
      for (std::size_t q = 0; q < m; ++q) {
        poly.corners.push_back({shrunk[k][q], 0, 0});
      }
      for (std::size_t q = 0; q < m; ++q) poly.edges.push_back({poly.corners[q].base, poly.corners[(q + 1) % m].base, 0, 0});
      polys.push_back(std::move(poly));
    }
    matrix_grain = static_cast<int>(shrunk.size());
    for (Vec2& s : g.seeds) s = o.periodic ? reduce_periodic(s - st.window_origin, W, H) : s;
  }

  cut_into_cell(polys, t, matrix_grain, matrix_grain >= 0 ? o.matrix_phase : -1);

  // Grains and statistics.
  const int grains = static_cast<int>(polys.size());
  t.grains.resize(grains + (matrix_grain >= 0 ? 1 : 0));
  std::vector<int> cell_to_grain(g.rings.size(), -1);
  for (int k = 0; k < grains; ++k) cell_to_grain[grain_cell[k]] = k;
  for (int k = 0; k < grains; ++k) {
    Grain& gr = t.grains[k];
    gr.id = k;
    gr.phase = polys[k].phase;
    gr.seed = g.seeds[grain_cell[k]];
  }
  if (matrix_grain >= 0) {
    Grain& m = t.grains[matrix_grain];
    m.id = matrix_grain;
    m.phase = o.matrix_phase;
    m.matrix = true;
    for (int k = 0; k < grains; ++k) {
      t.grains[k].neighbours = {matrix_grain};
      m.neighbours.push_back(k);
    }
  } else {
    for (int k = 0; k < grains; ++k)
      for (int nb : neighbours[k]) t.grains[k].neighbours.push_back(cell_to_grain[cells[nb]]);
  }
  for (const Region& r : t.regions) t.grains[r.grain].area += region_area(t, r);
  std::vector<double> areas, diameters;
  for (int k = 0; k < grains; ++k) {
    areas.push_back(t.grains[k].area);
    diameters.push_back(std::sqrt(4.0 * t.grains[k].area / std::numbers::pi));
  }
  st.grains = grains;
  mean_std(areas, &st.area_mean, &st.area_std);
  mean_std(diameters, &st.diameter_mean, &st.diameter_std);
  st.shortest_edge = 1e300;
  for (const TessEdge& e : t.edges) st.shortest_edge = std::min(st.shortest_edge, norm(t.vertices[e.v1] - t.vertices[e.v0]));
  double sharpest = 2.0 * std::numbers::pi;
  for (const Region& r : t.regions) sharpest = std::min(sharpest, region_sharpest(t, r));
  st.sharpest_corner_deg = sharpest / kDegree;
  st.phases.assign(o.phases.size(), {});
  for (std::size_t p = 0; p < o.phases.size(); ++p) st.phases[p].target_fraction = target_fraction(o.phases, static_cast<int>(p));
  for (const Grain& gr : t.grains) {
    st.phases[gr.phase].achieved_fraction += gr.area / (W * H);
    st.phases[gr.phase].grains += gr.matrix ? 0 : 1;
  }
  validate(t);
  const std::vector<PhaseDescriptors> descriptors = phase_descriptors(t);
  for (std::size_t p = 0; p < descriptors.size(); ++p) {
    st.phases[p].contiguity = descriptors[p].contiguity;
    st.phases[p].intercept_length = descriptors[p].intercept_length;
    st.phases[p].mean_free_path = descriptors[p].mean_free_path;
  }
  return t;
}

void validate(const Tessellation& t) {
  const double W = t.width, H = t.height;
  // Every index names something that exists (what follows relies on it).
  const int nv = static_cast<int>(t.vertices.size()), nr = static_cast<int>(t.regions.size());
  const auto vertex = [&](int v) { return v >= 0 && v < nv; };
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (t.grains[g].phase < 0 || t.grains[g].phase >= static_cast<int>(t.phases.size()))
      throw GeometryError("tessellation: grain " + std::to_string(g) + " names phase " +
                          std::to_string(t.grains[g].phase) + ", which does not exist");
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    const Region& region = t.regions[r];
    if (region.grain < 0 || region.grain >= static_cast<int>(t.grains.size()))
      throw GeometryError("tessellation: region " + std::to_string(r) + " names grain " + std::to_string(region.grain) +
                          ", which does not exist");
    if (region.phase < 0 || region.phase >= static_cast<int>(t.phases.size()))
      throw GeometryError("tessellation: region " + std::to_string(r) + " names phase " + std::to_string(region.phase) +
                          ", which does not exist");
    if (region.rings.empty()) throw GeometryError("tessellation: region " + std::to_string(r) + " has no ring");
    for (const auto& ring : region.rings)
      for (int v : ring)
        if (!vertex(v))
          throw GeometryError("tessellation: region " + std::to_string(r) + " names vertex " + std::to_string(v) +
                              ", which does not exist");
  }
  for (std::size_t k = 0; k < t.edges.size(); ++k) {
    const TessEdge& e = t.edges[k];
    if (!vertex(e.v0) || !vertex(e.v1) || e.left < -1 || e.left >= nr || e.right < -1 || e.right >= nr)
      throw GeometryError("tessellation: edge " + std::to_string(k) + " names a vertex or region that does not exist");
  }
  for (const auto* pairs : {&t.partners_x, &t.partners_y})
    for (const auto& [a, b] : *pairs)
      if (!vertex(a) || !vertex(b)) throw GeometryError("tessellation: a periodic partner names a vertex that does not exist");
  double total = 0.0;
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    for (const auto& ring : t.regions[r].rings) {
      std::vector<Vec2> pts;
      for (int v : ring) pts.push_back(t.vertices[v]);
      if (!(polygon_area(pts) > 0.0)) throw GeometryError("tessellation: region " + std::to_string(r) + " has a ring that is not counter-clockwise");
      if (!ring_is_simple(pts)) throw GeometryError("tessellation: region " + std::to_string(r) + " has a ring that is not simple");
    }
    total += region_area(t, t.regions[r]);
  }
  if (std::abs(total - W * H) > 1e-9 * W * H)
    throw GeometryError("tessellation: region areas sum to " + std::to_string(total) + ", not W x H");
  // Grains are numbered by position; each grain's recorded area is the area of its regions
  // (what the mesh is checked against), and its regions carry its phase.
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (t.grains[g].id != static_cast<int>(g))
      throw GeometryError("tessellation: grain " + std::to_string(g) + " has id " + std::to_string(t.grains[g].id));
  std::vector<double> grain_area(t.grains.size(), 0.0);
  for (const Region& r : t.regions) {
    if (r.phase != t.grains[r.grain].phase)
      throw GeometryError("tessellation: a region of grain " + std::to_string(r.grain) + " has phase " +
                          std::to_string(r.phase) + ", its grain " + std::to_string(t.grains[r.grain].phase));
    grain_area[r.grain] += region_area(t, r);
  }
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (!(std::abs(grain_area[g] - t.grains[g].area) <= 1e-9 * grain_area[g]))
      throw GeometryError("tessellation: grain " + std::to_string(g) + " records area " + to_text(t.grains[g].area, 12) +
                          " but its regions cover " + to_text(grain_area[g], 12));
  // The edges are exactly the rings' segments, each once, with the regions on its sides.
  std::map<std::pair<int, int>, std::size_t> edge_of;
  std::vector<int> uses(t.edges.size(), 0);
  for (std::size_t k = 0; k < t.edges.size(); ++k) {
    const TessEdge& e = t.edges[k];
    if (e.v0 == e.v1) throw GeometryError("tessellation: edge " + std::to_string(k) + " joins a vertex to itself");
    if (e.left == e.right) throw GeometryError("tessellation: an edge has the same region on both sides");
    if ((e.left < 0 || e.right < 0) && cell_side(t, t.vertices[e.v0], t.vertices[e.v1]) == kNoSide)
      throw GeometryError("tessellation: an edge with one side lies inside the cell");
    if (!edge_of.emplace(std::minmax(e.v0, e.v1), k).second)
      throw GeometryError("tessellation: two edges join vertices " + std::to_string(e.v0) + " and " + std::to_string(e.v1));
  }
  for (std::size_t r = 0; r < t.regions.size(); ++r)
    for (std::size_t q = 0; q < t.regions[r].rings.size(); ++q) {
      const auto& ring = t.regions[r].rings[q];
      const bool hole = q > 0;  // counter-clockwise too: the region lies on its right
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const int a = ring[k], b = ring[(k + 1) % ring.size()];
        const auto it = edge_of.find(std::minmax(a, b));
        if (it == edge_of.end())
          throw GeometryError("tessellation: region " + std::to_string(r) + " runs from vertex " + std::to_string(a) +
                              " to " + std::to_string(b) + " along no edge");
        const TessEdge& e = t.edges[it->second];
        if (((e.v0 == a) != hole ? e.left : e.right) != static_cast<int>(r))
          throw GeometryError("tessellation: edge " + std::to_string(it->second) + " does not have region " +
                              std::to_string(r) + " on the side its ring says");
        ++uses[it->second];
      }
    }
  for (std::size_t k = 0; k < t.edges.size(); ++k)
    if (uses[k] != (t.edges[k].left >= 0) + (t.edges[k].right >= 0))
      throw GeometryError("tessellation: edge " + std::to_string(k) + " is not a segment of the regions it names");
  const double tol = 1e-12 * std::max(W, H);
  for (const auto& [l, r] : t.partners_x)
    if (std::abs(t.vertices[r].x - t.vertices[l].x - W) > tol || std::abs(t.vertices[r].y - t.vertices[l].y) > tol)
      throw GeometryError("tessellation: x partners do not match");
  for (const auto& [b, u] : t.partners_y)
    if (std::abs(t.vertices[u].y - t.vertices[b].y - H) > tol || std::abs(t.vertices[u].x - t.vertices[b].x) > tol)
      throw GeometryError("tessellation: y partners do not match");
}

}  // namespace grainmesh
