#include "grains3d/surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "common/errors.hpp"
#include "common/geometry.hpp"
#include "common/ring.hpp"
#include "mesh/delaunay.hpp"
#include "tessellate/solid_moments.hpp"
#include "tessellate/bent_face.hpp"

namespace grainmesh {

namespace {

// A bent face's pieces meeting at a larger angle than this keep their diagonal as an edge
// of the mesh (its volume exact there); across gentler folds the triangles run straight.
constexpr double kFold = 20.0 * std::numbers::pi / 180.0;

// A face to mesh: its ring (turning about its normal) and, for a bent face
// the regularisation split into planar pieces, those pieces and its inner vertices.
struct FaceToMesh {
  std::vector<int> ring;                   // vertex ids
  std::vector<std::array<int, 3>> pieces;  // empty: one planar face
  std::vector<int> inner;                  // tessellation vertices inside it (a fan's centre)
  std::vector<std::pair<int, int>> folds;  // diagonals between pieces bent by more than kFold, kept as edges
};

struct Edges {
  std::map<std::pair<int, int>, int> id;  // (min, max) vertex ids -> edge
  std::vector<std::pair<int, int>> ends;  // canonical direction: lexicographically smaller point first
  std::vector<std::vector<int>> seeds;    // point ids of the seeds from ends.first to ends.second
};

// Every edge once (the faces' rings and the folds kept), cut into equal pieces of length
// nearest h. The direction is fixed by the points alone (lexicographic), so an edge and its
// periodic image are seeded alike: their seeds differ by exactly the box's edge in the
// side's coordinate.
Edges seed_edges(const std::vector<std::pair<std::vector<int>, FaceToMesh>>& faces, double h, std::vector<Vec3>& points) {
  Edges e;
  auto seed = [&](int a, int b) {
    if (!e.id.emplace(std::minmax(a, b), static_cast<int>(e.ends.size())).second) return;
    const Vec3 pa = points[a], pb = points[b];
    if (std::tie(pb.x, pb.y, pb.z) < std::tie(pa.x, pa.y, pa.z)) std::swap(a, b);
    e.ends.emplace_back(a, b);
    const Vec3 p = points[a], q = points[b];
    const int n = std::max(1, static_cast<int>(std::lround(norm(q - p) / h)));
    std::vector<int> seeds;
    for (int s = 1; s < n; ++s) {
      const double u = static_cast<double>(s) / n;
      seeds.push_back(static_cast<int>(points.size()));
      points.push_back({p.x + u * (q.x - p.x), p.y + u * (q.y - p.y), p.z + u * (q.z - p.z)});
    }
    e.seeds.push_back(std::move(seeds));
  };
  for (const auto& [group, f] : faces) {
    for (std::size_t k = 0; k < f.ring.size(); ++k) seed(f.ring[k], f.ring[(k + 1) % f.ring.size()]);
    for (const auto& [a, b] : f.folds) seed(a, b);
  }
  return e;
}

// The seeds of edge a b, from a to b.
std::vector<int> edge_seeds(int a, int b, const Edges& e) {
  const int id = e.id.at(std::minmax(a, b));
  const auto& seeds = e.seeds[id];
  if (e.ends[id].first == a) return seeds;
  return {seeds.rbegin(), seeds.rend()};
}

// The boundary of a ring as point ids: its vertices with the seeds of each edge between.
std::vector<int> ring_boundary(const std::vector<int>& ring, const Edges& e) {
  std::vector<int> out;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    out.push_back(ring[k]);
    const auto seeds = edge_seeds(ring[k], ring[(k + 1) % ring.size()], e);
    out.insert(out.end(), seeds.begin(), seeds.end());
  }
  return out;
}

Vec3 unit_normal(const std::vector<Vec3>& p, const std::vector<int>& ring) {
  const Vec3 n = ring_normal(p, ring);
  return n / norm(n);
}

// A face in its plane: the first `nb` points its boundary, the rest up to the
// constraints' fixed; lattice points of spacing h added 0.6 h clear of the boundary, the
// fixed points and the constraints, a constrained Delaunay triangulation, Laplacian
// smoothing of the lattice points with flips (xy gets them).
Triangulation triangulate_plane(std::vector<Vec2>& xy, std::size_t nb, const std::vector<std::array<int, 2>>& constraints,
                                double h) {
  const std::size_t fixed = xy.size();
  Box bounds;
  for (Vec2 p : xy) bounds.extend(p);
  const double row = h * std::sqrt(3.0) / 2.0;
  const std::vector<Vec2> ring(xy.begin(), xy.begin() + static_cast<std::ptrdiff_t>(nb));
  for (int j = 0; bounds.lo.y + (j + 0.5) * row < bounds.hi.y; ++j)
    for (int i = 0; bounds.lo.x + (i + 0.5) * h < bounds.hi.x; ++i) {
      const Vec2 p{bounds.lo.x + (i + (j % 2 == 0 ? 0.5 : 1.0)) * h, bounds.lo.y + (j + 0.5) * row};
      if (!inside_ring(ring, p)) continue;
      double clear = 1e300;
      for (std::size_t k = 0; k < nb; ++k) clear = std::min(clear, segment_distance2(p, xy[k], xy[(k + 1) % nb]));
      for (std::size_t k = nb; k < fixed; ++k) clear = std::min(clear, norm2(p - xy[k]));
      for (std::size_t k = nb; k < constraints.size(); ++k)
        clear = std::min(clear, segment_distance2(p, xy[constraints[k][0]], xy[constraints[k][1]]));
      if (clear >= 0.36 * h * h) xy.push_back(p);
    }
  Triangulation tri = constrained_delaunay_triangulation(xy, constraints);
  for (int pass = 0; pass < 5 && xy.size() > fixed; ++pass) {
    std::vector<Vec2> sum(xy.size(), Vec2{});
    std::vector<int> count(xy.size(), 0);
    for (const auto& tr : tri.triangles)
      for (int k = 0; k < 3; ++k)
        for (int m = 1; m < 3; ++m) {
          sum[tr[k]] += xy[tr[(k + m) % 3]];
          ++count[tr[k]];
        }
    for (std::size_t p = fixed; p < xy.size(); ++p)
      if (count[p] > 0) xy[p] = sum[p] / static_cast<double>(count[p]);
    if (!restore_delaunay(tri, xy)) tri = constrained_delaunay_triangulation(xy, constraints);
  }
  return tri;
}

// Meshes one face in its plane (a bent face: in the plane of its boundary, each point
// lifted onto the piece under it): lattice points inside, a constrained Delaunay
// triangulation, Laplacian smoothing of the lattice points with flips. New points are
// appended to `points` (on the box side `side` exactly, when axis >= 0); returns the
// triangles and, for a bent face, the piece under each one's centroid.
std::vector<std::array<int, 3>> mesh_face(const FaceToMesh& face, const Edges& edges, std::pair<int, int> side,
                                          Vec3 box, double h, std::vector<Vec3>& points, std::vector<int>& piece_of) {
  const std::vector<int> boundary = ring_boundary(face.ring, edges);
  const Vec3 n = unit_normal(points, boundary);
  const Vec3 o = points[boundary[0]];
  Vec3 u = points[boundary[1]] - o;
  u = u / norm(u);
  const Vec3 w = cross(n, u);
  auto flat = [&](int id) { return Vec2{dot(points[id] - o, u), dot(points[id] - o, w)}; };
  std::vector<Vec2> xy;
  for (int id : boundary) xy.push_back(flat(id));
  const std::size_t nb = xy.size();
  for (int id : face.inner) xy.push_back(flat(id));
  std::vector<int> id(boundary);
  id.insert(id.end(), face.inner.begin(), face.inner.end());
  std::vector<std::array<int, 2>> constraints;
  for (std::size_t k = 0; k < nb; ++k) constraints.push_back({static_cast<int>(k), static_cast<int>((k + 1) % nb)});
  // The folds kept: their seeds fixed, their pieces constraints.
  for (const auto& [a, b] : face.folds) {
    const auto at = [&](int v) { return static_cast<int>(std::find(id.begin(), id.end(), v) - id.begin()); };
    int last = at(a);
    for (int v : edge_seeds(a, b, edges)) {
      id.push_back(v);
      xy.push_back(flat(v));
      constraints.push_back({last, static_cast<int>(xy.size()) - 1});
      last = static_cast<int>(xy.size()) - 1;
    }
    constraints.push_back({last, at(b)});
  }
  const std::size_t fixed = xy.size();
  const Triangulation tri = triangulate_plane(xy, nb, constraints, h);
  if (tri.triangles.empty()) throw GeometryError("3D surface mesh: a face could not be triangulated");
  // The piece under a point of the plane: the one whose smallest barycentric coordinate
  // there is largest (inside it: >= 0), with those coordinates.
  auto under = [&](Vec2 p) {
    std::pair<int, std::array<double, 3>> best{-1, {}};
    double best_min = -1e300;
    for (std::size_t k = 0; k < face.pieces.size(); ++k) {
      const Vec2 a = flat(face.pieces[k][0]), b = flat(face.pieces[k][1]), c = flat(face.pieces[k][2]);
      const double area = cross(b - a, c - a);
      const std::array<double, 3> l{cross(b - p, c - p) / area, cross(c - p, a - p) / area, cross(a - p, b - p) / area};
      const double m = std::min({l[0], l[1], l[2]});
      if (m > best_min) best_min = m, best = {static_cast<int>(k), l};
    }
    return best;
  };
  for (std::size_t p = fixed; p < xy.size(); ++p) {
    Vec3 q = o + xy[p].x * u + xy[p].y * w;
    if (!face.pieces.empty()) {
      const auto [k, l] = under(xy[p]);
      const auto& piece = face.pieces[k];
      q = l[0] * points[piece[0]] + l[1] * points[piece[1]] + l[2] * points[piece[2]];
    }
    if (side.first >= 0) q[side.first] = side.second == 0 ? 0.0 : box[side.first];
    id.push_back(static_cast<int>(points.size()));
    points.push_back(q);
  }
  std::vector<std::array<int, 3>> out;
  piece_of.clear();
  for (const auto& tr : tri.triangles) {
    out.push_back({id[tr[0]], id[tr[1]], id[tr[2]]});
    if (!face.pieces.empty()) piece_of.push_back(under((xy[tr[0]] + xy[tr[1]] + xy[tr[2]]) / 3.0).first);
  }
  return out;
}

FaceToMesh alone(const Face3& f) {
  FaceToMesh out;
  out.ring = f.ring;
  return out;
}

// The planar pieces a bent face was split into (the triangles between two regions) as one
// surface: when they turn alike, their outer edges make one ring, seen from whose plane
// every piece turns as the ring does (and, once meshed, no triangle edge lies in a side
// of the box: in_a_side).
std::optional<FaceToMesh> whole_face(const Tessellation3& t, const std::vector<int>& group) {
  const std::vector<Vec3>& points = t.vertices;
  if (group.size() < 2) return std::nullopt;
  std::set<std::pair<int, int>> directed;  // edge a -> b as a piece turns
  for (int f : group) {
    if (t.faces[f].back != t.faces[group.front()].back) return std::nullopt;
    const auto& r = t.faces[f].ring;
    for (int k = 0; k < 3; ++k)
      if (!directed.emplace(r[k], r[(k + 1) % 3]).second) return std::nullopt;
  }
  std::map<int, int> next;  // the ring's edges: those no other piece turns back along
  std::set<int> vertices;
  for (const auto& [a, b] : directed) {
    vertices.insert(a);
    if (!directed.contains({b, a}) && !next.emplace(a, b).second) return std::nullopt;
  }
  FaceToMesh whole;
  whole.ring.push_back(next.begin()->first);
  for (std::size_t k = 1; k < next.size(); ++k) {
    const auto it = next.find(whole.ring.back());
    if (it == next.end() || it->second == whole.ring.front()) return std::nullopt;
    whole.ring.push_back(it->second);
  }
  if (next.at(whole.ring.back()) != whole.ring.front()) return std::nullopt;
  for (int v : vertices)
    if (!next.contains(v)) whole.inner.push_back(v);
  const Vec3 n = ring_normal(points, whole.ring);
  std::map<std::pair<int, int>, Vec3> normal;  // a -> b: the unit normal of the piece it turns in
  for (int f : group) {
    const auto& r = t.faces[f].ring;
    const Vec3 m = ring_normal(points, r);
    if (!(dot(m, n) > 0.0)) return std::nullopt;
    whole.pieces.push_back({r[0], r[1], r[2]});
    for (int k = 0; k < 3; ++k) normal[{r[k], r[(k + 1) % 3]}] = m / norm(m);
  }
  for (const auto& [ab, m] : normal) {
    const auto other = normal.find({ab.second, ab.first});
    if (ab.first < ab.second && other != normal.end() && dot(m, other->second) < std::cos(kFold))
      whole.folds.push_back(ab);
  }
  return whole;
}

// The faces to mesh, each with its face ids (ascending): every face alone, but a bent
// face's pieces (regularise_3d.cpp) as one surface where whole_face takes them and its
// first face is not in `split`.
using FacesToMesh = std::vector<std::pair<std::vector<int>, FaceToMesh>>;
FacesToMesh faces_to_mesh(const Tessellation3& t, const std::set<int>& split) {
  std::map<std::pair<int, int>, std::vector<int>> between;
  std::vector<std::pair<std::vector<int>, FaceToMesh>> out;
  for (int f = 0; f < static_cast<int>(t.faces.size()); ++f) {
    const Face3& face = t.faces[f];
    if (face.front >= 0 && face.ring.size() == 3) between[std::minmax(face.back, face.front)].push_back(f);
    else out.push_back({{f}, alone(face)});
  }
  for (const auto& [regions, group] : between) {
    std::optional<FaceToMesh> whole;
    if (!split.contains(group.front())) whole = whole_face(t, group);
    if (whole) out.push_back({group, std::move(*whole)});
    else
      for (int f : group) out.push_back({{f}, alone(t.faces[f])});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first.front() < b.first.front(); });
  return out;
}

