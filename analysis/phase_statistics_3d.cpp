#include "analysis/phase_statistics_3d.hpp"

#include <cmath>
#include <numeric>

namespace grainmesh {

double von_mises_3d(const double* s) {
  const double xx = s[0], xy = s[1], xz = s[2], yy = s[3], yz = s[4], zz = s[5];
  return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) +
                   3.0 * (xy * xy + yz * yz + xz * xz));
}

std::vector<double> phase_volume_fractions(const std::vector<double>& volume, const std::vector<int>& phase, int phases) {
  std::vector<double> f(static_cast<std::size_t>(phases), 0.0);
  double total = 0.0;
  for (std::size_t c = 0; c < volume.size(); ++c) {
    f[static_cast<std::size_t>(phase[c])] += volume[c];
    total += volume[c];
  }
  for (double& x : f) x /= total;
  return f;
}

std::vector<PhaseStresses3> phase_stresses_3d(const FieldValues& sigma, const std::vector<double>& volume,
                                              const std::vector<int>& phase, int phases, const FieldValues* balanced) {
  std::vector<PhaseStresses3> out(static_cast<std::size_t>(phases));
  std::vector<std::vector<double>> mises(out.size()), mean(out.size()), weight(out.size());
  const std::vector<double> fraction = phase_volume_fractions(volume, phase, phases);
  for (std::size_t c = 0; c < volume.size(); ++c) {
    const double* s = sigma[c];
    const std::size_t p = static_cast<std::size_t>(phase[c]);
    const double* m = balanced != nullptr ? (*balanced)[c] : s;
    const std::array<double, 6> v{m[0], m[3], m[5], m[4], m[2], m[1]};  // xx yy zz yz xz xy
    for (int i = 0; i < 6; ++i) out[p].mean[i] += volume[c] * v[i];
    mises[p].push_back(von_mises_3d(s));
    mean[p].push_back((s[0] + s[3] + s[5]) / 3.0);
    weight[p].push_back(volume[c]);
  }
  for (std::size_t p = 0; p < out.size(); ++p) {
    out[p].volume_fraction = fraction[p];
    const double phase_volume = std::accumulate(weight[p].begin(), weight[p].end(), 0.0);
    if (phase_volume > 0.0)
      for (double& m : out[p].mean) m /= phase_volume;
    out[p].von_mises = distribution(mises[p], weight[p]);
    out[p].hydrostatic = distribution(mean[p], weight[p]);
  }
  return out;
}

}  // namespace grainmesh
