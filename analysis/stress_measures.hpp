// The scalar measures of a stress state that materials scientists read: von Mises, the
// largest principal stress, the hydrostatic stress. Two representations: a 2D cell's
// StressState (the in-plane components and the out-of-plane normal stress: plane strain's
// holding, zero in plane stress), and the full symmetric tensor of either dimension in
// Voigt order (StressTensor), which the phase statistics work on.
#pragma once

#include <array>
#include <vector>

namespace grainmesh {

struct StressState {
  double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0;
};

// A symmetric stress tensor in Voigt order: xx yy zz yz xz xy (Pa).
using StressTensor = std::array<double, 6>;

// sqrt(((xx - yy)^2 + (yy - zz)^2 + (zz - xx)^2) / 2 + 3 xy^2).
double von_mises(const StressState& s);
// The largest eigenvalue of the 3 x 3 tensor: the in-plane maximum or zz.
double largest_principal(const StressState& s);
// (xx + yy + zz) / 3.
double hydrostatic(const StressState& s);
// VTK's order of a symmetric tensor: xx yy zz xy yz xz.
std::array<double, 6> vtk_components(const StressState& s);

// sqrt(((xx - yy)^2 + (yy - zz)^2 + (zz - xx)^2) / 2 + 3 (xy^2 + yz^2 + xz^2)).
double von_mises(const StressTensor& s);
// The largest eigenvalue (closed form: the in-plane one against zz when yz = xz = 0, else
// the trigonometric solution of the characteristic cubic).
double largest_principal(const StressTensor& s);
// (xx + yy + zz) / 3.
double hydrostatic(const StressTensor& s);

// A 2D state as the tensor (yz = xz = 0).
StressTensor stress_tensor(const StressState& s);
// The 2D cells' tensors; with the cells' `virial` stresses (from the face forces, in plane
// only) their in-plane components are the virial's and zz the cell's own.
std::vector<StressTensor> stress_tensors(const std::vector<StressState>& own,
                                         const std::vector<StressState>* virial = nullptr);
// A tensor as OpenFOAM writes one (xx xy xz yy yz zz).
StressTensor openfoam_stress(const double* s);

}  // namespace grainmesh
