// `tessellation.neper`: a Neper tessellation (written by the test from a known one of ours,
// periodic or not) run through everything downstream as a user would — meshed
// conformingly, exported, solved (2D: checkMesh clean), phases from its cell groups — and
// bad files and keys refused in one line naming them, nothing written.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "../tessellate/neper_writer.hpp"
#include "helpers.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/laguerre_3d.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;

namespace {

std::vector<Phase> two_phases() {
  return {Phase{.name = "WC", .fraction = 0.0, .rest = true, .youngs_modulus = 700e9, .poisson_ratio = 0.2, .alpha = {}},
          Phase{.name = "Co", .fraction = 0.2, .rest = false, .youngs_modulus = 200e9, .poisson_ratio = 0.3, .alpha = {}}};
}

// A config reading `tess`, with `domain` lines and `more` sections.
void write_config(const fs::path& file, const fs::path& tess, const std::string& domain, const std::string& more = "") {
  std::ofstream(file) << "[domain]\n" << domain << "\n[tessellation]\nneper = " << tess.string()
                      << "\nseed = 2\n[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.2\n[phase.Co]\nfraction = 0.2\n"
                         "E = 200e9\nnu = 0.3\n[output]\npictures = none\n[export]\nconvert_to_meters = 1e-6\n" << more;
}

Tessellation plane(double width, int grains, std::uint64_t seed) {
  TessellationOptions o;
  o.width = width;
  o.height = 1.0;
  o.periodic = false;
  o.grains = grains;
  o.lloyd_iterations = 2;
  o.phases = two_phases();
  Rng rng(seed);
  return tessellate(o, rng);
}

Tessellation3 solid(double depth, int grains, std::uint64_t seed) {
  Tessellation3Options o;
  o.depth = depth;
  o.periodic = false;
  o.grains = grains;
  o.phases = two_phases();
  Rng rng(seed);
  return tessellate_3d(o, rng);
}

nlohmann::json report(const fs::path& dir) { return nlohmann::json::parse(test::read_file(dir / "report.json")); }

}  // namespace

