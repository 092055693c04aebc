// Neper tessellations (.tess, format 3.4) written by the test from a known tessellation of
// ours, with the domain moved off the origin, read back to the same cells: the same grain
// count, seeds and neighbours, each cell's area or volume within 1e-9, a valid
// tessellation; files that are not what is read refused naming the file.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <string_view>

#include "common/errors.hpp"
#include "helpers.hpp"
#include "neper_writer.hpp"
#include "tessellate/neper_import.hpp"
#include "tessellate/neper_tess.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;

namespace {

std::vector<Phase> two_phases() {
  return {Phase{.name = "WC", .fraction = 0.8, .rest = false, .youngs_modulus = 700e9, .poisson_ratio = 0.2, .alpha = {}},
          Phase{.name = "Co", .fraction = 0.0, .rest = true, .youngs_modulus = 200e9, .poisson_ratio = 0.3, .alpha = {}}};
}

Tessellation plane(int grains) {
  TessellationOptions o;
  o.width = 2.0;
  o.height = 1.0;
  o.periodic = false;
  o.grains = grains;
  o.lloyd_iterations = 2;
  o.phases = two_phases();
  Rng rng(3);
  return tessellate(o, rng);
}

Tessellation3 solid(int grains) {
  Tessellation3Options o;
  o.width = 1.0;
  o.height = 0.8;
  o.depth = 0.6;
  o.periodic = false;
  o.grains = grains;
  o.phases = two_phases();
  Rng rng(5);
  return tessellate_3d(o, rng);
}

}  // namespace

TEST_CASE("A 2D Neper tessellation reads back to the same cells, seeds and neighbours", "[tessellate][neper]") {
  test::ScratchDir dir("neper-2d");
  const Tessellation t = plane(40);
  test::write_tess(dir / "a.tess", t, {10.5, -3.25, 0.0});
  const NeperTess n = read_neper_tess(dir / "a.tess");
  CHECK(n.dimensions == 2);
  CHECK(n.cells() == 40);
  Rng rng(1);
  const Tessellation back = plane_tessellation(n, two_phases(), Arrangement::random, rng, "a.tess");
  CHECK(back.width == Approx(2.0).epsilon(1e-15));
  CHECK(back.height == Approx(1.0).epsilon(1e-15));
  CHECK_FALSE(back.periodic);
  REQUIRE(back.grains.size() == t.grains.size());
  // The grains sharing an edge inside the cell (the generated ones also list neighbours
  // they meet only outside it).
  std::vector<std::set<int>> sharing(t.grains.size());
  for (const TessEdge& e : t.edges)
    if (e.left >= 0 && e.right >= 0) {
      sharing[t.regions[e.left].grain].insert(t.regions[e.right].grain);
      sharing[t.regions[e.right].grain].insert(t.regions[e.left].grain);
    }
  double covered = 0.0;
  for (std::size_t g = 0; g < t.grains.size(); ++g) {
    INFO("grain " << g);
    CHECK(std::abs(back.grains[g].area - t.grains[g].area) < 1e-9 * t.width * t.height);
    CHECK(back.grains[g].neighbours == std::vector<int>(sharing[g].begin(), sharing[g].end()));
    CHECK(std::abs(back.grains[g].seed.x - t.grains[g].seed.x) < 1e-12);
    CHECK(std::abs(back.grains[g].seed.y - t.grains[g].seed.y) < 1e-12);
    covered += back.grains[g].area;
  }
  CHECK(covered == Approx(2.0).epsilon(1e-12));
  // The phases by our rules: the fractions met as for a generated cell.
  CHECK(back.stats.phases[0].achieved_fraction == Approx(0.8).margin(0.05));
  CHECK(back.stats.grains == 40);
}

TEST_CASE("A 3D Neper tessellation reads back to the same cells, volumes and neighbours", "[tessellate][neper]") {
  test::ScratchDir dir("neper-3d");
  const Tessellation3 t = solid(14);
  test::write_tess(dir / "a.tess", t, {-1.0, 2.5, 0.125});
  const NeperTess n = read_neper_tess(dir / "a.tess");
  CHECK(n.dimensions == 3);
  Rng rng(1);
  const Tessellation3 back = solid_tessellation(n, two_phases(), Arrangement::random, rng, "a.tess");
  CHECK(back.size().x == Approx(1.0).epsilon(1e-15));
  CHECK(back.size().z == Approx(0.6).epsilon(1e-15));
  REQUIRE(back.grains.size() == t.grains.size());
  double total = 0.0;
  for (std::size_t g = 0; g < t.grains.size(); ++g) {
    INFO("grain " << g);
    CHECK(std::abs(back.grains[g].volume - t.grains[g].volume) < 1e-9 * 0.48);
    CHECK(back.grains[g].neighbours == t.grains[g].neighbours);
    total += back.grains[g].volume;
  }
  CHECK(total == Approx(0.48).epsilon(1e-12));
  CHECK(back.stats.grains == 14);
}

TEST_CASE("Neper files that are not what is read are refused naming the file", "[tessellate][neper]") {
  test::ScratchDir dir("neper-bad");
  const Tessellation t = plane(6);
  auto refused = [&](const std::string& name, const std::string& says) {
    INFO(name);
    try {
      const NeperTess n = read_neper_tess(dir / name);
      Rng rng(1);
      plane_tessellation(n, two_phases(), Arrangement::random, rng, (dir / name).string());
      FAIL("read " << name);
    } catch (const GeometryError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find((dir / name).string()) != std::string::npos);
      CHECK(what.find(says) != std::string::npos);
    }
  };
  test::write_tess(dir / "old.tess", t, {}, "2.0");
  refused("old.tess", "format 2.0 is not read");
  test::write_tess(dir / "circle.tess", t, {}, "3.4", "circle");
  refused("circle.tess", "a circle domain");
  test::write_tess(dir / "periodic.tess", t, {}, "3.4", "square", " **periodicity\n  *general\n   1 1 0\n");
  refused("periodic.tess", "periodic");
  std::ofstream(dir / "text.tess") << "a picture, not a tessellation\n";
  refused("text.tess", "not a Neper tessellation");
  const std::string whole = test::read_file(dir / "old.tess");
  const std::size_t general = whole.find(" **general"), face = whole.find(" **face");
  REQUIRE(face > general);
  std::ofstream(dir / "cut.tess") << "***tess\n **format\n   3.4\n" << std::string_view(whole).substr(general, face - general);
  refused("cut.tess", "ends before ***end");
  CHECK_THROWS_AS(read_neper_tess(dir / "missing.tess"), IoError);
}
