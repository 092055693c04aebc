// OpenFOAM output: the triangle mesh extruded one cell thick into prisms, written as a
// polyMesh with phase cellZones and grain-boundary faceZones, and a case that
// solidDisplacementFoam (OpenFOAM v1912) runs as it is: two-phase linear elasticity.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "common/geometry.hpp"
#include "common/periodic_pairs.hpp"
#include "common/vec3.hpp"
#include "grains/grain_mesh.hpp"
#include "mesh/cell_mesh.hpp"
#include "mesh/trimesh.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// How the written case solves: pseudo-time steps of one correction each, stopped when the
// displacement equation's initial residual falls below kSolverTolerance (OpenFOAM's own
// measure, in the case; grainmesh's solve judges a scale-aware one, see solve_monitor.hpp),
// or at kMaxCorrections. The answer is the effective stress: the case logs the force
// through its loaded sides every correction, and grainmesh's solve requires it to have
// settled - no correction of the last kStressWindow changed it by more than
// kStressTolerance (relative) - before it reports a number. The residual tolerance is
// where that holds with a wide margin (measured: the stress settles to 1e-6 around a
// residual of 1e-3 to 1e-4, and is within 1e-8 of its final value at 1e-5).
inline constexpr double kSolverTolerance = 1e-5;
inline constexpr double kStressTolerance = 1e-6;
inline constexpr int kStressWindow = 5;
inline constexpr int kMaxCorrections = 20000;
// The field every solved case holds the stress in, however it stopped: solidDisplacementFoam's
// sigmaD (the stress over rho, and rho is 1), written by the case's writeObjects.
inline constexpr const char* kStressField = "sigmaD";
// The displacement gradient a cyclic case writes beside it (grad(D), by a grad function object).
inline constexpr const char* kGradientField = "grad(D)";

// The environment OpenFOAM's programs run in, the written Allrun and grainmesh's solve
// alike: the Debian package's WM_PROJECT_DIR unless one is set, and glibc's allocator told
// to keep the memory it frees (common/allocator.hpp). The solver allocates and frees whole
// fields every correction; by default glibc maps and unmaps each from the kernel, which
// took half the solve's time (1,000 grains, 46k cells: 2.8 s, 1.3 s with these; the same
// numbers). A user's own GLIBC_TUNABLES follow ours, so theirs win. As NAME=value entries
// to add to this process's environment for a child.
inline constexpr const char* kFoamProjectDir = "/usr/share/openfoam";
std::vector<std::string> foam_environment();

struct FoamPhase {
  std::string name;
  double youngs_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;   // nu, in (-1, 0.5)
  double alpha = 0.0;           // linear thermal expansion, 1/K
};

// What the export needs of a mesh: triangles with a grain and a phase each,
// the phases, and the cell whose sides become the patches left, right, bottom, top
// (boundary edges elsewhere, e.g. around a hole, form the patch `boundary`).
struct ExportMesh {
  CellMesh mesh;                  // triangles, or polygons (the dual)
  std::vector<int> grain;         // #T
  std::vector<int> phase;         // #T, index into phases
  std::vector<FoamPhase> phases;
  Box cell;
  bool periodic = false;          // opposite sides carry matching nodes,
  PeriodicPairs pairs;            // ... paired (the cyclic faces are paired through them)
};

// Cases of more cells than this are written in binary unless export.format asks for
// ASCII: at 10.5 M cells the ASCII case took 42 s and most of 3.5 GiB (grainmesh run);
// at 100,000 an ASCII 2D case is 45 MB, about twice its binary form, and a case that
// size is read by programs, not by eye.
inline constexpr std::size_t kBinaryCaseAboveCells = 100'000;