// Meshes every face (a bent face's triangles go to the piece under each) but those on a
// high side of a periodic box, which are returned to be copied from their partners;
// `interior`: each face's own new points, [first, last).
std::vector<int> mesh_faces(const Tessellation3& t, const std::vector<std::pair<std::vector<int>, FaceToMesh>>& faces,
                            const Edges& edges, double h, SurfaceMesh& s, std::vector<std::pair<int, int>>& interior) {
  s.faces.resize(t.faces.size());
  std::vector<int> deferred;
  std::vector<int> piece_of;
  for (const auto& [group, face] : faces) {
    const int f = group.front();
    const auto side = group.size() == 1 ? box_side(t, t.faces[f].ring) : std::pair{-1, 0};
    if (t.periodic && side.first >= 0 && side.second == 1) {
      deferred.push_back(f);
      continue;
    }
    const int first = static_cast<int>(s.points.size());
    const auto triangles = mesh_face(face, edges, side, t.size(), h, s.points, piece_of);
    interior[f] = {first, static_cast<int>(s.points.size())};
    if (group.size() == 1) s.faces[f] = triangles;
    else
      for (std::size_t k = 0; k < triangles.size(); ++k) s.faces[group[piece_of[k]]].push_back(triangles[k]);
  }
  return deferred;
}

