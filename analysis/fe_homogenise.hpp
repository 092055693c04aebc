// A reference answer independent of OpenFOAM: periodic finite-element homogenisation on
// the cells of the exported mesh, one contract for 2D and 3D (N the Voigt size). Quadratic
// Lagrange elements — 6-node triangles in 2D under the cell's plane state, 10-node
// tetrahedra in 3D — each of its phase's isotropic stiffness (isotropic_stiffness). The
// displacement is the macroscopic strain's plus a periodic fluctuation: the nodes on the
// cell's sides are tied to their images through the mesh's periodic pairs (a midside node
// with the images of its edge's ends), and one node is held (a translation is free). Each
// load is a macroscopic strain, one per Voigt component (the shears as engineering
// strains); the thermal one a unit temperature change at zero mean strain, each phase
// expanding freely by its free_expansion (2D; alpha in 3D). One sparse Cholesky
// factorisation (SuiteSparse's CHOLMOD) serves every load. The effective stress is the
// exact volume (2D: area) average over the elements, so the answer is exact for a
// displacement quadratic within each element: laminates whose layers the mesh follows,
// one material.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "analysis/voigt.hpp"
#include "export/export_mesh.hpp"

namespace grainmesh {

template <std::size_t N>
struct FeHomogenised {
  Stiffness<N> stiffness{};                        // Pa; column j from load j, per engineering strain
  std::optional<std::array<double, N>> expansion;  // free thermal expansion, tensor components, 1/K
  std::size_t unknowns = 0;                        // the fluctuation's, once tied and held
  double seconds = 0.0;
  int iterations = 0;  // the conjugate gradients' cycles when solved iteratively; 0: factorised
};

// Two nested levels of one cell: `coarse` factorised, `fine` (its nested split).
template <std::size_t N>
struct FeNested {
  FeHomogenised<N> coarse, fine;
};

// What the reference may take: its sparse factor's memory, estimated from CHOLMOD's
// analysis before it is made, against `memory_mib` (0: what the machine or the job's
// control group has available, common/memory.hpp).
struct FeOptions {
  double memory_mib = 0.0;
  // The key that asked for them, named when they are refused: homogenise.solver, or
  // homogenise.reference when they are OpenFOAM's reference.
  bool reference = false;
  // The coarse of two nested levels is factorised when its factor costs at most this many
  // operations (CHOLMOD's count; 1e10, about 2 s on one core), else solved iteratively
  // (fe_homogenise_nested). Measured: the 1,000-grain 2D cell's 3.8e9 both ways alike, the
  // 3D example's 4.9e10 by the cycles 7.6 s → 5.5 s.
  double coarse_factor_flops = 1e10;
};

// The periodic cell `m` homogenised (2D: triangles only, under plane strain or
// `plane_stress`), with its thermal expansion when `thermal`. Throws GeometryError when
// the mesh is not periodic, has a cell that is no triangle (2D) or a side point without
// its image, and when the stiffness matrix is not positive definite (a phase without
// stiffness, an inverted element); ConfigError naming homogenise.solver (or
// homogenise.reference, o.reference) when the factor would not fit in memory.
FeHomogenised<3> fe_homogenise(const ExportMesh<2>& m, bool plane_stress, bool thermal, const FeOptions& o = {});
FeHomogenised<6> fe_homogenise(const ExportMesh<3>& m, bool thermal, const FeOptions& o = {});

// The same on two nested levels: `coarse`, and `fine` = split_nested(coarse) (fine element
// 2^D c + k a child of coarse element c). The coarse level is factorised where its factor
// takes at most o.coarse_factor_flops operations, else solved by conjugate gradients
// preconditioned by a two-grid cycle on its own mesh's linear elements (their factor a
// few per cent of its cost: on the 1,000-grain 3D cell a factor of 5.7e12 operations,
// 156 s, gave way to 16 s), to the fine level's tolerance. The fine level is solved by
// conjugate gradients preconditioned by a two-grid cycle whose coarse correction is the
// coarse level's factor or one cycle of its own (a V-cycle over three levels;
// fe_two_grid.hpp), from the coarse solution, to a residual of 1e-4 of each load's —
// the answer as the fine level's factor gives it to about 1e-8, without its fill (3D: a
// fraction of the operations); either level factorised instead when 200 cycles do not reach it. The
// coarse level is solved beside the fine level's assembly (on two threads where
// limit_fe_threads allows), on one BLAS thread: the same answer to the bit on any number
// of threads. `seconds`: the coarse level's to its answer, the fine level's from there;
// `iterations` each level's cycles (0: factorised). Throws as fe_homogenise, and
// GeometryError when `fine` has not 2^D times coarse's elements.
FeNested<3> fe_homogenise_nested(const ExportMesh<2>& coarse, const ExportMesh<2>& fine, bool plane_stress,
                                 bool thermal, const FeOptions& o = {});
FeNested<6> fe_homogenise_nested(const ExportMesh<3>& coarse, const ExportMesh<3>& fine, bool thermal,
                                 const FeOptions& o = {});

// The threads the finite elements may take: their dense kernels' (OpenBLAS's, where it is
// the BLAS; another BLAS is left as it is) and the fine level's conjugate gradients' (the
// loads in groups side by side; all cores until limited): 1 where runs share the cores
// (sweep --jobs 2 or more), since two runs' threads waiting on each other took a third
// longer (the 3D example's finite elements, two side by side: 30 s each, 20 s
// single-threaded).
void limit_fe_threads(int threads);

}  // namespace grainmesh
