// Neper tessellation files (.tess, format 3.4) written by the tests from a known
// tessellation, as Neper's documentation lays them out and with its 12 decimals, the
// domain moved to `origin`: what grainmesh must read back to the same cells. Periodic ones
// hold whole cells (a power diagram's, reaching out of the domain) and the periodicity
// section pairing each vertex's images.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/random.hpp"
#include "common/ring.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/torus.hpp"

namespace grainmesh::test {

inline std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12f", v);
  return buf;
}

// The header, the cells' (groups and) seeds (shifted by `origin`) and the vertices.
inline void write_tess_start(std::ofstream& f, int dim, const std::vector<grainmesh::Vec3>& seeds,
                             const std::vector<grainmesh::Vec3>& vertices, grainmesh::Vec3 origin,
                             const std::string& format, const std::string& type = "standard",
                             const std::vector<int>& groups = {}) {
  f << "***tess\n **format\n   " << format << "\n **general\n   " << dim << " " << type << "\n **cell\n  "
    << seeds.size() << "\n  *id\n  ";
  for (std::size_t k = 0; k < seeds.size(); ++k) f << " " << k + 1;
  if (!groups.empty()) {
    f << "\n  *group\n  ";
    for (int g : groups) f << " " << g;
  }
  f << "\n  *crysym\n   triclinic\n  *seed\n";
  for (std::size_t k = 0; k < seeds.size(); ++k)
    f << "   " << k + 1 << " " << num(seeds[k].x + origin.x) << " " << num(seeds[k].y + origin.y) << " "
      << num(seeds[k].z + origin.z) << " 0.000000000000\n";
  f << "  *ori\n   rodrigues:active\n";
  for (std::size_t k = 0; k < seeds.size(); ++k) f << "   0.1 0.2 0.3\n";
  f << " **vertex\n " << vertices.size() << "\n";
  for (std::size_t k = 0; k < vertices.size(); ++k)
    f << "   " << k + 1 << " " << num(vertices[k].x + origin.x) << " " << num(vertices[k].y + origin.y) << " "
      << num(vertices[k].z + origin.z) << " 0\n";
}

// The edges of the faces' rings, each once, and a face's edges signed by direction.
struct TessEdges {
  std::map<std::pair<int, int>, int> id;  // (low, high) vertex -> edge id (1-based)
  std::vector<std::pair<int, int>> list;
  int signed_edge(int a, int b) {
    const auto key = std::minmax(a, b);
    auto [it, added] = id.emplace(key, static_cast<int>(list.size()) + 1);
    if (added) list.push_back(key);
    return a < b ? it->second : -it->second;
  }
};

inline void write_faces(std::ofstream& f, const std::vector<std::vector<int>>& rings, TessEdges& edges) {
  std::vector<std::vector<int>> face_edges;
  for (const auto& ring : rings) {
    std::vector<int> e;
    for (std::size_t k = 0; k < ring.size(); ++k) e.push_back(edges.signed_edge(ring[k], ring[(k + 1) % ring.size()]));
    face_edges.push_back(e);
  }
  f << " **edge\n " << edges.list.size() << "\n";
  for (std::size_t k = 0; k < edges.list.size(); ++k)
    f << "   " << k + 1 << " " << edges.list[k].first + 1 << " " << edges.list[k].second + 1 << " 0\n";
  f << " **face\n " << rings.size() << "\n";
  for (std::size_t k = 0; k < rings.size(); ++k) {
    f << "   " << k + 1 << " " << rings[k].size();
    for (int v : rings[k]) f << " " << v + 1;
    f << "\n     " << face_edges[k].size();
    for (int e : face_edges[k]) f << " " << e;
    f << "\n    0.000000000000 0.000000000000 0.000000000000 1.000000000000\n     0 0 0.000000000000 "
         "0.000000000000 0.000000000000\n";
  }
}

// The domain (Neper 4 calls a 2D square one a cube too): its corners (labels as Neper gives them), the rest of its description left out
// of what grainmesh reads but present.
inline void write_domain(std::ofstream& f, int dim, grainmesh::Vec3 origin, grainmesh::Vec3 size,
                         const std::string& type) {
  f << " **domain\n  *general\n   " << type << "\n  *vertex\n   " << (dim == 2 ? 4 : 8) << "\n";
  int id = 0;
  for (int z = 0; z < (dim == 2 ? 1 : 2); ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) {
        f << "   " << ++id << " " << num(origin.x + x * size.x) << " " << num(origin.y + y * size.y) << " "
          << num(origin.z + z * size.z) << " x" << x << "y" << y;
        if (dim == 3) f << "z" << z;
        f << "\n      1 1\n";
      }
  f << "  *edge\n   0\n";
}

