#include "tessellate/radii.hpp"

#include <cmath>
#include <numbers>

namespace grainmesh {

std::vector<double> lognormal_radii(int n, double cv, Rng& rng) {
  const double sigma = std::sqrt(std::log1p(cv * cv));
  std::vector<double> radii(n);
  for (double& r : radii) {
    const double u1 = 1.0 - uniform01(rng);  // (0, 1]
    const double u2 = uniform01(rng);
    const double normal = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    r = std::exp(sigma * normal);
  }
  return radii;
}

}  // namespace grainmesh
