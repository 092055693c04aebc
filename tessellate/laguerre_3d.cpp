// The 3D power diagram through CGAL's regular triangulation, in floating point for the
// relaxation and in exact rationals for the cut (see laguerre_3d.hpp).
#include "tessellate/laguerre_3d.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <type_traits>

#include "common/errors.hpp"
#include "tessellate/exact_polyhedron.hpp"
#include "tessellate/solid_moments.hpp"

namespace grainmesh {

namespace {

// Sites are the seeds' copies the triangulation holds: periodic, 27 images per seed
// (site = seed * 27 + image, image 13 the seed itself); bounded, the seed and its six
// mirror images (site = seed * 7 + k, k = 0 the seed, 1 + 2 axis + high its mirror
// across that side).
struct SiteCode {
  bool periodic = true;
  int per_seed() const { return periodic ? 27 : 7; }
  int own() const { return periodic ? 13 : 0; }
};

// The lattice shift of periodic image k, each component in {-1, 0, 1}.
std::array<int, 3> image_shift(int k) { return {k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1}; }

template <class K>
struct Diagram {
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  using Vb0 = CGAL::Regular_triangulation_vertex_base_3<K>;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, K, Vb0>;  // site
  using Cb0 = CGAL::Regular_triangulation_cell_base_3<K>;
  using Cb = CGAL::Triangulation_cell_base_with_info_3<int, K, Cb0>;  // power vertex id, -1 unset
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
  using Regular = CGAL::Regular_triangulation_3<K, Tds>;
  using WPoint = typename Regular::Weighted_point;

  struct LessXyz {
    bool operator()(const Point& a, const Point& b) const { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }
  };

  // One seed's cell: its corners (ids into `points`) and faces, each ring counter-
  // clockwise seen from outside, with the site across it.
  struct Cell {
    std::vector<std::vector<int>> rings;
    std::vector<int> across;
  };

  SiteCode code;
  double reach2 = 0.0;        // the squared distance no seed's cell reaches beyond: twice the box's diagonal
  std::vector<Point> points;  // the diagram's vertices, each exact point once
  std::vector<Cell> cells;    // per seed; no rings when hidden

  Diagram(const std::vector<Vec3>& seeds, const std::vector<double>& weights, Vec3 box, bool periodic) {
    code.periodic = periodic;
    reach2 = 4.0 * dot(box, box);
    const int n = static_cast<int>(seeds.size());
    std::vector<std::pair<WPoint, int>> sites;
    sites.reserve(static_cast<std::size_t>(n) * code.per_seed());
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < code.per_seed(); ++k)
        sites.emplace_back(site_point(seeds[i], weights[i], box, k), i * code.per_seed() + k);
    Regular rt;
    rt.insert(sites.begin(), sites.end());

    std::vector<typename Regular::Vertex_handle> own(n);
    for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v)
      if (v->info() % code.per_seed() == code.own()) own[v->info() / code.per_seed()] = v;
    for (auto c = rt.all_cells_begin(); c != rt.all_cells_end(); ++c) c->info() = -1;
    std::map<Point, int, LessXyz> ids;
    cells.resize(n);
    for (int i = 0; i < n; ++i)
      if (own[i] != typename Regular::Vertex_handle()) cells[i] = cell_of(rt, own[i], ids);
  }

  WPoint site_point(Vec3 s, double w, Vec3 box, int k) const {
    std::array<FT, 3> p{FT(s.x), FT(s.y), FT(s.z)};
    if (code.periodic) {
      const auto shift = image_shift(k);
      for (int a = 0; a < 3; ++a)
        if (shift[a] != 0) p[a] = p[a] + FT(box[a]) * FT(shift[a]);
    } else if (k > 0) {
      const int a = (k - 1) / 2;
      p[a] = (k - 1) % 2 == 0 ? -p[a] : FT(box[a]) * FT(2) - p[a];
    }
    return WPoint(Point(p[0], p[1], p[2]), FT(w));
  }

  int vertex_of(const Regular& rt, typename Regular::Cell_handle c, std::map<Point, int, LessXyz>& ids) {
    if (c->info() < 0) {
      if (rt.is_infinite(c)) throw GeometryError("3D Laguerre diagram: a seed's cell is unbounded");
      const Point p = power_centre(c);
      const auto [it, added] = ids.emplace(p, static_cast<int>(points.size()));
      if (added) points.push_back(p);
      c->info() = it->second;
    }
    return c->info();
  }

