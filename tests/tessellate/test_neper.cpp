// Neper tessellations (.tess, format 3.4) written by the test from a known tessellation of
// ours, with the domain moved off the origin, read back to the same cells: the same grain
// count, seeds and neighbours, each cell's area or volume within 1e-9, a valid
// tessellation. Periodic ones (whole cells of a power diagram on the torus) come back cut
// into pieces that match across the box's sides, each cell's pieces adding up to it.
// Phases from the cells' groups through a table. Files that are not what is read are
// refused naming the file.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <string_view>

#include "common/errors.hpp"
#include "helpers.hpp"
#include "neper_writer.hpp"
#include "tessellate/laguerre_3d.hpp"
#include "tessellate/neper_import.hpp"
#include "tessellate/neper_tess.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/tessellate_3d.hpp"
#include "tessellate/torus.hpp"

using namespace grainmesh;

namespace {

std::vector<Phase> two_phases() {
  return {
      Phase{.name = "WC", .fraction = 0.8, .rest = false, .youngs_modulus = 700e9, .poisson_ratio = 0.2, .alpha = {}},
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

NeperPhases by_rules() { return {.phases = two_phases(), .arrangement = Arrangement::random, .group_phases = {}}; }

// Whether two whole cells share a side (2D: an edge, 3D: a face's corner set) once one is
// moved by whole periods: the neighbours, found from positions.
bool share_a_side(const std::vector<std::vector<Vec3>>& a, const std::vector<std::vector<Vec3>>& b, Vec3 box, int dim) {
  auto sides = [&](const std::vector<std::vector<Vec3>>& faces) {
    std::vector<std::vector<Vec3>> out;
    if (dim == 3) return faces;
    const auto& ring = faces[0];
    for (std::size_t k = 0; k < ring.size(); ++k) out.push_back({ring[k], ring[(k + 1) % ring.size()]});
    return out;
  };
  for (const auto& p : sides(a))
    for (const auto& q : sides(b)) {
      if (p.size() != q.size()) continue;
      Vec3 shift;
      for (int d = 0; d < dim; ++d) shift[d] = std::round((q[0][d] - p[0][d]) / box[d]) * box[d];
      // q's corners are p's moved by the shift, in some order.
      bool all = true;
      for (const Vec3& x : p) {
        bool found = false;
        for (const Vec3& y : q) found = found || norm(x + shift - y) < 1e-9;
        all = all && found;
      }
      if (all) return true;
    }
  return false;
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
  const Tessellation back = plane_tessellation(n, by_rules(), rng, "a.tess");
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
  const Tessellation3 back = solid_tessellation(n, by_rules(), rng, "a.tess");
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
      plane_tessellation(n, by_rules(), rng, (dir / name).string());
      FAIL("read " << name);
    } catch (const GeometryError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find((dir / name).string()) != std::string::npos);
      CHECK(what.find(says) != std::string::npos);
    }
  };
  test::write_tess(dir / "old.tess", t, {}, "2.0");
  refused("old.tess", "format 2.0 is not read (grainmesh reads the formats Neper 4 writes, 3.4 or 3.5)");
  test::write_tess(dir / "circle.tess", t, {}, "3.4", "circle");
  refused("circle.tess", "a circle domain");
  // Neper 4 writes a 2D square domain as a cube; "square" is read too. A rotated square
  // is not a box of ours.
  Rng rng(1);
  test::write_tess(dir / "square.tess", t, {}, "3.4", "square");
  CHECK(plane_tessellation(read_neper_tess(dir / "square.tess"), by_rules(), rng, "square.tess").grains.size() == 6);
  {
    std::string text = test::read_file(dir / "square.tess");
    const std::size_t at = text.find(" x1y0");
    REQUIRE(at != std::string::npos);
    const std::size_t y = text.rfind(' ', text.rfind(' ', at - 1) - 1) + 1;  // the corner's y
    text.replace(y, text.rfind(' ', at - 1) - y, "0.100000000000");
    std::ofstream(dir / "rotated.tess") << text;
  }
  refused("rotated.tess", "the domain is not a square with sides along the axes");
  test::write_tess(dir / "periodic.tess", t, {}, "3.4", "cube", " **periodicity\n  *general\n   1 1 0\n   1 1 0\n");
  refused("periodic.tess", "has a **periodicity but is of type standard");
  test::WholeCells half = test::plane_whole_cells(test::random_seeds(6, {1.0, 1.0, 0.0}, 4), 1.0, 1.0);
  test::write_periodic_tess(dir / "x-only.tess", half, {});
  {
    std::string text = test::read_file(dir / "x-only.tess");
    const std::size_t at = text.find("*general\n   1 1 0");
    REQUIRE(at != std::string::npos);
    text.replace(at, 18, "*general\n   1 0 0");
    std::ofstream(dir / "x-only.tess") << text;
  }
  refused("x-only.tess", "periodic along some axes only (not y)");
  test::write_periodic_tess(dir / "moved.tess", half, {});
  {
    // A secondary vertex moved off its primary's image.
    std::string text = test::read_file(dir / "moved.tess");
    const std::size_t images = text.find("  *vertex\n", text.find("**periodicity"));
    const std::size_t line = text.find('\n', text.find('\n', images + 11) + 1);  // the first image's line
    const std::string first = text.substr(text.find('\n', images + 11) + 1, line - text.find('\n', images + 11) - 1);
    const int secondary = std::stoi(first);
    const std::string tag = "\n   " + std::to_string(secondary) + " ";
    const std::size_t entry = text.find(tag, text.find("**vertex"));
    REQUIRE(entry != std::string::npos);
    const std::size_t x = text.find_first_not_of(' ', entry + tag.size()), end = text.find(' ', x);
    text.replace(x, end - x, test::num(std::stod(text.substr(x, end - x)) + 1e-6));  // its x moved by 1e-6
    std::ofstream(dir / "moved.tess") << text;
  }
  refused("moved.tess", "is not its primary, vertex");
  std::ofstream(dir / "text.tess") << "a picture, not a tessellation\n";
  refused("text.tess", "not a Neper tessellation");
  const std::string whole = test::read_file(dir / "old.tess");
  const std::size_t general = whole.find(" **general"), face = whole.find(" **face");
  REQUIRE(face > general);
  std::ofstream(dir / "cut.tess") << "***tess\n **format\n   3.4\n"
                                  << std::string_view(whole).substr(general, face - general);
  refused("cut.tess", "ends before ***end");
  CHECK_THROWS_AS(read_neper_tess(dir / "missing.tess"), IoError);
}

