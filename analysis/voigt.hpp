// Stiffnesses and compliances in Voigt notation, one type and one set of operations for
// 2D and 3D: N = 3 in 2D (rows and columns xx, yy, xy; plane strain or plane stress) and
// N = 6 in 3D (xx, yy, zz, yz, xz, xy), the shears as engineering strains (sigma_xy =
// C66 gamma_xy), in Pa. Defined for N = 3 and N = 6.
#pragma once

#include <array>
#include <cstddef>
#include <string>

namespace grainmesh {

template <std::size_t N>
using Stiffness = std::array<std::array<double, N>, N>;

// The Voigt size of a dimension: 3 in 2D, 6 in 3D.
constexpr std::size_t voigt_size(int dimensions) { return dimensions == 2 ? 3 : 6; }
// The dimensions of Voigt size N: 2 for N = 3, 3 for N = 6; also how many normal
// components (xx, yy[, zz]) come first, the shears after them.
template <std::size_t N>
constexpr std::size_t voigt_dimensions() {
  return N == 3 ? 2 : 3;
}

// The components of a symmetric tensor in Voigt order: xx, yy, xy (N = 3) or xx, yy, zz,
// yz, xz, xy (N = 6); the names of load cases, report fields and engineering constants.
template <std::size_t N>
const std::array<const char*, N>& voigt_names();

// The name of stiffness entry (i, j) by its Voigt indices, 1-based: C11, C12, C66 in 2D
// (xx, yy, xy are 1, 2, 6), C11 to C66 in 3D.
template <std::size_t N>
std::string stiffness_name(std::size_t i, std::size_t j);

// The index of Voigt-N component k among the six of the 3D tensor (xx yy zz yz xz xy):
// 2D's xx, yy, xy are 0, 1, 5.
template <std::size_t N>
constexpr std::size_t tensor_index(std::size_t k) {
  return N == 3 && k == 2 ? 5 : k;
}

// The largest |entry|.
template <std::size_t N>
double largest_entry(const Stiffness<N>& c);

// The inverse (a compliance, and back), by Gauss-Jordan elimination with partial
// pivoting. Throws GeometryError when singular (a pivot below 1e-14 of the largest entry).
template <std::size_t N>
Stiffness<N> inverse(const Stiffness<N>& c);

// Whether upper - lower (its symmetric part) is positive semidefinite, to `rounding`
// relative to the largest entry: its LDL^T factorisation meets no pivot below -rounding x
// scale, and a pivot within the rounding of zero leaves its column zero too.
template <std::size_t N>
bool semidefinite_order(const Stiffness<N>& lower, const Stiffness<N>& upper, double rounding = 1e-6);

// The stiffness made symmetric, each Cij the mean of Cij and Cji (of the two load cases
// that give it), and how far it was from symmetric: max |Cij - Cji| / max |Cij|.
template <std::size_t N>
Stiffness<N> symmetric_part(const Stiffness<N>& c);
template <std::size_t N>
double symmetry_error(const Stiffness<N>& c);

// The bulk and shear moduli of a stiffness isotropic in the mean. 2D (in plane): K the
// mean stress over the area strain, (C11 + C22 + C12 + C21) / 4; mu the mean of the shear
// stiffness in the axes and at 45 degrees, C66 / 2 + (C11 + C22 - C12 - C21) / 8. 3D
// (Voigt's averages over orientations): K = (C11 + C22 + C33 + 2 (C12 + C13 + C23)) / 9,
// mu = (C11 + C22 + C33 - (C12 + C13 + C23) + 3 (C44 + C55 + C66)) / 15. Both exact for
// an isotropic stiffness.
template <std::size_t N>
double bulk_modulus(const Stiffness<N>& c);
template <std::size_t N>
double shear_modulus(const Stiffness<N>& c);

}  // namespace grainmesh
