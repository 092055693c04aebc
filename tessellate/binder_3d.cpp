#include "tessellate/binder_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/contiguity.hpp"
#include "tessellate/phases.hpp"
#include "tessellate/solid_moments.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

namespace {

// A whole cell's pieces at scale 1 about its centre: each face's area and pyramid volume,
// and each edge as the two faces meeting there with the triangle from the centre to it.
struct CellPieces {
  std::vector<double> area, pyramid;
  struct Side {
    int face_a = 0, face_b = 0;
    double triangle = 0.0;
  };
  std::vector<Side> sides;
};

using Key = std::array<double, 3>;
Key key(Vec3 p) { return {p.x, p.y, p.z}; }

CellPieces cell_pieces(const std::vector<WholeFace>& faces, Vec3 c) {
  CellPieces out;
  std::map<std::pair<Key, Key>, int> runs;  // edge a -> b: the face running it so
  for (int k = 0; k < static_cast<int>(faces.size()); ++k) {
    const std::vector<Vec3>& r = faces[k].ring;
    Vec3 n{};
    for (std::size_t e = 1; e + 1 < r.size(); ++e) n += cross(r[e] - r[0], r[e + 1] - r[0]);
    const double area = 0.5 * norm(n);
    out.area.push_back(area);
    out.pyramid.push_back(dot(n, r[0] - c) / 6.0);
    for (std::size_t e = 0; e < r.size(); ++e) runs[{key(r[e]), key(r[(e + 1) % r.size()])}] = k;
  }
  for (int k = 0; k < static_cast<int>(faces.size()); ++k) {
    const std::vector<Vec3>& r = faces[k].ring;
    for (std::size_t e = 0; e < r.size(); ++e) {
      const Vec3 a = r[e], b = r[(e + 1) % r.size()];
      const auto it = runs.find({key(b), key(a)});
      if (it == runs.end()) throw GeometryError("3D binder: a cell is not closed at an edge");
      if (it->second < k) continue;  // each edge once
      out.sides.push_back({k, it->second, 0.5 * norm(cross(a - c, b - c))});
    }
  }
  return out;
}

struct Layout {
  std::vector<CellPieces> cells;
  std::vector<std::pair<int, int>> order;  // contact candidates (seed, face), drawn order
  const std::vector<std::vector<WholeFace>>* whole = nullptr;
  double binder_volume = 0.0;

  // Contact flags for the first n candidates (both sides of each face).
  std::vector<std::vector<char>> contacts(int n) const {
    std::vector<std::vector<char>> c(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) c[i].assign(cells[i].area.size(), 0);
    for (int m = 0; m < n; ++m) {
      const auto [i, k] = order[static_cast<std::size_t>(m)];
      const WholeFace& f = (*whole)[i][k];
      c[i][k] = 1;
      c[f.across][f.across_face] = 1;
    }
    return c;
  }
  // The scale leaving the binder its volume with these contacts; 0 when none does.
  double scale(const std::vector<std::vector<char>>& c) const {
    double pyramids = 0.0;
    for (std::size_t i = 0; i < cells.size(); ++i)
      for (std::size_t k = 0; k < c[i].size(); ++k)
        if (!c[i][k]) pyramids += cells[i].pyramid[k];
    if (!(binder_volume < pyramids)) return 0.0;
    const double s = std::cbrt(1.0 - binder_volume / pyramids);
    return s >= kMinCoreScale3 ? s : 0.0;
  }
  double contiguity(const std::vector<std::vector<char>>& c, double s) const {
    double touching = 0.0, wetted = 0.0;  // grain-grain (both sides), grain-binder
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const CellPieces& p = cells[i];
      for (std::size_t k = 0; k < c[i].size(); ++k) {
        if (c[i][k])
          touching += p.area[k];
        else
          wetted += s * s * p.area[k];  // the core's face in the binder
      }
      for (const CellPieces::Side& side : p.sides)
        if (c[i][side.face_a] != c[i][side.face_b]) wetted += (1.0 - s * s) * side.triangle;
    }
    return touching + wetted > 0.0 ? touching / (touching + wetted) : 0.0;
  }
};

}  // namespace

std::vector<Vec3> layer_centres(const std::vector<std::vector<WholeFace>>& whole, const std::vector<Vec3>& seeds,
                                bool voronoi) {
  std::vector<Vec3> out = seeds;
  if (voronoi) return out;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    if (whole[i].empty()) continue;
    SolidMoments m(whole[i][0].ring[0]);
    for (const WholeFace& f : whole[i])
      for (std::size_t e = 1; e + 1 < f.ring.size(); ++e) m.add_triangle(f.ring[0], f.ring[e], f.ring[e + 1]);
    out[i] = m.centroid();
  }
  return out;
}

BinderLayout3 binder_layout_3d(const std::vector<std::vector<WholeFace>>& whole, const std::vector<Vec3>& centres,
                               double volume, double fraction, std::optional<double> contiguity, Rng& rng) {
  Layout l;
  l.whole = &whole;
  l.binder_volume = fraction * volume;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    l.cells.push_back(cell_pieces(whole[i], centres[i]));
    for (int k = 0; k < static_cast<int>(whole[i].size()); ++k)
      if (whole[i][k].across > static_cast<int>(i)) l.order.emplace_back(static_cast<int>(i), k);
  }
  for (std::size_t k = l.order.size(); k > 1; --k)
    std::swap(l.order[k - 1], l.order[static_cast<std::size_t>(uniform01(rng) * static_cast<double>(k))]);

  BinderLayout3 out;
  auto settle = [&](int n) {
    out.contact = l.contacts(n);
    out.contacts = n;
    out.scale = l.scale(out.contact);
    out.contiguity = l.contiguity(out.contact, out.scale);
  };
  settle(0);
  if (out.scale == 0.0)
    throw ConfigError("a binder fraction of " + to_text(fraction, 3) + " leaves the grains' cores below " +
                      to_text(kMinCoreScale3, 2) + " of their cells' size; ask for less binder");
  if (!contiguity) return out;
  // The most contacts the binder's fraction allows, then the fewest that reach the target.
  int lo = 0, hi = static_cast<int>(l.order.size());
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (l.scale(l.contacts(mid)) > 0.0)
      lo = mid;
    else
      hi = mid - 1;
  }
  const int most = lo;
  auto reached = [&](int n) {
    const auto c = l.contacts(n);
    return l.contiguity(c, l.scale(c));
  };
  settle(contacts_nearest(most, *contiguity, reached));
  if (std::abs(out.contiguity - *contiguity) > kContiguityTolerance) out.range = std::pair{0.0, reached(most)};
  return out;
}

std::vector<int> binder_phases(const Tessellation3& t, const Tessellation3Options& o, Rng& rng) {
  std::vector<double> volumes;
  std::vector<std::vector<int>> neighbours;
  for (const Grain3& g : t.grains)
    if (!g.matrix) {
      volumes.push_back(g.volume);
      neighbours.push_back({});
      for (int m : g.neighbours)
        if (!t.grains[static_cast<std::size_t>(m)].matrix) neighbours.back().push_back(m);
    }
  std::vector<int> hard;
  for (int p = 0; p < static_cast<int>(o.phases.size()); ++p)
    if (p != o.matrix_phase) hard.push_back(p);
  std::vector<int> label =
      assign_phases(volumes, neighbours, o.phases, hard, o.width * o.height * o.depth, o.arrangement, rng);
  label.push_back(o.matrix_phase);
  return label;
}

}  // namespace grainmesh
