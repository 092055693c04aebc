// Regularisation of a cut 3D tessellation (regularise_3d.cpp).
#pragma once

#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// Collapses the edges shorter than `threshold`, shortest first, pass after pass: the two
// ends merge at the midpoint. Periodic: or at the end on more sides of the box, which
// stays where it is; an edge on a side collapses with its periodic images, so partners
// stay exact. Bounded: the midpoint put on every side either end lies on.
// A collapse that would fold a face, make a dihedral angle of a region sharper than 8
// degrees (or than it was), move more than 5 % of a grain's volume to its neighbours (a
// laminate's layer the box cut in two), or leave a region open, with fewer than four faces
// or without volume is not made, except that a region it flattens (a sliver the box cut off a grain)
// is removed, its opposite faces joined, when its grain keeps another region. A
// triangular face that loses an edge disappears. Faces left bent are split into planar
// triangles (no new vertex; the triangulation with the largest smallest angle), so every
// face stays planar and volumes stay exact.
// Vertices and regions are renumbered.
struct Regularisation {
  int collapsed_edges = 0;  // periodic images counted once
  int removed_regions = 0;
};
Regularisation collapse_short_edges(Tessellation3& t, double threshold);

// The tessellation once its faces are `faces` (old face f became faces replaced[f], their
// regions still the old numbers) and the regions `removed` are gone: regions and
// vertices renumbered, the vertices no face uses dropped (regularise_3d_renumber.cpp).
void renumber(Tessellation3& t, std::vector<Face3> faces, const std::vector<std::vector<int>>& replaced,
              const std::vector<bool>& removed);

}  // namespace grainmesh
