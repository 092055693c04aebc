// The mesh stage on tessellations: shared seeding, conformity, periodic pairs, threads.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "mesh/grain_mesh.hpp"
#include "mesh/quality.hpp"

using namespace grainmesh;

namespace {

Tessellation cell(int grains, double w, bool periodic, PhaseMode mode, int lloyd, std::uint64_t seed) {
  TessellationOptions o;
  o.width = w;
  o.height = 1.0;
  o.grains = grains;
  o.periodic = periodic;
  o.lloyd_iterations = lloyd;
  o.phase_mode = mode;
  o.matrix_phase = 1;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24}, Phase{"Co", 0.12, false, 211e9, 0.31}};
  Rng rng(seed);
  return tessellate(o, rng);
}

// Edge length for about `per_grain` triangles per grain.
double size_for(const Tessellation& t, double per_grain) {
  const double area = t.width * t.height / t.stats.grains;
  return std::sqrt(4.0 * area / (per_grain * std::sqrt(3.0)));
}

}  // namespace

TEST_CASE("shared seeds: opposite sides of a periodic cell carry the same points", "[mesh][grain]") {
  const Tessellation t = cell(60, 2.0, true, PhaseMode::grain, 2, 1);
  GrainMeshOptions o{.size = size_for(t, 80), .phase_size = {}};
  const auto seeds = seed_edges(t, o, tessellation_size(t, o));
  std::size_t on_left = 0, on_right = 0;
  for (std::size_t e = 0; e < seeds.size(); ++e)
    for (const Vec2 p : seeds[e]) {
      on_left += p.x == 0.0 ? 1 : 0;
      on_right += p.x == t.width ? 1 : 0;
    }
  CHECK(on_left > 0);
  CHECK(on_left == on_right);
}

namespace {

// Conformity, exact areas and pairs, and the same mesh from 1 and 2 threads.
void check_mesh(const Tessellation& t, double per_grain) {
  GrainMeshOptions o{.size = size_for(t, per_grain), .phase_size = {}, .threads = 1};
  const GrainMesh m = mesh_tessellation(t, o);
  const Conformity c = check_conformity(t, m);
  CHECK(c.max_area_error <= 1e-9);
  CHECK(c.max_pair_mismatch <= 1e-12 * std::max(t.width, t.height));
  CHECK(m.phase.size() == m.mesh.triangles.size());
  CHECK(m.pairs_x.empty() != t.periodic);
  o.threads = 2;
  const GrainMesh m2 = mesh_tessellation(t, o);
  CHECK(m2.mesh.points == m.mesh.points);
  CHECK(m2.mesh.triangles == m.mesh.triangles);
}

}  // namespace

TEST_CASE("grain-mode meshes conform to their tessellation", "[mesh][grain]") {
  for (bool periodic : {true, false})
    for (std::uint64_t seed : {1u, 2u}) {
      INFO("periodic " << periodic << " seed " << seed);
      check_mesh(cell(40, 1.5, periodic, PhaseMode::grain, seed == 1 ? 2 : 0, seed), 60);
    }
}

TEST_CASE("binder-mode meshes conform to their tessellation", "[mesh][grain]") {
  for (bool periodic : {true, false}) {
    INFO("periodic " << periodic);
    TessellationOptions o;
    o.grains = 12;
    o.periodic = periodic;
    o.lloyd_iterations = 2;
    o.phase_mode = PhaseMode::binder;
    o.matrix_phase = 1;
    o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24}, Phase{"Co", 0.3, false, 211e9, 0.31}};
    Rng rng(3);
    check_mesh(tessellate(o, rng), 30);
  }
}
