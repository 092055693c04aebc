#include "domain/size_grading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainmesh {

namespace {

constexpr double kMaxNodes = 4e6;

}  // namespace

SizeGrading::SizeGrading(const Box& box, double spacing, double gradient, const Sampler& sample) {
  const double w = std::max(box.width(), 0.0), h = std::max(box.height(), 0.0);
  step_ = std::max(spacing, std::sqrt(w * h / kMaxNodes));
  nx_ = static_cast<int>(std::ceil(w / step_)) + 1;
  ny_ = static_cast<int>(std::ceil(h / step_)) + 1;
  lo_ = box.lo;
  std::vector<Vec2> nodes;
  nodes.reserve(static_cast<std::size_t>(nx_) * ny_);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) nodes.push_back(lo_ + step_ * Vec2{1.0 * i, 1.0 * j});
  h_.assign(nodes.size(), std::numeric_limits<double>::infinity());
  sample(nodes, h_);
  const std::vector<double> asked = h_;

  // Chamfer propagation h(n) = min(h(n), h(m) + g |n - m|) over the 8 neighbours, in
  // forward and backward sweeps; two rounds settle paths that bend. Between the eight
  // directions the chamfer distance exceeds the Euclidean by up to 8 %: the graded size
  // grows a little faster than g there.
  const double straight = gradient * step_, diagonal = gradient * step_ * std::sqrt(2.0);
  auto relax = [&](int i, int j, int di, int dj, double cost) {
    const int a = i + di, b = j + dj;
    if (a < 0 || a >= nx_ || b < 0 || b >= ny_) return;
    double& here = h_[static_cast<std::size_t>(j) * nx_ + i];
    here = std::min(here, h_[static_cast<std::size_t>(b) * nx_ + a] + cost);
  };
  for (int round = 0; round < 2; ++round) {
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        relax(i, j, -1, 0, straight);
        relax(i, j, 0, -1, straight);
        relax(i, j, -1, -1, diagonal);
        relax(i, j, 1, -1, diagonal);
      }
    for (int back_j = 0; back_j < ny_; ++back_j)
      for (int back_i = 0; back_i < nx_; ++back_i) {
        const int i = nx_ - 1 - back_i, j = ny_ - 1 - back_j;
        relax(i, j, 1, 0, straight);
        relax(i, j, 0, 1, straight);
        relax(i, j, 1, 1, diagonal);
        relax(i, j, -1, 1, diagonal);
      }
  }
  for (std::size_t n = 0; n < h_.size(); ++n)
    if (h_[n] < asked[n] * (1.0 - 1e-9)) limits_ = true;
}

double SizeGrading::at(Vec2 x, double h) const {
  // Bilinear in the grid cell holding x (clamped to the grid), from nodes with a size.
  const double fx = std::clamp((x.x - lo_.x) / step_, 0.0, nx_ - 1.0);
  const double fy = std::clamp((x.y - lo_.y) / step_, 0.0, ny_ - 1.0);
  const int i = std::min(static_cast<int>(fx), std::max(nx_ - 2, 0));
  const int j = std::min(static_cast<int>(fy), std::max(ny_ - 2, 0));
  const double u = fx - i, v = fy - j;
  double value = 0.0, weight = 0.0;
  for (int dj = 0; dj <= 1; ++dj)
    for (int di = 0; di <= 1; ++di) {
      const int a = std::min(i + di, nx_ - 1), b = std::min(j + dj, ny_ - 1);
      const double node = h_[static_cast<std::size_t>(b) * nx_ + a];
      const double wgt = (di ? u : 1.0 - u) * (dj ? v : 1.0 - v);
      if (!std::isfinite(node) || wgt == 0.0) continue;
      value += wgt * node;
      weight += wgt;
    }
  return weight > 0.0 ? std::min(h, value / weight) : h;
}

}  // namespace grainmesh
