// The median dual of a tetrahedral grain mesh as OpenFOAM's polyhedral cells, split at
// grain boundaries (foam_3d.hpp: build_dual_polymesh_3d).
#include "export/polymesh_dual_3d.hpp"

#include <algorithm>
#include <iterator>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include <boost/pending/disjoint_sets.hpp>
#include <tbb/parallel_sort.h>

#include "common/errors.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_geometry.hpp"
#include "export/foam_mesh_check.hpp"
#include "export/join_cells.hpp"
#include "export/dual_interface.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "export/pin_translation.hpp"
#include "export/polymesh.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

namespace {

using Triangle = std::array<int, 3>;

// Each tetrahedron's faces turning outward: opposite corner k, for a positive abcd.
constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
// The corners of a tetrahedron's six edges, and for each the other two so that (i, j, k,
// l) is an even permutation of (0, 1, 2, 3).
constexpr int kEdge[6][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 2, 0}, {2, 3, 0, 1}};

Triangle sorted(Triangle t) {
  std::sort(t.begin(), t.end());
  return t;
}

// The corner of tetrahedron t at point v, as 4 t + its index.
int corner_of(const std::vector<std::array<int, 4>>& T, int t, int v) {
  return 4 * t + static_cast<int>(std::find(T[t].begin(), T[t].end(), v) - T[t].begin());
}

// The dual's corners before numbering: the mesh's points, its edges' midpoints, its faces'
// centroids and its tetrahedra's centroids, one id range after the other.
class Nodes {
 public:
  Nodes(const TetMesh& mesh, std::vector<char> interface, std::vector<std::array<int, 2>> edges, std::vector<Triangle> triangles)
      : mesh_(mesh), interface_(std::move(interface)), edges_(std::move(edges)), triangles_(std::move(triangles)),
        of_tet_(mesh.tets.size()) {
    // Each tetrahedron's edge and face nodes, looked up once for every build of the dual.
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const auto& T = mesh.tets[t];
      for (int e = 0; e < 6; ++e) of_tet_[t][e] = edge(T[kEdge[e][0]], T[kEdge[e][1]]);
      for (int k = 0; k < 4; ++k) of_tet_[t][6 + k] = triangle({T[kFace[k][0]], T[kFace[k][1]], T[kFace[k][2]]});
    }
  }
  // Tetrahedron t's node of its edge kEdge[e], of its face opposite corner k.
  int tet_edge(std::size_t t, int e) const { return of_tet_[t][e]; }
  int tet_face(std::size_t t, int k) const { return of_tet_[t][6 + k]; }
  int point(int v) const { return v; }
  int edge(int a, int b) const {
    const std::array<int, 2> e{std::min(a, b), std::max(a, b)};
    return points() + static_cast<int>(std::lower_bound(edges_.begin(), edges_.end(), e) - edges_.begin());
  }
  int triangle(const Triangle& t) const {
    const Triangle s = sorted(t);
    return points() + static_cast<int>(edges_.size()) +
           static_cast<int>(std::lower_bound(triangles_.begin(), triangles_.end(), s) - triangles_.begin());
  }
  int tet(int t) const { return points() + static_cast<int>(edges_.size() + triangles_.size()) + t; }
  int size() const { return tet(static_cast<int>(mesh_.tets.size())); }
  bool has_edge(int a, int b) const {
    const int e = edge(a, b) - points();
    return e < static_cast<int>(edges_.size()) && edges_[e] == std::array<int, 2>{std::min(a, b), std::max(a, b)};
  }
  bool has_triangle(const Triangle& t) const {
    const int f = triangle(t) - points() - static_cast<int>(edges_.size());
    return f < static_cast<int>(triangles_.size()) && triangles_[f] == sorted(t);
  }

  // The mesh points a node is the mean of.
  std::vector<int> generators(int n) const {
    if (n < points()) return {n};
    n -= points();
    if (n < static_cast<int>(edges_.size())) return {edges_[n][0], edges_[n][1]};
    n -= static_cast<int>(edges_.size());
    if (n < static_cast<int>(triangles_.size())) return {triangles_[n].begin(), triangles_[n].end()};
    n -= static_cast<int>(triangles_.size());
    return {mesh_.tets[n].begin(), mesh_.tets[n].end()};
  }
  // The mean of the generators; a coordinate they all share kept exactly (on a box side).
  Vec3 position(int n, double interface_weight) const {
    const std::vector<int> g = generators(n);
    Vec3 sum{};
    double total = 0.0;
    for (int v : g) {
      const double w = interface_[v] ? interface_weight : 1.0;
      sum += w * mesh_.points[v];
      total += w;
    }
    Vec3 p = sum / total;
    for (int a = 0; a < 3; ++a)
      if (std::all_of(g.begin(), g.end(), [&](int v) { return mesh_.points[v][a] == mesh_.points[g[0]][a]; }))
        p[a] = mesh_.points[g[0]][a];
    return p;
  }
  // The node made of the images of n's generators (`image` maps points; -1 when one has
  // none or the image is not a node).
  int image(int n, const std::map<int, int>& image) const {
    std::vector<int> g = generators(n);
    for (int& v : g) {
      const auto it = image.find(v);
      if (it == image.end()) return -1;
      v = it->second;
    }
    if (g.size() == 1) return g[0];
    if (g.size() == 2) return has_edge(g[0], g[1]) ? edge(g[0], g[1]) : -1;
    if (g.size() == 3) return has_triangle({g[0], g[1], g[2]}) ? triangle({g[0], g[1], g[2]}) : -1;
    return -1;
  }

 private:
  int points() const { return static_cast<int>(mesh_.points.size()); }
  const TetMesh& mesh_;
  std::vector<char> interface_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<Triangle> triangles_;
  std::vector<std::array<int, 10>> of_tet_;
};