struct FoamOptions {
  double thickness = 0.0;          // extrusion, mesh units; 0 = the mean edge length
  double convert_to_meters = 1e-6; // mesh units to metres (config lengths in micrometres)
  bool cyclic = false;             // periodic meshes: left/right and bottom/top as cyclic pairs,
                                   // the load a displacement jump across them (cyclic_strain)
  // A cyclic case's macroscopic strain (tensor components in Voigt order: xx, yy, zz, yz,
  // xz, xy; a 2D case has only xx, yy and xy), imposed as the jump of D across each pair,
  // strain times the pair's separation; all zero: the load's displacement / width along x
  // alone.
  std::array<double, 6> strain{};
  bool binary = false;             // binary polyMesh and fields instead of ASCII
  bool grain_zones = false;        // a cellZone per grain besides one per phase
  // The load: a normal displacement of `right` (mesh units; the thesis' 0.001 um) or a
  // normal traction on it, symmetry planes on left and bottom, and on top unless uniaxial
  // (then traction-free).
  double displacement = 0.001;
  double traction = 0.0;           // Pa; when not 0, `right` carries this normal traction instead
  bool uniaxial = false;
  bool plane_stress = false;       // default plane strain
  // A uniform temperature change (K; e.g. -1000 for cooling from sintering): the case
  // solves solidDisplacementFoam's thermal stress, the phases' alpha from 0/alpha. Only
  // on a cyclic case, at its `strain`; the free expansion follows by superposition with
  // the mechanical cases (analysis/thermal.hpp).
  double delta_T = 0.0;
  // MPI processes the solve runs on: above 1, the case is split by decomposePar
  // (system/decomposeParDict), solved by mpirun ... -parallel and put together again by
  // reconstructPar (solver_command, Allrun).
  int processes = 1;
  // How the stiffness 2 mu + lambda is interpolated to faces in laplacian(DD,D).
  // Harmonic is exact across an interface, but solidDisplacementFoam's explicit
  // correction is interpolated linearly, and the two together diverge once the phases'
  // stiffnesses differ by more than about 4 (measured); auto takes harmonic up to a
  // ratio of 3, linear above.
  enum class Interpolation { automatic, harmonic, linear } interpolation = Interpolation::automatic;
  // The cells (export.cells): the mesh's triangles, or the polygons of its dual split at
  // grain boundaries (polygon_cells).
  enum class Cells { triangles, polygons } cells = Cells::triangles;
  // The linear solver of D's equation: automatic is multigrid (GAMG: fastest) in 2D and
  // conjugate gradients (PCG with DIC) in 3D, where GAMG blew up; the solve falls back on
  // conjugate gradients when multigrid diverges (analysis/solve.cpp).
  enum class LinearSolver { automatic, multigrid, conjugate_gradients } linear_solver = LinearSolver::automatic;
};


// A 2D case's out-of-plane condition as reports name it: "plane_strain" (the default:
// held, e_zz = 0, a stress sigma_zz carried) or "plane_stress" (free, sigma_zz = 0).
inline const char* plane_state(const FoamOptions& o) { return o.plane_stress ? "plane_stress" : "plane_strain"; }

// The command that solves a written case: solidDisplacementFoam, or on o.processes > 1
// `mpirun --oversubscribe -np N solidDisplacementFoam -parallel` (Open MPI; run as root,
// it needs OMPI_ALLOW_RUN_AS_ROOT and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM, which
// foam_environment sets there and Allrun too).
std::vector<std::string> solver_command(const FoamOptions& options);

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

// A phase's in-plane Lame constants as solidDisplacementFoam has them (rho = 1): mu =
// E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)) in plane strain, E nu / ((1 +
// nu)(1 - nu)) in plane stress; gamma = 2 mu + lambda is the stiffness its implicit
// operator carries.
struct Lame {
  double lambda = 0.0, mu = 0.0;
  double gamma() const { return lambda + 2 * mu; }
};
Lame lame(const FoamPhase& phase, bool plane_stress);

