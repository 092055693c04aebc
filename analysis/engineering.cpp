#include "analysis/engineering.hpp"

#include <cmath>
#include <stdexcept>

namespace grainmesh {

double EngineeringConstants::operator[](const std::string& name) const {
  for (const Named& n : constants)
    if (n.name == name) return n.value;
  throw std::out_of_range("no engineering constant " + name);
}

template <std::size_t N>
EngineeringConstants engineering_constants(const Stiffness<N>& c) {
  constexpr std::size_t d = voigt_dimensions<N>();  // normal directions, the first d Voigt indices
  static const char* axis = "xyz";
  const Stiffness<N> s = inverse(c);
  EngineeringConstants e;
  for (std::size_t i = 0; i < d; ++i) e.constants.push_back({std::string("E_") + axis[i], 1 / s[i][i]});
  for (std::size_t k = d; k < N; ++k) e.constants.push_back({std::string("G_") + voigt_names<N>()[k], 1 / s[k][k]});
  for (std::size_t i = 0; i < d; ++i)
    for (std::size_t j = 0; j < d; ++j)
      if (i != j) e.constants.push_back({std::string("nu_") + axis[i] + axis[j], -s[j][i] / s[i][i]});
  // The Reuss averages from the compliance's invariants: 1 / K_R = S_iijj; 1 / G_R from
  // S_ijij and S_iijj (d = 2: S_ijij - S_iijj / 2; d = 3: (3 S_ijij - S_iijj) / 15, in
  // Voigt terms as below).
  double normal = 0.0, off = 0.0, shear = 0.0;
  for (std::size_t i = 0; i < d; ++i) {
    normal += s[i][i];
    for (std::size_t j = i + 1; j < d; ++j) off += s[i][j];
  }
  for (std::size_t k = d; k < N; ++k) shear += s[k][k];
  const double K_R = 1 / (normal + 2 * off);
  const double G_R = d == 2 ? 2 / (normal - 2 * off + shear) : 15 / (4 * normal - 4 * off + 3 * shear);
  const double modes = d * (d + 1) / 2.0;  // the symmetric tensor's components
  e.universal_anisotropy = bulk_modulus(c) / K_R + (modes - 1) * shear_modulus(c) / G_R - modes;
  if constexpr (N == 3) {
    e.normal_anisotropy = std::abs(c[0][0] - c[1][1]) / (c[0][0] + c[1][1]);
    e.shear_anisotropy = 2 * c[2][2] / (c[0][0] - c[0][1]);
  }
  return e;
}

template EngineeringConstants engineering_constants(const Stiffness<3>&);
template EngineeringConstants engineering_constants(const Stiffness<6>&);

}  // namespace grainmesh