// A piece of a dual face: the triangle apex, from, to, turning so that its normal points
// from the face's first cell to its second (or out of the box). The pieces of one face
// share its apex; their from -> to segments chain into its outline.
struct Piece {
  int first, second;  // cells; second = -1 - side for a face on a side of the box
  int part;           // the face's group: -2 - the node of the edge or point the pieces are round, else its own number
  int apex, from, to;
  auto face() const { return std::array<int, 3>{first, second, part}; }
  auto key() const { return std::array<int, 4>{first, second, part, from}; }
};

// A dual face: its corners (nodes) in turn, its owner and neighbour (-1 - side on the box).
struct DualFace {
  std::vector<int> nodes;
  int owner, neighbour;
};

// The faces of one group of pieces (one pair of cells, or one cell and side): each open
// chain of segments closed through the apex, each closed one as it is.
void chain(std::vector<Piece>::const_iterator begin, std::vector<Piece>::const_iterator end,
           std::vector<DualFace>& out) {
  const std::vector<Piece> pieces(begin, end);
  auto find_from = [&](int node) {
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (pieces[k].from == node) return static_cast<int>(k);
    return -1;
  };
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto count = std::count_if(pieces.begin(), pieces.end(), [&](const Piece& p) { return p.from == pieces[k].from; });
    const auto into = std::count_if(pieces.begin(), pieces.end(), [&](const Piece& p) { return p.to == pieces[k].to; });
    if (count > 1 || into > 1)
      throw GeometryError("export: the dual's face between cells " + std::to_string(begin->first) + " and " +
                          std::to_string(begin->second) + " is not simple (a grain boundary not manifold?)");
  }
  std::vector<char> used(pieces.size(), 0);
  auto follow = [&](int k, std::vector<int>& nodes) {
    while (k >= 0 && !used[k]) {
      used[k] = 1;
      nodes.push_back(pieces[k].from);
      k = find_from(pieces[k].to);
    }
  };
  // Open chains first: from a segment nothing leads into.
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const bool start = std::none_of(pieces.begin(), pieces.end(), [&](const Piece& p) { return p.to == pieces[k].from; });
    if (!start) continue;
    DualFace f{{pieces[k].apex}, begin->first, begin->second};
    follow(static_cast<int>(k), f.nodes);
    // The chain's last node: where its last segment ends.
    int last = static_cast<int>(k);
    while (find_from(pieces[last].to) >= 0) last = find_from(pieces[last].to);
    f.nodes.push_back(pieces[last].to);
    out.push_back(std::move(f));
  }
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (used[k]) continue;
    DualFace f{{}, begin->first, begin->second};
    follow(static_cast<int>(k), f.nodes);
    out.push_back(std::move(f));
  }
}

