// The WC-Co descriptors (contiguity, mean linear intercept, mean free path) against exact
// values: one phase, squares with phases by rows, strips with alternating phases,
// regular hexagons.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include <nlohmann/json.hpp>

#include "tessellate/descriptors.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_json.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/validate.hpp"

using namespace grainmesh;

namespace {

Phase phase(const std::string& name, double fraction, bool rest = false) {
  return Phase{.name = name, .fraction = fraction, .rest = rest, .youngs_modulus = 1.0, .poisson_ratio = 0.3, .alpha = {}};
}

// A periodic grid of n x m rectangles a x b, each its own grain of phase `of(i, j)`
// (i along x): built by hand, so its boundary lengths are known exactly.
template <class Of>
Tessellation grid(int n, int m, double a, double b, Of of) {
  Tessellation t;
  t.width = n * a;
  t.height = m * b;
  t.periodic = true;
  t.phases = {phase("WC", 0.5, true), phase("Co", 0.5)};
  auto v = [&](int i, int j) { return j * (n + 1) + i; };
  auto region = [&](int i, int j) { return j * n + i; };
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) t.vertices.push_back({i * a, j * b});
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      t.regions.push_back(
          {.grain = region(i, j), .phase = of(i, j), .rings = {{v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)}}});
      t.grains.push_back({.id = region(i, j), .phase = of(i, j), .seed = {(i + 0.5) * a, (j + 0.5) * b}, .area = a * b,
                          .neighbours = {}, .matrix = false});
    }
  // Left of each edge: above a rightward edge, left of an upward one; -1 outside.
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i < n; ++i)
      t.edges.push_back({v(i, j), v(i + 1, j), j < m ? region(i, j) : -1, j > 0 ? region(i, j - 1) : -1});
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < m; ++j)
      t.edges.push_back({v(i, j), v(i, j + 1), i > 0 ? region(i - 1, j) : -1, i < n ? region(i, j) : -1});
  for (int j = 0; j <= m; ++j) t.partners.axis[0].push_back({v(0, j), v(n, j)});
  for (int i = 0; i <= n; ++i) t.partners.axis[1].push_back({v(i, 0), v(i, m)});
  validate(t);
  return t;
}

}  // namespace

TEST_CASE("one phase touches only itself: contiguity 1, no free path", "[tessellate][descriptors]") {
  for (bool periodic : {true, false}) {
    TessellationOptions o;
    o.width = 2.0;
    o.height = 1.0;
    o.periodic = periodic;
    o.grains = 60;
    o.phases = {phase("WC", 1.0, true)};
    Rng rng(3);
    const Tessellation t = tessellate(o, rng);
    const PhaseStats& s = t.stats.phases[0];
    CHECK(s.contiguity == 1.0);
    CHECK(std::isinf(s.mean_free_path));
    // The intercept from the boundary length summed here independently: pi A / (2 L).
    double boundary = 0.0;
    for (const TessEdge& e : t.edges)
      if (e.left >= 0 && e.right >= 0) boundary += norm(t.vertices[e.v1] - t.vertices[e.v0]);
    if (!periodic) CHECK(s.intercept_length == Approx(std::numbers::pi * 2.0 / (2.0 * boundary)).epsilon(1e-12));
    CHECK(s.intercept_length < std::numbers::pi * 2.0 / (2.0 * boundary) + 1e-12);  // sides can only add
    // In the reports: null where undefined.
    const auto j = descriptors_json(t.phases, t.stats.phases);
    CHECK(j["contiguity"]["WC"].get<double>() == 1.0);
    CHECK(j["mean_free_path"]["WC"].is_null());
  }
}

TEST_CASE("rectangles with phases by rows: contiguity 1/2 and the exact intercepts", "[tessellate][descriptors]") {
  // Each a x a square shares its 2 vertical sides with its own phase (its row) and its 2
  // horizontal ones with the other: C = 2 a / (2 a + 2 a) = 1/2, intercept pi a^2 / (4 a),
  // mean free path pi a^2 / (2 a) = pi a / 2 (the mean chord of a row, a strip a wide).
  const double a = 0.2;
  const Tessellation t = grid(6, 4, a, a, [](int, int j) { return j % 2; });
  for (const PhaseDescriptors& d : phase_descriptors(t)) {
    CHECK(d.area == Approx(12 * a * a).epsilon(1e-12));
    CHECK(d.own_boundary == Approx(12 * a).epsilon(1e-12));    // 2 rows of 6 vertical sides, the side pair once
    CHECK(d.other_boundary == Approx(24 * a).epsilon(1e-12));  // 4 rows of 6 horizontal sides
    CHECK(d.contiguity == Approx(0.5).epsilon(1e-12));
    CHECK(d.intercept_length == Approx(std::numbers::pi * a / 4.0).epsilon(1e-12));
    CHECK(d.mean_free_path == Approx(std::numbers::pi * a / 2.0).epsilon(1e-12));
  }
}

