// A size field that grows no faster than a gradient: h_g(x) = min over y of h(y) + g |x - y|,
// on a regular grid. A user's size function may jump (a discontinuity, or a 1000-fold
// step): DistMesh then puts huge triangles against tiny ones. Grading first makes the
// sizes meet gently, as the mesh stage's own sizes always do.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

class SizeGrading {
 public:
  // `sample` fills absolute sizes at grid nodes (+inf where no size is asked, e.g. outside
  // the domain). The grid covers `box` at about `spacing` (coarser when that would exceed
  // a few million nodes).
  using Sampler = std::function<void(std::span<const Vec2>, std::span<double>)>;
  SizeGrading(const Box& box, double spacing, double gradient, const Sampler& sample);

  // True when grading lowered the size anywhere: the field is steeper than the gradient.
  bool limits() const { return limits_; }
  // min(h, h_g(x)): the graded size at x (interpolated), never above h.
  double at(Vec2 x, double h) const;

 private:
  Vec2 lo_{};
  double step_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<double> h_;  // node (i, j) at lo + step (i, j), row-major
  bool limits_ = false;
};

}  // namespace grainmesh