// The mesh's faces (sorted points, 4 t + k), sorted so that a shared face's two come
// together; its edges and its distinct triangles, sorted.
struct MeshFaces {
  std::vector<std::pair<Triangle, int>> faces;
  std::vector<std::array<int, 2>> edges;
  std::vector<Triangle> triangles;
};
MeshFaces mesh_faces(const std::vector<std::array<int, 4>>& T) {
  MeshFaces out;
  out.faces.reserve(4 * T.size());
  out.edges.reserve(6 * T.size());
  for (std::size_t t = 0; t < T.size(); ++t) {
    for (int k = 0; k < 4; ++k)
      out.faces.push_back({sorted({T[t][kFace[k][0]], T[t][kFace[k][1]], T[t][kFace[k][2]]}), static_cast<int>(4 * t) + k});
    for (const auto& e : kEdge) out.edges.push_back({std::min(T[t][e[0]], T[t][e[1]]), std::max(T[t][e[0]], T[t][e[1]])});
  }
  std::sort(out.faces.begin(), out.faces.end());
  std::sort(out.edges.begin(), out.edges.end());
  out.edges.erase(std::unique(out.edges.begin(), out.edges.end()), out.edges.end());
  for (const auto& f : out.faces)
    if (out.triangles.empty() || out.triangles.back() != f.first) out.triangles.push_back(f.first);
  return out;
}

// A triangle between two cells' pieces: face k of tetrahedron t, outward into
// tetrahedron u (-1 - side on the box).
struct Between {
  int t, k, u;
};

// The dual's cells: a tetrahedron's corners joined across faces between tetrahedra of one
// grain, numbered in the order of their points, then of their first corner; each cell's
// grain and phase into `out`, each corner's cell into out.corner_cell. Returns the
// triangles between cells of one point: grain boundaries and the box's sides.
std::vector<Between> dual_cells(const ExportMesh<3>& m, const MeshFaces& mf, FoamMesh3& out) {
  const std::vector<std::array<int, 4>>& T = m.mesh.tets;
  const std::vector<Vec3>& P = m.mesh.points;
  const std::size_t corners = 4 * T.size();
  std::vector<int> rank(corners, 0), parent(corners);
  boost::disjoint_sets<int*, int*> sets(rank.data(), parent.data());
  for (std::size_t c = 0; c < corners; ++c) sets.make_set(static_cast<int>(c));
  std::vector<Between> splits;
  const auto& faces = mf.faces;
  for (std::size_t i = 0; i < faces.size();) {
    const int t = faces[i].second / 4, k = faces[i].second % 4;
    if (i + 1 < faces.size() && faces[i + 1].first == faces[i].first) {
      const int u = faces[i + 1].second / 4;
      if (m.grain[t] == m.grain[u])
        for (int v : faces[i].first) sets.union_set(corner_of(T, t, v), corner_of(T, u, v));
      else
        splits.push_back({t, k, u});
      i += 2;
      continue;
    }
    const int side = box_side_of(P, faces[i].first, m.cell);
    if (side < 0) throw GeometryError("export: a boundary face of tetrahedron " + std::to_string(t) + " lies on no side of the box");
    splits.push_back({t, k, -1 - side});
    ++i;
  }
  std::vector<std::array<int, 3>> order;  // point, first corner, root
  std::vector<int> first(corners, -1);
  for (std::size_t c = 0; c < corners; ++c) {
    const int r = sets.find_set(static_cast<int>(c));
    if (first[r] < 0) {
      first[r] = static_cast<int>(c);
      order.push_back({T[c / 4][c % 4], static_cast<int>(c), r});
    }
  }
  std::sort(order.begin(), order.end());
  std::vector<int> cell_of_root(corners, -1);
  for (const auto& [v, c, r] : order) {
    cell_of_root[r] = static_cast<int>(out.grain.size());
    out.grain.push_back(m.grain[c / 4]);
    out.phase.push_back(m.phase[c / 4]);
  }
  out.corner_cell.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) out.corner_cell[c] = cell_of_root[sets.find_set(static_cast<int>(c))];
  return splits;
}

