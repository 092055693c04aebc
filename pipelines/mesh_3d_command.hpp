// `grainmesh mesh TESSELLATION.json -o OUT` for a 3D tessellation (version 2): OUT/
// mesh.vtu (VTK tetrahedra with grain, phase, region and quality), mesh.png (a section)
// and report.json (last) with the mesh's size, quality and seconds per stage.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "grains3d/grain_mesh_3d.hpp"
#include "pipelines/config.hpp"
#include "pipelines/mesh_job.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// Meshes the cell and checks the mesh's conformity (check_conformity throws otherwise).
GrainMesh3 run_mesh_3d_job(const Tessellation3& t, const Mesh3Job& job);

// Writes mesh.vtu and, when `pictures`, mesh.png (the section at section_height, its
// scale bar in `length_unit`, empty: unnamed) into `dir`; returns what report.json says of
// the mesh (`mesh` with its quality, counts, seconds per stage, section_z); a sliver left
// in the mesh becomes a warning.
Json write_mesh_3d_files(const std::filesystem::path& dir, const Tessellation3& t, const GrainMesh3& m, const Mesh3Job& job,
                         Warnings& warnings, bool pictures, const std::string& length_unit);

// The mesh's one-line summary, on stdout, from the `mesh` write_mesh_3d_files reported.
void print_mesh_3d_summary(const Json& mesh, double seconds);

void run_mesh_3d_command(const Tessellation3& t, const std::filesystem::path& tessellation, const Config& config,
                         const std::filesystem::path& out);

}  // namespace grainmesh
