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

namespace grainmesh {

// The mesh keys, read; the size per grain and per phase resolved against a tessellation
// by resolve_mesh_job.
struct MeshJob {
  GrainMeshOptions options;
  int picture_width = 1200;  // pixels
  std::optional<double> per_grain;                          // mesh.triangles_per_grain, when no size is given
  std::string size_key;                                     // mesh.size or mesh.h, when given
  std::vector<std::pair<std::string, double>> phase_sizes;  // phase.NAME.size, by name
  ConfigOrigin origin;                                      // names the key at fault in resolve_mesh_job's errors
};

// Reads and checks the mesh keys (all that can be checked without the tessellation).
// Throws ConfigError naming the key.
MeshJob read_mesh_job(const Config& config);
// The job for tessellation `t`: options.size from mesh.triangles_per_grain and the grains'
// mean area, options.phase_size by the tessellation's phases; refuses (ConfigError naming
// the key) an unknown phase and a size that asks for more than 2 kMaxMeshPoints triangles.
MeshJob resolve_mesh_job(MeshJob job, const Tessellation& t);
// Both at once (the mesh command's and the tests' way).
MeshJob read_mesh_job(const Config& config, const Tessellation& t);

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
