#include "tessellate/binder.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/binder_contacts.hpp"
#include "tessellate/contiguity.hpp"
#include "tessellate/cut.hpp"
#include "tessellate/phases.hpp"
#include "tessellate/window.hpp"

namespace grainmesh {
namespace {

// Binder layers (twice the shrink offset) thinner than this share of the grain spacing
// sqrt(W H / N) are refused: the pockets where they meet mesh into slivers.
constexpr double kMinBinderLayer = 2e-3;

// The offset t that leaves the grains 1 - f_m of the cell, `grain_area(t)` falling as t
// grows (bisection to 1e-13 of the spacing); refuses a fraction out of reach and layers
// (twice the offset) thinner than kMinBinderLayer of the grain spacing, naming the
// fraction that would do.
template <typename GrainArea>
double binder_offset(const GrainArea& grain_area, const TessellationOptions& o, double f_m, double spacing) {
  const double W = o.width, H = o.height;
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

// The square steps' half-width at offset t: a step costs the layer at most a quarter of its thickness.
double step_width(double scale, double t) { return std::min(scale, 0.25 * t); }

// How many of `contacts` to make, and the offset with them, for the contiguity target:
// the fewest whose contiguity reaches it, or one fewer when that is nearer (bisection on
// the count; the contiguity grows with it). Out of reach: every contact, and the range.
std::pair<int, double> contacts_for_target(const std::vector<std::vector<Vec2>>& cell_poly,
                                           const std::vector<Contact>& contacts, const TessellationOptions& o,
                                           double f_m, double spacing, double scale, Vec2 origin,
                                           TessellationStats& st) {
  auto bridged = [&](int count, double t) {
    return bridged_grains(cell_poly, contacts, count, t, origin, o.width, o.height, o.periodic, step_width(scale, t));
  };
  auto offset = [&](int count) {
    return binder_offset([&](double t) { return bridged(count, t).area; }, o, f_m, spacing);
  };
  auto contiguity = [&](int count) { return bridged(count, offset(count)).contiguity(); };
  const double target = *o.contiguity;
  int hi = static_cast<int>(contacts.size());
  const double most = contiguity(hi);
  if (most < target - kContiguityTolerance) {
    st.contiguity_range = std::pair{0.0, most};
    return {hi, offset(hi)};
  }
  const int best = contacts_nearest(hi, target, contiguity);
  return {best, offset(best)};
}

// A grain's corners after square steps: the steps' new points are its own; every other
// corner keeps what it was (a shared one its neighbour's bits), and an edge stays shared
// only where no step went into it.
std::vector<BinderCorner> squared(const std::vector<BinderCorner>& grain, double W, double H, bool periodic, double step,
                                  int* jogs) {
  std::vector<Vec2> pts = points_of(grain);
  *jogs += square_shallow_crossings(pts, W, H, periodic, kMinSideAngle, step);
  std::vector<BinderCorner> out;
  std::size_t next = 0;
  for (const Vec2& p : pts) {
    if (next < grain.size() && grain[next].p == p) {
      out.push_back(grain[next++]);
    } else {
      if (!out.empty()) out.back().shared = -1;
      out.push_back({p, p, 0, 0, -1});
    }
  }
  return out;
}

// A grain as the cut takes it: each corner by its own bits (a borrowed one by its
// neighbour's, with the lattice shift), each shared edge by the one canonical line.
CutPolygon cut_polygon(const std::vector<BinderCorner>& grain, int id, int phase, const std::vector<CutEdge>& shared) {
  CutPolygon poly{id, phase, {}, {}};
  const std::size_t m = grain.size();
  for (const BinderCorner& c : grain) poly.corners.push_back({c.base, c.i, c.j});
  for (std::size_t q = 0; q < m; ++q) {
    const BinderCorner& c = grain[q];
    if (c.shared >= 0) {
      CutEdge e = shared[static_cast<std::size_t>(c.shared)];
      e.i = c.i, e.j = c.j;
      poly.edges.push_back(e);
    } else {
      poly.edges.push_back({c.p, grain[(q + 1) % m].p, 0, 0});
    }
  }
  return poly;
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
  // Every grain wrapped: the offset, and the window placed clear of the grains' corners.
  st.binder_offset = binder_offset(
      [&](double off) {
        double a = 0.0;
        for (const auto& p : cell_poly) {
          auto s = shrink_polygon(p, off);
          if (!o.periodic && !s.empty()) s = clip_to_cell(std::move(s), W, H);
          if (s.size() >= 3) a += polygon_area(s);
        }
        return a;
      },
      o, f_m, spacing);
  if (o.periodic) {
    std::vector<Segment> segs;
    std::vector<Vec2> pts;
    for (const auto& p : cell_poly) {
      const auto s = shrink_polygon(p, st.binder_offset);
      for (std::size_t k = 0; k < s.size(); ++k) {
        segs.push_back({s[k], s[(k + 1) % s.size()]});
        pts.push_back(s[k]);
      }
    }
    if (pts.empty()) throw ConfigError(what + " leaves no grain");
    st.window_origin = window_candidates(segs, pts, W, H, std::min(scale, st.binder_offset), 1).front();
  }
  // A contiguity target: grains touching across the interfaces left without binder.
  std::vector<Contact> contacts;
  int count = 0;
  if (o.contiguity) {
    contacts = contact_candidates(g, cells, rng);
    std::tie(count, st.binder_offset) =
        contacts_for_target(cell_poly, contacts, o, f_m, spacing, scale, st.window_origin, st);
  }
  const BridgedGrains bridged = bridged_grains(cell_poly, contacts, count, st.binder_offset, st.window_origin, W, H,
                                               o.periodic, step_width(scale, st.binder_offset));
  std::vector<std::vector<BinderCorner>> grains;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (bridged.grains[k].empty()) {
      ++st.removed_grains;  // swallowed by the matrix
      continue;
    }
    // Square off shallow side crossings (never at a contact: those stay clear of the lines).
    grains.push_back(squared(bridged.grains[k], W, H, o.periodic, step_width(scale, st.binder_offset), &st.side_jogs));
    out.grain_cell.push_back(cells[k]);
  }
  if (grains.empty()) throw ConfigError(what + " leaves no grain");
  std::vector<double> areas;
  for (const auto& s : grains) {
    const std::vector<Vec2> pts = points_of(s);
    areas.push_back(polygon_area(o.periodic ? pts : clip_to_cell(pts, W, H)));
  }
  std::vector<std::vector<int>> none(grains.size());
  const auto label = assign_phases(areas, none, o.phases, hard, W * H, o.arrangement, rng);
  for (std::size_t k = 0; k < grains.size(); ++k)
    out.polygons.push_back(cut_polygon(grains[k], static_cast<int>(k), label[k], bridged.shared_edge));
  out.matrix_grain = static_cast<int>(grains.size());
  for (Vec2& s : g.seeds) s = o.periodic ? reduce_periodic(s - st.window_origin, W, H) : s;
  return out;
}

std::vector<Vec2> shrink_polygon(const std::vector<Vec2>& ring, double t) {
  std::vector<Vec2> poly;
  for (const TaggedCorner& c : shrink_tagged(ring, t)) poly.push_back(c.p);
  return poly;
}

}  // namespace grainmesh
