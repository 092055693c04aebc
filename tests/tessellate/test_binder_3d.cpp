// 3D binder mode: the binder's fraction to rounding, every grain wrapped when no target
// asks for contacts (and kept off a bounded box's sides), contiguity targets met from the
// closed-form areas as the cut measures them, out-of-reach targets refused with the range.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

#include "common/errors.hpp"
#include "tessellate/tessellate_3d.hpp"
#include "tessellate/tessellation_json.hpp"

using namespace grainmesh;

namespace {

Tessellation3Options binder_options(int grains, bool periodic, double binder) {
  Tessellation3Options o;
  o.periodic = periodic;
  o.grains = grains;
  o.lloyd_iterations = 3;
  o.phases = {
      Phase{.name = "WC", .fraction = 0.0, .rest = true, .youngs_modulus = 700e9, .poisson_ratio = 0.24, .alpha = {}},
      Phase{.name = "Co",
            .fraction = binder,
            .rest = false,
            .youngs_modulus = 211e9,
            .poisson_ratio = 0.31,
            .alpha = {}}};
  o.phase_mode = PhaseMode::binder;
  o.matrix_phase = 1;
  o.contiguity_phase = 0;
  return o;
}

Tessellation3 make(const Tessellation3Options& o, std::uint64_t seed) {
  Rng rng(seed);
  return tessellate_3d(o, rng);
}

// Faces between two different grains neither of which is the matrix.
int grain_contacts(const Tessellation3& t) {
  int n = 0;
  for (const Face3& f : t.faces)
    if (f.front >= 0) {
      const int a = t.regions[f.back].grain, b = t.regions[f.front].grain;
      n += a != b && !t.grains[a].matrix && !t.grains[b].matrix;
    }
  return n;
}

}  // namespace

TEST_CASE("3D binder: the binder's fraction exact, every grain wrapped, bounded grains off the box", "[binder3d]") {
  for (const bool periodic : {true, false}) {
    const Tessellation3 t = make(binder_options(24, periodic, 0.12), 3);
    INFO((periodic ? "periodic" : "bounded"));
    REQUIRE(t.grains.back().matrix);
    CHECK(t.stats.grains == 24);
    CHECK(t.stats.phases[1].achieved_fraction == Approx(0.12).epsilon(1e-9));
    CHECK(t.stats.phases[0].achieved_fraction == Approx(0.88).epsilon(1e-9));
    // No contact: every frustum is binder and the pyramids fill the box, so 1 - s^3 is the
    // binder's fraction exactly.
    CHECK(t.stats.binder_scale == Approx(std::cbrt(1.0 - 0.12)).epsilon(1e-12));
    CHECK(grain_contacts(t) == 0);
    CHECK(t.stats.phases[0].contiguity == 0.0);
    if (!periodic)
      for (const Face3& f : t.faces)
        if (f.front < 0) CHECK(t.grains[t.regions[f.back].grain].matrix);  // only binder meets the box
  }
}

TEST_CASE("3D binder: on Kelvin cells the layer's thickness, the intercept and the free path are the closed form's",
          "[binder3d]") {
  // Seeds on a body-centred cubic lattice of spacing L give truncated octahedra: volume
  // L^3 / 2, area (6 + 12 sqrt 3) L^2 / 8. Wrapped cores are the cells scaled by s about
  // their seeds, so binder_layer (2 x binder volume / its area with the grains) is
  // 2 (1 - s^3) V / (s^2 A), the binder's mean free path (4 V / S) twice that, and the
  // carbide's mean intercept 4 s^3 V / (s^2 A).
  constexpr int n = 2;
  constexpr double L = 1.0 / n, binder = 0.1;
  Tessellation3Options o = binder_options(2 * n * n * n, true, binder);
  o.lloyd_iterations = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const double c : {0.25, 0.75}) o.seeds.push_back({(i + c) * L, (j + c) * L, (k + c) * L});
  const Tessellation3 t = make(o, 1);
  const double s = std::cbrt(1.0 - binder), V = L * L * L / 2, A = (6 + 12 * std::sqrt(3.0)) * L * L / 8;
  REQUIRE(t.stats.grains == 2 * n * n * n);
  for (const Grain3& g : t.grains)
    if (!g.matrix) CHECK(g.volume == Approx(s * s * s * V).epsilon(1e-9));
  CHECK(t.stats.binder_scale == Approx(s).epsilon(1e-12));
  CHECK(t.stats.binder_layer == Approx(2 * (1 - s * s * s) * V / (s * s * A)).epsilon(1e-9));
  const PhaseStats &wc = t.stats.phases[0], &co = t.stats.phases[1];
  CHECK(co.mean_free_path == Approx(4 * (1 - s * s * s) * V / (s * s * A)).epsilon(1e-9));
  CHECK(co.intercept_length == Approx(co.mean_free_path).epsilon(1e-12));  // no Co-Co boundary
  CHECK(wc.intercept_length == Approx(4 * s * V / A).epsilon(1e-9));
  CHECK(wc.mean_free_path == Approx(wc.intercept_length).epsilon(1e-12));  // no contact
}

