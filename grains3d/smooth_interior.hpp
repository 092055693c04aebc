// Smoothing of a tetrahedral mesh's free points, the surface kept.
#pragma once

#include <array>
#include <vector>

#include "common/vec3.hpp"

namespace grainmesh {

// Moves each point with index >= first_free (those inside a region; the surface ones
// before them stay bit for bit) to the better of the mean of its neighbours and the
// volume-weighted mean of its tetrahedra's circumcentres (the optimal Delaunay
// triangulation's update), when that raises the smallest radius ratio of its
// tetrahedra; `passes` sweeps in index order, so the result depends on the input alone.
// Returns the points moved in the last sweep.
int smooth_free_points(std::vector<Vec3>& points, const std::vector<std::array<int, 4>>& tets, int first_free, int passes);

}  // namespace grainmesh
