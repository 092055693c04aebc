// Regularisation of a cut 3D tessellation: short edges collapsed (their ends merged), the
// faces it bends split into planar triangles.
#include "tessellate/regularise_3d.hpp"

#include "tessellate/bent_face.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <unordered_map>

namespace grainmesh {

namespace {

// The sharpest dihedral angle of a region a collapse may make (20 degrees kept needle faces
// that made the mesh's sharpest tetrahedra: docs/3d.md), and a bent face's centre fan.
constexpr double kCollapseMinDihedral = 8.0 * std::numbers::pi / 180.0, kFanMinDihedral = 20.0 * std::numbers::pi / 180.0;
// Angles equal to this (radians) count as unchanged: a collapse that leaves a region's
// sharpest angle where it was must not be refused by the rounding of its recomputation.
constexpr double kAngleRounding = 1e-9;
// Nor move more than this share of a grain's volume to its neighbours: a short edge's
// collapse moves a sliver; a layer of a laminate the box cut in two (pieces half its
// thickness, below the threshold when the layers are thin) must keep its volume.
constexpr double kMaxGrainVolumeChange = 0.05;

struct PointHash {
  std::size_t operator()(const Vec3& p) const {
    const std::hash<double> h;
    return h(p.x) ^ (h(p.y) * 31u) ^ (h(p.z) * 1000003u);
  }
};

class Collapser {
 public:
  Collapser(Tessellation3& t, double threshold) : t_(t), box_(t.size()), threshold_(threshold) {
    vertex_faces_.resize(t.vertices.size());
    for (int f = 0; f < static_cast<int>(t.faces.size()); ++f)
      for (int v : t.faces[f].ring) vertex_faces_[v].push_back(f);
    dead_.assign(t.faces.size(), false);
    dead_region_.assign(t.regions.size(), false);
    for (const Region3& r : t.regions) {
      if (r.grain >= static_cast<int>(grain_regions_.size())) grain_regions_.resize(r.grain + 1, 0);
      ++grain_regions_[r.grain];
    }
    grain_volume_.assign(grain_regions_.size(), 0.0);
    for (int r = 0; r < static_cast<int>(t.regions.size()); ++r) grain_volume_[t.regions[r].grain] += volume(r);
    grain_now_ = grain_volume_;
    for (int v = 0; v < static_cast<int>(t.vertices.size()); ++v) at_.emplace(t.vertices[v], v);
  }

  // Passes over the edges shorter than the threshold, shortest first, until none
  // collapses. Returns the number collapsed (periodic images counted once).
  int run() {
    int collapsed = 0;
    for (int pass = 0; pass < 20; ++pass) {
      int now = 0;
      for (const auto& [length, e] : short_edges())
        if (present(e.first, e.second) && distance(e.first, e.second) < threshold_ && collapse(e.first, e.second)) ++now;
      collapsed += now;
      if (now == 0) break;
    }
    finish();
    return collapsed;
  }

 private:
  double distance(int a, int b) const { return norm(t_.vertices[a] - t_.vertices[b]); }

