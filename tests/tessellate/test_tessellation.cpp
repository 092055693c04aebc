// The tessellation stage: the power diagram against brute force, topology on the torus,
// the cut cell's invariants, regularisation, sharp corners, phases and reproducibility.
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "tessellate/phases.hpp"
#include "tessellate/regularise.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_json.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/validate.hpp"

using namespace grainmesh;

namespace {

Phase phase(const std::string& name, double fraction, bool rest = false) {
  return Phase{.name = name, .fraction = fraction, .rest = rest, .youngs_modulus = 1.0, .poisson_ratio = 0.3, .alpha = {}};
}

TessellationOptions options(int grains, double w, double h) {
  TessellationOptions o;
  o.width = w;
  o.height = h;
  o.grains = grains;
  o.phases = {phase("WC", 0.0, true), phase("Co", 0.2)};
  return o;
}

Tessellation make(const TessellationOptions& o, std::uint64_t seed) {
  Rng rng(seed);
  return tessellate(o, rng);
}

// The power cell of seed s among all seeds and their images, by clipping a large square
// with every bisector: slow and obviously right.
double brute_force_cell_area(const std::vector<Vec2>& seeds, const std::vector<double>& w, double W, double H, int s) {
  const Vec2 p = seeds[s];
  const double R = 3.0 * std::max(W, H);
  std::vector<Vec2> poly{{p.x - R, p.y - R}, {p.x + R, p.y - R}, {p.x + R, p.y + R}, {p.x - R, p.y + R}};
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i)
      for (int q = 0; q < static_cast<int>(seeds.size()); ++q) {
        if (q == s && i == 0 && j == 0) continue;
        const Vec2 o{seeds[q].x + i * W, seeds[q].y + j * H};
        // Keep x with 2 (o - p) . x <= |o|^2 - |p|^2 - w_q + w_s.
        const Vec2 n = 2.0 * (o - p);
        const double c = norm2(o) - norm2(p) - w[q] + w[s];
        std::vector<Vec2> out;
        for (std::size_t k = 0; k < poly.size(); ++k) {
          const Vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
          const double da = c - dot(n, a), db = c - dot(n, b);
          if (da >= 0) out.push_back(a);
          if ((da >= 0) != (db >= 0)) out.push_back(a + (da / (da - db)) * (b - a));
        }
        poly = out;
        if (poly.size() < 3) return 0.0;
      }
  return polygon_area(poly);
}

std::vector<Vec2> ring_points(const Tessellation& t, const std::vector<int>& ring) {
  std::vector<Vec2> pts;
  for (int v : ring) pts.push_back(t.vertices[v]);
  return pts;
}

// Every acceptance invariant, checked here independently of validate().
void check_invariants(const Tessellation& t) {
  const double W = t.width, H = t.height;
  double total = 0.0;
  for (const Region& r : t.regions) {
    for (std::size_t q = 0; q < r.rings.size(); ++q) {
      const auto pts = ring_points(t, r.rings[q]);
      CHECK(polygon_area(pts) > 0.0);  // counter-clockwise, holes included
      CHECK(ring_is_simple(pts));
      total += (q == 0 ? 1.0 : -1.0) * polygon_area(pts);
    }
  }
  CHECK(std::abs(total - W * H) <= 1e-9 * W * H);
  for (const TessEdge& e : t.edges) {
    CHECK(e.left != e.right);
    if (e.left >= 0 && e.right >= 0) continue;
    const Vec2 a = t.vertices[e.v0], b = t.vertices[e.v1];
    const bool on_side = (a.x == 0 && b.x == 0) || (a.x == W && b.x == W) || (a.y == 0 && b.y == 0) || (a.y == H && b.y == H);
    CHECK(on_side);
  }
  const double tol = 1e-12 * std::max(W, H);
  std::size_t left = 0, bottom = 0;
  for (Vec2 v : t.vertices) {
    left += v.x == 0.0 ? 1 : 0;
    bottom += v.y == 0.0 ? 1 : 0;
  }
  if (t.periodic) {
    CHECK(t.partners.axis[0].size() == left);
    CHECK(t.partners.axis[1].size() == bottom);
    for (const auto& [a, b] : t.partners.axis[0]) {
      CHECK(t.vertices[a].x == 0.0);
      CHECK(std::abs(t.vertices[b].x - t.vertices[a].x - W) <= tol);
      CHECK(std::abs(t.vertices[b].y - t.vertices[a].y) <= tol);
    }
    for (const auto& [a, b] : t.partners.axis[1]) {
      CHECK(t.vertices[a].y == 0.0);
      CHECK(std::abs(t.vertices[b].y - t.vertices[a].y - H) <= tol);
      CHECK(std::abs(t.vertices[b].x - t.vertices[a].x) <= tol);
    }
  } else {
    CHECK(t.partners.axis[0].empty());
    CHECK(t.partners.axis[1].empty());
  }
  // Each grain's area is the sum of its pieces.
  std::vector<double> area(t.grains.size(), 0.0);
  for (const Region& r : t.regions) area[r.grain] += region_area(t, r);
  for (const Grain& g : t.grains) CHECK(g.area == Approx(area[g.id]).epsilon(1e-12));
}

}  // namespace

