#include "tessellate/exact_polyhedron.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace grainmesh {

// The part of `poly` on the side coord(axis) >= c (keep_above) or <= c, closed by a new
// face in the plane. Empty when nothing of positive volume is left.
ExactPolyhedron clip(const ExactPolyhedron& poly, int axis, const EK::FT& c, bool keep_above) {
  const std::size_t n = poly.points.size();
  std::vector<int> side(n);
  bool inside = false, outside = false;
  for (std::size_t k = 0; k < n; ++k) {
    const CGAL::Comparison_result r = CGAL::compare(coord(poly.points[k], axis), c);
    side[k] = r == CGAL::EQUAL ? 0 : ((r == CGAL::LARGER) == keep_above ? 1 : -1);
    inside = inside || side[k] > 0;
    outside = outside || side[k] < 0;
  }
  if (!inside) return {};
  if (!outside) return poly;
  ExactPolyhedron out;
  out.points = poly.points;
  std::map<std::pair<int, int>, int> crossing;
  auto cut = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = crossing.emplace(key, static_cast<int>(out.points.size()));
    if (added) {
      // From the lower id, so the point is computed the same way from either face.
      const EK::Point_3& p = poly.points[key.first];
      const EK::Point_3& q = poly.points[key.second];
      const EK::FT t = (c - coord(p, axis)) / (coord(q, axis) - coord(p, axis));
      out.points.push_back(p + (q - p) * t);
    }
    return it->second;
  };
  std::vector<int> on_plane;
  for (const auto& face : poly.faces) {
    std::vector<int> ring;
    bool keeps = false;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      if (side[a] >= 0) ring.push_back(a);
      if (side[a] == 0) on_plane.push_back(a);
      keeps = keeps || side[a] > 0;
      if (side[a] * side[b] < 0) {
        ring.push_back(cut(a, b));
        on_plane.push_back(ring.back());
      }
    }
    if (keeps && ring.size() >= 3) out.faces.push_back(std::move(ring));
  }
  std::sort(on_plane.begin(), on_plane.end());
  on_plane.erase(std::unique(on_plane.begin(), on_plane.end()), on_plane.end());
  // The new face: its points in the plane ordered by angle about their centroid, in the
  // (u, v) axes that make `axis` the right-hand normal; reversed to face outward.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  EK::FT cu(0), cv(0);
  for (int id : on_plane) {
    cu = cu + coord(out.points[id], u);
    cv = cv + coord(out.points[id], v);
  }
  cu = cu / EK::FT(static_cast<int>(on_plane.size()));
  cv = cv / EK::FT(static_cast<int>(on_plane.size()));
  auto half = [&](int id) {
    const auto du = CGAL::compare(coord(out.points[id], u), cu), dv = CGAL::compare(coord(out.points[id], v), cv);
    return dv == CGAL::LARGER || (dv == CGAL::EQUAL && du == CGAL::LARGER) ? 0 : 1;
  };
  std::sort(on_plane.begin(), on_plane.end(), [&](int a, int b) {
    const int ha = half(a), hb = half(b);
    if (ha != hb) return ha < hb;
    const EK::FT au = coord(out.points[a], u) - cu, av = coord(out.points[a], v) - cv;
    const EK::FT bu = coord(out.points[b], u) - cu, bv = coord(out.points[b], v) - cv;
    return CGAL::is_positive(au * bv - av * bu);
  });
  // Counter-clockwise about +axis; the outward normal is -axis when keeping above.
  if (keep_above) std::reverse(on_plane.begin(), on_plane.end());
  if (on_plane.size() >= 3) out.faces.push_back(std::move(on_plane));
  return out;
}

std::vector<ExactPolyhedron> core_and_frustums(const ExactPolyhedron& poly, const EK::Point_3& centre,
                                               const EK::FT& scale) {
  ExactPolyhedron core{.points = {}, .faces = poly.faces};
  for (const EK::Point_3& p : poly.points) core.points.push_back(centre + (p - centre) * scale);
  std::vector<ExactPolyhedron> out{core};
  const int m = static_cast<int>(poly.points.size());
  for (int k = 0; k < static_cast<int>(poly.faces.size()); ++k) {
    // Points: the face's corners, then their copies on the core (local ids shifted by m).
    const std::vector<int>& ring = poly.faces[k];
    ExactPolyhedron f;
    std::map<int, int> local;
    auto id = [&](int p) {
      const auto [it, added] = local.emplace(p, static_cast<int>(f.points.size()));
      if (added) f.points.push_back(p < m ? poly.points[p] : core.points[p - m]);
      return it->second;
    };
    std::vector<int> outer, inner;
    for (int p : ring) outer.push_back(id(p));
    for (auto it = ring.rbegin(); it != ring.rend(); ++it) inner.push_back(id(*it + m));
    f.faces = {outer, inner};
    // The side on edge a -> b runs it b -> a, as the frustum next to it runs it a -> b.
    for (std::size_t e = 0; e < ring.size(); ++e) {
      const int a = ring[e], b = ring[(e + 1) % ring.size()];
      f.faces.push_back({id(b), id(a), id(a + m), id(b + m)});
    }
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace grainmesh
