#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "common/predicates.hpp"
#include "common/random.hpp"
#include "mesh/delaunay.hpp"

using namespace grainmesh;

namespace {

// Triangles as a set of rotations starting at their least corner (orientation kept).
std::set<std::array<int, 3>> canonical(const Triangulation& t) {
  std::set<std::array<int, 3>> out;
  for (auto v : t.triangles) {
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    out.insert(v);
  }
  return out;
}

std::vector<Vec2> random_points(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Vec2> p(n);
  for (auto& q : p) q = {uniform01(rng), uniform01(rng)};
  return p;
}

// An n x n grid of spacing 1/n over the unit square, each point moved by up to a quarter
// spacing: nearly cocircular fours everywhere (many flips), no slivers.
std::vector<Vec2> jittered_grid(int n, Rng& rng) {
  std::vector<Vec2> p;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      p.push_back((Vec2{i + 0.5, j + 0.5} + 0.5 * Vec2{uniform01(rng) - 0.5, uniform01(rng) - 0.5}) / n);
  return p;
}

// Every triangle counter-clockwise, neighbours mutual across a shared edge, and no far
// corner inside the circumcircle across an edge.
void check_locally_delaunay(const Triangulation& t, const std::vector<Vec2>& p) {
  for (std::size_t s = 0; s < t.triangles.size(); ++s) {
    const auto& v = t.triangles[s];
    REQUIRE(orient2d(p[v[0]], p[v[1]], p[v[2]]) > 0);
    for (int i = 0; i < 3; ++i) {
      const int u = t.neighbours[s][i];
      if (u < 0) continue;
      const auto& w = t.triangles[u];
      const int back = static_cast<int>(std::find(t.neighbours[u].begin(), t.neighbours[u].end(), static_cast<int>(s)) -
                                        t.neighbours[u].begin());
      REQUIRE(back < 3);
      // The shared edge runs the other way round in u.
      CHECK(w[(back + 1) % 3] == v[(i + 2) % 3]);
      CHECK(w[(back + 2) % 3] == v[(i + 1) % 3]);
      CHECK(incircle(p[v[0]], p[v[1]], p[v[2]], p[w[back]]) <= 0);
    }
  }
}

}  // namespace

TEST_CASE("flips make a triangulation of moved points Delaunay again", "[delaunay]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    Rng rng(seed);
    std::vector<Vec2> p = jittered_grid(45, rng);
    Triangulation t = delaunay_triangulation(p);
    // Moves of up to a twentieth of the spacing: no triangle turns over, many edges flip.
    // (Not the outer rows: the hull's near-collinear points make slivers that would.)
    for (int j = 1; j < 44; ++j)
      for (int i = 1; i < 44; ++i) p[j * 45 + i] += (0.1 / 45) * Vec2{uniform01(rng) - 0.5, uniform01(rng) - 0.5};
    std::size_t flips = 0;
    REQUIRE(restore_delaunay(t, p, &flips));
    CHECK(flips > 0);
    check_locally_delaunay(t, p);
    // The same triangles as a new triangulation (the hull did not move).
    CHECK(canonical(t) == canonical(delaunay_triangulation(p)));
  }
}

TEST_CASE("flips refuse a triangulation whose points turned a triangle over", "[delaunay]") {
  Rng rng(4);
  std::vector<Vec2> p = jittered_grid(20, rng);
  Triangulation t = delaunay_triangulation(p);
  // Reflect one corner of a triangle across its opposite edge.
  const auto v = t.triangles[t.triangles.size() / 2];
  const Vec2 b = p[v[1]], d = p[v[2]] - p[v[1]];
  p[v[0]] = 2.0 * (b + (dot(p[v[0]] - b, d) / norm2(d)) * d) - p[v[0]];
  CHECK_FALSE(restore_delaunay(t, p));
}