TEST_CASE("A periodic 2D Neper tessellation's whole cells come back cut into matching pieces", "[tessellate][neper]") {
  test::ScratchDir dir("neper-periodic-2d");
  const double W = 2.0, H = 1.0;
  const test::WholeCells w = test::plane_whole_cells(test::random_seeds(30, {W, H, 0.0}, 11), W, H);
  test::write_periodic_tess(dir / "p.tess", w, {10.5, -3.25, 0.0});
  const NeperTess n = read_neper_tess(dir / "p.tess");
  CHECK(n.periodic);
  CHECK_FALSE(n.vertex_images.empty());
  Rng rng(1);
  const Tessellation back = plane_tessellation(n, by_rules(), rng, "p.tess");
  CHECK(back.periodic);
  CHECK(back.width == Approx(W).epsilon(1e-15));
  REQUIRE(back.grains.size() == 30);
  int cut = 0;  // cells the box's sides cut into more than one piece
  std::vector<int> pieces(30, 0);
  for (const Region& r : back.regions) ++pieces[r.grain];
  for (int g = 0; g < 30; ++g) {
    INFO("grain " << g);
    std::vector<Vec2> ring;
    for (const Vec3& p : w.faces[g][0]) ring.push_back({p.x, p.y});
    CHECK(std::abs(back.grains[g].area - polygon_area(ring)) < 1e-9 * W * H);
    CHECK(std::abs(back.grains[g].seed.x - w.seeds[g].x) < 1e-11);
    std::vector<int> expected;
    for (int h = 0; h < 30; ++h)
      if (h != g && share_a_side(w.faces[g], w.faces[h], w.box, 2)) expected.push_back(h);
    CHECK(back.grains[g].neighbours == expected);
    cut += pieces[g] > 1;
  }
  CHECK(cut >= 4);  // the sides do cut cells
  // Every vertex on a side has its partner on the opposite side (validate() holds it), and
  // the pieces fill the cell.
  CHECK(back.partners.axis[0].size() >= 2);
  CHECK(back.partners.axis[1].size() >= 2);
  double covered = 0.0;
  for (const Grain& g : back.grains) covered += g.area;
  CHECK(covered == Approx(W * H).epsilon(1e-12));
}