// The bent faces meshed as one surface that take a grain's volume beyond its budget
// (kBentFaceVolume of it, summed over its bent faces' volume changes in face order): their
// first faces. A bent face's change is the volume between its triangles and its pieces.
std::set<int> over_budget(const Tessellation3& t, const FacesToMesh& faces, const SurfaceMesh& s) {
  std::vector<double> spent(t.grains.size(), 0.0);
  std::set<int> over;
  for (const auto& [group, face] : faces) {
    if (face.pieces.empty()) continue;
    // The triangles and the pieces turned back: a closed surface (they share their ring).
    SolidMoments between(0.5 * t.size());
    for (int f : group)
      for (const auto& [a, b, c] : s.faces[f]) between.add_triangle(s.points[a], s.points[b], s.points[c]);
    for (const auto& [a, b, c] : face.pieces) between.add_triangle(t.vertices[a], t.vertices[c], t.vertices[b]);
    const double change = between.volume();
    const Face3& first = t.faces[group.front()];
    const int a = t.regions[first.back].grain, b = t.regions[first.front].grain;
    auto fits = [&](int g) { return spent[g] + std::abs(change) <= kBentFaceVolume * t.grains[g].volume; };
    if (!fits(a) || !fits(b)) {
      over.insert(group.front());
      continue;
    }
    spent[a] += std::abs(change);
    if (b != a) spent[b] += std::abs(change);
  }
  return over;
}