TEST_CASE("the periodic power diagram matches brute force on rectangles", "[tessellate]") {
  for (const auto& [W, H] : {std::pair{1.0, 1.0}, std::pair{3.0, 1.0}, std::pair{1.0, 2.5}}) {
    for (double cv : {0.0, 0.5}) {
      Rng rng(11);
      const int n = 40;
      std::vector<Vec2> seeds(n);
      std::vector<double> w(n, 0.0);
      for (auto& s : seeds) s = {W * uniform01(rng), H * uniform01(rng)};
      for (auto& x : w) x = cv * W * H / n * uniform01(rng);
      const TorusGraph g = power_diagram(seeds, w, W, H, true, 1e-12);
      double total = 0.0;
      for (int s = 0; s < n; ++s) {
        const double mine = g.rings[s].empty() ? 0.0 : polygon_area(g.polygon(s));
        CHECK(mine == Approx(brute_force_cell_area(seeds, w, W, H, s)).margin(1e-12 * W * H));
        total += mine;
      }
      CHECK(total == Approx(W * H).epsilon(1e-12));
    }
  }
}

TEST_CASE("Euler on the torus: only triple junctions give exactly 6 edges per grain", "[tessellate]") {
  for (int n : {1, 7, 50, 400}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      Rng rng(seed);
      std::vector<Vec2> seeds(n);
      for (auto& s : seeds) s = {2.0 * uniform01(rng), uniform01(rng)};
      const TorusGraph g = power_diagram(seeds, std::vector<double>(n, 0.0), 2.0, 1.0, true, 1e-12);
      const auto vc = vertex_cells(g);
      const long long V = static_cast<long long>(g.vertices.size());
      const long long E = static_cast<long long>(unique_edges(g).size());
      const long long F = g.live_cells();
      CHECK(V - E + F == 0);
      if (n < 7) continue;  // a handful of seeds may see themselves across the torus
      CHECK(2 * E == 3 * V);
      long long corners = 0;
      for (const auto& r : g.rings) corners += static_cast<long long>(r.size());
      CHECK(static_cast<double>(corners) / static_cast<double>(F) == 6.0);
    }
  }
  auto o = options(300, 3.0, 1.7);
  o.min_edge = 0.0;
  CHECK(make(o, 5).stats.edges_per_grain_mean == 6.0);
}

TEST_CASE("cut cells keep every invariant in each mode", "[tessellate]") {
  for (bool periodic : {true, false})
    for (PhaseMode mode : {PhaseMode::grain, PhaseMode::binder})
      for (double w : {1.0, 3.0})
        for (std::uint64_t seed : {1u, 2u, 3u}) {
          auto o = options(120, w, 1.0);
          o.periodic = periodic;
          o.lloyd_iterations = seed == 3 ? 0 : 2;
          o.size_cv = seed == 2 ? 0.4 : 0.0;
          o.phase_mode = mode;
          o.matrix_phase = 1;
          INFO("periodic " << periodic << " binder " << (mode == PhaseMode::binder) << " w " << w << " seed " << seed);
          const Tessellation t = make(o, seed);
          check_invariants(t);
          if (mode == PhaseMode::binder) {
            // The binder is one layer: its regions in the cell (a corner may be cut off
            // by a grain) join into one through the periodic sides.
            std::vector<int> parent(t.regions.size());
            for (std::size_t r = 0; r < parent.size(); ++r) parent[r] = static_cast<int>(r);
            auto root = [&](int r) {
              while (parent[r] != r) r = parent[r];
              return r;
            };
            std::map<int, int> matrix_of_vertex;
            std::size_t holes = 0;
            std::set<int> matrix;
            for (std::size_t r = 0; r < t.regions.size(); ++r) {
              if (!t.grains[t.regions[r].grain].matrix) continue;
              matrix.insert(static_cast<int>(r));
              holes += t.regions[r].rings.size() - 1;
              for (int v : t.regions[r].rings[0]) matrix_of_vertex[v] = static_cast<int>(r);
            }
            for (const auto* pairs : {&t.partners.axis[0], &t.partners.axis[1]})
              for (const auto& [a, b] : *pairs)
                if (matrix_of_vertex.count(a) && matrix_of_vertex.count(b))
                  parent[root(matrix_of_vertex[a])] = root(matrix_of_vertex[b]);
            std::set<int> roots;
            for (int r : matrix) roots.insert(root(r));
            CHECK(roots.size() == (periodic ? 1u : matrix.size()));
            CHECK(matrix.size() <= (periodic ? 5u : 1u));
            CHECK(holes > 50);  // whose holes are the grains inside the cell
          }
        }
}

