// Property test: every tessellation the tessellate stage accepts meshes, degenerate ones
// included. Seeds in a row (a laminate of slabs, the simplest 3D check there is), on a
// lattice (cubes: eight cells meet at every vertex), on a plane, on the box's sides and
// edge lines, two seeds, with Lloyd steps (which move a lattice by rounding: vertices a
// rounding apart) and without, periodic and bounded, in thin boxes: `grainmesh run` writes
// the whole output, pictures included, and in 3D, where the seeds are evenly spaced, every
// grain has the same volume — a laminate stays a laminate. (A 2D cell's window pushes
// junctions near its sides away from them, which moves a few per cent of a strip's area.)
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "helpers.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

struct SeedSet {
  std::string name;
  std::vector<double> box;       // W H (D)
  std::vector<std::vector<double>> seeds;
  bool periodic = true;
  int lloyd = 0;
  bool equal = true;             // evenly spaced: every grain the same size
};

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

// n seeds evenly along `axis` at the other coordinates `at` (fractions of the box).
std::vector<std::vector<double>> row(const std::vector<double>& box, int n, int axis, std::vector<double> at) {
  std::vector<std::vector<double>> seeds;
  for (int i = 0; i < n; ++i) {
    std::vector<double> s;
    for (std::size_t a = 0, k = 0; a < box.size(); ++a)
      s.push_back(box[a] * (static_cast<int>(a) == axis ? (i + 0.5) / n : at[k++]));
    seeds.push_back(s);
  }
  return seeds;
}

// An n x n (x n) lattice, each seed `offset` of its lattice cell in.
std::vector<std::vector<double>> lattice(const std::vector<double>& box, int n, double offset) {
  std::vector<std::vector<double>> seeds;
  const int d = static_cast<int>(box.size());
  const int count = d == 2 ? n * n : n * n * n;
  for (int k = 0; k < count; ++k) {
    std::vector<double> s;
    for (int a = 0, rest = k; a < d; ++a, rest /= n) s.push_back(box[a] * ((rest % n) + offset) / n);
    seeds.push_back(s);
  }
  return seeds;
}

std::vector<SeedSet> seed_sets() {
  const std::vector<double> cube{1, 1, 1}, thin{1, 0.3, 0.3}, tall{0.5, 0.5, 2}, square{1, 1}, strip{1, 0.3};
  std::vector<SeedSet> sets{
      {"3D: ten seeds in a row along x (slabs)", cube, row(cube, 10, 0, {0.5, 0.5})},
      {"3D: ten in a row in a thin box", thin, row(thin, 10, 0, {0.5, 0.5})},
      {"3D: a row off the middle", cube, row(cube, 7, 0, {0.3, 0.7})},
      {"3D: a row along y", cube, row(cube, 6, 1, {0.5, 0.5})},
      {"3D: a row along z in a tall box", tall, row(tall, 8, 2, {0.3, 0.6})},
      {"3D: a row on the box's edge line", cube, row(cube, 10, 0, {0.0, 0.0})},
      {"3D: a 3 x 3 x 3 lattice", cube, lattice(cube, 3, 0.5)},
      {"3D: a 2 x 2 x 2 lattice off centre", cube, lattice(cube, 2, 0.25)},
      {"3D: a lattice on the box's sides and corners", cube, lattice(cube, 3, 0.0)},
      {"3D: two seeds", cube, {{0.25, 0.5, 0.5}, {0.75, 0.5, 0.5}}},
      {"2D: ten seeds in a row (strips)", square, row(square, 10, 0, {0.5})},
      {"2D: a row in a thin strip", strip, row(strip, 10, 0, {0.5})},
      {"2D: a column off the middle", square, row(square, 7, 1, {0.3})},
      {"2D: a 3 x 3 lattice", square, lattice(square, 3, 0.5)},
      {"2D: a lattice on the sides and corners", square, lattice(square, 4, 0.0)},
  };
  // Lloyd steps (a lattice moved by rounding), and bounded boxes where the seeds lie inside.
  const std::size_t plain = sets.size();
  for (std::size_t k = 0; k < plain; ++k) {
    const SeedSet s = sets[k];  // a copy: the pushes below move the vector
    bool inside = true;
    for (const auto& p : s.seeds)
      for (std::size_t a = 0; a < p.size(); ++a) inside = inside && p[a] > 0.0 && p[a] < s.box[a];
    // Bounded, the cells are equal only where the seeds sit symmetric in the box.
    const bool centred = s.name.find("off centre") == std::string::npos;
    if (inside) {
      SeedSet bounded = s;
      bounded.name += ", bounded";
      bounded.periodic = false;
      bounded.equal = centred;
      sets.push_back(bounded);
    }
    if (s.name.find("lattice") != std::string::npos || s.name.find("row along x") != std::string::npos) {
      SeedSet relaxed = s;
      relaxed.name += ", 3 Lloyd steps";
      relaxed.lloyd = 3;
      sets.push_back(relaxed);
      if (inside) {
        relaxed.name += ", bounded";
        relaxed.periodic = false;
        relaxed.equal = centred;
        sets.push_back(relaxed);
      }
    }
  }
  return sets;
}

