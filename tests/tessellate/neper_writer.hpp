// Neper tessellation files (.tess, format 3.4) written by the tests from a known
// tessellation, as Neper's documentation lays them out, with the domain moved to `origin`:
// what grainmesh must read back to the same cells.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh::test {

inline std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The header, the cells' seeds (shifted by `origin`) and the vertices.
inline void write_tess_start(std::ofstream& f, int dim, const std::vector<grainmesh::Vec3>& seeds,
                             const std::vector<grainmesh::Vec3>& vertices, grainmesh::Vec3 origin,
                             const std::string& format) {
  f << "***tess\n **format\n   " << format << "\n **general\n   " << dim << " standard\n **cell\n  " << seeds.size()
    << "\n  *id\n  ";
  for (std::size_t k = 0; k < seeds.size(); ++k) f << " " << k + 1;
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

// The domain: its corners (labels as Neper gives them), the rest of its description left out
// of what grainmesh reads but present.
inline void write_domain(std::ofstream& f, int dim, grainmesh::Vec3 origin, grainmesh::Vec3 size, const std::string& type) {
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
                       const std::string& format = "3.4", const std::string& domain = "square",
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
    for (int face : t.regions[r].faces) f << " " << (t.faces[face].back == static_cast<int>(r) ? face + 1 : -(face + 1));
    f << "\n";
  }
  write_domain(f, 3, origin, t.size(), "cube");
  f << "***end\n";
}

}  // namespace grainmesh::test
