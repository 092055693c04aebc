// Richardson extrapolation of a quantity computed on meshes refined by a constant ratio:
// the observed order of convergence and the estimate of the mesh-independent limit.
#pragma once

#include <optional>
#include <vector>

namespace grainmesh {

struct RichardsonEstimate {
  double limit = 0.0;            // the extrapolated value (the finest value when not asymptotic)
  std::optional<double> order;   // the observed order p; none when the last three values
                                 // do not converge monotonically (or are equal)
  bool asymptotic = false;       // the last three values shrink monotonically towards a limit
  bool settled = false;          // or they differ by no more than kSettled: the finest is the limit
};

// Relative differences at which a quantity counts as settled: below the solver's and the
// meshes' noise, where no order can be observed.
inline constexpr double kSettled = 1e-4;

// From the values `f` on meshes refined by `ratio` (> 1) in their element size h from one
// to the next (coarse to fine, at least three; nested refinement: 2), of the last three:
//   p = ln((f2 - f1) / (f3 - f2)) / ln r,   limit = f3 + (f3 - f2) / (r^p - 1);
// when the last three differ by less than kSettled (relative), the finest value.
// Throws GeometryError for fewer than three levels or a ratio not above 1.
RichardsonEstimate richardson(const std::vector<double>& f, double ratio);

// The first level (coarse to fine) whose value lies within `tolerance` (relative) of
// `limit`, and stays so on every finer level; none when there is none.
std::optional<int> first_within(const std::vector<double>& f, double limit, double tolerance);

}  // namespace grainmesh
