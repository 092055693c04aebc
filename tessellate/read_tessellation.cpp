#include "tessellate/read_tessellation.hpp"

#include <algorithm>
#include <numeric>

#include "common/errors.hpp"
#include "tessellate/phases.hpp"
#include "tessellate/tessellate.hpp"

namespace grainmesh {

std::vector<std::vector<int>> neighbour_lists(std::size_t grains, const std::set<std::pair<int, int>>& pairs) {
  std::vector<std::vector<int>> out(grains);
  for (const auto& [a, b] : pairs) {
    out[a].push_back(b);
    out[b].push_back(a);
  }
  for (auto& l : out) std::sort(l.begin(), l.end());
  return out;
}

std::vector<int> phases_by_rules(const std::vector<double>& sizes, const std::vector<std::vector<int>>& neighbours,
                                 const std::vector<Phase>& phases, Arrangement arrangement, double total, Rng& rng) {
  std::vector<int> all(phases.size());
  std::iota(all.begin(), all.end(), 0);
  return assign_phases(sizes, neighbours, phases, all, total, arrangement, rng);
}

int phase_of_label(const std::vector<LabelPhase>& table, std::uint32_t label) {
  int phase = -1;
  for (const LabelPhase& lp : table)
    if (label >= lp.lo && label <= lp.hi) phase = lp.phase;
  return phase;
}

void measure_read_tessellation(Tessellation& t, const std::string& source) {
  try {
    measure_tessellation(t);
  } catch (const GeometryError& e) {
    throw GeometryError(source + ": " + e.what());
  }
  t.stats.shortest_torus_edge = t.stats.shortest_edge;
}

}  // namespace grainmesh