// The dual's faces: two pieces per tetrahedron edge (between its ends' cells), two per
// corner of a triangle in `splits`, chained (with `plane_faces` the pieces round an edge
// each a face of its own). A point's quarters of the triangles between two of its cells
// are a face each or, where `fold` (#points) is set, one: a folded polygon fanned from the
// point, or the ring round it where they close round it, as where a grain's tip pokes
// into another (there the quarters' normals turn right round, and no line between the two
// cells' centres crosses them all near square: checkMesh fails them). Folding moves each
// grain's volume a little (the cone between the point and the ring changes sides: 6e-5 of
// the binder's on the binder example). Each node's phase (of a tetrahedron it lies in)
// into `node_phase`.
std::vector<DualFace> dual_faces(const ExportMesh<3>& m, const Nodes& nodes, const std::vector<int>& cell,
                                 const std::vector<Between>& splits, const std::vector<char>& fold, bool plane_faces,
                                 std::vector<int>& node_phase) {
  const std::vector<std::array<int, 4>>& T = m.mesh.tets;
  std::vector<Piece> pieces;
  pieces.reserve(12 * T.size() + 6 * splits.size());
  auto add = [&](int a, int b, int part, int apex, int from, int to) {
    if (a == b) return;  // inside a joined cell
    if (b >= 0 && b < a) {
      std::swap(a, b);
      std::swap(from, to);
    }
    pieces.push_back({a, b, part, apex, from, to});
  };
  for (std::size_t t = 0; t < T.size(); ++t)
    for (int e = 0; e < 6; ++e) {
      // Around edge ij from the centroid of face ijk (opposite l) through the tetrahedron's
      // to face ijl's: the normal points from corner i to corner j.
      const auto [i, j, k, l] = kEdge[e];
      const int a = cell[4 * t + i], b = cell[4 * t + j];
      const int apex = nodes.tet_edge(t, e), centre = nodes.tet(static_cast<int>(t));
      const int fk = nodes.tet_face(t, l), fl = nodes.tet_face(t, k);
      add(a, b, -2 - apex, apex, fk, centre);  // a face per edge: joined cells may meet round several
      add(a, b, -2 - apex, apex, centre, fl);
      for (int n : {apex, centre, fk, fl}) node_phase[n] = m.phase[t];
    }
  for (std::size_t k = 0; k < splits.size(); ++k) {
    const Between& s = splits[k];
    const Triangle f{T[s.t][kFace[s.k][0]], T[s.t][kFace[s.k][1]], T[s.t][kFace[s.k][2]]};
    const int centroid = nodes.triangle(f);
    for (int q = 0; q < 3; ++q) {
      // Point v's quarter of the triangle, turning as the triangle (outward from t): a
      // face of its own (plane, so that grains and the box keep their volumes exactly), or
      // where v is to `fold`, one face with v's other quarters between the same two cells.
      const int v = f[q], next = f[(q + 1) % 3], previous = f[(q + 2) % 3];
      const int a = cell[corner_of(T, s.t, v)], b = s.u >= 0 ? cell[corner_of(T, s.u, v)] : s.u;
      const int part = fold[v] && s.u >= 0 ? -2 - nodes.point(v) : static_cast<int>(3 * k) + q;
      add(a, b, part, nodes.point(v), nodes.edge(v, next), centroid);
      add(a, b, part, nodes.point(v), centroid, nodes.edge(v, previous));
      for (int n : {nodes.point(v), nodes.edge(v, next), centroid}) node_phase[n] = m.phase[s.t];
    }
  }
  tbb::parallel_sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) { return x.key() < y.key(); });
  std::vector<DualFace> dual;
  for (auto it = pieces.begin(); it != pieces.end();) {
    auto end = it;
    while (end != pieces.end() && end->face() == it->face()) ++end;
    if (plane_faces && it->part < 0)
      for (auto p = it; p != end; ++p) dual.push_back({{p->apex, p->from, p->to}, p->first, p->second});
    else
      chain(it, end, dual);
    it = end;
  }
  return dual;
}

