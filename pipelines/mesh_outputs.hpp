// The mesh stage, plane and solid cells alike: the mesh made and checked, its files and
// pictures, the fields report.json gives it, and its summary line (used by `grainmesh
// mesh` and `grainmesh run`).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "grains/grain_mesh.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "mesh/quality.hpp"
#include "pipelines/drawing.hpp"
#include "pipelines/mesh_job.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// Meshes the cell (2D: progress through job.options.progress) and checks the mesh's
// conformity (GeometryError otherwise); regions stopped at mesh.max_iterations become a
// warning (2D).
GrainMesh run_mesh_job(const Tessellation& t, const MeshJob<2>& job, Warnings& warnings);
GrainMesh3 run_mesh_job(const Tessellation3& t, const MeshJob<3>& job, Warnings& warnings);

// The finite elements' coarse level of a cell whose run mesh has `cells` elements: meshed
// at twice the job's sizes, and once more, coarser, when its nested refinement (2^D
// children a cell) would hold more than 1.25 times `cells`: the fine level then costs
// about what the run's mesh would. Quietly: the run's mesh has had its warnings.
GrainMesh fe_coarse_mesh(const Tessellation& t, const MeshJob<2>& job, std::size_t cells);
GrainMesh3 fe_coarse_mesh(const Tessellation3& t, const MeshJob<3>& job, std::size_t cells);

// Writes mesh.vtu (cell arrays grain, phase, quality; 3D also region) into `dir` and, when
// drawing.pictures, mesh.png (3D: the section at the job's height); 2D also mesh.json (the
// cell and phases, for the export) and, when drawing.detail, mesh_detail.png. A poor mesh
// (a triangle below kPoorQuality, a dihedral angle below 5 degrees) becomes a warning.
// Returns report.json's fields on the mesh: `mesh` {points, cells, the quality measures,
// cells_per_grain_mean, ...}, size, pairs {x, y(, z)}, conforming, threads (3D: the
// surface's counts, the stages' seconds and section_z).
Json write_mesh_files(const std::filesystem::path& dir, const Tessellation& t, const GrainMesh& m,
                      const MeshJob<2>& job, const Drawing& drawing, Warnings& warnings);
Json write_mesh_files(const std::filesystem::path& dir, const Tessellation3& t, const GrainMesh3& m,
                      const MeshJob<3>& job, const Drawing& drawing, Warnings& warnings);

// The mesh's one-line summary, on stdout, from the `mesh` fields write_mesh_files returned.
void print_mesh_summary(const GrainMesh& m, const Json& mesh);
void print_mesh_summary(const GrainMesh3& m, const Json& mesh);

// Below this worst triangle quality a mesh is reported as poor (q = 1 equilateral).
inline constexpr double kPoorQuality = 0.5;

// "mesh: q_min ... is below 0.5 (N triangles below 0.5): look at mesh.png; CAUSES cause
// it" when the worst triangle is poor; any mesh's (domain's too).
std::optional<std::string> poor_quality_warning(const MeshQuality& q, std::size_t triangles, const std::string& causes);

// The window of mesh_detail.png: at the cell's centre, three mean grain diameters wide,
// where single elements show.
Box detail_view(const Tessellation& t);

}  // namespace grainmesh
