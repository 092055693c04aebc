// The tessellation stage: topology, areas, periodicity, regularisation, phases.
#include <catch2/catch.hpp>

#include <cmath>

#include "tessellate/steps.hpp"
#include "tessellate/tessellation.hpp"

using namespace grainmesh;

namespace {

TessellationOptions options(int grains, double w, double h) {
  TessellationOptions o;
  o.width = w;
  o.height = h;
  o.grains = grains;
  o.phases = {Phase{.name = "WC", .fraction = 1.0, .rest = false, .youngs_modulus = 700e9, .poisson_ratio = 0.2}};
  return o;
}

Tessellation make(const TessellationOptions& o, std::uint64_t seed) {
  Rng rng(seed);
  return tessellate(o, rng);
}

}  // namespace

TEST_CASE("smoke: a periodic Voronoi tessellation validates") {
  auto o = options(50, 3.0, 1.7);
  o.min_edge = 0.0;
  const Tessellation t = make(o, 1);
  CHECK(t.stats.grains == 50);
  CHECK(t.stats.edges_per_grain_mean == Approx(6.0).epsilon(1e-12));
  INFO("sharpest " << t.stats.sharpest_corner_deg << " jogs " << t.stats.side_jogs << " shortest " << t.stats.shortest_edge);
  CHECK(t.stats.sharpest_corner_deg > 0.0);
}
