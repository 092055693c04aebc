// tessellate(): seeds -> power diagram -> Lloyd -> regularisation -> phases -> window ->
// cut, and the checks and statistics of the result.
#include "tessellate/tessellate.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/binder.hpp"
#include "tessellate/contiguity.hpp"
#include "tessellate/cut.hpp"
#include "tessellate/descriptors.hpp"
#include "tessellate/phases.hpp"
#include "tessellate/radii.hpp"
#include "tessellate/regularise.hpp"
#include "tessellate/validate.hpp"
#include "tessellate/window.hpp"

namespace grainmesh {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// The corner angle that moving a vertex off a cell side may not go below.
constexpr double kMinCorner = 30.0 * kDegree;
// Vertices closer than this x the short-edge length to a cell side are moved off it, so
// a square step next to them still has legs of the full length.
constexpr double kPushDistance = 1.25;
// Cells up to this many grains try this many windows (x) as many (y) and keep the best.
constexpr std::size_t kTrialCells = 5000;
constexpr int kWindowTrials = 4;
// The polygon of a cell as it counts for areas and centroids: clipped when not periodic.
std::vector<Vec2> counted_polygon(const TorusGraph& g, int c) {
  auto poly = g.polygon(c);
  return g.periodic ? poly : clip_to_cell(std::move(poly), g.width, g.height);
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
    std::vector<Vec2> pts = ring_points(t.vertices, r.rings[q]);
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
  if (o.contiguity && (!(*o.contiguity > 0.0 && *o.contiguity < 1.0) || o.contiguity_phase < 0 ||
                       o.contiguity_phase >= static_cast<int>(o.phases.size()) ||
                       (o.phase_mode == PhaseMode::binder && (o.phases.size() != 2 || o.contiguity_phase == o.matrix_phase))))
    throw ConfigError("a contiguity target lies in (0, 1), for a phase (in binder mode the one grain phase)");
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

// The seeds (drawn from `rng`, or the given ones), their Laguerre weights (lognormal radii
// when size_cv > 0) and the power diagram after the Lloyd iterations; draws from `rng`
// in that order.
TorusGraph relaxed_diagram(const TessellationOptions& o, Rng& rng) {
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
    // Radii scaled so their disks would cover half the cell; weights are radii squared.
    const std::vector<double> radii = lognormal_radii(n, o.size_cv, rng);
    double disks = 0.0;
    for (int c = 0; c < n; ++c) {
      weights[c] = radii[c] * radii[c];
      disks += std::numbers::pi * weights[c];
    }
    const double scale = 0.5 * W * H / disks;
    for (double& w : weights) w *= scale;
  }
  const double merge = 1e-9 * std::sqrt(W * H / n);
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

  return g;
}

// The diagram's statistics before the cut: the mean equivalent diameter, grains removed,
// short edges collapsed (edges below min_edge x that diameter).
void collapse_and_measure(TorusGraph& g, const TessellationOptions& o, TessellationStats& st) {
  const int n = o.grains;
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
}

// Grain mode: the cells' polygons with the phases assigned (to the contiguity target, if
// one is set), after the window is placed.
std::vector<CutPolygon> grain_polygons(TorusGraph& g, const std::vector<int>& cells,
                                       const std::vector<std::vector<int>>& neighbours, const TessellationOptions& o,
                                       double scale, const std::vector<int>& hard, TessellationStats& st, Rng& rng) {
  const double W = o.width, H = o.height;
  place_window(g, cells, scale, st);
  std::vector<double> areas;
  for (int c : cells) areas.push_back(polygon_area(counted_polygon(g, c)));
  auto label = assign_phases(areas, neighbours, o.phases, hard, W * H, o.arrangement, rng);
  if (o.contiguity) {
    // Trades keep the phase's area within half a percent of the cell of its target.
    const SharedBoundaries shared = shared_boundaries(g, cells);
    const double target_area = target_fraction(o.phases, o.contiguity_phase) * W * H, slack = 0.005 * W * H;
    st.contiguity_range = reach_contiguity(label, areas, shared, o.contiguity_phase, *o.contiguity, target_area, slack,
                                           kContiguityTolerance, rng);
  }
  std::vector<CutPolygon> polys = cell_polygons(g, cells);
  for (std::size_t k = 0; k < polys.size(); ++k) polys[k].phase = label[k];
  return polys;
}

// The grains of the cut cell (ids, phases, seeds, neighbours, areas) and the statistics
// of the result; validates it.
void finish_tessellation(Tessellation& t, const TorusGraph& g, const std::vector<CutPolygon>& polys,
                         const std::vector<int>& grain_cell, int matrix_grain, const std::vector<int>& cells,
                         const std::vector<std::vector<int>>& neighbours, const TessellationOptions& o) {
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
  measure_tessellation(t);
}

}  // namespace




void measure_tessellation(Tessellation& t) {
  TessellationStats& st = t.stats;
  const auto grains = static_cast<int>(std::count_if(t.grains.begin(), t.grains.end(),
                                                     [](const Grain& g) { return !g.matrix; }));
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
  st.phases.assign(t.phases.size(), {});
  for (std::size_t p = 0; p < t.phases.size(); ++p) st.phases[p].target_fraction = target_fraction(t.phases, static_cast<int>(p));
  for (const Grain& gr : t.grains) {
    st.phases[gr.phase].achieved_fraction += gr.area / (t.width * t.height);
    st.phases[gr.phase].grains += gr.matrix ? 0 : 1;
  }
  validate(t);
  const std::vector<PhaseDescriptors> descriptors = phase_descriptors(t);
  for (std::size_t p = 0; p < descriptors.size(); ++p) {
    st.phases[p].contiguity = descriptors[p].contiguity;
    st.phases[p].intercept_length = descriptors[p].intercept_length;
    st.phases[p].mean_free_path = descriptors[p].mean_free_path;
  }
}

Tessellation tessellate(const TessellationOptions& o, Rng& rng) {
  check_options(o);
  TorusGraph g = relaxed_diagram(o, rng);
  Tessellation t;
  t.width = o.width;
  t.height = o.height;
  t.periodic = o.periodic;
  t.phases = o.phases;
  TessellationStats& st = t.stats;
  collapse_and_measure(g, o, st);
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
    polys = grain_polygons(g, cells, neighbours, o, scale, hard, st, rng);
    grain_cell = cells;
  } else {
    BinderGrains b = binder_grains(g, cells, o, scale, hard, st, rng);
    polys = std::move(b.polygons);
    grain_cell = std::move(b.grain_cell);
    matrix_grain = b.matrix_grain;
  }
  cut_into_cell(polys, t, matrix_grain, matrix_grain >= 0 ? o.matrix_phase : -1);
  finish_tessellation(t, g, polys, grain_cell, matrix_grain, cells, neighbours, o);
  return t;
}

}  // namespace grainmesh