// The high side's faces of axis `a` as the images of the low side's, in their order, each
// the partner's corners reversed from the image of its first (into `images`, which must
// have room: pointers into it are returned).
std::vector<const DualFace*> image_faces(const std::vector<const DualFace*>& low, const std::vector<const DualFace*>& high,
                                         const Nodes& nodes, const std::vector<std::pair<int, int>>& pairs, int a,
                                         std::vector<DualFace>& images) {
  const std::map<int, int> image(pairs.begin(), pairs.end());
  std::map<std::vector<int>, const DualFace*> by_corners;
  for (const DualFace* f : high) {
    std::vector<int> key = f->nodes;
    std::sort(key.begin(), key.end());
    by_corners.emplace(key, f);
  }
  const std::string unpaired = std::string("export: the dual's faces of ") + kSideNames3[2 * a] + " and " +
                               kSideNames3[2 * a + 1] + " do not pair (is the mesh periodic?)";
  if (low.size() != high.size()) throw GeometryError(unpaired);
  std::vector<const DualFace*> paired;
  for (const DualFace* f : low) {
    std::vector<int> turned;
    for (int n : f->nodes) turned.push_back(nodes.image(n, image));
    std::vector<int> key = turned;
    std::sort(key.begin(), key.end());
    const auto it = by_corners.find(key);
    if (it == by_corners.end()) throw GeometryError(unpaired);
    std::reverse(turned.begin() + 1, turned.end());
    images.push_back({turned, it->second->owner, it->second->neighbour});
    paired.push_back(&images.back());
  }
  return paired;
}

// The polyMesh of the cells `out` holds (grain, phase, corner_cell), and its geometry:
// internal faces by owner and neighbour, then the sides'; points as their faces first use
// them.
void assemble(const ExportMesh<3>& m, const Nodes& nodes, const std::vector<Between>& splits, const std::vector<char>& fold,
              const std::vector<double>& weight, const FoamOptions& o, FoamMesh3& out) {
  std::vector<int> node_phase(static_cast<std::size_t>(nodes.size()), 0);
  const std::vector<DualFace> dual = dual_faces(m, nodes, out.corner_cell, splits, fold, o.plane_faces, node_phase);
  PolyMesh& pm = out.mesh;
  pm.cells = static_cast<int>(out.grain.size());
  std::vector<int> point_id(static_cast<std::size_t>(nodes.size()), -1);
  auto add_face = [&](const std::vector<int>& corners, int owner) {
    pm.face_start.push_back(static_cast<int>(pm.face_points.size()));
    for (int n : corners) {
      if (point_id[n] < 0) {
        point_id[n] = static_cast<int>(pm.points3d.size());
        pm.points3d.push_back(nodes.position(n, weight[node_phase[n]]));
      }
      pm.face_points.push_back(point_id[n]);
    }
    pm.owner.push_back(owner);
  };
  std::array<std::vector<const DualFace*>, 6> sides;
  std::vector<const DualFace*> internal;
  for (const DualFace& f : dual) (f.neighbour >= 0 ? internal : sides[-1 - f.neighbour]).push_back(&f);
  std::stable_sort(internal.begin(), internal.end(), [](const DualFace* x, const DualFace* y) {
    return x->owner != y->owner ? x->owner < y->owner : x->neighbour < y->neighbour;
  });
  for (const DualFace* f : internal) {
    add_face(f->nodes, f->owner);
    pm.neighbour.push_back(f->neighbour);
  }
  std::vector<DualFace> images;
  images.reserve(dual.size());
  if (o.cyclic)
    for (int a = 0; a < 3; ++a) sides[2 * a + 1] = image_faces(sides[2 * a], sides[2 * a + 1], nodes, m.pairs.axis[a], a, images);
  for (int s = 0; s < 6; ++s) {
    if (sides[s].empty()) throw GeometryError(std::string("export: no face lies on the box's ") + kSideNames3[s] + " side");
    PolyMesh::Patch p = side_patch(s, m.cell.size(), o);
    p.start = pm.faces();
    p.size = static_cast<int>(sides[s].size());
    for (const DualFace* f : sides[s]) add_face(f->nodes, f->owner);
    pm.patches.push_back(p);
  }
  pm.face_start.push_back(static_cast<int>(pm.face_points.size()));
  if (o.cyclic) pin_translation(pm, out.phase, {});
  add_zones(out.grain, out.phase, m.phases, o.grain_zones, pm);
  foam_cell_geometry(out.mesh, out.centre, out.volume);
}