// A plane tessellation (not periodic, one ring per region) as a .tess.
inline void write_tess(const std::filesystem::path& file, const grainmesh::Tessellation& t, grainmesh::Vec3 origin,
                       const std::string& format = "3.4", const std::string& domain = "cube",
                       const std::string& extra = "") {
  std::ofstream f(file);
  std::vector<grainmesh::Vec3> seeds, vertices;
  for (const auto& g : t.grains) seeds.push_back({g.seed.x, g.seed.y, 0.0});
  for (const auto& v : t.vertices) vertices.push_back({v.x, v.y, 0.0});
  write_tess_start(f, 2, seeds, vertices, origin, format);
  std::vector<std::vector<int>> rings(t.grains.size());
  for (const auto& r : t.regions) rings[r.grain] = r.rings[0];
  TessEdges edges;
  write_faces(f, rings, edges);
  write_domain(f, 2, origin, {t.width, t.height, 0.0}, domain);
  f << extra << "***end\n";
}

// A solid tessellation (not periodic, one region per grain) as a .tess; a polyhedron's
// face signed + where the face's normal points out of it.
inline void write_tess(const std::filesystem::path& file, const grainmesh::Tessellation3& t, grainmesh::Vec3 origin,
                       const std::string& format = "3.4") {
  std::ofstream f(file);
  std::vector<grainmesh::Vec3> seeds;
  for (const auto& g : t.grains) seeds.push_back(g.seed);
  write_tess_start(f, 3, seeds, t.vertices, origin, format);
  std::vector<std::vector<int>> rings;
  for (const auto& face : t.faces) rings.push_back(face.ring);
  TessEdges edges;
  write_faces(f, rings, edges);
  f << " **polyhedron\n " << t.regions.size() << "\n";
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    f << "   " << r + 1 << " " << t.regions[r].faces.size();
    for (int face : t.regions[r].faces)
      f << " " << (t.faces[face].back == static_cast<int>(r) ? face + 1 : -(face + 1));
    f << "\n";
  }
  write_domain(f, 3, origin, t.size(), "cube");
  f << "***end\n";
}

// Whole periodic cells and what a periodic .tess says of them besides.
struct WholeCells {
  int dim = 2;
  grainmesh::Vec3 box;                 // the domain's sides (z 0 in 2D)
  std::vector<grainmesh::Vec3> seeds;  // in the domain
  std::vector<std::vector<std::vector<grainmesh::Vec3>>>
      faces;                // per cell (2D: its one ring), counter-clockwise from outside
  std::vector<int> groups;  // per cell, or none
};