TEST_CASE("a grain cut by the cell's sides keeps its id in every piece", "[tessellate]") {
  const Tessellation t = make(options(60, 1.0, 1.0), 4);
  std::map<int, int> pieces;
  for (const Region& r : t.regions) ++pieces[r.grain];
  CHECK(static_cast<int>(pieces.size()) == t.stats.grains);
  int cut = 0;
  for (const auto& [g, n] : pieces) cut += n > 1 ? 1 : 0;
  CHECK(cut >= 4);  // sides cross grains, and their pieces share the grain's id
  CHECK(t.regions.size() > pieces.size());
}

TEST_CASE("regularisation leaves no edge shorter than its threshold", "[tessellate]") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    auto o = options(300, 2.0, 1.0);
    o.min_edge = 0.2;  // Poisson-Voronoi: many short edges
    const Tessellation t = make(o, seed);
    CHECK(t.stats.collapsed_edges > 10);
    CHECK(t.stats.shortest_torus_edge >= t.stats.edge_threshold);
    check_invariants(t);
    // Without regularisation the same cell has much shorter edges.
    o.min_edge = 0.0;
    CHECK(make(o, seed).stats.shortest_torus_edge < 0.2 * t.stats.edge_threshold);
  }
}

TEST_CASE("three Lloyd iterations: no region corner sharper than 30 degrees", "[tessellate]") {
  for (double aspect : {1.0, 3.0})
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      auto o = options(200, aspect, 1.0);
      o.lloyd_iterations = 3;
      const Tessellation t = make(o, seed);
      INFO("aspect " << aspect << " seed " << seed);
      CHECK(t.stats.sharpest_corner_deg >= 30.0);
      // Junctions kept off the sides: no cut edge much shorter than the threshold.
      CHECK(t.stats.shortest_edge >= 0.9 * t.stats.edge_threshold);
      double sharpest = 360.0;  // recomputed from the regions
      for (const Region& r : t.regions)
        sharpest = std::min(sharpest, sharpest_corner(ring_points(t, r.rings[0])) * 180.0 / std::numbers::pi);
      CHECK(sharpest == Approx(t.stats.sharpest_corner_deg).margin(1e-9));
    }
}

TEST_CASE("Lloyd relaxation evens out grain sizes and Laguerre weights spread them", "[tessellate]") {
  auto o = options(400, 1.0, 1.0);
  const double poisson = make(o, 1).stats.area_std;
  o.lloyd_iterations = 5;
  const TessellationStats lloyd = make(o, 1).stats;
  CHECK(lloyd.area_std < 0.5 * poisson);
  o.size_cv = 0.8;
  const TessellationStats laguerre = make(o, 1).stats;
  INFO("diameter spread: Lloyd " << lloyd.diameter_std << ", Laguerre " << laguerre.diameter_std);
  CHECK(laguerre.diameter_std > 2.0 * lloyd.diameter_std);
}

TEST_CASE("grain mode meets every phase target within 1 percent", "[tessellate]") {
  for (double target : {0.1, 0.3, 0.5})
    for (std::uint64_t seed = 1; seed <= 5; ++seed)
      for (Arrangement a : {Arrangement::random, Arrangement::dispersed, Arrangement::clustered}) {
        auto o = options(60, 2.0, 1.0);
        o.lloyd_iterations = 1;
        o.arrangement = a;
        o.phases = {phase("WC", 0.0, true), phase("Co", target), phase("TiC", 0.1)};
        const Tessellation t = make(o, seed);
        INFO("target " << target << " seed " << seed);
        for (const PhaseStats& p : t.stats.phases) CHECK(std::abs(p.achieved_fraction - p.target_fraction) <= 0.01);
        CHECK(t.stats.phases[0].target_fraction == Approx(0.9 - target));
      }
}

