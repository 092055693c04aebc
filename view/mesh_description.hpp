// mesh.json, written beside mesh.vtu by the mesh and domain stages: what the VTU file does
// not say (the cell, whether it is periodic, the phases with the moduli they know).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

// mesh.json: what mesh.vtu does not say. Phases without known moduli have them unset.
struct MeshDescription {
  Box cell;
  bool periodic = false;
  struct PhaseInfo {
    std::string name;
    std::optional<double> youngs_modulus, poisson_ratio;
  };
  std::vector<PhaseInfo> phases;
};


// Writes `description` as `file` (JSON, format grainmesh-mesh version 1).
void write_mesh_description(const std::filesystem::path& file, const MeshDescription& description);

// Reads a mesh.json. Throws IoError (the file), GeometryError (its contents).
MeshDescription read_mesh_description(const std::filesystem::path& file);

}  // namespace grainmesh
