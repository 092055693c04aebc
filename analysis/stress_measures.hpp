// The scalar measures of a stress state that materials scientists read: von Mises, the
// largest principal stress, the hydrostatic stress. The state is a 2D cell's: the in-plane
// components and the out-of-plane normal stress (plane strain: what keeps the cell from
// straining out of plane; plane stress: zero).
#pragma once

#include <array>

namespace grainmesh {

struct StressState {
  double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0;
};

// sqrt(((xx - yy)^2 + (yy - zz)^2 + (zz - xx)^2) / 2 + 3 xy^2).
double von_mises(const StressState& s);
// The largest eigenvalue of the 3 x 3 tensor: the in-plane maximum or zz.
double largest_principal(const StressState& s);
// (xx + yy + zz) / 3.
double hydrostatic(const StressState& s);
// VTK's order of a symmetric tensor: xx yy zz xy yz xz.
std::array<double, 6> vtk_components(const StressState& s);

}  // namespace grainmesh
