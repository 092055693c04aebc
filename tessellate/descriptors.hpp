// The WC-Co microstructure descriptors of a cut tessellation, per phase, from the exact
// lengths of its boundaries: the stereology of ISO 4499-2 (Gurland's contiguity, the mean
// linear intercept grain size, the binder mean free path) with the section itself in place
// of test lines. For isotropic random test lines the number of boundary crossings per unit
// line length is (2 / pi) times the boundary length per unit area, which turns the line
// counts of the standard into these lengths.
#pragma once

#include <vector>

#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct PhaseDescriptors {
  double area = 0.0;            // A_p: the phase's area in the cell
  double own_boundary = 0.0;    // L_pp: boundary between two grains both of phase p
  double other_boundary = 0.0;  // L_pq: boundary between p and any other phase
  // Contiguity C_p = 2 L_pp / (2 L_pp + L_pq): the share of a p grain's perimeter it
  // shares with its own phase (1 for a phase touching only itself, 0 for a phase whose
  // grains never touch). NaN when the phase has no boundary at all.
  double contiguity = 0.0;
  // Mean linear intercept size of the phase's grains: pi A_p / (2 L_pp + L_pq) (the mean
  // chord of a random line through them; ISO 4499-2's 2 V_p / N_L). NaN without boundary.
  double intercept_length = 0.0;
  // Mean free path through the phase, between boundaries with other phases: pi A_p / L_pq
  // (the binder mean free path for the binder, 2 V_p / N_L^pq). Infinite when no other
  // phase touches it.
  double mean_free_path = 0.0;
};

// Gurland's contiguity and the mean chords of a phase from its size (area in a plane,
// volume in space) and its boundary with its own phase (each boundary once) and with the
// others (lengths in a plane, areas in space). A random line crosses (2 / pi) L_A
// boundaries per unit length in a plane and S_V / 2 in space, so a mean chord is
// pi A / L or 4 V / S (Cauchy). NaN without boundary; the free path infinite when no
// other phase touches.
struct Stereology {
  double contiguity = 0.0;
  double intercept_length = 0.0;
  double mean_free_path = 0.0;
};
Stereology stereology(int dimensions, double size, double own_boundary, double other_boundary);

// Per phase of `t`, in its order. In a periodic cell a grain boundary along a cell side
// counts once (the pieces across the side are compared); in a plane cell the sides are the
// cell's edge, not a boundary.
std::vector<PhaseDescriptors> phase_descriptors(const Tessellation& t);

}  // namespace grainmesh