  // The power centre of cell c: its dual vertex. In floating point it is what CGAL
  // constructs, unless the cell is so flat that the point misses its corners' power
  // distances, or lies further from them than any seed's cell reaches (a lattice of
  // seeds moved by rounding: cospherical corners make slivers, whose centres came out on
  // their axis 1e14 away, where the power distances round alike); then it is constructed
  // exactly and rounded.
  Point power_centre(typename Regular::Cell_handle c) const {
        const Point p = c->weighted_circumcenter();
    if constexpr (std::is_same_v<K, EK>) {
      return p;
    } else {
      double lo = 0.0, hi = 0.0, scale = 0.0;
      for (int k = 0; k < 4; ++k) {
        const auto& w = c->vertex(k)->point();
        const double d = CGAL::to_double(CGAL::squared_distance(p, w.point()) - w.weight());
        lo = k == 0 ? d : std::min(lo, d);
        hi = k == 0 ? d : std::max(hi, d);
        scale = std::max(scale, CGAL::to_double(CGAL::squared_distance(c->vertex(0)->point().point(), w.point())));
      }
      if (hi - lo <= 1e-9 * scale && hi <= reach2) return p;
      std::array<EK::Weighted_point_3, 4> exact;
      for (int k = 0; k < 4; ++k) {
        const auto& w = c->vertex(k)->point();
        exact[k] = EK::Weighted_point_3(EK::Point_3(w.x(), w.y(), w.z()), EK::FT(w.weight()));
      }
      const EK::Point_3 q = EK().construct_weighted_circumcenter_3_object()(exact[0], exact[1], exact[2], exact[3]);
      return Point(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
    }
  }

  Cell cell_of(const Regular& rt, typename Regular::Vertex_handle v, std::map<Point, int, LessXyz>& ids) {
    Cell cell;
    std::vector<typename Regular::Edge> edges;
    rt.incident_edges(v, std::back_inserter(edges));
    for (const auto& e : edges) {
      const auto a = e.first->vertex(e.second), b = e.first->vertex(e.third);
      const auto w = a == v ? b : a;
      if (rt.is_infinite(w)) throw GeometryError("3D Laguerre diagram: a seed's cell is unbounded");
      std::vector<int> ring;
      auto cc = rt.incident_cells(e), end = cc;
      do {
        const int id = vertex_of(rt, cc, ids);
        if (ring.empty() || ring.back() != id) ring.push_back(id);
        ++cc;
      } while (cc != end);
      while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
      if (ring.size() < 3) continue;  // touches in an edge or a point only
      // Counter-clockwise seen from outside: the ring's normal towards the other site.
      typename K::Vector_3 normal(0, 0, 0);
      for (std::size_t k = 1; k + 1 < ring.size(); ++k)
        normal = normal + CGAL::cross_product(points[ring[k]] - points[ring[0]], points[ring[k + 1]] - points[ring[0]]);
      const auto outward = w->point().point() - v->point().point();
      if (CGAL::is_negative(normal * outward)) std::reverse(ring.begin(), ring.end());
      cell.rings.push_back(std::move(ring));
      cell.across.push_back(w->info());
    }
    return cell;
  }
};

using Approx = Diagram<CGAL::Exact_predicates_inexact_constructions_kernel>;
using Exact = Diagram<CGAL::Exact_predicates_exact_constructions_kernel>;

Vec3 to_vec(const CGAL::Exact_predicates_inexact_constructions_kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace

CellMoments laguerre_moments(const std::vector<Vec3>& seeds, const std::vector<double>& weights, Vec3 box,
                             bool periodic) {
  const Approx d(seeds, weights, box, periodic);
  CellMoments m;
  m.volume.assign(seeds.size(), 0.0);
  m.centroid = seeds;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    SolidMoments solid(seeds[i]);
    for (const auto& ring : d.cells[i].rings) {
      const Vec3 a = to_vec(d.points[ring[0]]);
      for (std::size_t k = 1; k + 1 < ring.size(); ++k)
        solid.add_triangle(a, to_vec(d.points[ring[k]]), to_vec(d.points[ring[k + 1]]));
      for (std::size_t k = 0; k < ring.size(); ++k) {
        m.vertices.push_back(to_vec(d.points[ring[k]]));
        m.edges.emplace_back(m.vertices.back(), to_vec(d.points[ring[(k + 1) % ring.size()]]));
      }
    }
    m.volume[i] = solid.volume();
    m.centroid[i] = solid.centroid();
  }
  return m;
}

namespace {

// Each exact point once, rounded once: a point reached from two pieces (or from two
// periodic images, shifted back exactly) is one vertex with one set of bits.
class ExactVertices {
 public:
  explicit ExactVertices(std::vector<Vec3>& out) : out_(out) {}
  int id(const EK::Point_3& p) {
    const auto [it, added] = ids_.emplace(p, static_cast<int>(out_.size()));
    if (added)
      out_.push_back({CGAL::to_double(CGAL::exact(p.x())), CGAL::to_double(CGAL::exact(p.y())),
                      CGAL::to_double(CGAL::exact(p.z()))});
    return it->second;
  }

