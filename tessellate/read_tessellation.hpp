// What the tessellations read from files (Neper's, label images) share: who touches whom
// as sorted lists, phases by our rules or from a table of the file's labels (an image's
// values, a Neper file's cell groups), and the statistics of a generated one with any
// error naming the file.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "common/random.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// The sorted neighbour list of each of `grains` grains, from pairs (a, b).
std::vector<std::vector<int>> neighbour_lists(std::size_t grains, const std::set<std::pair<int, int>>& pairs);

// A phase for each grain by our rules (assign_phases over all `phases`) from the grains'
// sizes (areas or volumes) and neighbours; `total` the cell's size.
std::vector<int> phases_by_rules(const std::vector<double>& sizes, const std::vector<std::vector<int>>& neighbours,
                                 const std::vector<Phase>& phases, Arrangement arrangement, double total, Rng& rng);

// Labels lo .. hi are of phase `phase`.
struct LabelPhase {
  std::uint32_t lo = 0;
  std::uint32_t hi = 0;
  int phase = 0;
};

// A label of the file the phase table does not name.
struct UnnamedLabelError : GeometryError {
  using GeometryError::GeometryError;
};

// The phase the table gives `label`, -1 when it names none (the last entry naming it wins).
int phase_of_label(const std::vector<LabelPhase>& table, std::uint32_t label);

// measure_tessellation, a GeometryError it throws prefixed "SOURCE: "; the torus's
// shortest edge is the cell's (a read tessellation has no torus).
void measure_read_tessellation(Tessellation& t, const std::string& source);

}  // namespace grainmesh
