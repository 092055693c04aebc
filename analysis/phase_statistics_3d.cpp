#include "analysis/phase_statistics_3d.hpp"

#include <cmath>

namespace grainmesh {

std::vector<PhaseStresses3> phase_stresses_3d(const FieldValues& sigma, const std::vector<double>& volume,
                                              const std::vector<int>& phase, int phases) {
  std::vector<PhaseStresses3> out(static_cast<std::size_t>(phases));
  std::vector<std::vector<double>> mises(out.size()), mean(out.size()), weight(out.size());
  double total = 0.0;
  for (std::size_t c = 0; c < volume.size(); ++c) {
    const double* s = sigma[c];
    const double xx = s[0], xy = s[1], xz = s[2], yy = s[3], yz = s[4], zz = s[5];
    const std::size_t p = static_cast<std::size_t>(phase[c]);
    const std::array<double, 6> v{xx, yy, zz, yz, xz, xy};
    for (int i = 0; i < 6; ++i) out[p].mean[i] += volume[c] * v[i];
    mises[p].push_back(std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) +
                                 3.0 * (xy * xy + yz * yz + xz * xz)));
    mean[p].push_back((xx + yy + zz) / 3.0);
    weight[p].push_back(volume[c]);
    out[p].volume_fraction += volume[c];
    total += volume[c];
  }
  for (std::size_t p = 0; p < out.size(); ++p) {
    if (out[p].volume_fraction > 0.0)
      for (double& m : out[p].mean) m /= out[p].volume_fraction;
    out[p].volume_fraction /= total;
    out[p].von_mises = distribution(mises[p], weight[p]);
    out[p].hydrostatic = distribution(mean[p], weight[p]);
  }
  return out;
}

}  // namespace grainmesh
