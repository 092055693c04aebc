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

std::vector<PhaseStresses> phase_stresses(const std::vector<StressState>& states, const CellMesh& mesh,
                                          const std::vector<int>& phase, int phases, int loaded_component,
                                          const std::vector<StressState>* balanced) {
  auto loaded = [&](const StressState& s) {
    return loaded_component == 0 ? s.xx : loaded_component == 1 ? s.yy : loaded_component == 2 ? s.xy : 0.0;
  };
  std::vector<PhaseStresses> out(static_cast<std::size_t>(phases));
  std::vector<std::vector<double>> weights(out.size()), mises(out.size()), principal(out.size()), pressure(out.size());
  double total_area = 0.0, cell_loaded = 0.0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const double a = cell_area(mesh, k);
    const StressState& s = states[k];
    const std::size_t p = static_cast<std::size_t>(phase[k]);
    PhaseStresses& ps = out[p];
    ps.area_fraction += a;
    // The in-plane mean from the balanced stresses where given; zz is the cells' own.
    const StressState& b = balanced ? (*balanced)[k] : s;
    ps.mean.xx += a * b.xx, ps.mean.yy += a * b.yy, ps.mean.zz += a * s.zz, ps.mean.xy += a * b.xy;
    weights[p].push_back(a);
    mises[p].push_back(von_mises(s));
    principal[p].push_back(largest_principal(s));
    pressure[p].push_back(hydrostatic(s));
    total_area += a;
    cell_loaded += a * loaded(b);
  }
  const double cell_mean = cell_loaded / total_area;
  for (std::size_t p = 0; p < out.size(); ++p) {
    PhaseStresses& ps = out[p];
    if (ps.area_fraction > 0.0) {
      ps.mean.xx /= ps.area_fraction, ps.mean.yy /= ps.area_fraction, ps.mean.zz /= ps.area_fraction;
      ps.mean.xy /= ps.area_fraction;
    }
    ps.area_fraction /= total_area;
    ps.von_mises = distribution(mises[p], weights[p]);
    ps.max_principal = distribution(principal[p], weights[p]);
    ps.hydrostatic = distribution(pressure[p], weights[p]);
    ps.partition = cell_mean != 0.0 ? loaded(ps.mean) / cell_mean : 0.0;
  }
  return out;
}

std::vector<std::vector<Vec2>> von_mises_histograms(const std::vector<StressState>& cell_stress, const CellMesh& mesh,
                                                    const std::vector<int>& phase, int phases, int bins) {
  std::vector<double> mises, area;
  for (std::size_t k = 0; k < cell_stress.size(); ++k) {
    mises.push_back(von_mises(cell_stress[k]));
    area.push_back(cell_area(mesh, k));
  }
  return phase_histograms(mises, area, phase, phases, bins);
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
