// Neper's tessellation files (.tess, the formats 3.4 and 3.5 Neper 4 writes) read as they
// are: seeds, cell groups, vertices, faces and polyhedra, the domain's box and type, and
// the periodicity (which vertex is which one's periodic image). neper_import.hpp makes our
// tessellation of it.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace grainmesh {

struct NeperTess {
  int dimensions = 3;                       // 2 or 3
  std::vector<Vec3> seeds;                  // #cells, as written (z = 0 in 2D)
  std::vector<Vec3> vertices;               // #V
  std::vector<std::vector<int>> faces;      // #F, each its vertex ids (0-based) in order round it
  std::vector<std::vector<int>> polyhedra;  // #P (3D), each its faces as id + 1, negative when the
                                            // face's normal points into it
  std::vector<int> groups;                  // #cells (*group), empty when the file has none
  std::string domain_type;                  // cube (Neper 4 writes it for a 2D square too), square, circle, ...
  std::vector<Vec3> domain_vertices;        // as written
  Box3 domain;                              // the domain vertices' bounding box
  // Periodic files (type periodic, a **periodicity section): the axes that are periodic,
  // their periods, and each secondary vertex's primary and lattice shift (vertex =
  // primary + shift x period); the cells are whole and reach out of the domain.
  bool periodic = false;
  std::array<bool, 3> periodic_axes{false, false, false};
  Vec3 period;
  struct Image {
    int vertex = 0;   // the secondary vertex (0-based)
    int primary = 0;  // its primary (0-based)
    std::array<int, 3> shift{0, 0, 0};
  };
  std::vector<Image> vertex_images;
  int cells() const { return static_cast<int>(seeds.size()); }
};

// The format versions Neper 4 writes (4.0 to 4.9: 3.4; 4.10 on: 3.5), the ones read.
inline constexpr const char* kNeperFormats = "3.4 or 3.5";

// Reads `file`. Throws IoError when it cannot be read, GeometryError "FILE: what is wrong"
// when it is not a Neper tessellation of format 3.4 or 3.5 or its parts do not fit together.
NeperTess read_neper_tess(const std::filesystem::path& file);

}  // namespace grainmesh