// The stress a phase's free thermal strain would carry per kelvin of temperature change,
// as solidDisplacementFoam has it: threeK alpha, threeK = E / (1 - 2 nu) in plane strain
// (3 lambda + 2 mu), E / (1 - nu) in plane stress (the in-plane 2 (lambda + mu)). The
// stress is C : grad(D) - threeK alpha delta_T I (plane stress: its in-plane part).
double thermal_stress_per_kelvin(const FoamPhase& phase, bool plane_stress);
// The in-plane strain a phase takes when free to expand, per kelvin: (1 + nu) alpha under
// plane strain (held out of plane), alpha under plane stress. (In 3D: alpha itself.)
double free_expansion(const FoamPhase& phase, bool plane_stress);
// Per cell (cell_phase, an index into `phases`): threeK alpha delta_T of its phase (Pa),
// what the solver's sigmaD leaves out of the stress; all zero without a temperature change.
std::vector<double> thermal_stress(const std::vector<FoamPhase>& phases, const std::vector<int>& cell_phase,
                                   const FoamOptions& options);

// A grain mesh with its tessellation's cell and phases.
ExportMesh grain_export_mesh(const Tessellation& t, const GrainMesh& m);
// A mesh of triangles as polygons: the dual (dual_mesh.hpp) split at grain boundaries,
// each cell with the grain and phase of its triangles, the periodic pairs carried.
ExportMesh polygon_cells(const ExportMesh& triangles);
// The export's mesh of a grain mesh: grain_export_mesh, as polygon_cells when asked.
ExportMesh export_mesh(const Tessellation& t, const GrainMesh& m, FoamOptions::Cells cells);

// What a case's dictionaries, its load's checks and its solve need of the mesh, 2D or 3D:
// the phases and the cell's extents (mesh units; z = 0 for a 2D cell, which the case
// extrudes one cell thick), and whether opposite sides match.
struct FoamCell {
  const std::vector<FoamPhase>& phases;
  Vec3 size;
  bool periodic = false;
  int dimensions() const { return size.z > 0.0 ? 3 : 2; }
};
FoamCell foam_cell(const ExportMesh& m);

// The ratio of the stiffest phase's 2 mu + lambda to the softest's, and whether the case
// interpolates the stiffness harmonically (see FoamOptions::interpolation; a 3D case's
// `auto` is linear: harmonic diverged on tetrahedra, measured on a WC-Co cell at a
// contrast of 2.8 and on laminates of 3 and 20, and on their dual on the WC-Co cell).
double stiffness_contrast(const std::vector<FoamPhase>& phases, const FoamOptions& options);
bool harmonic_stiffness(const FoamCell& cell, const FoamOptions& options);

// Whether the case solves solidDisplacementFoam's compact form (2D, and 3D polyhedra),
// where the force through a face is gamma_f |S| snGrad(D) + S . (sigma - gamma
// grad(D))_f, or the plain one (3D tetrahedra), where it is S . sigma_f
// (analysis/traction.hpp).
inline bool compact_normal_stress(const FoamCell& cell, const FoamOptions& options) {
  return cell.dimensions() == 2 || options.cells == FoamOptions::Cells::polygons;
}

// The linear solver a case uses: options.linear_solver, automatic resolved by the cell's
// dimensions.
FoamOptions::LinearSolver linear_solver(const FoamCell& cell, const FoamOptions& options);
// Its name in OpenFOAM (GAMG, PCG).
const char* linear_solver_name(FoamOptions::LinearSolver solver);
// Writes DIR/system/fvSolution of the case write_foam_case writes.
void write_fv_solution(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& options);

// The phases' elastic constants as the case carries them.
std::vector<FoamPhase> foam_phases(const std::vector<Phase>& phases);

// The mean strain a load gives the cell, at most: |displacement| / width, |traction|
// over the softest phase's E, or the largest component of a cyclic case's strain.
double load_strain(const FoamCell& cell, const FoamOptions& options);

// The largest free thermal strain of a phase under the case's temperature change:
// |free_expansion delta_T| in 2D, |alpha delta_T| in 3D (0 without one).
double thermal_strain(const FoamCell& cell, const FoamOptions& options);

