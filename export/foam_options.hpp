// How a case is written and solved: the mesh's scale and extrusion, the load (a
// displacement or traction, a cyclic mean strain, a temperature change), the out-of-plane
// state of a 2D case, the cells, the stiffness interpolation, the linear solver and the
// processes. Plain data, the defaults here; the config reader fills it.
#pragma once

#include <array>
#include <cstddef>

namespace grainmesh {

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
  // 3D polyhedra (the dual): each face round a tetrahedron's edge (a ring of face and
  // tetrahedron centroids about the edge's midpoint, not plane) split into the plane
  // triangles it is made of, so that OpenFOAM's face areas and cell volumes are the
  // polyhedra's exactly; false: one polygon per face.
  bool plane_faces = false;
  // 3D dual: where checkMesh would fail a face or a cell, fold the faces between a point's
  // cells and join cells (polymesh_dual_3d.hpp); false (tests) builds the plain dual.
  bool mend_checks = true;
  // The linear solver of D's equation: automatic is multigrid (GAMG: fastest) in 2D and
  // conjugate gradients (PCG with DIC) in 3D, where GAMG blew up; the solve falls back on
  // conjugate gradients when multigrid diverges (analysis/solve.cpp).
  enum class LinearSolver { automatic, multigrid, conjugate_gradients } linear_solver = LinearSolver::automatic;
};


// A 2D case's out-of-plane condition as reports name it: "plane_strain" (the default:
// held, e_zz = 0, a stress sigma_zz carried) or "plane_stress" (free, sigma_zz = 0).
inline const char* plane_state(const FoamOptions& o) { return o.plane_stress ? "plane_stress" : "plane_strain"; }

}  // namespace grainmesh
