// The nodes along the tessellation's edges, made once and shared by the regions on both
// sides (and by a periodic side's partner): what makes the grain meshes conform.
#pragma once

#include <vector>

#include "grains/edge_index.hpp"
#include "grains/feature_size.hpp"
#include "grains/grain_mesh_options.hpp"

namespace grainmesh {

// Points along each tessellation edge (its end vertices excluded), from v0 to v1, evenly
// in the integral of 1/h along it, h the size field capped by the edge's phase size (the
// finer of its two sides). Edges on the right (top) side of a periodic cell get the
// points of their partner on the left (bottom) side moved by W (H), bit for bit.
std::vector<std::vector<Vec2>> seed_edges(const Tessellation& t, const GrainMeshOptions& options,
                                          const FeatureSize& size);

// The same with the tessellation's edge index and side partners (below) given.
struct SidePartner;
std::vector<std::vector<Vec2>> seed_edges(const Tessellation& t, const GrainMeshOptions& options,
                                          const FeatureSize& size, const EdgeIndex& index,
                                          const std::vector<SidePartner>& partner);

// Of an edge on the right (top) side of a periodic cell: its partner on the left (bottom)
// side, and whether the two run in opposite directions (v0 here the partner of the low
// edge's v1). low = -1 for every other edge.
struct SidePartner {
  int low = -1;
  bool reversed = false;
};

// Every edge's partner, from the tessellation's vertex partners. Throws GeometryError for
// a side edge without one.
std::vector<SidePartner> side_partners(const Tessellation& t, const EdgeIndex& index);

// The periodic node pairs of a mesh whose nodes are the tessellation's vertices (node v is
// vertex v) and the edge seeds (edge e's at first_id[e] on): the cut's vertex partners and
// each copied seed with the seed it was copied from. Sorted by low node.
PeriodicPairs node_pairs(const Tessellation& t, const std::vector<SidePartner>& partner,
                         const std::vector<int>& first_id, const std::vector<std::vector<Vec2>>& seeds);

}  // namespace grainmesh