std::string config(const SeedSet& s) {
  const bool three = s.box.size() == 3;
  std::string ini = "[domain]\nwidth = " + number(s.box[0]) + "\nheight = " + number(s.box[1]) + "\n" +
                    (three ? "depth = " + number(s.box[2]) + "\n" : std::string()) +
                    "periodic = " + (s.periodic ? "true" : "false") + "\n[tessellation]\nseeds = ";
  for (std::size_t k = 0; k < s.seeds.size(); ++k) {
    ini += k ? ", " : "";
    for (std::size_t a = 0; a < s.seeds[k].size(); ++a) {
      if (a > 0) ini += ' ';
      ini += number(s.seeds[k][a]);
    }
  }
  ini += "\nlloyd_iterations = " + std::to_string(s.lloyd) + "\n";
  // Two phases where there are grains enough for both.
  ini += "[phase.hard]\nfraction = rest\nE = 700e9\nnu = 0.2\n";
  if (s.seeds.size() >= 4) ini += "[phase.soft]\nfraction = 0.3\nE = 70e9\nnu = 0.3\n";
  ini += three ? "[mesh]\ntets_per_grain = 100\n" : "[mesh]\ntriangles_per_grain = 50\n";
  return ini;
}

}  // namespace

TEST_CASE("degenerate seed sets tessellate and mesh: rows, lattices, planes, the box's sides, Lloyd steps",
          "[property][degenerate]") {
  test::ScratchDir dir("degenerate-seeds");
  std::vector<SeedSet> sets = seed_sets();
#ifdef GRAINMESH_SANITIZED
  // The sanitizer build's point is memory and undefined behaviour: every fourth set.
  std::vector<SeedSet> some;
  for (std::size_t k = 0; k < sets.size(); k += 4) some.push_back(sets[k]);
  sets = some;
#endif
  for (const SeedSet& s : sets) {
    INFO(s.name << "\n" << config(s));
    std::ofstream(dir / "cell.ini") << config(s);
    const fs::path out = dir / "out";
    const auto r = test::run_grainmesh({"run", (dir / "cell.ini").string(), "-o", out.string(), "--quiet"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(fs::exists(out / "tessellation.png"));
    CHECK(fs::exists(out / "mesh.png"));
    const auto t = nlohmann::json::parse(test::read_file(out / "tessellation.json"));
    CHECK(t["grains"].size() == s.seeds.size());
    if (s.equal && s.box.size() == 3) {
      const char* size = "volume";
      const double first = t["grains"][0][size].get<double>();
      for (const auto& g : t["grains"]) CHECK(g[size].get<double>() == Approx(first).epsilon(1e-9));
    }
    fs::remove_all(out);
  }
}

TEST_CASE("a 3D laminate of ten slabs solves its periodic load cases", "[degenerate][openfoam]") {
  // The user's simplest 3D check: ten seeds in a row, no Lloyd, periodic, solved.
  test::ScratchDir dir("laminate-solve");
  const std::vector<double> cube{1, 1, 1};
  const SeedSet s{"slabs", cube, row(cube, 10, 0, {0.5, 0.5})};
  std::ofstream(dir / "cell.ini") << config(s) << "[homogenise]\nboundary = periodic\n[output]\npictures = none\n";
  const auto r = test::run_grainmesh({"run", (dir / "cell.ini").string(), "-o", (dir / "out").string(), "--solve", "--quiet"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto report = nlohmann::json::parse(test::read_file(dir / "out/report.json"));
  CHECK(report["effective"]["stiffness"]["C11"].get<double>() > 0.0);
  CHECK_FALSE(fs::exists(dir / "out/tessellation.png"));  // output.pictures = none: none drawn
  CHECK_FALSE(fs::exists(dir / "out/mesh.png"));
}
