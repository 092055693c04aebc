// The nodes along the tessellation's edges, made once and shared by the regions on both
// sides (and by a periodic side's partner): what makes the grain meshes conform.
#pragma once

#include <vector>

#include "grains/feature_size.hpp"
#include "grains/grain_mesh.hpp"

namespace grainmesh {

// Points along each tessellation edge (its end vertices excluded), from v0 to v1, evenly
// in the integral of 1/h along it, h the size field capped by the edge's phase size (the
// finer of its two sides). Edges on the right (top) side of a periodic cell get the
// points of their partner on the left (bottom) side moved by W (H), bit for bit.
std::vector<std::vector<Vec2>> seed_edges(const Tessellation& t, const GrainMeshOptions& options,
                                          const FeatureSize& size);

}  // namespace grainmesh