  std::vector<std::pair<double, std::pair<int, int>>> short_edges() const {
    std::set<std::pair<int, int>> seen;
    std::vector<std::pair<double, std::pair<int, int>>> out;
    for (int f = 0; f < static_cast<int>(t_.faces.size()); ++f) {
      if (dead_[f]) continue;
      const auto& r = t_.faces[f].ring;
      for (std::size_t k = 0; k < r.size(); ++k) {
        const auto e = std::minmax(r[k], r[(k + 1) % r.size()]);
        if (distance(e.first, e.second) < threshold_ && seen.insert(e).second) out.push_back({distance(e.first, e.second), e});
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  bool present(int a, int b) const {
    for (int f : vertex_faces_[a]) {
      if (dead_[f]) continue;
      const auto& r = t_.faces[f].ring;
      for (std::size_t k = 0; k < r.size(); ++k)
        if ((r[k] == a && r[(k + 1) % r.size()] == b) || (r[k] == b && r[(k + 1) % r.size()] == a)) return true;
    }
    return false;
  }

  // The vertex at p shifted by toggling the box sides in `toggle` (bits as side_mask), or -1.
  int image(int v, int toggle) const {
    Vec3 p = t_.vertices[v];
    for (int a = 0; a < 3; ++a)
      if (toggle & (3 << (2 * a))) p[a] = p[a] == 0.0 ? box_[a] : 0.0;
    const auto it = at_.find(p);
    return it == at_.end() ? -1 : it->second;
  }

  struct Saved {
    std::vector<std::pair<int, std::vector<int>>> rings;  // face, ring before
    std::vector<std::pair<int, Vec3>> moved;              // vertex, position before
    std::vector<int> killed;
  };

  // Merges b into a at p, recording what it changes.
  void merge(int a, int b, Vec3 p, Saved& s) {
    s.moved.emplace_back(a, t_.vertices[a]);
    t_.vertices[a] = p;
    for (int f : vertex_faces_[b]) {
      if (dead_[f]) continue;
      s.rings.emplace_back(f, t_.faces[f].ring);
      std::vector<int> ring;
      for (int v : t_.faces[f].ring) {
        const int w = v == b ? a : v;
        if (ring.empty() || ring.back() != w) ring.push_back(w);
      }
      while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
      t_.faces[f].ring = std::move(ring);
      if (t_.faces[f].ring.size() < 3) {
        dead_[f] = true;
        s.killed.push_back(f);
      }
    }
    for (int f : vertex_faces_[a]) {
      if (dead_[f]) continue;
      bool saved = false;
      for (const auto& r : s.rings) saved = saved || r.first == f;
      if (!saved) s.rings.emplace_back(f, t_.faces[f].ring);
    }
  }

  void revert(const Saved& s) {
    for (auto it = s.rings.rbegin(); it != s.rings.rend(); ++it) t_.faces[it->first].ring = it->second;
    for (auto it = s.moved.rbegin(); it != s.moved.rend(); ++it) t_.vertices[it->first] = it->second;
    for (int f : s.killed) dead_[f] = false;
  }

  double flat() const { return 1e-12 * (box_.x + box_.y + box_.z); }

  // A face that is planar or has a triangulation turning with it (face_shape).
  bool face_ok(int f) const { return face_shape(t_.vertices, t_.faces[f].ring, flat(), box_).valid; }

  // A face inside the box meets a side only along edges of the box's own faces: an edge
  // of it lying in a side but not bounding a face on that side would cut through one.
  bool touches_box_by_its_faces(int f) const {
    const auto& ring = t_.faces[f].ring;
    if (t_.faces[f].front < 0) return true;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const int x = ring[k], y = ring[(k + 1) % ring.size()];
      const int common = side_mask(t_.vertices[x], box_) & side_mask(t_.vertices[y], box_);
      if (common == 0) continue;
      bool bounded = false;
      for (int g : vertex_faces_[x]) {
        if (dead_[g] || t_.faces[g].front >= 0) continue;
        const auto& r = t_.faces[g].ring;
        for (std::size_t m = 0; m < r.size() && !bounded; ++m)
          bounded = (r[m] == x && r[(m + 1) % r.size()] == y) || (r[m] == y && r[(m + 1) % r.size()] == x);
      }
      if (!bounded) return false;
    }
    return true;
  }

  // Region r's volume, its faces as finish() will make them.
  double volume(int r) const {
    double v = 0.0;
    const Vec3 o = t_.vertices[t_.faces[t_.regions[r].faces[0]].ring[0]];
    for (int f : t_.regions[r].faces) {
      if (dead_[f]) continue;
      const Face3& face = t_.faces[f];
      const double sign = face.back == r ? 1.0 : -1.0;
      for (const auto& [a, b, c] : triangles(face.ring))
        v += sign * dot(t_.vertices[a] - o, cross(t_.vertices[b] - o, t_.vertices[c] - o));
    }
    return v / 6.0;
  }

  // The grains' volumes now that the regions `regions` changed (their volumes before by
  // grain in `before`), when no grain has moved more than kMaxGrainVolumeChange from its
  // volume before any collapse; empty otherwise.
  std::map<int, double> grains_kept(const std::set<int>& regions, const std::map<int, double>& before) const {
    std::map<int, double> after;
    for (int r : regions) after[t_.regions[r].grain] += volume(r);
    std::map<int, double> now;
    for (const auto& [g, v] : before) {
      now[g] = grain_now_[g] + after[g] - v;
      if (std::abs(now[g] - grain_volume_[g]) > kMaxGrainVolumeChange * grain_volume_[g]) return {};
    }
    return now;
  }

  // A region still closed and outward, with at least four faces and positive volume.
  bool region_ok(int r) const {
    std::map<std::pair<int, int>, int> edges;
    std::set<std::vector<int>> faces;
    int alive = 0;
    for (int f : t_.regions[r].faces) {
      if (dead_[f]) continue;
      ++alive;
      const Face3& face = t_.faces[f];
      std::vector<int> key = face.ring;
      std::sort(key.begin(), key.end());
      if (!faces.insert(key).second) return false;
      for (std::size_t k = 0; k < face.ring.size(); ++k) {
        int a = face.ring[k], b = face.ring[(k + 1) % face.ring.size()];
        if (face.back != r) std::swap(a, b);
        if (++edges[{a, b}] > 1) return false;
      }
    }
    if (alive < 4) return false;
    for (const auto& [e, count] : edges)
      if (!edges.contains({e.second, e.first})) return false;
    return volume(r) > 0.0;
  }

  // A face's triangles as finish() will make them: a fan from its first vertex when
  // planar, else face_shape's.
  std::vector<std::array<int, 3>> triangles(const std::vector<int>& ring) const {
    FaceShape shape = face_shape(t_.vertices, ring, flat(), box_);
    if (!shape.planar) return shape.triangles;
    std::vector<std::array<int, 3>> fan;
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) fan.push_back({ring[0], ring[k], ring[k + 1]});
    return fan;
  }

  // The sharpest interior dihedral angle of region r (radians; a reflex angle counts by
  // how far it falls short of a full turn) over the edges of its faces' triangles: what
  // the finished faces will have, a bent face's diagonals included.
  double region_sharpest(int r) const {
    // Per edge: the first face's outward normal and a point of it off the edge.
    std::map<std::pair<int, int>, std::pair<Vec3, Vec3>> first;
    double sharpest = std::numbers::pi;
    auto meet = [&](int x, int y, Vec3 n, Vec3 off) {
      const auto [it, added] = first.emplace(std::minmax(x, y), std::pair{n, off});
      if (added) return;
      const double angle = interior_dihedral(it->second.first, n, off, t_.vertices[x]);
      sharpest = std::min({sharpest, angle, 2.0 * std::numbers::pi - angle});
    };
    for (int f : t_.regions[r].faces) {
      if (dead_[f]) continue;
      const double sign = t_.faces[f].back == r ? 1.0 : -1.0;
      const std::vector<int>& ring = t_.faces[f].ring;
      // A planar face: its own normal at its edges, its centroid off them (a fan of it may
      // hold zero-area triangles where vertices line up along a side of the box).
      FaceShape shape = face_shape(t_.vertices, ring, flat(), box_);
      if (const auto centre = fan_centre_.find(f); centre != fan_centre_.end()) {
        shape.triangles.clear();
        for (std::size_t k = 0; k < ring.size(); ++k) shape.triangles.push_back({centre->second, ring[k], ring[(k + 1) % ring.size()]});
      } else if (shape.planar) {
        Vec3 n{}, c{};
        for (std::size_t k = 0; k < ring.size(); ++k) {
          n += cross(t_.vertices[ring[k]], t_.vertices[ring[(k + 1) % ring.size()]]);
          c += t_.vertices[ring[k]];
        }
        n = sign * (n / norm(n));
        c = c / static_cast<double>(ring.size());
        for (std::size_t k = 0; k < ring.size(); ++k) meet(ring[k], ring[(k + 1) % ring.size()], n, c);
        continue;
      }
      for (const auto& [a, b, c] : shape.triangles) {
        Vec3 n = cross(t_.vertices[b] - t_.vertices[a], t_.vertices[c] - t_.vertices[a]);
        n = sign * (n / norm(n));
        meet(a, b, n, t_.vertices[c]);
        meet(b, c, n, t_.vertices[a]);
        meet(c, a, n, t_.vertices[b]);
      }
    }
    return sharpest;
  }

  // Collapses edge ab and its periodic images, all or none.
  bool collapse(int a, int b) {
    const int ma = side_mask(t_.vertices[a], box_), mb = side_mask(t_.vertices[b], box_);
    if (!t_.periodic) return collapse_bounded(a, b, ma | mb);
    if ((ma & mb) != ma && (ma & mb) != mb) return false;  // sides neither holds whole: keep
    if ((ma & mb) == ma && ma != mb) std::swap(a, b);      // a the vertex on more sides, which stays on them
    const int common = side_mask(t_.vertices[b], box_);    // the sides both lie on
    std::vector<std::pair<int, int>> edges{{a, b}};
    for (int toggle = 1; toggle < 64; ++toggle) {
      if ((toggle & ~common) != 0) continue;
      bool one_per_axis = true;
      for (int ax = 0; ax < 3; ++ax) one_per_axis = one_per_axis && ((toggle >> (2 * ax)) & 3) != 3;
      if (!one_per_axis) continue;
      const int ia = image(a, toggle), ib = image(b, toggle);
      if (ia < 0 || ib < 0) return false;
      edges.emplace_back(ia, ib);
    }
    std::vector<Vec3> targets;
    for (const auto& [u, w] : edges)
      targets.push_back(side_mask(t_.vertices[u], box_) == side_mask(t_.vertices[w], box_) ? 0.5 * (t_.vertices[u] + t_.vertices[w])
                                                                                          : t_.vertices[u]);
    return collapse_all(edges, targets);
  }

  // In a bounded box no partner follows a vertex: the merged point is the midpoint put on
  // every side either end lies on (a short edge from one side to another ends on the
  // box's edge line between them).
  bool collapse_bounded(int a, int b, int sides) {
    Vec3 p = 0.5 * (t_.vertices[a] + t_.vertices[b]);
    for (int ax = 0; ax < 3; ++ax) {
      const int on = (sides >> (2 * ax)) & 3;
      if (on == 3) return false;  // an edge across the box
      if (on == 1) p[ax] = 0.0;
      if (on == 2) p[ax] = box_[ax];
    }
    return collapse_all({{a, b}}, {p});
  }

  // Merges the second end of each edge into the first at its target: all or none.
  bool collapse_all(const std::vector<std::pair<int, int>>& edges, const std::vector<Vec3>& targets) {
    std::set<int> regions;
    for (const auto& [u, w] : edges)
      for (int v : {u, w})
        for (int f : vertex_faces_[v]) {
          if (dead_[f]) continue;
          regions.insert(t_.faces[f].back);
          if (t_.faces[f].front >= 0) regions.insert(t_.faces[f].front);
        }
    std::map<int, double> before, grain_before;
    for (int r : regions) {
      before[r] = region_sharpest(r);
      grain_before[t_.regions[r].grain] += volume(r);
    }
    Saved s;
    for (std::size_t k = 0; k < edges.size(); ++k) merge(edges[k].first, edges[k].second, targets[k], s);
    const std::map<int, double> grain_after = grains_kept(regions, grain_before);
    bool ok = !grain_after.empty();
    for (const auto& [f, ring] : s.rings)
      if (!dead_[f]) ok = ok && face_ok(f) && touches_box_by_its_faces(f);
    // No region may lose its shape: no dihedral angle sharper than kCollapseMinDihedral made (or
    // sharper than it was, where it was already).
    // A region flattened (a sliver the box cut off a grain) goes, its opposite faces
    // joined, if its grain keeps another region.
    std::vector<int> flattened;
    for (int r : regions) {
      if (!ok) break;
      if (flat(r) && removable(r, flattened)) flattened.push_back(r);
      else ok = region_ok(r) && region_sharpest(r) >= std::min(before[r], kCollapseMinDihedral) - kAngleRounding;
    }
    if (!ok) {
      revert(s);
      return false;
    }
    for (const auto& [u, w] : edges) {
      at_.erase(t_.vertices[w]);
      for (int f : vertex_faces_[w]) vertex_faces_[u].push_back(f);
      vertex_faces_[w].clear();
    }
    for (const auto& [u, old] : s.moved) {
      at_.erase(old);
      at_[t_.vertices[u]] = u;
    }
    for (const auto& [u, w] : edges) {
      auto& list = vertex_faces_[u];
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    for (int r : flattened) remove(r);
    for (const auto& [g, v] : grain_after) grain_now_[g] = v;
    return true;
  }

  // The alive faces of region r paired up by vertex set: nothing left of its volume.
  std::map<std::vector<int>, std::vector<int>> faces_by_key(int r) const {
    std::map<std::vector<int>, std::vector<int>> by_key;
    for (int f : t_.regions[r].faces) {
      if (dead_[f]) continue;
      std::vector<int> key = t_.faces[f].ring;
      std::sort(key.begin(), key.end());
      by_key[key].push_back(f);
    }
    return by_key;
  }
  bool flat(int r) const {
    for (const auto& [key, faces] : faces_by_key(r))
      if (faces.size() != 2) return false;
    return true;
  }
  static int other_side(const Face3& f, int r) { return f.back == r ? f.front : f.back; }

  // Region r can go when each pair of its faces joins two different regions (or a region
  // and the box) and its grain has another region (`also_going` are going too).
  bool removable(int r, const std::vector<int>& also_going) const {
    int going = 1;
    for (int q : also_going) going += t_.regions[q].grain == t_.regions[r].grain;
    if (grain_regions_[t_.regions[r].grain] <= going) return false;
    for (const auto& [key, faces] : faces_by_key(r)) {
      const int x = other_side(t_.faces[faces[0]], r), y = other_side(t_.faces[faces[1]], r);
      if (x == y) return false;  // also both on the box
      for (int q : also_going)
        if (x == q || y == q) return false;
    }
    return true;
  }

  // Removes flat region r: each pair of its faces becomes one face between the regions
  // (or region and box) on their far sides.
  void remove(int r) {
    for (const auto& [key, faces] : faces_by_key(r)) {
      Face3& keep = t_.faces[faces[0]];
      const Face3& drop = t_.faces[faces[1]];
      const int x = other_side(keep, r), y = other_side(drop, r);
      if (x >= 0) {
        if (keep.back != x) std::reverse(keep.ring.begin(), keep.ring.end());
        keep.back = x;
        keep.front = y;
      } else {
        keep.ring = drop.ring;
        if (drop.back != y) std::reverse(keep.ring.begin(), keep.ring.end());
        keep.back = y;
        keep.front = -1;
      }
      dead_[faces[1]] = true;
      if (y >= 0) std::replace(t_.regions[y].faces.begin(), t_.regions[y].faces.end(), faces[1], faces[0]);
    }
    dead_region_[r] = true;
    --grain_regions_[t_.regions[r].grain];
    ++removed_regions_;
  }

  // Bent face f split about a new centre point (centre_fan) rather than by diagonals
  // (`shape`): when the fan's smallest angle is larger and its regions' sharpest dihedral
  // angles stay at least min(what they were, kFanMinDihedral). Then the centre is a new
  // vertex, in fan_centre_.
  bool fan_is_better(int f, const FaceShape& shape) {
    const Face3& face = t_.faces[f];
    const CentreFan fan = centre_fan(t_.vertices, face.ring);
    if (!fan.valid || !(fan.smallest_angle > smallest_angle(t_.vertices, shape.triangles))) return false;
    auto sharpest = [&] { return std::min(region_sharpest(face.back), face.front >= 0 ? region_sharpest(face.front) : std::numbers::pi); };
    const double before = sharpest();
    fan_centre_[f] = static_cast<int>(t_.vertices.size());
    t_.vertices.push_back(fan.centre);
    if (sharpest() >= std::min(before, kFanMinDihedral) - kAngleRounding) return true;
    fan_centre_.erase(f);
    t_.vertices.pop_back();
    return false;
  }

  // Dead faces dropped, bent faces split into triangles (face_shape's, or the centre
  // fan's when its smallest angle is larger), unused vertices dropped.
  void finish() {
    std::vector<std::vector<int>> replaced(t_.faces.size());
    std::vector<Face3> faces;
    for (int f = 0; f < static_cast<int>(t_.faces.size()); ++f) {
      if (dead_[f]) continue;
      const Face3& face = t_.faces[f];
      const FaceShape shape = face_shape(t_.vertices, face.ring, flat(), box_);
      if (shape.planar) {
        replaced[f].push_back(static_cast<int>(faces.size()));
        faces.push_back(face);
        continue;
      }
      std::vector<std::array<int, 3>> triangles = shape.triangles;
      if (fan_is_better(f, shape)) {
        triangles.clear();
        for (std::size_t k = 0; k < face.ring.size(); ++k)
          triangles.push_back({fan_centre_.at(f), face.ring[k], face.ring[(k + 1) % face.ring.size()]});
      }
      for (const auto& [a, b, c] : triangles) {
        replaced[f].push_back(static_cast<int>(faces.size()));
        faces.push_back({.ring = {a, b, c}, .back = face.back, .front = face.front});
      }
    }
    renumber(t_, std::move(faces), replaced, dead_region_);
  }

  Tessellation3& t_;
  Vec3 box_;
  double threshold_;
  std::vector<std::vector<int>> vertex_faces_;
  std::vector<bool> dead_;
  std::vector<bool> dead_region_;
  std::map<int, int> fan_centre_;  // bent faces split about a new centre point: face -> its vertex
  std::vector<int> grain_regions_;  // live regions of each grain
  std::vector<double> grain_volume_;  // each grain's volume before any collapse
  std::vector<double> grain_now_;     // and after those made
  std::unordered_map<Vec3, int, PointHash> at_;

 public:
  int removed_regions_ = 0;
};

}  // namespace

Regularisation collapse_short_edges(Tessellation3& t, double threshold) {
  if (!(threshold > 0.0)) return {};
  Collapser c(t, threshold);
  const int collapsed = c.run();
  return {.collapsed_edges = collapsed, .removed_regions = c.removed_regions_};
}

}  // namespace grainmesh