TEST_CASE("dispersed phases touch themselves less than clustered ones", "[tessellate]") {
  auto same_phase_contacts = [](Arrangement a) {
    auto o = options(400, 1.0, 1.0);
    o.lloyd_iterations = 2;
    o.arrangement = a;
    o.phases = {phase("WC", 0.0, true), phase("Co", 0.25)};
    const Tessellation t = make(o, 3);
    int contacts = 0;
    for (const Grain& g : t.grains)
      for (int n : g.neighbours) contacts += (g.phase == 1 && t.grains[n].phase == 1) ? 1 : 0;
    return contacts;
  };
  const int dispersed = same_phase_contacts(Arrangement::dispersed);
  const int random = same_phase_contacts(Arrangement::random);
  const int clustered = same_phase_contacts(Arrangement::clustered);
  CHECK(dispersed < random);
  CHECK(random < clustered);
}

TEST_CASE("binder mode meets the matrix fraction within 0.5 percent", "[tessellate]") {
  for (double target : {0.05, 0.15, 0.3})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      auto o = options(80, 1.5, 1.0);
      o.lloyd_iterations = 2;
      o.phase_mode = PhaseMode::binder;
      o.phases = {phase("WC", 0.0, true), phase("Co", target)};
      o.matrix_phase = 1;
      const Tessellation t = make(o, seed);
      INFO("target " << target << " seed " << seed);
      CHECK(std::abs(t.stats.phases[1].achieved_fraction - target) <= 0.005);
      CHECK(t.stats.binder_offset > 0.0);
    }
}

TEST_CASE("unreachable options are refused", "[tessellate]") {
  auto o = options(50, 1.0, 1.0);
  o.phase_mode = PhaseMode::binder;
  o.matrix_phase = 1;
  o.phases = {phase("WC", 1.0), phase("Co", 0.0, true)};  // nothing left for the matrix
  CHECK_THROWS_AS(make(o, 1), ConfigError);
  o.phases = {phase("WC", 0.5), phase("Co", 0.4)};
  CHECK_THROWS_AS(make(o, 1), ConfigError);
  o.grains = 0;
  CHECK_THROWS_AS(make(o, 1), ConfigError);
}

TEST_CASE("same seed same bytes, different seed different tessellation", "[tessellate]") {
  auto o = options(150, 3.0, 1.7);
  o.lloyd_iterations = 2;
  o.size_cv = 0.3;
  const std::string a = tessellation_to_json(make(o, 42));
  CHECK(a == tessellation_to_json(make(o, 42)));
  CHECK(a != tessellation_to_json(make(o, 43)));
}

TEST_CASE("tessellation.json reads back bit for bit", "[tessellate]") {
  auto o = options(80, 2.0, 1.0);
  o.phase_mode = PhaseMode::binder;
  o.matrix_phase = 1;
  const Tessellation t = make(o, 9);
  const Tessellation back = tessellation_from_json<2>(tessellation_to_json(t), "t.json");
  REQUIRE(back.vertices.size() == t.vertices.size());
  for (std::size_t v = 0; v < t.vertices.size(); ++v) CHECK(back.vertices[v] == t.vertices[v]);
  CHECK(back.regions.size() == t.regions.size());
  CHECK(back.partners.axis[0] == t.partners.axis[0]);
  CHECK(tessellation_to_json(back).find("\"regions\"") != std::string::npos);
  CHECK_THROWS_WITH(tessellation_from_json<2>("{\"format\": \"other\"}", "x.json"), Catch::Contains("x.json"));
}

TEST_CASE("tessellation.json indices must be integers within int's range", "[tessellate]") {
  const std::string text = tessellation_to_json(make(options(12, 1.0, 1.0), 3));
  const auto with_first_edge_end = [&](const nlohmann::json& value) {
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
    j["edges"][0][0] = value;
    return j.dump();
  };
  REQUIRE_NOTHROW(tessellation_from_json<2>(with_first_edge_end(0), "t.json"));
  // 1e80 was undefined behaviour in the cast and 2^32 wrapped to vertex 0 (found by fuzzing).
  CHECK_THROWS_WITH(tessellation_from_json<2>(with_first_edge_end(-5e80), "t.json"),
                    Catch::Contains("t.json") && Catch::Contains("expected an integer, found -5e+80"));
  CHECK_THROWS_WITH(tessellation_from_json<2>(with_first_edge_end(std::uint64_t{1} << 32), "t.json"),
                    Catch::Contains("integer 4294967296 is out of range"));
  CHECK_THROWS_WITH(tessellation_from_json<2>(with_first_edge_end(1.5), "t.json"),
                    Catch::Contains("expected an integer, found 1.5"));
}