TEST_CASE("a 2D Neper tessellation is meshed conformingly, exported and solved like a generated one",
          "[cli][neper]") {
  test::ScratchDir dir("neper-run-2d");
  const Tessellation t = plane(2.0, 24, 7);
  test::write_tess(dir / "cells.tess", t, {5.0, 5.0, 0.0});
  write_config(dir / "run.ini", dir / "cells.tess", "periodic = false", "[mesh]\ntriangles_per_grain = 40\n");
  const auto r = run_grainmesh({"run", (dir / "run.ini").string(), "-o", (dir / "out").string(), "--solve"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto rep = report(dir / "out");
  CHECK(rep["grains"] == 24);
  CHECK(rep["mesh_check"]["failed_checks"] == 0);
  CHECK(rep["solved"] == true);
  // The mesh covers the cell: its area is the domain's, grain by grain as tessellated.
  const auto tess = nlohmann::json::parse(test::read_file(dir / "out" / "tessellation.json"));
  CHECK(tess["domain"]["width"].get<double>() == Approx(2.0).epsilon(1e-15));
  CHECK(tess["grains"].size() == 24);
}

TEST_CASE("a 3D Neper tessellation is meshed conformingly and answered like a generated one", "[cli][neper]") {
  test::ScratchDir dir("neper-run-3d");
  const Tessellation3 t = solid(0.8, 8, 9);
  test::write_tess(dir / "cells.tess", t, {});
  write_config(dir / "run.ini", dir / "cells.tess", "periodic = false\ndepth = 0.8", "[mesh]\ntets_per_grain = 120\n");
  const auto r = run_grainmesh({"run", (dir / "run.ini").string(), "-o", (dir / "out").string()});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto rep = report(dir / "out");
  CHECK(rep["grains"] == 8);
  CHECK(rep["mesh"]["cells"].get<int>() > 8 * 60);
}

TEST_CASE("a periodic 2D Neper tessellation with cell groups is meshed periodically and solved, phases by group",
          "[cli][neper]") {
  test::ScratchDir dir("neper-run-periodic-2d");
  test::WholeCells w = test::plane_whole_cells(test::random_seeds(20, {2.0, 1.0, 0.0}, 3), 2.0, 1.0);
  for (int c = 0; c < 20; ++c) w.groups.push_back(c % 4 == 0 ? 2 : 1);
  test::write_periodic_tess(dir / "cells.tess", w, {1.0, 1.0, 0.0});
  write_config(dir / "run.ini", dir / "cells.tess", "",
               "[mesh]\ntriangles_per_grain = 40\n[tessellation]\nneper_phases = 1: WC, 2: Co\n");
  const auto r = run_grainmesh({"run", (dir / "run.ini").string(), "-o", (dir / "out").string(), "--solve"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find(".fraction") == std::string::npos);  // the groups' fractions are the file's, not targets
  const auto rep = report(dir / "out");
  CHECK(rep["grains"] == 20);
  CHECK(rep["mesh_check"]["failed_checks"] == 0);
  CHECK(rep["solved"] == true);
  const auto tess = nlohmann::json::parse(test::read_file(dir / "out" / "tessellation.json"));
  CHECK(tess["domain"]["periodic"] == true);
  for (int c = 0; c < 20; ++c) CHECK(tess["grains"][c]["phase"] == (c % 4 == 0 ? 1 : 0));
}

TEST_CASE("a periodic 3D Neper tessellation is meshed periodically", "[cli][neper]") {
  test::ScratchDir dir("neper-run-periodic-3d");
  const Vec3 box{1.0, 1.0, 0.8};
  const std::vector<Vec3> seeds = test::random_seeds(8, box, 21);
  const test::WholeCells w{.dim = 3, .box = box, .seeds = seeds,
                           .faces = laguerre_cells(seeds, std::vector<double>(8, 0.0), box, true), .groups = {}};
  test::write_periodic_tess(dir / "cells.tess", w, {});
  write_config(dir / "run.ini", dir / "cells.tess", "depth = 0.8", "[mesh]\ntets_per_grain = 120\n");
  const auto r = run_grainmesh({"run", (dir / "run.ini").string(), "-o", (dir / "out").string()});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto rep = report(dir / "out");
  CHECK(rep["grains"] == 8);
  CHECK(rep["mesh"]["cells"].get<int>() > 8 * 60);
  const auto tess = nlohmann::json::parse(test::read_file(dir / "out" / "tessellation.json"));
  CHECK(tess["domain"]["periodic"] == true);
}

TEST_CASE("bad Neper input is refused in one line naming the file or key, nothing written", "[cli][neper]") {
  test::ScratchDir dir("neper-bad-cli");
  const Tessellation t = plane(1.0, 6, 1);
  test::write_tess(dir / "good.tess", t, {});
  test::write_tess(dir / "old.tess", t, {}, "2.0");
  test::write_tess(dir / "solid.tess", solid(1.0, 4, 1), {});
  std::ofstream(dir / "photo.tess") << "\x89PNG\r\n";
  test::WholeCells whole = test::plane_whole_cells(test::random_seeds(6, {1.0, 1.0, 0.0}, 2), 1.0, 1.0);
  test::write_periodic_tess(dir / "periodic.tess", whole, {});
  whole.groups = {1, 2, 1, 3, 1, 2};
  test::write_periodic_tess(dir / "groups.tess", whole, {});
  const auto config = [&](const std::string& name, const fs::path& tess, const std::string& domain,
                          const std::string& more = "") {
    write_config(dir / name, tess, domain, more);
    return (dir / name).string();
  };
  const std::vector<test::Refusal> cases{
      {{"run", config("old.ini", dir / "old.tess", "periodic = false")}, 2, "old.tess: format 2.0 is not read"},
      {{"run", config("photo.ini", dir / "photo.tess", "periodic = false")}, 2, "photo.tess: not a Neper tessellation"},
      {{"run", config("none.ini", dir / "none.tess", "periodic = false")}, 2, "none.tess"},
      {{"run", config("periodic.ini", dir / "good.tess", "periodic = true")}, 2,
       "domain.periodic: " + (dir / "good.tess").string() + " is not periodic: set domain.periodic = false (or leave it out)"},
      {{"run", config("width.ini", dir / "good.tess", "periodic = false\nwidth = 3")}, 2, "domain.width: must be the domain of"},
      {{"run", config("grains.ini", dir / "good.tess", "periodic = false", "[tessellation]\ngrains = 5\n")}, 2,
       "tessellation.grains: the grains come from tessellation.neper"},
      {{"run", config("solid.ini", dir / "solid.tess", "periodic = false")}, 2, "is a 3D tessellation: set domain.depth (its domain is 1 x 1 x 1)"},
      {{"run", config("aperiodic.ini", dir / "periodic.tess", "periodic = false")}, 2,
       "domain.periodic: " + (dir / "periodic.tess").string() + " is periodic: set domain.periodic = true (or leave it out)"},
      {{"run", config("nogroups.ini", dir / "periodic.tess", "", "[tessellation]\nneper_phases = 1: WC\n")}, 2,
       "tessellation.neper_phases: " + (dir / "periodic.tess").string() + " has no cell groups"},
      {{"run", config("group3.ini", dir / "groups.tess", "", "[tessellation]\nneper_phases = 1: WC, 2: Co\n")}, 2,
       "tessellation.neper_phases: " + (dir / "groups.tess").string() + ": group 3 (1 cell) has no phase in the table"},
      {{"run", config("noneper.ini", dir / "groups.tess", "", "[tessellation]\nneper_phases = 1-3: TiC\n")}, 2,
       "tessellation.neper_phases: no phase is named 'TiC'"},
  };
  for (const auto& c : cases) test::check_refused(c, dir / "out");
}