TEST_CASE("strips of alternating phases: no contiguity, the mean chord pi w / 2", "[tessellate][descriptors]") {
  // The boundary between the last strip and the first lies along the cell's periodic
  // sides: counted once, from the pieces across it.
  const int strips = 10;
  const double w = 0.3;
  const Tessellation t = grid(strips, 1, w, 1.0, [](int i, int) { return i % 2; });
  for (const PhaseDescriptors& d : phase_descriptors(t)) {
    CHECK(d.own_boundary == Approx(0.0).margin(1e-12));
    CHECK(d.other_boundary == Approx(strips * 1.0).epsilon(1e-12));
    CHECK(d.contiguity == Approx(0.0).margin(1e-12));
    CHECK(d.mean_free_path == Approx(std::numbers::pi * w / 2.0).epsilon(1e-12));
    CHECK(d.intercept_length == Approx(std::numbers::pi * w / 2.0).epsilon(1e-12));
  }
  // The last strip of the first one's phase: it meets its own phase twice, inside the
  // cell (the strip before it) and along the periodic sides (the first strip).
  const Tessellation joined = grid(strips, 1, w, 1.0, [&](int i, int) { return i == strips - 1 ? 0 : i % 2; });
  CHECK(phase_descriptors(joined)[0].own_boundary == Approx(2.0).epsilon(1e-12));
  CHECK(phase_descriptors(joined)[1].own_boundary == Approx(0.0).margin(1e-12));
}

TEST_CASE("a hexagonal tessellation: the contiguity from the lattice's neighbour pairs, every boundary one side long",
          "[tessellate][descriptors]") {
  // Seeds on a triangular lattice of spacing a that tiles the periodic cell: regular
  // hexagons, each boundary a / sqrt(3) long, so C = 2 n_aa / (2 n_aa + n_ab) over the
  // lattice's neighbour pairs, whatever the phases drawn. The cell's sides cross the
  // hexagons a quarter of a from their centres (x) and through them (y), well away from
  // every junction and steeply: the window leaves them as they are.
  const int n = 12, m = 8;  // m rows (even, so the cell is periodic) of n seeds
  const double a = 0.25, row = a * std::sqrt(3.0) / 2.0;
  TessellationOptions o;
  o.width = n * a;
  o.height = m * row;
  o.periodic = true;
  o.min_edge = 0.0;
  o.phases = {phase("WC", 0.6, true), phase("Co", 0.4)};
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) o.seeds.push_back({(i + 0.25 + 0.5 * (j % 2)) * a, j * row});
  o.grains = n * m;
  // As drawn, and with the Co contiguity asked for (label trades: any pattern the lattice
  // allows, still counted exactly).
  for (const std::optional<double> target : {std::optional<double>{}, std::optional<double>{0.2}, std::optional<double>{0.6}})
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    o.contiguity = target;
    o.contiguity_phase = 1;
    Rng rng(seed);
    const Tessellation t = tessellate(o, rng);
    if (target) CHECK(std::abs(t.stats.phases[1].contiguity - *target) <= kContiguityTolerance);
    REQUIRE(t.stats.grains == n * m);
    // The lattice neighbours at distance a (the grains' seeds are the lattice moved with
    // the cell's window).
    std::array<double, 2> own{}, other{};
    for (std::size_t p = 0; p < t.grains.size(); ++p)
      for (std::size_t q = p + 1; q < t.grains.size(); ++q) {
        Vec2 d = t.grains[q].seed - t.grains[p].seed;
        d.x -= o.width * std::round(d.x / o.width);
        d.y -= o.height * std::round(d.y / o.height);
        if (std::abs(norm(d) - a) > 1e-9) continue;
        if (t.grains[p].phase == t.grains[q].phase) {
          own[static_cast<std::size_t>(t.grains[p].phase)] += 1;
        } else {
          other[0] += 1, other[1] += 1;
        }
      }
    INFO("seed " << static_cast<int>(seed) << ": WC pairs " << own[0] << ", Co pairs " << own[1] << ", unlike " << other[0]);
    for (int p = 0; p < 2; ++p)
      CHECK(t.stats.phases[p].contiguity == Approx(2 * own[p] / (2 * own[p] + other[p])).epsilon(1e-9));
  }
}