// The bent faces meshed as one surface with an edge inside them (not on their ring) whose
// ends lie on one side of the box: the edge lies in that side, where the box's own face
// is. Their first faces. (Refusing every ring that merely could have such an edge, two of
// its corners on one side and not next to each other, left the pieces of 7-degree corners
// that made the 100-grain bench cell's tetrahedra below 5 degrees.)
std::set<int> in_a_side(const Tessellation3& t, const FacesToMesh& faces, const SurfaceMesh& s) {
  std::set<int> out;
  for (const auto& [group, face] : faces) {
    if (face.pieces.empty()) continue;
    std::map<std::pair<int, int>, int> uses;
    for (int f : group)
      for (const auto& tr : s.faces[f])
        for (int k = 0; k < 3; ++k) ++uses[std::minmax(tr[k], tr[(k + 1) % 3])];
    for (const auto& [e, n] : uses)
      if (n == 2 && (side_mask(s.points[e.first], t.size()) & side_mask(s.points[e.second], t.size())) != 0) {
        out.insert(group.front());
        break;
      }
  }
  return out;
}

// The faces meshed (faces_to_mesh) and, when periodic, the high sides' copies.
SurfaceMesh mesh_surfaces(const Tessellation3& t, double h, const FacesToMesh& faces);

}  // namespace

