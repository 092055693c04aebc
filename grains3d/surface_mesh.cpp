#include "grains3d/surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "common/errors.hpp"
#include "common/geometry.hpp"
#include "common/ring.hpp"
#include "mesh/delaunay.hpp"

namespace grainmesh {

namespace {

struct Edges {
  std::map<std::pair<int, int>, int> id;  // (min, max) vertex ids -> edge
  std::vector<std::pair<int, int>> ends;  // canonical direction: lexicographically smaller point first
  std::vector<std::vector<int>> seeds;    // point ids of the seeds from ends.first to ends.second
};

// Every edge once, cut into equal pieces of length nearest h. The direction is fixed by
// the points alone (lexicographic), so an edge and its periodic image are seeded alike:
// their seeds differ by exactly the box's edge in the side's coordinate.
Edges seed_edges(const Tessellation3& t, double h, std::vector<Vec3>& points) {
  Edges e;
  for (const Face3& f : t.faces)
    for (std::size_t k = 0; k < f.ring.size(); ++k) {
      int a = f.ring[k], b = f.ring[(k + 1) % f.ring.size()];
      if (!e.id.emplace(std::minmax(a, b), static_cast<int>(e.ends.size())).second) continue;
      const Vec3 pa = t.vertices[a], pb = t.vertices[b];
      if (std::tie(pb.x, pb.y, pb.z) < std::tie(pa.x, pa.y, pa.z)) std::swap(a, b);
      e.ends.emplace_back(a, b);
      const Vec3 p = t.vertices[a], q = t.vertices[b];
      const int n = std::max(1, static_cast<int>(std::lround(norm(q - p) / h)));
      std::vector<int> seeds;
      for (int s = 1; s < n; ++s) {
        const double u = static_cast<double>(s) / n;
        seeds.push_back(static_cast<int>(points.size()));
        points.push_back({p.x + u * (q.x - p.x), p.y + u * (q.y - p.y), p.z + u * (q.z - p.z)});
      }
      e.seeds.push_back(std::move(seeds));
    }
  return e;
}

// The boundary of face f as point ids, counter-clockwise about its normal: its vertices
// with the seeds of each edge between.
std::vector<int> face_boundary(const Face3& f, const Edges& e) {
  std::vector<int> out;
  for (std::size_t k = 0; k < f.ring.size(); ++k) {
    const int a = f.ring[k], b = f.ring[(k + 1) % f.ring.size()];
    const int id = e.id.at(std::minmax(a, b));
    out.push_back(a);
    const auto& seeds = e.seeds[id];
    if (e.ends[id].first == a) out.insert(out.end(), seeds.begin(), seeds.end());
    else out.insert(out.end(), seeds.rbegin(), seeds.rend());
  }
  return out;
}

Vec3 newell_normal(const std::vector<Vec3>& p, const std::vector<int>& ring) {
  Vec3 n{};
  for (std::size_t k = 0; k < ring.size(); ++k) n += cross(p[ring[k]], p[ring[(k + 1) % ring.size()]]);
  return n / norm(n);
}

// Meshes one planar face: lattice points inside, a constrained Delaunay triangulation,
// Laplacian smoothing of the inner points with flips. New points are appended to
// `points` (on the box side `side` exactly, when axis >= 0); returns the triangles.
std::vector<std::array<int, 3>> mesh_face(const std::vector<int>& boundary, std::pair<int, int> side, Vec3 box,
                                          double h, std::vector<Vec3>& points) {
  const Vec3 n = newell_normal(points, boundary);
  const Vec3 o = points[boundary[0]];
  Vec3 u = points[boundary[1]] - o;
  u = u / norm(u);
  const Vec3 w = cross(n, u);
  std::vector<Vec2> xy;
  for (int id : boundary) xy.push_back({dot(points[id] - o, u), dot(points[id] - o, w)});
  const std::size_t nb = xy.size();
  Box bounds;
  for (Vec2 p : xy) bounds.extend(p);
  const double row = h * std::sqrt(3.0) / 2.0;
  const std::vector<Vec2> ring(xy.begin(), xy.end());
  for (int j = 0; bounds.lo.y + (j + 0.5) * row < bounds.hi.y; ++j)
    for (int i = 0; bounds.lo.x + (i + 0.5) * h < bounds.hi.x; ++i) {
      const Vec2 p{bounds.lo.x + (i + (j % 2 == 0 ? 0.5 : 1.0)) * h, bounds.lo.y + (j + 0.5) * row};
      if (!inside_ring(ring, p)) continue;
      double clear = 1e300;
      for (std::size_t k = 0; k < nb; ++k) clear = std::min(clear, segment_distance2(p, xy[k], xy[(k + 1) % nb]));
      if (clear >= 0.36 * h * h) xy.push_back(p);
    }
  std::vector<std::array<int, 2>> constraints;
  for (std::size_t k = 0; k < nb; ++k) constraints.push_back({static_cast<int>(k), static_cast<int>((k + 1) % nb)});
  Triangulation tri = constrained_delaunay_triangulation(xy, constraints);
  for (int pass = 0; pass < 5 && xy.size() > nb; ++pass) {
    std::vector<Vec2> sum(xy.size(), Vec2{});
    std::vector<int> count(xy.size(), 0);
    for (const auto& tr : tri.triangles)
      for (int k = 0; k < 3; ++k)
        for (int m = 1; m < 3; ++m) {
          sum[tr[k]] += xy[tr[(k + m) % 3]];
          ++count[tr[k]];
        }
    for (std::size_t p = nb; p < xy.size(); ++p)
      if (count[p] > 0) xy[p] = sum[p] / static_cast<double>(count[p]);
    if (!restore_delaunay(tri, xy)) tri = constrained_delaunay_triangulation(xy, constraints);
  }
  std::vector<int> id(boundary);
  for (std::size_t p = nb; p < xy.size(); ++p) {
    Vec3 q = o + xy[p].x * u + xy[p].y * w;
    if (side.first >= 0) q[side.first] = side.second == 0 ? 0.0 : box[side.first];
    id.push_back(static_cast<int>(points.size()));
    points.push_back(q);
  }
  if (tri.triangles.empty()) throw GeometryError("3D surface mesh: a face could not be triangulated");
  std::vector<std::array<int, 3>> out;
  for (const auto& tr : tri.triangles) out.push_back({id[tr[0]], id[tr[1]], id[tr[2]]});
  return out;
}

}  // namespace

SurfaceMesh mesh_surfaces(const Tessellation3& t, double h) {
  if (!(h > 0.0)) throw GeometryError("3D surface mesh: the element size must be positive");
  SurfaceMesh s;
  s.points = t.vertices;
  const Edges edges = seed_edges(t, h, s.points);
  const Vec3 box = t.size();
  s.faces.resize(t.faces.size());
  std::vector<std::pair<int, int>> interior(t.faces.size());  // [first, last) of each face's own points
  std::vector<int> deferred;                                 // high-side faces, copied below
  for (int f = 0; f < static_cast<int>(t.faces.size()); ++f) {
    const auto side = box_side(t, t.faces[f].ring);
    if (t.periodic && side.first >= 0 && side.second == 1) {
      deferred.push_back(f);
      continue;
    }
    const int first = static_cast<int>(s.points.size());
    s.faces[f] = mesh_face(face_boundary(t.faces[f], edges), side, box, h, s.points);
    interior[f] = {first, static_cast<int>(s.points.size())};
  }
  if (!t.periodic) return s;

  // The images: a vertex's partner, an edge's image edge, a low face's image face.
  for (int a = 0; a < 3; ++a) {
    std::map<int, int> image(t.partners.axis[a].begin(), t.partners.axis[a].end());
    auto& pairs = s.pairs.axis[a];
    pairs = t.partners.axis[a];
    std::vector<int> node_image(s.points.size(), -1);
    for (const auto& [lo, hi] : t.partners.axis[a]) node_image[lo] = hi;
    for (std::size_t e = 0; e < edges.ends.size(); ++e) {
      const auto [p, q] = edges.ends[e];
      if (!image.contains(p) || !image.contains(q)) continue;
      const auto it = edges.id.find(std::minmax(image.at(p), image.at(q)));
      if (it == edges.id.end()) continue;  // p and q on the side, the edge across the box
      const auto& mine = edges.seeds[e];
      const auto& theirs = edges.seeds[it->second];
      if (mine.size() != theirs.size() || edges.ends[it->second].first != image.at(p))
        throw GeometryError("3D surface mesh: an edge on the box is seeded unlike its periodic image");
      for (std::size_t k = 0; k < mine.size(); ++k) {
        node_image[mine[k]] = theirs[k];
        pairs.emplace_back(mine[k], theirs[k]);
      }
    }
    std::map<std::vector<int>, int> low_faces;  // by sorted image ring
    for (int f = 0; f < static_cast<int>(t.faces.size()); ++f) {
      const auto side = box_side(t, t.faces[f].ring);
      if (side.first != a || side.second != 0) continue;
      std::vector<int> key;
      for (int v : t.faces[f].ring) key.push_back(image.at(v));
      std::sort(key.begin(), key.end());
      low_faces.emplace(std::move(key), f);
    }
    for (int f : deferred) {
      if (box_side(t, t.faces[f].ring).first != a) continue;
      std::vector<int> key = t.faces[f].ring;
      std::sort(key.begin(), key.end());
      const auto it = low_faces.find(key);
      if (it == low_faces.end()) throw GeometryError("3D surface mesh: a face on the box has no periodic image");
      const int low = it->second;
      for (int p = interior[low].first; p < interior[low].second; ++p) {
        Vec3 q = s.points[p];
        q[a] = box[a];
        node_image[p] = static_cast<int>(s.points.size());
        pairs.emplace_back(p, node_image[p]);
        s.points.push_back(q);
      }
      node_image.resize(s.points.size(), -1);
      for (const auto& tr : s.faces[low]) {
        for (int v : tr)
          if (node_image[v] < 0) throw GeometryError("3D surface mesh: a point on the box has no periodic image");
        s.faces[f].push_back({node_image[tr[0]], node_image[tr[1]], node_image[tr[2]]});
      }
      // The copy turns as the low face does; the high face's ring may turn the other way.
      const Vec3 want = newell_normal(s.points, t.faces[f].ring);
      const auto& tr = s.faces[f].front();
      if (dot(cross(s.points[tr[1]] - s.points[tr[0]], s.points[tr[2]] - s.points[tr[0]]), want) < 0.0)
        for (auto& x : s.faces[f]) std::swap(x[1], x[2]);
    }
  }
  return s;
}

}  // namespace grainmesh
