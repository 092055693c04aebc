#include "analysis/richardson.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace grainmesh {

RichardsonEstimate richardson(const std::vector<double>& f, double ratio) {
  const std::size_t n = f.size();
  if (n < 3) throw GeometryError("Richardson extrapolation needs three levels or more");
  if (!(ratio > 1.0)) throw GeometryError("Richardson extrapolation needs levels refined by a ratio above 1");
  const double f1 = f[n - 3], f2 = f[n - 2], f3 = f[n - 1], r = ratio;
  RichardsonEstimate e;
  e.limit = f3;
  const double e21 = f2 - f1, e32 = f3 - f2;
  e.settled = std::max(std::abs(e21), std::abs(e32)) <= kSettled * std::abs(f3);
  if (e.settled) return e;
  if (e21 == 0.0 || e32 == 0.0 || (e21 > 0) != (e32 > 0) || std::abs(e32) >= std::abs(e21)) return e;
  const double p = std::log(e21 / e32) / std::log(r);
  e.order = p;
  e.asymptotic = true;
  e.limit = f3 + e32 / (std::pow(r, p) - 1.0);
  return e;
}

std::optional<int> first_within(const std::vector<double>& f, double limit, double tolerance) {
  std::optional<int> first;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const bool within = std::abs(f[k] - limit) <= tolerance * std::abs(limit);
    if (within && !first) first = static_cast<int>(k);
    if (!within) first.reset();
  }
  return first;
}

}  // namespace grainmesh
