// VTK XML unstructured grids (.vtu) of triangle meshes, through the VTK library.
#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "mesh/trimesh.hpp"

namespace grainmesh {

// One value per triangle, named as ParaView will show it.
struct CellField {
  std::string name;
  std::variant<std::vector<int>, std::vector<double>> values;  // #T
};

// Writes the mesh (z = 0) and its cell fields as binary VTU. Deterministic: the same
// mesh gives the same bytes. Throws IoError when the file cannot be written.
void write_vtu(const std::filesystem::path& file, const TriMesh& mesh, const std::vector<CellField>& fields);

// Reads a VTU written by write_vtu: points, triangles and every cell array (integer
// arrays as int, the rest as double). `mesh.region` is filled from a cell array named
// "region" when there is one. Throws IoError.
struct VtuContents {
  TriMesh mesh;
  std::vector<CellField> fields;
};
VtuContents read_vtu(const std::filesystem::path& file);

}  // namespace grainmesh
