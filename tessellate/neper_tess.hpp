// Neper's tessellation files (.tess, the format 3.4 Neper 4 writes) read as they are:
// seeds, vertices, edges, faces and polyhedra, the domain's box and type, and whether the
// file is periodic. neper_import.hpp makes our tessellation of it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace grainmesh {

struct NeperTess {
  int dimensions = 3;                          // 2 or 3
  std::vector<Vec3> seeds;                     // #cells, as written (z = 0 in 2D)
  std::vector<Vec3> vertices;                  // #V
  std::vector<std::vector<int>> faces;         // #F, each its vertex ids (0-based) in order round it
  std::vector<std::vector<int>> polyhedra;     // #P (3D), each its faces as id + 1, negative when the
                                               // face's normal points into it
  std::string domain_type;                     // square, cube, circle, poly, ...
  Box3 domain;                                 // the domain vertices' bounding box
  bool periodic = false;                       // a **periodicity section
  int cells() const { return static_cast<int>(seeds.size()); }
};

// The format version Neper 4 writes, the one read.
inline constexpr const char* kNeperFormat = "3.4";

// Reads `file`. Throws IoError when it cannot be read, GeometryError "FILE: what is wrong"
// when it is not a Neper tessellation of format 3.4 or its parts do not fit together.
NeperTess read_neper_tess(const std::filesystem::path& file);

}  // namespace grainmesh