 private:
  std::vector<Vec3>& out_;
  std::map<EK::Point_3, int, Exact::LessXyz> ids_;
};

// The pieces of `poly` in the periodic box's images m (lo[a] <= m[a] <= hi[a]), each moved
// back by -m periods, as pieces of `seed`; a bounded box (periodic false) keeps it whole.
void add_pieces(const ExactPolyhedron& poly, int seed, int face, Vec3 box, bool periodic, std::array<int, 3> lo,
                std::array<int, 3> hi, ExactVertices& vertices, LaguerreCut& out) {
  if (!periodic) lo = hi = {0, 0, 0};
  // Only the images the polyhedron's rounded extent (with a margin) reaches.
  for (int a = 0; a < 3 && periodic; ++a) {
    double pmin = std::numeric_limits<double>::infinity(), pmax = -pmin;
    for (const EK::Point_3& p : poly.points) {
      const double x = CGAL::to_double(coord(p, a));
      pmin = std::min(pmin, x);
      pmax = std::max(pmax, x);
    }
    const double margin = 1e-6 * box[a];
    lo[a] = std::max(lo[a], static_cast<int>(std::floor((pmin - margin) / box[a])));
    hi[a] = std::min(hi[a], static_cast<int>(std::floor((pmax + margin) / box[a])));
  }
  for (int mz = lo[2]; mz <= hi[2]; ++mz)
    for (int my = lo[1]; my <= hi[1]; ++my)
      for (int mx = lo[0]; mx <= hi[0]; ++mx) {
        const std::array<int, 3> m{mx, my, mz};
        ExactPolyhedron piece = poly;  // bounded: the mirrors already bound the cell by the box
        for (int a = 0; a < 3 && periodic && !piece.faces.empty(); ++a) {
          const EK::FT low = EK::FT(box[a]) * EK::FT(m[a]);
          piece = clip(piece, a, low, true);
          if (!piece.faces.empty()) piece = clip(piece, a, low + EK::FT(box[a]), false);
        }
        if (piece.faces.empty()) continue;
        const bool home = m == std::array<int, 3>{0, 0, 0};
        const EK::Vector_3 back(EK::FT(box.x) * EK::FT(-m[0]), EK::FT(box.y) * EK::FT(-m[1]),
                                EK::FT(box.z) * EK::FT(-m[2]));
        std::vector<int> global(piece.points.size(), -1);
        BoxPiece bp{.seed = seed, .face = face, .faces = {}};
        for (const auto& face : piece.faces) {
          std::vector<int> ring;
          for (int id : face) {
            if (global[id] < 0) global[id] = vertices.id(home ? piece.points[id] : piece.points[id] + back);
            ring.push_back(global[id]);
          }
          bp.faces.push_back(std::move(ring));
        }
        out.pieces.push_back(std::move(bp));
      }
}

}  // namespace

std::vector<std::vector<std::vector<Vec3>>> laguerre_cells(const std::vector<Vec3>& seeds,
                                                           const std::vector<double>& weights, Vec3 box,
                                                           bool periodic) {
  const Approx d(seeds, weights, box, periodic);
  std::vector<std::vector<std::vector<Vec3>>> out(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
    for (const auto& ring : d.cells[i].rings) {
      std::vector<Vec3> face;
      for (int id : ring) face.push_back(to_vec(d.points[id]));
      out[i].push_back(std::move(face));
    }
  return out;
}

namespace {

// The whole cells' faces with the seed and face across each (see WholeFace).
std::vector<std::vector<WholeFace>> whole_faces(const Exact& d) {
  const int n = static_cast<int>(d.cells.size()), per = d.code.per_seed();
  std::map<std::pair<int, int>, int> face_of;  // (seed, site across) -> face index
  std::vector<std::vector<WholeFace>> out(n);
  for (int i = 0; i < n; ++i)
    for (std::size_t k = 0; k < d.cells[i].rings.size(); ++k) {
      WholeFace f;
      for (int id : d.cells[i].rings[k]) {
        const auto& p = d.points[id];
        f.ring.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
      }
      const int site = d.cells[i].across[k];
      if (d.code.periodic || site % per == d.code.own()) f.across = site / per;
      face_of[{i, site}] = static_cast<int>(k);
      out[i].push_back(std::move(f));
    }
  // Across the face of i towards j's image m lies j's face towards i's image -m.
  for (int i = 0; i < n; ++i)
    for (std::size_t k = 0; k < out[i].size(); ++k) {
      WholeFace& f = out[i][k];
      if (f.across < 0) continue;
      const int image = d.cells[i].across[k] % per;
      const int back = i * per + (d.code.periodic ? 26 - image : d.code.own());
      const auto it = face_of.find({f.across, back});
      if (it == face_of.end()) throw GeometryError("3D Laguerre diagram: a face has no partner across it");
      f.across_face = it->second;
    }
  return out;
}

// Binder mode: the cell's core and its frustums, each cut into the box as a piece.
void add_layers(const ExactPolyhedron& poly, int seed, const EK::Point_3& centre, const EK::FT& scale, Vec3 box,
                bool periodic, ExactVertices& vertices, LaguerreCut& out) {
  const std::vector<ExactPolyhedron> parts = core_and_frustums(poly, centre, scale);
  for (int k = 0; k < static_cast<int>(parts.size()); ++k)
    add_pieces(parts[k], seed, k - 1, box, periodic, {-1, -1, -1}, {1, 1, 1}, vertices, out);
}

}  // namespace

LaguerreCut laguerre_box_cut(const std::vector<Vec3>& seeds, const std::vector<double>& weights, Vec3 box,
                             bool periodic, const LayeringOf& layering_of) {
  const Exact d(seeds, weights, box, periodic);
  LaguerreCut out;
  const int n = static_cast<int>(seeds.size());
  out.cell_faces.assign(n, 0);
  out.neighbours.resize(n);
  out.whole = whole_faces(d);
  const std::optional<Layering> layering = layering_of ? layering_of(out.whole) : std::nullopt;
  ExactVertices vertices(out.vertices);
  for (int i = 0; i < n; ++i) {
    const Exact::Cell& cell = d.cells[i];
    out.cell_faces[i] = static_cast<int>(cell.rings.size());
    for (int site : cell.across) {
      const int j = site / d.code.per_seed();
      if (j != i && (periodic || site % d.code.per_seed() == d.code.own())) out.neighbours[i].push_back(j);
    }
    std::sort(out.neighbours[i].begin(), out.neighbours[i].end());
    out.neighbours[i].erase(std::unique(out.neighbours[i].begin(), out.neighbours[i].end()), out.neighbours[i].end());
    if (cell.rings.empty()) continue;

    ExactPolyhedron poly;
    std::map<int, int> local;
    for (const auto& ring : cell.rings) {
      std::vector<int> face;
      for (int id : ring) {
        const auto [it, added] = local.emplace(id, static_cast<int>(poly.points.size()));
        if (added) poly.points.push_back(d.points[id]);
        face.push_back(it->second);
      }
      poly.faces.push_back(std::move(face));
    }
    if (layering) {
      const Vec3 c = layering->centres[i];
      add_layers(poly, i, EK::Point_3(c.x, c.y, c.z), EK::FT(layering->scale), box, periodic, vertices, out);
    } else {
      add_pieces(poly, i, -1, box, periodic, {-1, -1, -1}, {1, 1, 1}, vertices, out);
    }
  }
  return out;
}

LaguerreCut periodic_box_cut(const std::vector<Vec3>& bases,
                             const std::vector<std::vector<std::vector<LatticeCorner>>>& cells, Vec3 box) {
  LaguerreCut out;
  ExactVertices vertices(out.vertices);
  for (int c = 0; c < static_cast<int>(cells.size()); ++c) {
    ExactPolyhedron poly;
    std::map<std::pair<int, std::array<int, 3>>, int> local;
    std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const auto& ring : cells[c]) {
      std::vector<int> face;
      for (const LatticeCorner& corner : ring) {
        const auto [it, added] =
            local.emplace(std::pair{corner.base, corner.shift}, static_cast<int>(poly.points.size()));
        if (added) {
          const Vec3 b = bases[corner.base];
          std::array<EK::FT, 3> p{EK::FT(b.x), EK::FT(b.y), EK::FT(b.z)};
          for (int a = 0; a < 3; ++a) {
            if (corner.shift[a] != 0) p[a] = p[a] + EK::FT(box[a]) * EK::FT(corner.shift[a]);
            const double x = b[a] + corner.shift[a] * box[a];
            lo[a] = std::min(lo[a], x);
            hi[a] = std::max(hi[a], x);
          }
          poly.points.emplace_back(p[0], p[1], p[2]);
        }
        face.push_back(it->second);
      }
      poly.faces.push_back(std::move(face));
    }
    // The box images the cell may reach, one more each way than its rounded extent says.
    std::array<int, 3> mlo{}, mhi{};
    for (int a = 0; a < 3; ++a) {
      mlo[a] = static_cast<int>(std::floor(lo[a] / box[a])) - 1;
      mhi[a] = static_cast<int>(std::floor(hi[a] / box[a])) + 1;
    }
    add_pieces(poly, c, -1, box, true, mlo, mhi, vertices, out);
  }
  return out;
}

}  // namespace grainmesh
