// The polyMesh OpenFOAM reads, built from a 2D mesh (its cells extruded one cell thick)
// with its patches and zones, and written in ASCII or binary; the 3D builders fill the
// same type (foam_3d.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry.hpp"
#include "common/vec3.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

// The polyMesh as OpenFOAM orders it: internal faces first, sorted by owner then
// neighbour (owner < neighbour, normals from owner to neighbour), then the boundary
// faces patch by patch, outward. Cells are the triangles, in their order.
struct PolyMesh {
  struct Patch {
    std::string name, type;        // type: patch, symmetryPlane, empty, cyclic
    int start = 0, size = 0;
    std::string neighbour_patch;   // cyclic only
    Vec3 separation{};             // cyclic only: neighbour = this + separation (mesh units)
    Vec3 at{};                     // a pinned face's patch (pin_translation.hpp): where its
                                   // displacement is fixed, mesh units from the cell's low corner
  };
  struct FaceZone {
    std::string name;
    std::vector<int> faces;
    std::vector<char> flip;        // 1 where the face points from the higher label to the lower
  };
  std::vector<Vec2> points2d;      // a 2D mesh's points; the polyMesh has them at z = 0 and z = thickness
  double thickness = 0.0;
  std::vector<Vec3> points3d;      // a 3D mesh's points (then points2d is empty)
  std::vector<int> face_start, face_points;  // face f: face_points[face_start[f] .. face_start[f + 1])
  std::vector<int> owner, neighbour;         // neighbour for internal faces only
  std::vector<Patch> patches;
  std::vector<std::pair<std::string, std::vector<int>>> cell_zones;
  std::vector<FaceZone> face_zones;
  int cells = 0;
  int internal_faces() const { return static_cast<int>(neighbour.size()); }
  int faces() const { return static_cast<int>(owner.size()); }
};

// Builds the polyMesh. Throws ConfigError naming a patch the load needs that has no face
// (right, left, bottom, and top unless uniaxial), GeometryError when a cyclic side's faces
// do not pair, or a boundary edge lies on no side while the mesh is to be cyclic.
PolyMesh build_polymesh(const ExportMesh& m, const FoamOptions& options);

// The zones of a built polyMesh (cells in its order, internal faces counted): a cellZone
// per phase (every cell in exactly one), one per grain when `grain_zones`; faceZones
// grainBoundaries and phaseInterfaces, a face's flip set where it points from the higher
// label to the lower. For the 2D and the 3D builders.
void add_zones(const std::vector<int>& grain, const std::vector<int>& phase, const std::vector<FoamPhase>& phases,
               bool grain_zones, PolyMesh& pm);

// Writes constant/polyMesh (points, faces, owner, neighbour, boundary, cellZones,
// faceZones) of `pm` into `dir`, ASCII or binary as `options` says.
void write_polymesh(const std::filesystem::path& dir, const PolyMesh& pm, const FoamOptions& options);

}  // namespace grainmesh
