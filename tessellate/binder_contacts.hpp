// Binder mode with a contiguity target: which interfaces between grains carry no binder.
// Every grain is first its torus cell shrunk by the binder offset t (binder.hpp); a contact
// of grains A and B then grows A across the binder layer up to B's side of it, so the two
// share B's edge exactly and nothing lies between them there. The contiguity of the hard
// grains, 2 L_contact / (2 L_contact + L_binder), is 2 L_contact / P with P their whole
// perimeter: choosing how many contacts (in an order drawn from the seed) sets it.
#pragma once

#include <vector>

#include "common/geometry.hpp"
#include "common/random.hpp"
#include "tessellate/cut.hpp"
#include "tessellate/torus.hpp"

namespace grainmesh {

// The inward offset by `t` of a convex counter-clockwise ring (the points at distance >= t
// inside every edge's line): its corners, each with the ring edge its outgoing side lies
// on. Empty when nothing is left.
struct TaggedCorner {
  Vec2 p;
  int edge = -1;
};
std::vector<TaggedCorner> shrink_tagged(const std::vector<Vec2>& ring, double t);

// Two neighbouring cells whose shared torus edge may become a contact.
struct Contact {
  int a = 0, edge_a = 0;  // the growing grain (an index into the cells) and its ring edge facing b
  int b = 0, edge_b = 0;  // the other, and its ring edge facing a
  int di = 0, dj = 0;     // b's frame moved by (di W, dj H) is a's
};

// Every pair of cells (indices into `cells`) sharing a torus edge, once per edge, in an
// order drawn from `rng`.
std::vector<Contact> contact_candidates(const TorusGraph& g, const std::vector<int>& cells, Rng& rng);

// A grain's corner: where it is in its own cell's frame (moved by the window) and, for a
// corner taken from a neighbour, that neighbour's bits and the lattice shift between them,
// so both sides compute it alike; `shared` >= 0 when the edge to the next corner is one both
// grains have (its canonical endpoints in `shared_edge`).
struct BinderCorner {
  Vec2 p;
  Vec2 base;
  int i = 0, j = 0;
  int shared = -1;
};

// A grain's corners as points (in its own frame).
std::vector<Vec2> points_of(const std::vector<BinderCorner>& grain);

struct BridgedGrains {
  std::vector<std::vector<BinderCorner>> grains;  // per cell, counter-clockwise; empty: swallowed by the binder
  std::vector<CutEdge> shared_edge;               // per contact made: B's edge, in B's frame
  double area = 0.0;                              // of the grains (inside the cell when not periodic)
  double perimeter = 0.0;  // their boundary (inside the cell, not along its sides, when not periodic)
  double contact = 0.0;    // length where two grains touch
  int contacts = 0;        // contacts made (of those asked: one whose bridge would come near a cell line is not)
  double contiguity() const { return perimeter > 0.0 ? 2.0 * contact / perimeter : 0.0; }
};

// The cells' polygons `cell_poly` (each in its own unwrapped frame) shrunk by `t`, moved by
// -`origin`, with the first `count` of `contacts` made; a contact is left out when either
// face has vanished at t or its bridge would come within `step` of a cell line (x = k W,
// y = k H; the cell's sides when not periodic), where square steps may change it.
BridgedGrains bridged_grains(const std::vector<std::vector<Vec2>>& cell_poly, const std::vector<Contact>& contacts,
                             int count, double t, Vec2 origin, double W, double H, bool periodic, double step);

}  // namespace grainmesh
