#include "grains/size_field.hpp"

#include <algorithm>

namespace grainmesh {

FeatureSize tessellation_size(const Tessellation& t, const GrainMeshOptions& o) {
  double largest = o.size, finest = o.size;
  std::vector<double> phase_size;
  for (std::size_t p = 0; p < t.phases.size(); ++p) {
    phase_size.push_back(region_size(o, static_cast<int>(p)));
    largest = std::max(largest, phase_size.back());
    finest = std::min(finest, phase_size.back());
  }
  std::vector<SizeSource> sources;
  if (o.feature_size) sources = feature_sources(t, 0.5 * finest, largest, o.feature_fraction, o.gradient);
  const auto graded = grading_sources(t, o.boundary_size, o.junction_size, phase_size, largest, o.gradient);
  sources.insert(sources.end(), graded.begin(), graded.end());
  return FeatureSize(std::move(sources), largest, o.gradient);
}

}  // namespace grainmesh