TEST_CASE("A periodic 3D Neper tessellation's whole cells come back cut into matching pieces", "[tessellate][neper]") {
  test::ScratchDir dir("neper-periodic-3d");
  const Vec3 box{1.0, 0.8, 0.6};
  const std::vector<Vec3> seeds = test::random_seeds(16, box, 12);
  const std::vector<double> weights(seeds.size(), 0.0);
  test::WholeCells w{
      .dim = 3, .box = box, .seeds = seeds, .faces = laguerre_cells(seeds, weights, box, true), .groups = {}};
  test::write_periodic_tess(dir / "p.tess", w, {-1.0, 2.5, 0.125});
  const NeperTess n = read_neper_tess(dir / "p.tess");
  CHECK(n.periodic);
  Rng rng(1);
  const Tessellation3 back = solid_tessellation(n, by_rules(), rng, "p.tess");
  CHECK(back.periodic);
  REQUIRE(back.grains.size() == 16);
  // The reference: the same diagram's cells from CGAL in floating point, their neighbours
  // from the exact diagram.
  const CellMoments m = laguerre_moments(seeds, weights, box, true);
  const LaguerreCut exact = laguerre_box_cut(seeds, weights, box, true);
  const double V = box.x * box.y * box.z;
  double total = 0.0;
  for (int g = 0; g < 16; ++g) {
    INFO("grain " << g);
    CHECK(std::abs(back.grains[g].volume - m.volume[g]) < 1e-9 * V);
    CHECK(back.grains[g].neighbours == exact.neighbours[g]);
    CHECK(norm(back.grains[g].seed - seeds[g]) < 1e-11);
    total += back.grains[g].volume;
  }
  CHECK(total == Approx(V).epsilon(1e-12));
  CHECK(back.regions.size() > 16);  // cells cut by the sides come in pieces
  for (int a = 0; a < 3; ++a) CHECK(back.partners.axis[a].size() >= 3);
}

TEST_CASE("A Neper file's cell groups give the phases through a table", "[tessellate][neper]") {
  test::ScratchDir dir("neper-groups");
  test::WholeCells w = test::plane_whole_cells(test::random_seeds(12, {1.0, 1.0, 0.0}, 5), 1.0, 1.0);
  for (int c = 0; c < 12; ++c) w.groups.push_back(c % 3 == 0 ? 2 : 1);
  test::write_periodic_tess(dir / "g.tess", w, {});
  const NeperTess n = read_neper_tess(dir / "g.tess");
  REQUIRE(n.groups.size() == 12);
  // 1: WC, 2: Co.
  NeperPhases table = by_rules();
  table.group_phases = {LabelPhase{.lo = 1, .hi = 1, .phase = 0}, LabelPhase{.lo = 2, .hi = 2, .phase = 1}};
  Rng rng(1);
  const Tessellation t = plane_tessellation(n, table, rng, "g.tess");
  for (int c = 0; c < 12; ++c) CHECK(t.grains[c].phase == (c % 3 == 0 ? 1 : 0));
  for (const Region& r : t.regions) CHECK(r.phase == t.grains[r.grain].phase);
  // A group the table misses, and a file without groups, are refused naming the file.
  table.group_phases.pop_back();
  try {
    plane_tessellation(n, table, rng, "g.tess");
    FAIL("group 2 had no phase");
  } catch (const UnnamedLabelError& e) {
    CHECK(std::string(e.what()) == "g.tess: group 2 (4 cells) has no phase in the table");
  }
  w.groups.clear();
  test::write_periodic_tess(dir / "none.tess", w, {});
  CHECK_THROWS_WITH(plane_tessellation(read_neper_tess(dir / "none.tess"), table, rng, "none.tess"),
                    "none.tess: has no cell groups (*group) to take the phases from");
}