// Checks a load against the cell it acts on, before any mesh is made: export.cyclic only
// on a periodic cell (and with a displacement load), a cell of at least 1 nm in metres, a
// mean strain (displacement / width, or traction / the softest E) of at most 1 %, each
// phase's free thermal strain (alpha delta_T) at most 5 %, and a non-zero load. Throws
// ConfigError naming the key that makes the strain. Returns warnings: a cell above 1 m.
std::vector<std::string> check_load(const FoamCell& cell, const FoamOptions& options);

// The macroscopic strain (Voigt order, tensor components) a cyclic case imposes
// (FoamOptions::strain).
std::array<double, 6> cyclic_strain(const FoamCell& cell, const FoamOptions& options);

// The jump of D (metres) a cyclic case gives the pair of patch `name` (left/right,
// bottom/top, back/front): the mean `strain` (Voigt order) times the pair's separation,
// the cell's extent along its axis times `scale` (metres per mesh unit); the low patch's,
// the high one has its negative.
Vec3 cyclic_jump(const std::array<double, 6>& strain, const std::string& name, const FoamCell& cell, double scale);

// The case's own stop (runTimeControl): OpenFOAM's initial residual of D below
// `tolerance` (kSolverTolerance, a hundredth of it for a cyclic case), of one component
// alone, at a hundredth again, when the others' exact solution is zero (one material
// under a load that moves it along one axis only: the default load, or a cyclic case's
// normal strain).
struct CaseStop {
  int alone = -1;  // the component watched alone (0 x, 1 y, 2 z); -1 all
  double tolerance = kSolverTolerance;
};
CaseStop case_stop(const FoamCell& cell, const FoamOptions& options);

// Writes DIR/system/controlDict of the case write_foam_case writes, its run bounded at
// `end_step` corrections (where it is written if it gets there), its own stop at
// `tighter` times the usual tolerance; from time 0, or (`start` > 0) continued from the
// latest time written.
void write_control_dict(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& options,
                        int end_step, double tighter = 1.0, int start = 0);

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

// system/decomposeParDict: o.processes pieces, the cell cut into nx x ny (x nz in 3D)
// blocks as near cubic as the count allows (hierarchical: Debian's OpenFOAM has no
// working scotch or metis), each cyclic face kept on one processor with its partner
// (fixedJump does not cross processors).
void write_decompose_dict(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& options);

// Writes a complete case into `dir` (which must exist and be empty): constant/polyMesh
// (points, faces, owner, neighbour, boundary, cellZones, faceZones), 0/D, 0/E, 0/nu,
// constant/mechanicalProperties and thermalProperties, system/controlDict, fvSchemes,
// fvSolution, Allrun and an empty case.foam. Throws ConfigError for a phase without a
// usable E or nu, IoError when a file cannot be written. Returns the mesh it wrote.
PolyMesh write_foam_case(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& options);

// What write_foam_case writes of a 2D or 3D case around its built polyMesh `pm`: 0/D (the
// solve started from the imposed mean strain at each cell's `centroid`, mesh units from
// the cell's low corner), 0/E, 0/nu (each cell's `phase`), the properties, the system
// dictionaries, Allrun and case.foam; the polyMesh's files copied from `polymesh_from`
// when given (a case of the same mesh written before: formatting them is the most of a
// case's writing). `check_case` first: it refuses what the case cannot
// carry (a phase without a usable E, nu or alpha; a cell without a grain or a phase;
// check_load), throwing ConfigError naming the key.
void check_case(const FoamCell& cell, const std::vector<int>& grain, const std::vector<int>& phase, std::size_t cells,
                const FoamOptions& options);
void write_case_files(const std::filesystem::path& dir, const FoamCell& cell, const std::vector<int>& phase,
                      const std::vector<Vec3>& centroid, const PolyMesh& pm, const FoamOptions& options,
                      const std::filesystem::path& polymesh_from = {});

}  // namespace grainmesh