TEST_CASE("validate refuses grains out of order, regions of another phase and stray edges", "[tessellate]") {
  const Tessellation t = make(options(30, 1.0, 1.0), 5);
  REQUIRE_NOTHROW(validate(t));
  Tessellation renumbered = t;
  renumbered.grains[1].id = 0;  // two grains 0: a mesh would mix them up (found by fuzzing)
  CHECK_THROWS_WITH(validate(renumbered), Catch::Contains("grain 1 has id 0"));
  Tessellation recoloured = t;
  recoloured.regions[0].phase = 1 - recoloured.regions[0].phase;
  CHECK_THROWS_WITH(validate(recoloured), Catch::Contains("has phase"));
  // Edges must be exactly the rings' segments (a stray edge of zero length crashed the
  // seeding: found by fuzzing).
  Tessellation looped = t;
  looped.edges[0].v1 = looped.edges[0].v0;
  CHECK_THROWS_WITH(validate(looped), Catch::Contains("joins a vertex to itself"));
  Tessellation missing = t;
  missing.edges.pop_back();
  CHECK_THROWS_WITH(validate(missing), Catch::Contains("along no edge"));
  Tessellation swapped = t;
  std::swap(swapped.edges[0].left, swapped.edges[0].right);
  CHECK_THROWS_WITH(validate(swapped), Catch::Contains("on the side its ring says"));
  // Indices that name nothing are refused before anything is looked up by them (the
  // tessellation reader relies on this).
  Tessellation far_vertex = t;
  far_vertex.regions[0].rings[0][0] = static_cast<int>(t.vertices.size());
  CHECK_THROWS_WITH(validate(far_vertex), Catch::Contains("region 0 names vertex") && Catch::Contains("does not exist"));
  Tessellation far_phase = t;
  far_phase.grains[0].phase = 7;
  CHECK_THROWS_WITH(validate(far_phase), Catch::Contains("grain 0 names phase 7"));
  Tessellation below_outside = t;
  below_outside.edges[0].right = -5;
  CHECK_THROWS_WITH(validate(below_outside), Catch::Contains("edge 0 names a vertex or region that does not exist"));
  Tessellation far_partner = t;
  far_partner.partners.axis[0].push_back({0, -1});
  CHECK_THROWS_WITH(validate(far_partner), Catch::Contains("periodic partner names a vertex"));
}

TEST_CASE("given seeds: collinear, coincident, on a lattice or alone, the cell keeps every invariant",
          "[tessellate]") {
  struct Case {
    std::string name;
    std::vector<Vec2> seeds;
    int grains;  // expected; coincident seeds hide one another
  };
  std::vector<Case> cases;
  std::vector<Vec2> row, column, diagonal, lattice;
  for (int k = 0; k < 100; ++k) row.push_back({(k + 0.5) / 100, 0.5});
  for (int k = 0; k < 40; ++k) column.push_back({0.5, (k + 0.5) / 40});
  for (int k = 0; k < 40; ++k) diagonal.push_back({(k + 0.5) / 40, (k + 0.5) / 40});
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) lattice.push_back({i / 6.0, j / 6.0});  // every junction 4-fold
  cases.push_back({"100 seeds on a row (all images collinear within the first margin)", row, 100});
  cases.push_back({"40 seeds on a column", column, 40});
  cases.push_back({"40 seeds on the diagonal", diagonal, 40});
  cases.push_back({"a square lattice, seeds on the cell's sides", lattice, 36});
  cases.push_back({"seeds 1e-10 apart", {{0.3, 0.3}, {0.3, 0.3 + 1e-10}, {0.7, 0.6}, {0.2, 0.8}}, 4});
  cases.push_back({"one seed", {{0.5, 0.5}}, 1});
  for (bool periodic : {true, false})
    for (const Case& c : cases) {
      INFO(c.name << (periodic ? ", periodic" : ", plane"));
      auto o = options(static_cast<int>(c.seeds.size()), 1.0, 1.0);
      o.seeds = c.seeds;
      o.periodic = periodic;
      o.min_edge = 0.0;  // keep the degenerate geometry as it is
      Tessellation t;
      REQUIRE_NOTHROW(t = make(o, 1));
      REQUIRE_NOTHROW(validate(t));
      CHECK(t.stats.grains == c.grains);
    }
  auto o = options(2, 1.0, 1.0);
  o.seeds = {{0.5, 0.5}, {1.5, 0.5}};
  CHECK_THROWS_WITH(make(o, 1), Catch::Contains("outside the cell"));
}
