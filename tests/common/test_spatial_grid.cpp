#include <catch2/catch.hpp>

#include <map>
#include <random>

#include "common/spatial_grid.hpp"

using namespace grainmesh;

TEST_CASE("grid rings visit every cell once, nearest ring first", "[common][grid]") {
  const GridFrame g{.lo = {-1.0, 2.0}, .cell = 0.5, .nx = 7, .ny = 4};
  for (const auto& centre : {std::pair{0, 0}, std::pair{3, 2}, std::pair{6, 3}, std::pair{-2, 9}}) {
    const int cx = centre.first, cy = centre.second;
    std::map<std::pair<int, int>, int> seen;
    for (int r = 0; r <= 12; ++r)
      g.for_ring(cx, cy, r, [&](int x, int y) {
        REQUIRE(g.contains(x, y));
        CHECK(std::max(std::abs(x - cx), std::abs(y - cy)) == r);  // on ring r
        ++seen[{x, y}];
      });
    CHECK(seen.size() == g.cells());
    for (const auto& [cell, times] : seen) CHECK(times == 1);
  }
  // Columns and rows: floor, and clamped to the grid.
  CHECK(g.column(-1.0) == 0);
  CHECK(g.column(-1.0001) == -1);
  CHECK(g.row(4.0) == 4);
  CHECK(g.clamped_row(4.0) == 3);
  CHECK(g.clamped_column(-1e300) == 0);
  CHECK(g.clamped_column(1e300) == 6);
  CHECK(g.index(2, 3) == 23u);
}

TEST_CASE("cell lists hold each item in the cells it names, in ascending order", "[common][grid]") {
  // Item k covers cells k .. k + 2 (mod 5); item 3 none.
  const CellLists lists(5, 6, [](std::size_t k, auto&& emit) {
    if (k == 3) return;
    for (std::size_t c = k; c < k + 3; ++c) emit(c % 5);
  });
  for (std::size_t c = 0; c < 5; ++c) {
    std::vector<int> want;
    for (int k = 0; k < 6; ++k)
      if (k != 3 && (c + 5 - k % 5) % 5 < 3) want.push_back(k);
    CHECK(std::vector<int>(lists[c].begin(), lists[c].end()) == want);
  }
}

TEST_CASE("a hash grid keeps far cells apart and values in their order", "[common][grid]") {
  HashGrid<int> g(1e-9);
  CHECK(g.cell_of(-0.5e-9) == -1);
  CHECK(g.at(0, 0) == nullptr);
  // Cells 2^32 apart (tiny cells far out) must not share a bucket's values.
  const std::int64_t far = std::int64_t{1} << 32;
  g.add(5, 7, 1);
  g.add(5 + far, 7, 2);
  g.add(5, 7, 3);
  REQUIRE(g.at(5, 7) != nullptr);
  CHECK(*g.at(5, 7) == std::vector<int>{1, 3});
  CHECK(*g.at(5 + far, 7) == std::vector<int>{2});
  CHECK(g.at(7, 5) == nullptr);
}
