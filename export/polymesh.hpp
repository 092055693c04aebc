// The polyMesh OpenFOAM reads, 2D (extruded) and 3D alike: its points, faces, cells,
// patches and zones. Built by polymesh_2d.hpp and polymesh_3d.hpp (and the dual's
// polymesh_dual_3d.hpp), written by polymesh_files.hpp.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "common/geometry.hpp"
#include "common/vec3.hpp"
#include "export/foam_material.hpp"

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


// The index of patch `name` in pm.patches; -1 when there is none.
int patch_index(const PolyMesh& pm, const std::string& name);

// The zones of a built polyMesh (cells in its order, internal faces counted): a cellZone
// per phase (every cell in exactly one), one per grain when `grain_zones`; faceZones
// grainBoundaries and phaseInterfaces, a face's flip set where it points from the higher
// label to the lower. For the 2D and the 3D builders.
void add_zones(const std::vector<int>& grain, const std::vector<int>& phase, const std::vector<FoamPhase>& phases,
               bool grain_zones, PolyMesh& pm);


}  // namespace grainmesh
