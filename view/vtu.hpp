// VTK XML files through the VTK library: unstructured grids (.vtu) of triangle meshes,
// polydata (.vtp) of tessellations.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "export/polymesh.hpp"
#include "mesh/cell_mesh.hpp"
#include "mesh/tetmesh.hpp"
#include "mesh/trimesh.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// `components` values per triangle (consecutive), named as ParaView will show it: 1 a
// scalar, 3 a vector, 6 a symmetric tensor in VTK's order (xx yy zz xy yz xz).
struct CellField {
  std::string name;
  std::variant<std::vector<int>, std::vector<double>> values;  // components x #T
  int components = 1;
};

// Names stored with the grid (VTK field data: bytes, each name in UTF-8 ended by a NUL, a
// form meshio reads too): e.g. the phases' names, which the integer `phase` array numbers.
struct FieldLabels {
  std::string name;
  std::vector<std::string> labels;
};

// Writes the mesh (z = 0), its cell fields and labels as binary VTU. Deterministic: the
// same mesh gives the same bytes. Throws IoError when the file cannot be written.
void write_vtu(const std::filesystem::path& file, const TriMesh& mesh, const std::vector<CellField>& fields,
               const std::vector<FieldLabels>& labels = {});
// The same for polygonal cells (VTK polygons; triangles stay VTK triangles).
void write_vtu(const std::filesystem::path& file, const CellMesh& mesh, const std::vector<CellField>& fields,
               const std::vector<FieldLabels>& labels = {});

// The cells of a 3D polyMesh (points3d) as VTK polyhedra, each face turned outward, with
// cell fields and labels as above.
void write_vtu(const std::filesystem::path& file, const PolyMesh& mesh, const std::vector<CellField>& fields,
               const std::vector<FieldLabels>& labels = {});

// Reads a VTU written by write_vtu: points, cells (triangles and polygons), every cell
// array (integer arrays as int, the rest as double) and every list of labels in the field
// data (bytes, or a string array as older files have); 3D cells (polyhedra, tetrahedra) by
// their volumes alone. Throws IoError.
struct VtuContents {
  CellMesh mesh;  // triangles and polygons as written
  // Each 3D cell's volume from its faces as written (the divergence theorem, each face
  // fanned from its corners' mean): negative where faces turn inward.
  std::vector<double> solid_volumes;
  std::vector<CellField> fields;
  std::vector<FieldLabels> labels;
  // The integer scalar cell array `name` (e.g. "grain", "phase"), or nullptr.
  const std::vector<int>* ints(const std::string& name) const;
};
VtuContents read_vtu(const std::filesystem::path& file);

}  // namespace grainmesh

namespace grainmesh {

// Writes the tessellation as VTK polydata (z = 0): one polygon per region without holes
// (grain pieces), one line per edge. Cell arrays: kind (0 region, 1 edge), grain, phase,
// region (-1 on edges), and on edges the regions left and right (-1 on regions).
// Matrix regions with holes appear through their edges only. Throws IoError.
void write_tessellation_vtp(const std::filesystem::path& file, const Tessellation& t);

// Writes a tetrahedral mesh as binary VTU (VTK tetrahedra), with integer cell arrays
// (grain, phase, region: one value per tetrahedron) and real ones (quality). Throws IoError.
void write_tet_vtu(const std::filesystem::path& file, const TetMesh& mesh,
                   const std::vector<std::pair<std::string, const std::vector<int>*>>& ints,
                   const std::vector<std::pair<std::string, const std::vector<double>*>>& reals,
                   const std::vector<FieldLabels>& labels = {});

// Writes a 3D tessellation as an unstructured grid of VTK polyhedra, one per region, with
// cell arrays grain, phase and region, and the phases' names. Throws IoError.
void write_tessellation_vtu(const std::filesystem::path& file, const Tessellation3& t);

}  // namespace grainmesh
