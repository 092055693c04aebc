// constant/polyMesh as OpenFOAM reads it, from a built polyMesh (2D or 3D).
#pragma once

#include <filesystem>

#include "export/foam_options.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// Writes constant/polyMesh (points, faces, owner, neighbour, boundary, cellZones,
// faceZones) of `pm` into `dir`, ASCII or binary as `options` says.
void write_polymesh(const std::filesystem::path& dir, const PolyMesh& pm, const FoamOptions& options);

}  // namespace grainmesh