// Whole periodic cells as a periodic .tess: each point once per lattice image it is met at
// (a point within 1e-9 of another moved by whole periods is its image), the first met its
// primary; shared faces (3D) once, signed by which side they face.
inline void write_periodic_tess(const std::filesystem::path& file, const WholeCells& w, grainmesh::Vec3 origin) {
  using grainmesh::Vec3;
  std::vector<Vec3> primaries, vertices;
  std::map<std::pair<int, std::array<int, 3>>, int> entry;  // (primary, shift) -> vertex
  std::vector<int> first;                                   // primary -> its own vertex
  std::vector<std::pair<int, std::pair<int, std::array<int, 3>>>> images;
  auto vertex = [&](Vec3 p) {
    int root = -1;
    std::array<int, 3> shift{0, 0, 0};
    for (int r = 0; r < static_cast<int>(primaries.size()) && root < 0; ++r) {
      bool same = true;
      for (int a = 0; a < w.dim; ++a) {
        const double d = p[a] - primaries[r][a];
        shift[a] = static_cast<int>(std::lround(d / w.box[a]));
        same = same && std::abs(d - shift[a] * w.box[a]) < 1e-9;
      }
      if (same) root = r;
    }
    if (root < 0) {
      root = static_cast<int>(primaries.size());
      primaries.push_back(p);
      shift = {0, 0, 0};
    }
    const auto [it, added] = entry.emplace(std::pair{root, shift}, static_cast<int>(vertices.size()));
    if (added) {
      Vec3 q = primaries[root];
      for (int a = 0; a < w.dim; ++a) q[a] += shift[a] * w.box[a];
      vertices.push_back(q);
      if (root == static_cast<int>(first.size()))
        first.push_back(it->second);
      else
        images.push_back({it->second, {first[root], shift}});
    }
    return it->second;
  };
  std::vector<std::vector<std::vector<int>>> cells;
  for (const auto& cell : w.faces) {
    std::vector<std::vector<int>> rings;
    for (const auto& face : cell) {
      std::vector<int> ring;
      for (const Vec3& p : face) ring.push_back(vertex(p));
      rings.push_back(std::move(ring));
    }
    cells.push_back(std::move(rings));
  }
  std::ofstream f(file);
  write_tess_start(f, w.dim, w.seeds, vertices, origin, "3.4", "periodic", w.groups);
  TessEdges edges;
  if (w.dim == 2) {
    std::vector<std::vector<int>> rings;
    for (const auto& cell : cells) rings.push_back(cell[0]);
    write_faces(f, rings, edges);
  } else {
    std::map<std::vector<int>, int> face_id;
    std::vector<std::vector<int>> rings;
    std::vector<std::vector<int>> polyhedra;
    for (const auto& cell : cells) {
      std::vector<int> signed_faces;
      for (const auto& ring : cell) {
        std::vector<int> key = ring;
        std::sort(key.begin(), key.end());
        const auto [it, added] = face_id.emplace(key, static_cast<int>(rings.size()) + 1);
        if (added) rings.push_back(ring);
        signed_faces.push_back(added ? it->second : -it->second);
      }
      polyhedra.push_back(std::move(signed_faces));
    }
    write_faces(f, rings, edges);
    f << " **polyhedron\n " << polyhedra.size() << "\n";
    for (std::size_t c = 0; c < polyhedra.size(); ++c) {
      f << "   " << c + 1 << " " << polyhedra[c].size();
      for (int face : polyhedra[c]) f << " " << face;
      f << "\n";
    }
  }
  write_domain(f, w.dim, origin, w.box, "cube");
  f << " **periodicity\n  *general\n   1 1 " << (w.dim == 3 ? 1 : 0) << "\n   " << num(w.box.x) << " " << num(w.box.y)
    << " " << num(w.box.z) << "\n  *seed\n   0\n  *vertex\n   " << images.size() << "\n";
  for (const auto& [secondary, image] : images)
    f << "   " << secondary + 1 << " " << image.first + 1 << " " << image.second[0] << " " << image.second[1] << " "
      << image.second[2] << "\n";
  f << "  *edge\n   0\n";
  if (w.dim == 3) f << "  *face\n   0\n";
  f << "***end\n";
}

// Random seeds in a box of sides `box` (z 0 in 2D).
inline std::vector<grainmesh::Vec3> random_seeds(int count, grainmesh::Vec3 box, std::uint64_t seed) {
  grainmesh::Rng rng(seed);
  std::vector<grainmesh::Vec3> out;
  for (int k = 0; k < count; ++k)
    out.push_back(
        {grainmesh::uniform01(rng) * box.x, grainmesh::uniform01(rng) * box.y, grainmesh::uniform01(rng) * box.z});
  return out;
}

// The whole cells of the periodic Voronoi diagram of `seeds` in a W x H cell, each its
// polygon about its own seed.
inline WholeCells plane_whole_cells(const std::vector<grainmesh::Vec3>& seeds, double W, double H) {
  std::vector<grainmesh::Vec2> flat;
  for (const grainmesh::Vec3& s : seeds) flat.push_back({s.x, s.y});
  const grainmesh::TorusGraph g =
      grainmesh::power_diagram(flat, std::vector<double>(flat.size(), 0.0), W, H, true, 1e-12);
  WholeCells w{.dim = 2, .box = {W, H, 0.0}, .seeds = {}, .faces = {}, .groups = {}};
  for (int c = 0; c < static_cast<int>(g.rings.size()); ++c) {
    if (g.rings[c].empty()) throw std::runtime_error("a hidden cell");
    std::vector<grainmesh::Vec2> poly = g.polygon(c);
    // The lattice image of the polygon that holds the (reduced) seed.
    grainmesh::Vec2 shift{};
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j) {
        std::vector<grainmesh::Vec2> moved;
        for (grainmesh::Vec2 p : poly) moved.push_back({p.x + i * W, p.y + j * H});
        if (grainmesh::inside_ring(moved, g.seeds[c])) shift = {i * W, j * H};
      }
    std::vector<grainmesh::Vec3> ring;
    for (grainmesh::Vec2 p : poly) ring.push_back({p.x + shift.x, p.y + shift.y, 0.0});
    w.seeds.push_back({g.seeds[c].x, g.seeds[c].y, 0.0});
    w.faces.push_back({ring});
  }
  return w;
}

}  // namespace grainmesh::test