TEST_CASE("3D binder: Laguerre cells (layers about their centroids) and a bounded box reach a target too",
          "[binder3d]") {
  for (const bool periodic : {true, false}) {
    Tessellation3Options o = binder_options(30, periodic, 0.15);
    o.size_cv = 0.5;  // Laguerre cells: scaled about their centroids, not their seeds
    o.lloyd_iterations = 0;
    o.contiguity = 0.4;
    const Tessellation3 t = make(o, 4);
    INFO((periodic ? "periodic" : "bounded"));
    CHECK(t.stats.phases[1].achieved_fraction == Approx(0.15).epsilon(1e-9));
    CHECK(std::abs(t.stats.phases[0].contiguity - 0.4) <= kContiguityTolerance);
    CHECK(grain_contacts(t) > 0);
  }
}

TEST_CASE("3D binder: contiguity targets 0.2, 0.4 and 0.6 met on five seeds", "[binder3d]") {
#ifdef GRAINMESH_SANITIZED
  const int seeds = 1;  // memory, not coverage, is the point there
#else
  const int seeds = 5;
#endif
  const double binder = 0.12;
  for (const double target : {0.2, 0.4, 0.6})
    for (int seed = 1; seed <= seeds; ++seed) {
      Tessellation3Options o = binder_options(30, true, binder);
      o.lloyd_iterations = 0;  // the seeds are the layers' centres
      o.contiguity = target;
      const Tessellation3 t = make(o, static_cast<std::uint64_t>(seed));
      INFO("binder " << binder << ", target " << target << ", seed " << seed);
      CHECK(!t.stats.contiguity_range);
      CHECK(std::abs(t.stats.phases[0].contiguity - target) <= kContiguityTolerance);
      CHECK(t.stats.phases[1].achieved_fraction == Approx(binder).epsilon(1e-9));
      CHECK(grain_contacts(t) > 0);
      CHECK(t.stats.binder_contacts > 0);
      // Gurland and Fullman's relation between the three: the binder's free path is the
      // carbide's intercept times V_Co / (V_WC (1 - C)).
      const PhaseStats &wc = t.stats.phases[0], &co = t.stats.phases[1];
      CHECK(co.mean_free_path == Approx(wc.intercept_length * co.achieved_fraction /
                                        (wc.achieved_fraction * (1 - wc.contiguity)))
                                     .epsilon(1e-9));
    }
}

TEST_CASE("3D binder: a target out of reach gives the range, too much binder is refused", "[binder3d]") {
  Tessellation3Options o = binder_options(40, true, 0.15);
  o.contiguity = 0.95;
  const Tessellation3 t = make(o, 1);
  REQUIRE(t.stats.contiguity_range);
  CHECK(t.stats.contiguity_range->first == 0.0);
  CHECK(t.stats.contiguity_range->second > 0.5);
  CHECK(t.stats.contiguity_range->second < 0.93);
  CHECK_THROWS_AS(make(binder_options(40, true, 0.8), 1), ConfigError);
}

TEST_CASE("3D binder: the matrix and the layers' scale survive tessellation.json", "[binder3d]") {
  Tessellation3Options o = binder_options(20, true, 0.1);
  o.contiguity = 0.3;
  const Tessellation3 t = make(o, 2);
  const std::string text = tessellation_to_json(t);
  const Tessellation3 back = tessellation_from_json<3>(text, "memory");
  CHECK(back.grains.back().matrix);
  CHECK(back.stats.binder_scale == t.stats.binder_scale);
  CHECK(tessellation_to_json(back) == text);
}