// The points with a failing face between two of their own cells (across a grain
// boundary or a phase interface), added to `fold`.
std::vector<char> points_to_fold(const ExportMesh<3>& m, const FoamMesh3& built, const FoamCheckFailures& failing,
                                 std::vector<char> fold) {
  std::vector<std::vector<int>> points(built.grain.size());  // the points of the failing faces' cells
  std::vector<char> wanted(built.grain.size(), 0);
  for (int f : failing.faces)
    if (f < built.mesh.internal_faces()) wanted[built.mesh.owner[f]] = wanted[built.mesh.neighbour[f]] = 1;
  for (std::size_t c = 0; c < built.corner_cell.size(); ++c)
    if (wanted[built.corner_cell[c]]) points[built.corner_cell[c]].push_back(m.mesh.tets[c / 4][c % 4]);
  for (auto& p : points) {
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
  }
  for (int f : failing.faces) {
    if (f >= built.mesh.internal_faces()) continue;
    const auto& a = points[built.mesh.owner[f]];
    const auto& b = points[built.mesh.neighbour[f]];
    std::vector<int> shared;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
    for (int v : shared) fold[v] = 1;
  }
  return fold;
}

// At most this many builds after the first, each with more faces folded or cells joined.
constexpr int kMendRounds = 4;

}  // namespace

FoamMesh3 build_dual_polymesh_3d(const ExportMesh<3>& m, const FoamOptions& o) {
  if (o.cyclic && !m.periodic) throw ConfigError("export.cyclic: the mesh is not periodic");
  MeshFaces mf = mesh_faces(m.mesh.tets);
  FoamMesh3 cells;
  const std::vector<Between> splits = dual_cells(m, mf, cells);
  const Nodes nodes(m.mesh, interface_points(m), std::move(mf.edges), std::move(mf.triangles));
  const std::vector<double> weight = interface_weights(m.phases);
  // Where checkMesh would fail a face between two cells of one point, that point's faces
  // between its cells folded; where it would still fail a face or a cell, cells joined
  // (join_cells.hpp); each time the dual built again.
  std::vector<char> fold(m.mesh.points.size(), 0);
  const auto plain_cells = static_cast<int>(cells.grain.size());
  // The mended dual with what was mended and what still fails.
  auto mended = [&](FoamMesh3 out, const FoamCheckFailures& failing) {
    out.mending = DualMending{.folded_points = static_cast<int>(std::count(fold.begin(), fold.end(), 1)),
                              .joined_cells = plain_cells - out.mesh.cells,
                              .failing_faces = static_cast<int>(failing.faces.size()),
                              .failing_cells = static_cast<int>(failing.cells.size())};
    return out;
  };
  for (int round = 0;; ++round) {
    FoamMesh3 out{.mesh = {}, .grain = cells.grain, .phase = cells.phase, .centre = {}, .volume = {}, .corner_cell = cells.corner_cell, .mending = {}};
    assemble(m, nodes, splits, fold, weight, o, out);
    if (!o.mend_checks) return out;
    const FoamCheckFailures failing = FoamMeshCheck(out.mesh, out.centre, out.volume).failures();
    if (failing.empty() || round == kMendRounds) return mended(std::move(out), failing);
    std::vector<char> more = points_to_fold(m, out, failing, fold);
    if (more != fold) {
      fold = std::move(more);
      continue;
    }
    std::vector<int> number = joined_cells(out.mesh, out.grain, out.phase, out.centre, out.volume, failing);
    if (number.empty()) return mended(std::move(out), failing);
    join_cells(number, out, cells);
  }
}

}  // namespace grainmesh
