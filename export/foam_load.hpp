// The load on a case's cell: what a case needs of its cell (phases, extents, periodicity),
// the mean strain a load gives it, the checks that refuse a load the linear theory cannot
// carry (naming the key), and a cyclic case's mean strain and displacement jumps.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "common/vec3.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

// What a case's dictionaries, its load's checks and its solve need of the mesh, 2D or 3D:
// the phases and the cell's extents (mesh units; z = 0 for a 2D cell, which the case
// extrudes one cell thick), and whether opposite sides match.
struct FoamCell {
  const std::vector<FoamPhase>& phases;
  Vec3 size;
  bool periodic = false;
  int dimensions() const { return size.z > 0.0 ? 3 : 2; }
};

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

}  // namespace grainmesh
