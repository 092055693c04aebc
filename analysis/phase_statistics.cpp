#include "analysis/phase_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace grainmesh {

Distribution distribution(const std::vector<double>& values, const std::vector<double>& weights) {
  Distribution d;
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (values.empty() || !(total > 0.0)) return d;
  for (std::size_t k = 0; k < values.size(); ++k) d.mean += weights[k] * values[k];
  d.mean /= total;
  double variance = 0.0;
  for (std::size_t k = 0; k < values.size(); ++k) variance += weights[k] * (values[k] - d.mean) * (values[k] - d.mean);
  d.std = std::sqrt(variance / total);
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  // The smallest value with at least a share p of the area at or below it.
  auto percentile = [&](double p) {
    double below = 0.0;
    for (std::size_t k : order) {
      below += weights[k];
      if (below >= p * total) return values[k];
    }
    return values[order.back()];
  };
  d.p50 = percentile(0.50);
  d.p90 = percentile(0.90);
  d.p99 = percentile(0.99);
  d.max = values[order.back()];
  return d;
}

std::vector<double> phase_volume_fractions(const std::vector<double>& weight, const std::vector<int>& phase, int phases) {
  std::vector<double> f(static_cast<std::size_t>(phases), 0.0);
  double total = 0.0;
  for (std::size_t c = 0; c < weight.size(); ++c) {
    f[static_cast<std::size_t>(phase[c])] += weight[c];
    total += weight[c];
  }
  for (double& x : f) x /= total;
  return f;
}

std::vector<PhaseStresses> phase_stresses(const std::vector<StressTensor>& stress, const std::vector<double>& weight,
                                          const std::vector<int>& phase, int phases, int loaded,
                                          const std::vector<StressTensor>* balanced) {
  std::vector<PhaseStresses> out(static_cast<std::size_t>(phases));
  std::vector<std::vector<double>> weights(out.size()), mises(out.size()), principal(out.size()), pressure(out.size());
  std::vector<double> phase_weight(out.size(), 0.0);
  double total = 0.0, cell_loaded = 0.0;
  for (std::size_t c = 0; c < stress.size(); ++c) {
    const double w = weight[c];
    const StressTensor& s = stress[c];
    const StressTensor& b = balanced ? (*balanced)[c] : s;
    const std::size_t p = static_cast<std::size_t>(phase[c]);
    phase_weight[p] += w;
    for (std::size_t i = 0; i < 6; ++i) out[p].mean[i] += w * b[i];
    weights[p].push_back(w);
    mises[p].push_back(von_mises(s));
    principal[p].push_back(largest_principal(s));
    pressure[p].push_back(hydrostatic(s));
    total += w;
    if (loaded >= 0) cell_loaded += w * b[static_cast<std::size_t>(loaded)];
  }
  const double cell_mean = cell_loaded / total;
  for (std::size_t p = 0; p < out.size(); ++p) {
    PhaseStresses& ps = out[p];
    if (phase_weight[p] > 0.0)
      for (double& m : ps.mean) m /= phase_weight[p];
    ps.volume_fraction = phase_weight[p] / total;
    ps.von_mises = distribution(mises[p], weights[p]);
    ps.max_principal = distribution(principal[p], weights[p]);
    ps.hydrostatic = distribution(pressure[p], weights[p]);
    if (loaded >= 0) ps.partition = cell_mean != 0.0 ? ps.mean[static_cast<std::size_t>(loaded)] / cell_mean : 0.0;
  }
  return out;
}

std::vector<std::vector<Vec2>> von_mises_histograms(const std::vector<StressState>& cell_stress, const CellMesh& mesh,
                                                    const std::vector<int>& phase, int phases, int bins) {
  std::vector<double> mises;
  for (const StressState& s : cell_stress) mises.push_back(von_mises(s));
  return phase_histograms(mises, cell_areas(mesh), phase, phases, bins);
}

std::vector<std::vector<Vec2>> phase_histograms(const std::vector<double>& values, const std::vector<double>& weights,
                                                const std::vector<int>& phase, int phases, int bins) {
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const double low = values.empty() ? 0.0 : *lo, width = values.empty() || *hi == *lo ? 1.0 : (*hi - *lo) / bins;
  std::vector<std::vector<double>> share(static_cast<std::size_t>(phases), std::vector<double>(bins, 0.0));
  std::vector<double> total(static_cast<std::size_t>(phases), 0.0);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const int bin = std::clamp(static_cast<int>((values[k] - low) / width), 0, bins - 1);
    share[phase[k]][bin] += weights[k];
    total[phase[k]] += weights[k];
  }
  std::vector<std::vector<Vec2>> out(share.size());
  for (std::size_t p = 0; p < share.size(); ++p)
    for (int b = 0; b < bins; ++b)
      out[p].push_back({low + (b + 0.5) * width, total[p] > 0.0 ? share[p][b] / total[p] : 0.0});
  return out;
}

}  // namespace grainmesh
