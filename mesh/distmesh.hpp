// The force-equilibrium Delaunay mesher of Persson & Strang (DistMesh), as in the
// reference thesis: Algorithm 1, with the internal boundaries of Algorithm 3.
#pragma once

#include "common/random.hpp"
#include "mesh/distmesh_options.hpp"

namespace grainmesh {

// Meshes problem.domain. Randomness (the rejection step) comes from rng only.
// Always returns a valid mesh (see validate()) or throws: ConfigError for bad
// parameters, a size function that is not finite and positive in the domain or one that
// asks for more than kMaxMeshPoints points, GeometryError for an empty domain or fixed
// points outside it, TimeLimitError when options.deadline passes.
DistMeshResult distmesh(const DistMeshProblem& problem, const DistMeshOptions& options, Rng& rng);

}  // namespace grainmesh
