// `grainmesh mesh TESSELLATION.json -o OUT`: the mesh stage on a tessellation, written as
// OUT/mesh.vtu, OUT/mesh.json, OUT/mesh.png, OUT/mesh_detail.png and OUT/report.json (last).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "grains/grain_mesh.hpp"
#include "mesh/quality.hpp"
#include "pipelines/config.hpp"
#include "pipelines/mesh_job.hpp"

namespace grainmesh {

// Reads and validates tessellation.json. Throws IoError or GeometryError naming the file.
Tessellation read_tessellation_file(const std::filesystem::path& file);

// Below this worst triangle quality a mesh is reported as poor (q = 1 equilateral).
inline constexpr double kPoorQuality = 0.5;

// "mesh: q_min ... is below 0.5 (N triangles below 0.5): look at mesh.png; CAUSES cause
// it" when the worst triangle is poor; any mesh's (domain's too).
std::optional<std::string> poor_quality_warning(const MeshQuality& q, std::size_t triangles, const std::string& causes);

// What a mesh should tell its user: q_min below kPoorQuality, regions that stopped at the
// iteration limit.
std::vector<std::string> mesh_warnings(const GrainMesh& m, const MeshQuality& q, const GrainMeshOptions& o);

// Writes a grain mesh's files into `dir`: mesh.vtu (cell data grain, phase, quality),
// mesh.json (the cell and phases, for the export), mesh.png (not when picture_width is 0)
// and, when `detail`, mesh_detail.png; the pictures with the phases' legend and a scale
// bar in `length_unit` (empty: the config's own, unnamed).
void write_mesh_files(const std::filesystem::path& dir, const Tessellation& t, const GrainMesh& m, int picture_width,
                      bool detail = true, const std::string& length_unit = {});

// The window of mesh_detail.png: at the cell's centre, three mean grain diameters wide,
// where single elements show.
Box detail_view(const Tessellation& t);

void run_mesh_command(const std::filesystem::path& tessellation, const Config& config,
                      const std::filesystem::path& out);

// `grainmesh check TESSELLATION.json MESH.vtu`: the conformity checker on a written mesh
// (cell arrays grain and phase); prints its figures, or throws GeometryError naming the
// mesh file and the first violation (IoError for unreadable files).
void run_check_command(const std::filesystem::path& tessellation, const std::filesystem::path& mesh_file);

}  // namespace grainmesh
