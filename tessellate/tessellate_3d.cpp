// tessellate_3d(): seeds -> Laguerre diagram -> Lloyd -> window -> exact cut -> phases,
// the regions' shared faces and periodic partners, and the statistics of the result.
#include "tessellate/tessellate_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/binder_3d.hpp"
#include "tessellate/contiguity.hpp"
#include "tessellate/descriptors.hpp"
#include "tessellate/laguerre_3d.hpp"
#include "tessellate/phases.hpp"
#include "tessellate/radii.hpp"
#include "tessellate/regularise.hpp"
#include "tessellate/regularise_3d.hpp"
#include "tessellate/validate_3d.hpp"

namespace grainmesh {

namespace {

void check_options(const Tessellation3Options& o) {
  if (!(o.width > 0.0) || !(o.height > 0.0) || !(o.depth > 0.0))
    throw ConfigError("box width, height and depth must be positive");
  if (o.grains < 1) throw ConfigError("the number of grains must be at least 1");
  if (o.contiguity && (!(*o.contiguity > 0.0 && *o.contiguity < 1.0) || o.contiguity_phase < 0 ||
                       o.contiguity_phase >= static_cast<int>(o.phases.size())))
    throw ConfigError("a contiguity target lies in (0, 1), for a phase");
  if (o.phase_mode == PhaseMode::binder && (o.matrix_phase < 0 || o.matrix_phase >= static_cast<int>(o.phases.size()) ||
                                            o.phases.size() < 2))
    throw ConfigError("binder mode needs a matrix phase and a grain phase");
  if (!o.seeds.empty() && static_cast<int>(o.seeds.size()) != o.grains)
    throw ConfigError("the number of grains must equal the number of given seeds");
  const Vec3 box{o.width, o.height, o.depth};
  for (const Vec3& s : o.seeds)
    for (int a = 0; a < 3; ++a) {
      // A bounded box's seed on a side would be its own mirror image.
      const bool inside = o.periodic ? s[a] >= 0.0 && s[a] <= box[a] : s[a] > 0.0 && s[a] < box[a];
      if (!inside) throw ConfigError("seed (" + to_text(s.x) + ", " + to_text(s.y) + ", " + to_text(s.z) + ") lies " +
                                     (o.periodic ? "outside" : "outside or on a side of") + " the box");
    }
  if (o.phases.empty()) throw ConfigError("at least one phase is needed");
}

double reduce(double v, double period) {
  const double r = v - std::floor(v / period) * period;
  return r >= period ? 0.0 : r;  // v just below 0 rounds up to the period
}

// Seeds (drawn from `rng`, in (0, 1) of the box so none lies on a side, or the given
// ones) and their Laguerre weights: radii scaled so their spheres would fill half the
// box, squared; all 0 for a Voronoi diagram.
void draw_seeds(const Tessellation3Options& o, Rng& rng, std::vector<Vec3>& seeds, std::vector<double>& weights) {
  const Vec3 box{o.width, o.height, o.depth};
  seeds = o.seeds;
  if (seeds.empty()) {
    seeds.resize(o.grains);
    for (Vec3& s : seeds)
      for (int a = 0; a < 3; ++a) s[a] = (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53 * box[a];
  } else if (o.periodic) {
    for (Vec3& s : seeds)
      for (int a = 0; a < 3; ++a) s[a] = reduce(s[a], box[a]);
  }
  weights.assign(o.grains, 0.0);
  if (o.size_cv > 0.0) {
    const std::vector<double> radii = lognormal_radii(o.grains, o.size_cv, rng);
    double spheres = 0.0;
    for (double r : radii) spheres += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const double scale = std::cbrt(0.5 * o.width * o.height * o.depth / spheres);
    for (int i = 0; i < o.grains; ++i) weights[i] = radii[i] * scale * radii[i] * scale;
  }
}

// The `count` widest gaps between the values `c` on a circle of length `period`: their
// middles and half-widths, widest first.
std::vector<std::pair<double, double>> widest_gaps(std::vector<double> c, double period, int count) {
  std::vector<std::pair<double, double>> gaps;  // half-width, middle
  if (c.empty()) return {{0.5 * period, 0.0}};
  for (double& v : c) v = reduce(v, period);
  std::sort(c.begin(), c.end());
  gaps.emplace_back(0.5 * (c.front() + period - c.back()), reduce(c.back() + 0.5 * (c.front() + period - c.back()), period));
  for (std::size_t k = 1; k < c.size(); ++k) gaps.emplace_back(0.5 * (c[k] - c[k - 1]), 0.5 * (c[k] + c[k - 1]));
  std::sort(gaps.begin(), gaps.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  gaps.resize(std::min<std::size_t>(gaps.size(), count));
  std::vector<std::pair<double, double>> out;
  for (const auto& [half, middle] : gaps) out.emplace_back(middle, half);
  return out;
}

// How near the diagram's edges come to the box's edge lines (where two sides meet) with
// the box at `origin`: the smallest distance from an edge to a line along axis c through
// (origin[a], origin[b]) and its periodic images. An edge passing a line that closely is
// cut by both sides into a piece about that short. Stops at `floor` once it is that near
// (the window choice needs no more: that origin has lost).
double line_clearance(const std::vector<std::pair<Vec3, Vec3>>& edges, Vec3 origin, Vec3 box, double floor) {
  double best = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 3; ++c) {
    const int a = (c + 1) % 3, b = (c + 2) % 3;
    for (const auto& [p, q] : edges) {
      // The edge projected along c, shifted by whole periods so its start lies in
      // [0, box[a]) x [0, box[b]) about the line through the origin.
      const Vec2 u0{p[a] - origin[a], p[b] - origin[b]};
      const Vec2 shift{-std::floor(u0.x / box[a]) * box[a], -std::floor(u0.y / box[b]) * box[b]};
      const Vec2 u = u0 + shift, w = Vec2{q[a] - origin[a], q[b] - origin[b]} + shift;
      for (int i = -1; i <= 2; ++i)
        for (int j = -1; j <= 2; ++j)
          best = std::min(best, std::sqrt(segment_distance2({i * box[a], j * box[b]}, u, w)));
      if (best <= floor) return best;
    }
  }
  return best;
}

// Where the box's sides go on the torus: of the widest gaps between the diagram's
// vertices along each axis (so no side passes near a vertex), the combination whose edge
// lines the diagram's edges pass furthest from.
Vec3 window_origin(const CellMoments& m, Vec3 box) {
  constexpr int kCandidates = 4;  // per axis
  std::array<std::vector<std::pair<double, double>>, 3> gaps;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> c;
    for (const Vec3& v : m.vertices) c.push_back(v[a]);
    gaps[a] = widest_gaps(std::move(c), box[a], kCandidates);
  }
  Vec3 best{};
  double best_score = -1.0;
  for (const auto& [x, hx] : gaps[0])
    for (const auto& [y, hy] : gaps[1])
      for (const auto& [z, hz] : gaps[2]) {
        const Vec3 origin{x, y, z};
        // The score is at most the gaps' half-widths: when they cannot beat the best, the
        // edges need not be measured.
        if (!(std::min({hx, hy, hz}) > best_score)) continue;
        const double score = std::min({hx, hy, hz, line_clearance(m.edges, origin, box, best_score)});
        if (score > best_score) {
          best_score = score;
          best = origin;
        }
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

// Areas shared between grains (each grain's neighbours and the area it shares with each):
// what contiguity is made of. Faces on the box count once through their low-side copy,
// paired with the high-side face; a grain's boundary with its own periodic image is none.
SharedBoundaries grain_boundary_areas(const Tessellation3& t) {
  std::vector<std::map<int, double>> shared(t.grains.size());
  auto add = [&](int ga, int gb, double a) {
    if (ga == gb) return;
    shared[static_cast<std::size_t>(ga)][gb] += a;
    shared[static_cast<std::size_t>(gb)][ga] += a;
  };
  std::map<std::vector<int>, int> high_faces;  // high-side box face by its sorted ring
  for (int f = 0; f < static_cast<int>(t.faces.size()); ++f) {
    const Face3& face = t.faces[f];
    if (face.front >= 0) {
      add(t.regions[face.back].grain, t.regions[face.front].grain, face_area(t, face));
      continue;
    }
    std::vector<int> key = face.ring;
    std::sort(key.begin(), key.end());
    high_faces.emplace(std::move(key), f);
  }
  if (t.periodic)
    for (int a = 0; a < 3; ++a) {
      std::map<int, int> image(t.partners.axis[a].begin(), t.partners.axis[a].end());
      for (const Face3& face : t.faces) {
        if (face.front >= 0 || box_side(t, face.ring) != std::pair{a, 0}) continue;
        std::vector<int> key;
        for (int id : face.ring) key.push_back(image.at(id));
        std::sort(key.begin(), key.end());
        const auto it = high_faces.find(key);
        if (it == high_faces.end()) throw GeometryError("3D cut: a face on a side of the box has no periodic image");
        add(t.regions[face.back].grain, t.regions[t.faces[it->second].back].grain, face_area(t, face));
      }
    }
  SharedBoundaries out;
  for (const auto& m : shared) out.emplace_back(m.begin(), m.end());
  return out;
}

// The same per pair of phases.
std::vector<double> phase_boundary_areas(const Tessellation3& t) {
  const int np = static_cast<int>(t.phases.size());
  std::vector<double> area(static_cast<std::size_t>(np * np), 0.0);
  const SharedBoundaries shared = grain_boundary_areas(t);
  for (std::size_t g = 0; g < shared.size(); ++g)
    for (const auto& [m, a] : shared[g])
      area[static_cast<std::size_t>(t.grains[g].phase * np + t.grains[static_cast<std::size_t>(m)].phase)] += a;
  return area;
}

// The shortest edge, smallest face and sharpest interior dihedral angle (radians) of the
// regions.
struct Extremes {
  double shortest_edge = std::numeric_limits<double>::infinity();
  double smallest_face = std::numeric_limits<double>::infinity();
  double sharpest_dihedral = std::numbers::pi;
};
Extremes extremes(const Tessellation3& t) {
  Extremes x;
  for (const Face3& f : t.faces) {
    x.smallest_face = std::min(x.smallest_face, face_area(t, f));
    for (std::size_t k = 0; k < f.ring.size(); ++k)
      x.shortest_edge = std::min(x.shortest_edge, norm(t.vertices[f.ring[k]] - t.vertices[f.ring[(k + 1) % f.ring.size()]]));
  }
  // The interior dihedral angle of each region at each edge of its faces (a reflex one
  // by how far it falls short of a full turn).
  for (int r = 0; r < static_cast<int>(t.regions.size()); ++r) {
    std::map<std::pair<int, int>, std::pair<Vec3, Vec3>> first;  // normal, a point off the edge
    for (int f : t.regions[r].faces) {
      const Face3& face = t.faces[f];
      Vec3 n = ring_normal(t.vertices, face.ring), c{};
      n = (face.back == r ? 1.0 : -1.0) * (n / norm(n));
      for (int v : face.ring) c += t.vertices[v];
      c = c / static_cast<double>(face.ring.size());
      for (std::size_t k = 0; k < face.ring.size(); ++k) {
        const int a = face.ring[k], b = face.ring[(k + 1) % face.ring.size()];
        const auto [it, added] = first.emplace(std::minmax(a, b), std::pair{n, c});
        if (added) continue;
        const double angle = interior_dihedral(it->second.first, n, c, t.vertices[a]);
        x.sharpest_dihedral = std::min({x.sharpest_dihedral, angle, 2.0 * std::numbers::pi - angle});
      }
    }
  }
  return x;
}

}  // namespace

void measure_tessellation(Tessellation3& t) {
  Tessellation3Stats& st = t.stats;
  std::vector<double> volumes, diameters;
  double faces = 0.0, neighbours = 0.0;
  st.grains = 0;
  for (const Grain3& g : t.grains) {
    if (g.matrix) continue;
    ++st.grains;
    volumes.push_back(g.volume);
    diameters.push_back(std::cbrt(6.0 * g.volume / std::numbers::pi));
    faces += g.faces;
    for (int m : g.neighbours) neighbours += t.grains[static_cast<std::size_t>(m)].matrix ? 0.0 : 1.0;
  }
  mean_std(volumes, &st.volume_mean, &st.volume_std);
  mean_std(diameters, &st.diameter_mean, &st.diameter_std);
  st.faces_per_grain_mean = faces / st.grains;
  st.neighbours_mean = neighbours / st.grains;

  const Extremes x = extremes(t);
  st.shortest_edge = x.shortest_edge;
  st.smallest_face = x.smallest_face;
  st.sharpest_dihedral_deg = x.sharpest_dihedral * 180.0 / std::numbers::pi;

  const int np = static_cast<int>(t.phases.size());
  const double total = t.width * t.height * t.depth;
  const std::vector<double> shared = phase_boundary_areas(t);
  st.phases.assign(np, {});
  for (int p = 0; p < np; ++p) st.phases[p].target_fraction = target_fraction(t.phases, p);
  for (const Grain3& g : t.grains) {
    st.phases[g.phase].achieved_fraction += g.volume / total;
    ++st.phases[g.phase].grains;
  }
  for (int p = 0; p < np; ++p) {
    double own = 0.0, other = 0.0;
    for (int q = 0; q < np; ++q) (q == p ? own : other) += shared[p * np + q];
    own *= 0.5;  // counted from both grains
    PhaseStats& s = st.phases[p];
    const Stereology d = stereology(3, s.achieved_fraction * total, own, other);  // descriptors.hpp
    s.contiguity = d.contiguity;
    s.intercept_length = d.intercept_length;
    s.mean_free_path = d.mean_free_path;
  }
  // Binder mode: the binder touches only grains, so its layer (2 x its volume / its area
  // with them) is half its mean free path.
  for (const Grain3& g : t.grains)
    if (g.matrix && std::isfinite(st.phases[g.phase].mean_free_path))
      st.binder_layer = 0.5 * st.phases[g.phase].mean_free_path;
}

void assemble_box_cut(const LaguerreCut& cut, const std::vector<int>& grain_of_piece, Tessellation3& t) {
  t.vertices = cut.vertices;
  std::map<std::vector<int>, int> by_key;
  for (const BoxPiece& piece : cut.pieces) {
    const int r = static_cast<int>(t.regions.size());
    const int g = grain_of_piece[static_cast<std::size_t>(r)];
    Region3 region{.grain = g, .phase = t.grains[g].phase, .faces = {}, .volume = 0.0};
    for (const auto& ring : piece.faces) {
      std::vector<int> key = ring;
      std::sort(key.begin(), key.end());
      const auto [it, added] = by_key.emplace(std::move(key), static_cast<int>(t.faces.size()));
      if (added) {
        t.faces.push_back({.ring = ring, .back = r, .front = -1});
      } else {
        Face3& f = t.faces[it->second];
        if (f.front >= 0) throw GeometryError("3D cut: a face is shared by three regions");
        f.front = r;
      }
      region.faces.push_back(it->second);
    }
    t.regions.push_back(std::move(region));
  }
}

PeriodicPairs box_partners(const Tessellation3& t) {
  PeriodicPairs pairs;
  const Vec3 box = t.size();
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    std::map<std::pair<double, double>, int> high;
    for (int id = 0; id < static_cast<int>(t.vertices.size()); ++id)
      if (t.vertices[id][a] == box[a]) high.emplace(std::pair{t.vertices[id][u], t.vertices[id][v]}, id);
    for (int id = 0; id < static_cast<int>(t.vertices.size()); ++id) {
      if (t.vertices[id][a] != 0.0) continue;
      const auto it = high.find({t.vertices[id][u], t.vertices[id][v]});
      if (it == high.end())
        throw GeometryError("3D cut: vertex " + std::to_string(id) + " on a side of the box has no periodic image");
      pairs.axis[a].emplace_back(id, it->second);
    }
    if (pairs.axis[a].size() != high.size())
      throw GeometryError("3D cut: a vertex on a high side of the box has no periodic image");
  }
  return pairs;
}

namespace {

// Lloyd's relaxation of `seeds` (o.lloyd_iterations steps, each seed to its cell's
// centroid); the moments of the diagram it leaves.
CellMoments relax(const Tessellation3Options& o, const std::vector<double>& weights, std::vector<Vec3>& seeds) {
  const Vec3 box{o.width, o.height, o.depth};
  CellMoments m = laguerre_moments(seeds, weights, box, o.periodic);
  for (int it = 0; it < o.lloyd_iterations; ++it) {
    if (o.deadline.passed()) o.deadline.check("after " + std::to_string(it) + " Lloyd iterations");
    for (int i = 0; i < o.grains; ++i) {
      // A move below a trillionth of the box is rounding, not relaxation: a lattice of
      // seeds (cells that meet eight at a vertex) stays exactly one, where rounding would
      // leave vertices a rounding apart that no double can tell apart.
      if (m.volume[i] <= 0.0 || norm(m.centroid[i] - seeds[i]) < 1e-12 * norm(box)) continue;
      seeds[i] = m.centroid[i];
      if (o.periodic)
        for (int a = 0; a < 3; ++a) seeds[i][a] = reduce(seeds[i][a], box[a]);
    }
    m = laguerre_moments(seeds, weights, box, o.periodic);
  }
  return m;
}

// The grains' phases by volume (the grains' volumes known), to the contiguity target if
// one is set (label trades on the shared face areas; out of reach: the range in the stats).
std::vector<int> grain_phases(Tessellation3& t, const Tessellation3Options& o, Rng& rng) {
  std::vector<double> volumes;
  std::vector<std::vector<int>> neighbours;
  for (const Grain3& g : t.grains) {
    volumes.push_back(g.volume);
    neighbours.push_back(g.neighbours);
  }
  std::vector<int> all(o.phases.size());
  for (int p = 0; p < static_cast<int>(all.size()); ++p) all[p] = p;
  const double V = o.width * o.height * o.depth;
  std::vector<int> label = assign_phases(volumes, neighbours, o.phases, all, V, o.arrangement, rng);
  if (!o.contiguity) return label;
  // Trades keep the phase's volume within half a percent of the cell of its target.
  const SharedBoundaries shared = grain_boundary_areas(t);
  const double target_volume = target_fraction(o.phases, o.contiguity_phase) * V, slack = 0.005 * V;
  t.stats.contiguity_range = reach_contiguity(label, volumes, shared, o.contiguity_phase, *o.contiguity, target_volume,
                                              slack, kContiguityTolerance, rng);
  return label;
}

// Edges shorter than `threshold` collapsed (regularise_3d.hpp), the extremes before kept.
void regularise(Tessellation3& t, const Tessellation3Options& o, double threshold) {
  const Extremes before = extremes(t);
  Tessellation3Stats& st = t.stats;
  st.shortest_edge_before = before.shortest_edge;
  st.sharpest_dihedral_before_deg = before.sharpest_dihedral * 180.0 / std::numbers::pi;
  st.edge_threshold = o.min_edge > 0.0 ? threshold : 0.0;
  const Regularisation done = collapse_short_edges(t, st.edge_threshold);
  st.collapsed_edges = done.collapsed_edges;
  st.removed_regions = done.removed_regions;
}

// The exact cut of the cells into the box; in binder mode each cell split first into its
// core and frustums, as `layout` (chosen on the whole cells) says.
LaguerreCut box_cut(const Tessellation3Options& o, const std::vector<Vec3>& seeds, const std::vector<double>& weights,
                    Rng& rng, BinderLayout3& layout) {
  const Vec3 box{o.width, o.height, o.depth};
  if (o.phase_mode != PhaseMode::binder) return laguerre_box_cut(seeds, weights, box, o.periodic);
  const bool voronoi = std::all_of(weights.begin(), weights.end(), [&](double w) { return w == weights[0]; });
  return laguerre_box_cut(seeds, weights, box, o.periodic, [&](const std::vector<std::vector<WholeFace>>& whole) {
    Layering layering{.centres = layer_centres(whole, seeds, voronoi), .scale = 1.0};
    layout = binder_layout_3d(whole, layering.centres, o.width * o.height * o.depth,
                              target_fraction(o.phases, o.matrix_phase), o.contiguity, rng);
    layering.scale = layout.scale;
    return std::optional<Layering>(std::move(layering));
  });
}

}  // namespace

Tessellation3 tessellate_3d(const Tessellation3Options& o, Rng& rng) {
  check_options(o);
  const Vec3 box{o.width, o.height, o.depth};
  std::vector<Vec3> seeds;
  std::vector<double> weights;
  draw_seeds(o, rng, seeds, weights);
  const CellMoments m = relax(o, weights, seeds);

  Tessellation3 t;
  t.width = o.width;
  t.height = o.height;
  t.depth = o.depth;
  t.periodic = o.periodic;
  t.phases = o.phases;
  if (o.periodic) {
    const Vec3 origin = window_origin(m, box);
    for (Vec3& s : seeds)
      for (int a = 0; a < 3; ++a) s[a] = reduce(s[a] - origin[a], box[a]);
    t.stats.window_origin = origin;
  }
  BinderLayout3 layout;
  const LaguerreCut cut = box_cut(o, seeds, weights, rng, layout);

  // Grains: the seeds with a cell, numbered in seed order.
  std::vector<int> grain_of_seed(o.grains, -1), seed_of_grain;
  for (int i = 0; i < o.grains; ++i)
    if (cut.cell_faces[i] > 0) {
      grain_of_seed[i] = static_cast<int>(seed_of_grain.size());
      seed_of_grain.push_back(i);
    }
  t.stats.removed_grains = o.grains - static_cast<int>(seed_of_grain.size());
  for (int g = 0; g < static_cast<int>(seed_of_grain.size()); ++g) {
    const int i = seed_of_grain[g];
    Grain3 grain{.id = g, .phase = 0, .seed = seeds[i], .volume = 0.0, .faces = cut.cell_faces[i], .neighbours = {}};
    for (int j : cut.neighbours[i]) grain.neighbours.push_back(grain_of_seed[j]);
    t.grains.push_back(std::move(grain));
  }
  const double diameter =
      std::cbrt(6.0 * o.width * o.height * o.depth / (std::numbers::pi * static_cast<double>(seed_of_grain.size())));
  if (o.phase_mode == PhaseMode::binder) {
    t.stats.binder_scale = layout.scale;
    t.stats.binder_contacts = layout.contacts;
    t.stats.contiguity_range = layout.range;
    const int matrix = static_cast<int>(t.grains.size());
    Grain3 binder{.id = matrix, .phase = o.matrix_phase, .seed = {}, .volume = 0.0, .faces = 0, .neighbours = {}};
    binder.matrix = true;
    for (Grain3& g : t.grains) {
      g.neighbours.push_back(matrix);
      binder.neighbours.push_back(g.id);
    }
    t.grains.push_back(std::move(binder));
    std::vector<int> grain_of_piece;
    for (const BoxPiece& p : cut.pieces)
      grain_of_piece.push_back(p.face < 0 || layout.contact[p.seed][p.face] ? grain_of_seed[p.seed] : matrix);
    assemble_box_cut(cut, grain_of_piece, t);
    // No collapse: it would move the binder off its exact fraction, and on the cells tried
    // it made no better mesh (the short edges it may collapse are few).
    regularise(t, o, 0.0);
  } else {
    std::vector<int> grain_of_piece;
    for (const BoxPiece& p : cut.pieces) grain_of_piece.push_back(grain_of_seed[p.seed]);
    assemble_box_cut(cut, grain_of_piece, t);
    regularise(t, o, o.min_edge * diameter);
  }
  // Phases by volume, from the pieces' volumes (known before the labels are).
  for (Region3& r : t.regions) {
    r.volume = region_volume(t, r);
    t.grains[r.grain].volume += r.volume;
  }
  if (o.periodic) t.partners = box_partners(t);
  const std::vector<int> label = o.phase_mode == PhaseMode::binder ? binder_phases(t, o, rng) : grain_phases(t, o, rng);
  for (Grain3& g : t.grains) g.phase = label[g.id];
  for (Region3& r : t.regions) r.phase = t.grains[r.grain].phase;
  measure_tessellation(t);
  validate(t);
  return t;
}

}  // namespace grainmesh
