#include "analysis/voigt.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {

template <std::size_t N>
const std::array<const char*, N>& voigt_names() {
  if constexpr (N == 3) {
    static const std::array<const char*, 3> names{"xx", "yy", "xy"};
    return names;
  } else {
    static const std::array<const char*, 6> names{"xx", "yy", "zz", "yz", "xz", "xy"};
    return names;
  }
}

template <std::size_t N>
double largest_entry(const Stiffness<N>& c) {
  double scale = 0.0;
  for (const auto& row : c)
    for (double v : row) scale = std::max(scale, std::abs(v));
  return scale;
}

template <std::size_t N>
Stiffness<N> inverse(const Stiffness<N>& c) {
  std::array<std::array<double, 2 * N>, N> a{};
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) a[i][j] = c[i][j];
    a[i][N + i] = 1.0;
  }
  const double scale = largest_entry(c);
  for (std::size_t col = 0; col < N; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < N; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (!(std::abs(a[pivot][col]) > 1e-14 * scale)) throw GeometryError("a singular stiffness");
    std::swap(a[col], a[pivot]);
    const double d = a[col][col];
    for (double& v : a[col]) v /= d;
    for (std::size_t r = 0; r < N; ++r) {
      if (r == col) continue;
      const double f = a[r][col];
      for (std::size_t j = 0; j < 2 * N; ++j) a[r][j] -= f * a[col][j];
    }
  }
  Stiffness<N> inv{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) inv[i][j] = a[i][N + j];
  return inv;
}

template <std::size_t N>
bool semidefinite_order(const Stiffness<N>& lower, const Stiffness<N>& upper, double rounding) {
  Stiffness<N> a{};
  const double scale = std::max(largest_entry(lower), largest_entry(upper));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) a[i][j] = 0.5 * (upper[i][j] + upper[j][i] - lower[i][j] - lower[j][i]);
  const double tol = rounding * scale;
  // LDL^T without pivoting: a pivot at or below the tolerance is taken as zero, and then
  // its column must vanish too (to the tolerance) for the matrix to stay semidefinite.
  for (std::size_t k = 0; k < N; ++k) {
    const double d = a[k][k];
    if (d < -tol) return false;
    if (d <= tol) {
      for (std::size_t i = k + 1; i < N; ++i)
        if (std::abs(a[i][k]) > std::sqrt(tol * scale)) return false;
      continue;
    }
    for (std::size_t i = k + 1; i < N; ++i)
      for (std::size_t j = k + 1; j < N; ++j) a[i][j] -= a[i][k] * a[k][j] / d;
  }
  return true;
}

template <std::size_t N>
Stiffness<N> symmetric_part(const Stiffness<N>& c) {
  Stiffness<N> s{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) s[i][j] = 0.5 * (c[i][j] + c[j][i]);
  return s;
}

template <std::size_t N>
double symmetry_error(const Stiffness<N>& c) {
  double asymmetry = 0.0;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) asymmetry = std::max(asymmetry, std::abs(c[i][j] - c[j][i]));
  const double largest = largest_entry(c);
  return largest > 0.0 ? asymmetry / largest : 0.0;
}

template <std::size_t N>
double bulk_modulus(const Stiffness<N>& c) {
  if constexpr (N == 3) return 0.25 * (c[0][0] + c[1][1] + c[0][1] + c[1][0]);
  return (c[0][0] + c[1][1] + c[2][2] + 2.0 * (c[0][1] + c[0][2] + c[1][2])) / 9.0;
}

template <std::size_t N>
std::string stiffness_name(std::size_t i, std::size_t j) {
  // The Voigt index of component k: 1, 2, 6 in 2D.
  const auto index = [](std::size_t k) { return N == 3 ? "126"[k] : static_cast<char>('1' + k); };
  return {'C', index(i), index(j)};
}

template <std::size_t N>
double shear_modulus(const Stiffness<N>& c) {
  if constexpr (N == 3) return 0.5 * c[2][2] + 0.125 * (c[0][0] + c[1][1] - c[0][1] - c[1][0]);
  return (c[0][0] + c[1][1] + c[2][2] - (c[0][1] + c[0][2] + c[1][2]) + 3.0 * (c[3][3] + c[4][4] + c[5][5])) / 15.0;
}

#define GRAINMESH_VOIGT(N)                                                                     \
  template const std::array<const char*, N>& voigt_names<N>();                                \
  template std::string stiffness_name<N>(std::size_t, std::size_t);                          \
  template double largest_entry<N>(const Stiffness<N>&);                                      \
  template Stiffness<N> inverse<N>(const Stiffness<N>&);                                      \
  template bool semidefinite_order<N>(const Stiffness<N>&, const Stiffness<N>&, double);      \
  template Stiffness<N> symmetric_part<N>(const Stiffness<N>&);                               \
  template double symmetry_error<N>(const Stiffness<N>&);                                     \
  template double bulk_modulus<N>(const Stiffness<N>&);                                       \
  template double shear_modulus<N>(const Stiffness<N>&);
GRAINMESH_VOIGT(3)
GRAINMESH_VOIGT(6)
#undef GRAINMESH_VOIGT

}  // namespace grainmesh