TEST_CASE("inserted points give the Delaunay triangulation of all the points", "[delaunay]") {
  // The square's corners first, so that every later point lies inside the hull.
  std::vector<Vec2> p{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const Vec2 q : random_points(1500, 5)) p.push_back(Vec2{0.01, 0.01} + 0.98 * q);
  const std::size_t first = 1000;
  Triangulation t = delaunay_triangulation(std::span<const Vec2>(p).first(first));
  for (std::size_t k = first; k < p.size(); ++k) REQUIRE(insert_point(t, p, static_cast<int>(k), 0));
  check_locally_delaunay(t, p);
  CHECK(canonical(t) == canonical(delaunay_triangulation(p)));
}

TEST_CASE("a point beyond one hull edge gets one triangle on it", "[delaunay]") {
  std::vector<Vec2> p{{0, 0}, {1, 0}, {0.5, 1}, {0.5, -0.1}};
  Triangulation t = delaunay_triangulation(std::span<const Vec2>(p).first(3));
  REQUIRE(insert_point(t, p, 3, 0));
  CHECK(t.triangles.size() == 2);
  check_locally_delaunay(t, p);
  // On an edge: refused, unchanged.
  std::vector<Vec2> q{{0, 0}, {1, 0}, {0.5, 1}, {0.5, 0}};
  Triangulation u = delaunay_triangulation(std::span<const Vec2>(q).first(3));
  CHECK_FALSE(insert_point(u, q, 3, 0));
  CHECK(u.triangles.size() == 1);
}

TEST_CASE("flips keep the constraints of a constrained triangulation", "[delaunay]") {
  // A square ring of 40 fixed points around free points, which then move.
  std::vector<Vec2> p;
  std::vector<std::array<int, 2>> ring;
  for (int k = 0; k < 40; ++k) {
    const double s = (k % 10) / 10.0;
    const Vec2 corner[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, dir[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    p.push_back(corner[k / 10] + s * dir[k / 10]);
    ring.push_back({k, (k + 1) % 40});
  }
  Rng rng(6);
  for (const Vec2 q : jittered_grid(16, rng)) p.push_back(Vec2{0.05, 0.05} + 0.9 * q);
  Triangulation t = constrained_delaunay_triangulation(p, ring);
  for (std::size_t k = 40; k < p.size(); ++k) p[k] += 0.005 * Vec2{uniform01(rng) - 0.5, uniform01(rng) - 0.5};
  REQUIRE(restore_delaunay(t, p));
  check_locally_delaunay(t, p);
  // Every ring segment is still an edge with nothing beyond it.
  std::set<std::array<int, 2>> boundary;
  for (std::size_t s = 0; s < t.triangles.size(); ++s)
    for (int i = 0; i < 3; ++i)
      if (t.neighbours[s][i] < 0) boundary.insert({t.triangles[s][(i + 1) % 3], t.triangles[s][(i + 2) % 3]});
  CHECK(boundary.size() == ring.size());
  for (const auto& e : ring) CHECK(boundary.count(e) == 1);
}

TEST_CASE("a hull whose slivers turned over sheds them when it may shrink", "[delaunay]") {
  Rng rng(7);
  std::vector<Vec2> p = jittered_grid(30, rng);
  // The first column on the square's side, one point of it a hair outside: slivers on
  // the hull (fanned from that point to the column), which turn over as it slides a hair
  // inside, and are peeled one after another.
  int bulge = -1;
  for (std::size_t k = 0; k < p.size(); ++k)
    if (p[k].x < 1.0 / 30) {
      p[k].x = 0.0;
      if (bulge < 0 && p[k].y > 0.5) bulge = static_cast<int>(k);
    }
  p[bulge].x = -1e-9;
  Triangulation t = delaunay_triangulation(p);
  p[bulge].x = 1e-9;
  Triangulation strict = t;
  CHECK_FALSE(restore_delaunay(strict, p));
  const std::size_t before = t.triangles.size();
  REQUIRE(restore_delaunay(t, p, nullptr, true));
  CHECK(t.triangles.size() < before);
  check_locally_delaunay(t, p);
}
