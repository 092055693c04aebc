#include "tessellate/binder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/cut.hpp"
#include "tessellate/phases.hpp"
#include "tessellate/window.hpp"

namespace grainmesh {
namespace {

// Binder layers (twice the shrink offset) thinner than this share of the grain spacing
// sqrt(W H / N) are refused: the pockets where they meet mesh into slivers.
constexpr double kMinBinderLayer = 2e-3;

// The inward offset of the torus cells' polygons that leaves the grains 1 - f_m of the
// cell (bisection to 1e-13 of the spacing); refuses a fraction out of reach and layers
// (twice the offset) thinner than kMinBinderLayer of the grain spacing, naming the
// fraction that would do.
double binder_offset(const std::vector<std::vector<Vec2>>& cell_poly, const TessellationOptions& o, double f_m,
                     double spacing) {
  const double W = o.width, H = o.height;
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
  const double offset = 0.5 * (lo + hi);
  // Layers thinner than kMinBinderLayer of the grain spacing cannot be meshed well (the
  // pockets where they meet give slivers): say which fraction would do.
  const double layer = 2.0 * offset;
  if (layer < kMinBinderLayer * spacing) {
    const double needed = f_m * kMinBinderLayer * spacing / layer;  // layers grow about linearly
    throw ConfigError(what + " makes layers " + to_text(layer, 3) + " thick, " + to_text(layer / spacing, 3) +
                      " of the grain spacing (at least " + to_text(kMinBinderLayer) +
                      " meshes well): raise it to at least " + to_text(std::ceil(needed * 1e4) / 1e4) +
                      " or use tessellation.phase_mode = grain");
  }
  return offset;
}

}  // namespace

BinderGrains binder_grains(TorusGraph& g, const std::vector<int>& cells, const TessellationOptions& o, double scale,
                           const std::vector<int>& hard, TessellationStats& st, Rng& rng) {
  const double W = o.width, H = o.height;
  const double spacing = std::sqrt(W * H / o.grains);
  BinderGrains out;
  const double f_m = target_fraction(o.phases, o.matrix_phase);
  std::vector<std::vector<Vec2>> cell_poly;
  for (int c : cells) cell_poly.push_back(g.polygon(c));
  const std::string what = "binder matrix fraction " + to_text(f_m);
  st.binder_offset = binder_offset(cell_poly, o, f_m, spacing);
  std::vector<std::vector<Vec2>> shrunk;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    auto s = shrink_polygon(cell_poly[k], st.binder_offset);
    if (s.empty()) {
      ++st.removed_grains;  // swallowed by the matrix
      continue;
    }
    shrunk.push_back(std::move(s));
    out.grain_cell.push_back(cells[k]);
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
    out.polygons.push_back(std::move(poly));
  }
  out.matrix_grain = static_cast<int>(shrunk.size());
  for (Vec2& s : g.seeds) s = o.periodic ? reduce_periodic(s - st.window_origin, W, H) : s;
  return out;
}

std::vector<Vec2> shrink_polygon(const std::vector<Vec2>& ring, double t) {
  std::vector<Vec2> poly = ring;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n && poly.size() >= 3; ++k) {
    const Vec2 a = ring[k], b = ring[(k + 1) % n];
    const Vec2 dir = b - a;
    const double len = norm(dir);
    if (len == 0.0) continue;
    const Vec2 inward = perp(dir) / len;  // left of a counter-clockwise edge
    poly = clip_half_plane(poly, inward, dot(inward, a) + t);
  }
  if (poly.size() < 3 || !(polygon_area(poly) > 0.0)) return {};
  return poly;
}

}  // namespace grainmesh