SurfaceMesh mesh_surfaces(const Tessellation3& t, double h) {
  if (!(h > 0.0)) throw GeometryError("3D surface mesh: the element size must be positive");
  const FacesToMesh faces = faces_to_mesh(t, {});
  SurfaceMesh s = mesh_surfaces(t, h, faces);
  std::set<int> over = over_budget(t, faces, s);
  over.merge(in_a_side(t, faces, s));
  // Those over budget or in a side piece by piece; the others are meshed alike again (other point ids).
  return over.empty() ? s : mesh_surfaces(t, h, faces_to_mesh(t, over));
}

namespace {

SurfaceMesh mesh_surfaces(const Tessellation3& t, double h, const FacesToMesh& faces) {
  SurfaceMesh s;
  s.points = t.vertices;
  const Edges edges = seed_edges(faces, h, s.points);
  const Vec3 box = t.size();
  std::vector<std::pair<int, int>> interior(t.faces.size());  // [first, last) of each face's own points
  const std::vector<int> deferred = mesh_faces(t, faces, edges, h, s, interior);
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
      const Vec3 want = unit_normal(s.points, t.faces[f].ring);
      const auto& tr = s.faces[f].front();
      if (dot(cross(s.points[tr[1]] - s.points[tr[0]], s.points[tr[2]] - s.points[tr[0]]), want) < 0.0)
        for (auto& x : s.faces[f]) std::swap(x[1], x[2]);
    }
  }
  return s;
}

}  // namespace

}  // namespace grainmesh
