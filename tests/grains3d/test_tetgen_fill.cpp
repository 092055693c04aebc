// TetGen under a time budget: a surface on which TetGen 1.5 never finishes (a region of a
// user's 3D sweep, tests/grains3d/data/tetgen-hang-r123.smesh: `tetgen -pYzQ` runs for
// ever on it) is filled by the next point insertion order within its budget, its hung
// helper stopped; fills from several threads are the same as alone; a surface whose every
// try hangs fails naming the region, each try and the kept input.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

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

// The hang surface of tests/grains3d/data, its volume and options asking ~200 tetrahedra.
struct HangSurface {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  double volume = 0.0;
  HangSurface() {
    read_smesh(test::source_dir() / "tests/grains3d/data/tetgen-hang-r123.smesh", points, triangles);
    for (const auto& t : triangles) volume += dot(points[t[0]], cross(points[t[1]], points[t[2]])) / 6.0;
  }
};

double filled_volume(const TetgenFill& fill) {
  double filled = 0.0;
  for (const auto& t : fill.tets) {
    const double v = tet_volume(fill.points[t[0]], fill.points[t[1]], fill.points[t[2]], fill.points[t[3]]);
    CHECK(v > 0.0);
    filled += v;
  }
  return filled;
}

// Processes whose parent is this one (TetGen's helpers).
int children_of_this_process() {
  int n = 0;
  for (const auto& e : fs::directory_iterator("/proc")) {
    std::ifstream stat(e.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    const auto close = line.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 2));
    char state = 0;
    int ppid = 0;
    rest >> state >> ppid;
    n += ppid == getpid() && state != 'Z';
  }
  return n;
}

}  // namespace

TEST_CASE("TetGen: a surface that hangs its default order is filled by the next, within the budget",
          "[mesh3d][tetgen]") {
  const HangSurface surface;
  REQUIRE(surface.points.size() == 46);
  REQUIRE(surface.volume > 0.0);
  const TetgenOptions o{.max_volume = surface.volume / 200};
  const double budget = tetgen_budget(o, surface.volume);
  CHECK(budget < 3.0);  // two seconds and a little per tetrahedron
  const TetgenRunner tetgen;
  const auto t0 = Clock::now();
  const TetgenFill fill = tetgen.fill(surface.points, surface.triangles, o, "region 123");
  const double took = seconds_since(t0);
  CHECK(fill.tries == 2);  // the default order stopped at its budget, then b/1
  CHECK(fill.switches.find("b/1") != std::string::npos);
  CHECK(took >= budget);
  CHECK(took < budget + 10.0);
  CHECK(filled_volume(fill) == Approx(surface.volume).epsilon(1e-9));
  // The surface's points first, in their order.
  REQUIRE(fill.points.size() >= surface.points.size());
  CHECK(std::equal(surface.points.begin(), surface.points.end(), fill.points.begin()));
  // The hung try's helper was stopped, the one that worked has ended; the next surface is
  // filled at once.
  CHECK(children_of_this_process() == 0);
  const auto t1 = Clock::now();
  const TetgenFill again =
      tetgen.fill(surface.points, surface.triangles, {.max_volume = surface.volume / 50, .orders = {"b/1"}}, "r");
  CHECK(seconds_since(t1) < 1.0);
  CHECK(again.tries == 1);
  CHECK(filled_volume(again) == Approx(surface.volume).epsilon(1e-9));
  CHECK(again.tets.size() < fill.tets.size());  // a coarser bound, fewer tetrahedra
}

TEST_CASE("TetGen from several threads at once: each fill the same as alone, whatever was filled before",
          "[mesh3d][tetgen]") {
  const HangSurface surface;
  const TetgenOptions o{.max_volume = surface.volume / 100, .orders = {"b/1"}};
  const TetgenRunner tetgen;
  const TetgenFill alone = tetgen.fill(surface.points, surface.triangles, o, "r");
  std::vector<TetgenFill> fills(8);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k)
    threads.emplace_back([&, k] {
      for (int j = k; j < 8; j += 4) {
        // Another fill first in some threads, so that their histories differ.
        if (j % 3 == 0)
          tetgen.fill(surface.points, surface.triangles, {.max_volume = surface.volume / 20, .orders = {"b/1"}}, "r");
        fills[static_cast<std::size_t>(j)] = tetgen.fill(surface.points, surface.triangles, o, "r");
      }
    });
  for (auto& t : threads) t.join();
  CHECK(children_of_this_process() == 0);  // every helper gone
  for (const TetgenFill& f : fills) {
    CHECK(f.tets == alone.tets);
    CHECK(f.points == alone.points);
  }
}

TEST_CASE("TetGen hanging on every try of a region: one error naming it, every try and its kept input",
          "[mesh3d][tetgen]") {
  test::ScratchDir dir("tetgen-always-hangs");
  const HangSurface surface;
  // The default order twice: both hang.
  const TetgenOptions o{.max_volume = surface.volume / 200, .orders = {"", ""}};
  const double budget = tetgen_budget(o, surface.volume);
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string saved = tmpdir ? tmpdir : "";
  setenv("TMPDIR", dir.path().c_str(), 1);
  std::string message;
  const auto t0 = Clock::now();
  {
    const TetgenRunner tetgen;
    try {
      tetgen.fill(surface.points, surface.triangles, o, "region 123 (grain 45)");
    } catch (const GeometryError& e) {
      message = e.what();
    }
  }
  const double took = seconds_since(t0);
  tmpdir ? setenv("TMPDIR", saved.c_str(), 1) : unsetenv("TMPDIR");
  INFO(message);
  CHECK(message.find("TetGen could not fill region 123 (grain 45): ") == 0);
  CHECK(message.find("did not finish in") != std::string::npos);
  CHECK(message.find(", -pYzQ") != std::string::npos);  // both tries named
  CHECK(took >= 2 * budget);
  CHECK(took < 2 * budget + 10.0);
  CHECK(children_of_this_process() == 0);  // every try's helper stopped
  const auto kept_at = message.find("kept as ");
  REQUIRE(kept_at != std::string::npos);
  const fs::path kept = message.substr(kept_at + 8, message.find(' ', kept_at + 8) - kept_at - 8);
  CHECK(kept.parent_path() == dir.path());
  CHECK(test::read_file(kept).find("46 3 0 0\n") == 0);
  CHECK(test::entries(dir.path()) == 1);
}
