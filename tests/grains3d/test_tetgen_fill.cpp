// TetGen under a time budget: a surface on which TetGen 1.5 never finishes (a region of a
// user's 3D sweep, tests/grains3d/data/tetgen-hang-r123.smesh: `tetgen -pYzQ` runs for
// ever on it) is filled by the next point insertion order within its budget; stand-in
// tetgen programs on PATH that hang show a run completing past one hung try, and a run
// whose every try hangs failing in one line that names the region and the kept input.
#include <catch2/catch.hpp>

#include <chrono>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "grains3d/tetgen_fill.hpp"
#include "helpers.hpp"
#include "mesh/tetmesh.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A TetGen .smesh's points and triangles (the format tetgen_fill writes).
void read_smesh(const fs::path& file, std::vector<Vec3>& points, std::vector<std::array<int, 3>>& triangles) {
  std::istringstream in(test::read_file(file));
  std::size_t n = 0;
  int dim = 0, attributes = 0, markers = 0;
  in >> n >> dim >> attributes >> markers;
  for (std::size_t k = 0; k < n; ++k) {
    int id = 0;
    Vec3 p;
    in >> id >> p.x >> p.y >> p.z;
    points.push_back(p);
  }
  std::size_t m = 0;
  in >> m >> markers;
  for (std::size_t k = 0; k < m; ++k) {
    int corners = 0;
    std::array<int, 3> t{};
    in >> corners >> t[0] >> t[1] >> t[2];
    triangles.push_back(t);
  }
}

// A stand-in `tetgen` in DIR/bin: for region r0's input it runs `on_r0` (a shell line),
// for every other input the real TetGen.
fs::path stand_in_tetgen(const fs::path& dir, const std::string& on_r0) {
  const fs::path bin = dir / "bin";
  fs::create_directories(bin);
  std::ofstream(bin / "tetgen") << "#!/bin/sh\ncase \"$2\" in r0.smesh) " << on_r0
                                << " ;; esac\nexec /usr/bin/tetgen \"$@\"\n";
  fs::permissions(bin / "tetgen", fs::perms::owner_all);
  return bin;
}

// grainmesh run on small_cell with the stand-in tetgen of DIR/bin first on PATH and
// DIR/tmp as the temporary directory; limits.seconds = 60 the run's bound, should the
// budget not work.
test::CommandResult run_with_stand_in(const fs::path& dir, const fs::path& bin);

// A small 3D cell to mesh; no warnings of its own.
fs::path small_cell(const fs::path& dir) {
  const fs::path ini = dir / "cell.ini";
  std::ofstream(ini) << "[domain]\nwidth = 1\nheight = 1\ndepth = 1\nperiodic = true\n"
                        "[tessellation]\ngrains = 8\nseed = 3\nlloyd_iterations = 3\n"
                        "[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.2\n[mesh]\ntets_per_grain = 100\n";
  return ini;
}

test::CommandResult run_with_stand_in(const fs::path& dir, const fs::path& bin) {
  fs::create_directories(dir / "tmp");
  return test::run_grainmesh({"run", small_cell(dir).string(), "-o", (dir / "out").string(), "--quiet", "--set",
                              "limits.seconds=60"},
                             {},
                             "TMPDIR=" + test::shell_quote((dir / "tmp").string()) + " PATH=" +
                                 test::shell_quote(bin.string()) + ":$PATH");
}

}  // namespace

TEST_CASE("TetGen: a surface that hangs its default order is filled by the next, within the budget", "[mesh3d][tetgen]") {
  test::ScratchDir dir("tetgen-hang");
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  read_smesh(test::source_dir() / "tests/grains3d/data/tetgen-hang-r123.smesh", points, triangles);
  REQUIRE(points.size() == 46);
  double volume = 0.0;
  for (const auto& t : triangles) volume += dot(points[t[0]], cross(points[t[1]], points[t[2]])) / 6.0;
  REQUIRE(volume > 0.0);
  const TetgenOptions o{.max_volume = volume / 200};
  const double budget = tetgen_budget(o, volume);
  CHECK(budget < 3.0);  // two seconds and a little per tetrahedron
  const auto t0 = Clock::now();
  const TetgenFill fill = tetgen_fill(points, triangles, o, dir.path(), "r123", "region 123");
  const double took = seconds_since(t0);
  CHECK(fill.tries == 2);  // the default order stopped at its budget, then b/1
  CHECK(fill.switches.find("b/1") != std::string::npos);
  CHECK(took >= budget);
  CHECK(took < budget + 10.0);
  double filled = 0.0;
  for (const auto& t : fill.tets) {
    const double v = tet_volume(fill.points[t[0]], fill.points[t[1]], fill.points[t[2]], fill.points[t[3]]);
    CHECK(v > 0.0);
    filled += v;
  }
  CHECK(filled == Approx(volume).epsilon(1e-9));
  CHECK(test::entries(dir.path()) == 0);  // TetGen's files removed
}

TEST_CASE("TetGen hanging on one region: the run completes past the hung try", "[mesh3d][tetgen][cli]") {
  test::ScratchDir dir("tetgen-stand-in");
  const fs::path bin = stand_in_tetgen(dir.path(), "case \"$1\" in *b/*) ;; *) exec sleep 1000 ;; esac");
  const auto t0 = Clock::now();
  const auto r = run_with_stand_in(dir.path(), bin);
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(seconds_since(t0) < 30.0);
  CHECK(fs::exists(dir / "out/mesh.vtu"));
  CHECK(test::entries(dir / "tmp") == 0);  // TetGen's scratch gone
}

TEST_CASE("TetGen hanging on every try of a region: the run fails in one line naming it and its kept input",
          "[mesh3d][tetgen][cli]") {
  test::ScratchDir dir("tetgen-always-hangs");
  const fs::path bin = stand_in_tetgen(dir.path(), "exec sleep 1000");
  const auto t0 = Clock::now();
  const auto r = run_with_stand_in(dir.path(), bin);
  const double took = seconds_since(t0);
  INFO(r.err);
  CHECK(r.exit_code == 3);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find("TetGen could not fill region 0 (grain ") != std::string::npos);
  CHECK(r.err.find("did not finish in") != std::string::npos);
  CHECK(r.err.find("b/0.5") != std::string::npos);  // every order named
  CHECK(r.err.find("limits.seconds") == std::string::npos);  // not the run's limit, nor its advice
  // Three tries of about two seconds each, not the 6 h of limits.seconds.
  CHECK(took < 3 * 3.0 + 15.0);
  CHECK_FALSE(fs::exists(dir / "out"));
  // The input kept where the message says, and nothing else left in the temporary directory.
  const auto kept_at = r.err.find("kept as ");
  REQUIRE(kept_at != std::string::npos);
  const fs::path kept = r.err.substr(kept_at + 8, r.err.find(' ', kept_at + 8) - kept_at - 8);
  CHECK(kept.parent_path() == dir / "tmp");
  CHECK(test::read_file(kept).find(" 3 0 0\n") != std::string::npos);
  CHECK(test::entries(dir / "tmp") == 1);
}
