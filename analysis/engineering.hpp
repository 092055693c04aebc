// Engineering constants of an effective stiffness in Voigt notation, the same in 2D
// (N = 3: xx, yy, xy, in-plane constants under the cell's plane state) and 3D (N = 6: xx,
// yy, zz, yz, xz, xy), from its compliance S = C^-1: Young's moduli E_i = 1 / S_ii of the
// normal directions, the shear moduli G = 1 / S_kk of the shear ones, Poisson's ratios
// nu_ij = -S_ji / S_ii for every ordered pair of normal directions; and the universal
// anisotropy index of the tensor's own Voigt (C) and Reuss (S) averages, 0 exactly when
// isotropic: A^U = K_V / K_R + (d (d + 1) / 2 - 1) G_V / G_R - d (d + 1) / 2 in d
// dimensions (Ranganathan and Ostoja-Starzewski 2008; in 2D, K the area bulk modulus,
// Kube 2016). In 2D also the measures normal = |C11 - C22| / (C11 + C22) and shear =
// 2 C66 / (C11 - C12) (1 when isotropic).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/voigt.hpp"

namespace grainmesh {

struct EngineeringConstants {
  struct Named {
    std::string name;  // E_x, G_xy, nu_xy, ...
    double value;      // Pa (E, G), or a ratio (nu)
  };
  std::vector<Named> constants;  // the E, then the G in Voigt order, then the nu
  double universal_anisotropy = 0.0;
  std::optional<double> normal_anisotropy, shear_anisotropy;  // 2D

  // The constant called `name`; throws std::out_of_range when there is none.
  double operator[](const std::string& name) const;
};

template <std::size_t N>
EngineeringConstants engineering_constants(const Stiffness<N>& c);

}  // namespace grainmesh
