// The grainmesh command, driven as a user would: outputs, reproducibility, bad input.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "helpers.hpp"

using namespace grainmesh;
using test::entries;
using test::run_grainmesh;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

}  // namespace

TEST_CASE("grainmesh domain writes the mesh and its picture and the report", "[cli]") {
  test::ScratchDir dir("cli");
  const auto r = run_grainmesh({"domain", test::example("plate_with_hole").string(), "-o", (dir / "out").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("/out/{mesh.vtu, mesh.png, report.json}") != std::string::npos);
  CHECK(fs::file_size(dir / "out" / "mesh.vtu") > 1000);
  CHECK(fs::file_size(dir / "out" / "mesh.png") > 1000);
  const auto report = nlohmann::json::parse(test::read_file(dir / "out" / "report.json"));
  for (const char* key : {"points", "triangles", "area", "q_min", "q_mean", "min_angle_deg", "iterations",
                          "retriangulations", "converged", "seconds", "max_non_orthogonality_deg", "max_skewness",
                          "q_below_0_5", "peak_memory_mib"})
    CHECK(report.contains(key));
  CHECK(report["converged"] == true);
  CHECK(report["area"].get<double>() == Approx(4 - 3.14159265358979 / 4).epsilon(0.005));
  CHECK(entries(dir.path()) == 1);  // the staging directory is gone
}

TEST_CASE("the same config gives the same mesh byte for byte", "[cli]") {
  test::ScratchDir dir("cli");
  for (const char* out : {"a", "b"})
    REQUIRE(run_grainmesh({"domain", test::example("graded_hole").string(), "-o", (dir / out).string()}).exit_code == 0);
  CHECK(test::read_file(dir / "a" / "mesh.vtu") == test::read_file(dir / "b" / "mesh.vtu"));
  CHECK(test::read_file(dir / "a" / "mesh.png") == test::read_file(dir / "b" / "mesh.png"));
  // A different seed changes the graded mesh: the randomness comes from the seed.
  REQUIRE(run_grainmesh({"domain", test::example("graded_hole").string(), "-o", (dir / "c").string(), "--set",
                         "distmesh.seed=2"})
              .exit_code == 0);
  CHECK(test::read_file(dir / "a" / "mesh.vtu") != test::read_file(dir / "c" / "mesh.vtu"));
}

TEST_CASE("an earlier output is replaced but nothing else", "[cli]") {
  test::ScratchDir dir("cli");
  const std::string cfg = test::example("circle_h02").string();
  REQUIRE(run_grainmesh({"domain", cfg, "-o", (dir / "out").string()}).exit_code == 0);
  REQUIRE(run_grainmesh({"domain", cfg, "-o", (dir / "out").string(), "--set", "size.h0=0.1"}).exit_code == 0);
  const auto report = nlohmann::json::parse(test::read_file(dir / "out" / "report.json"));
  CHECK(report["h0"] == 0.1);
  CHECK(entries(dir.path()) == 1);

  fs::create_directories(dir / "precious");
  write(dir / "precious" / "thesis.tex", "do not delete");
  const auto r = run_grainmesh({"domain", cfg, "-o", (dir / "precious").string()});
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("not a grainmesh output") != std::string::npos);
  CHECK(test::read_file(dir / "precious" / "thesis.tex") == "do not delete");
}

TEST_CASE("bad input gives one line naming the problem and no output", "[cli]") {
  test::ScratchDir dir("cli");
  write(dir / "ok.ini", "[domain]\nshape = circle(0, 0, 1)\n[size]\nh0 = 0.1\n");
  const std::string ok = (dir / "ok.ini").string();
  struct Case {
    std::vector<std::string> args;
    int exit_code;
    std::string says;
  };
  const std::vector<Case> cases{
      {{"domain", ok, "--set", "size.hh=1"}, 2, "unknown key 'size.hh'"},
      {{"domain", (dir / "missing.ini").string()}, 4, "missing.ini: cannot open config file"},
      {{"domain", ok, "--set", "size.h0=0"}, 2, "size.h0: must be positive"},
      {{"domain", ok, "--set", "size.h0=-0.5"}, 2, "size.h0: must be positive"},
      {{"domain", ok, "--set", "size.h0=abc"}, 2, "size.h0: 'abc' is not a number"},
      {{"domain", ok, "--set", "domain.bbox=5 5 6 6"}, 3, "domain is empty inside its bounding box"},
      {{"domain", ok, "--set", "size.function=1 - 2*sqrt(x^2+y^2)"}, 2, "must be finite and positive"},
      {{"domain", ok, "--set", "size.function=1/(x*x - x*x)"}, 2, "is inf at"},
      {{"domain", ok, "--set", "size.function=sqrt(-1 - x^2)"}, 2, "is NaN at"},
      {{"domain", ok, "--set", "domain.shape=circle(0, 0)"}, 2, "domain.shape: expected ','"},
      {{"domain", ok, "--set", "domain.shape=polygon(0 0, 2 2, 2 0, 0 2)"}, 3, "domain.shape: polygon: edges"},
      {{"domain", ok, "--set", "fixed.points=5 5"}, 3, "fixed point (5, 5) lies outside the domain"},
      {{"domain", ok}, 2, "missing -o OUT"},
      {{"mesh-it"}, 2, "unknown command 'mesh-it'"},
      {{"domain", ok, "--bogus"}, 2, "unrecognised option '--bogus'"},
      // Boost's own message for this never finished.
      {{"domain", ok, "--%option%"}, 2, "cannot read option '--%option%' (see grainmesh domain --help)"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = c.args;
    if (args.front() == "domain" && c.says != "missing -o OUT") {
      args.push_back("-o");
      args.push_back((dir / "out").string());
    }
    const auto r = run_grainmesh(args);
    std::string shown;
    for (const std::string& a : args) shown += a + " ";
    INFO("args: " << shown << "\nstderr: " << r.err);
    CHECK(r.exit_code == c.exit_code);
    CHECK(r.err.find(c.says) != std::string::npos);
    CHECK(r.err.rfind("grainmesh: error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir / "out"));
    CHECK(entries(dir.path()) == 1);  // only ok.ini
  }
}

TEST_CASE("help and version", "[cli]") {
  CHECK(run_grainmesh({"--help"}).out.find("domain CONFIG -o OUT") != std::string::npos);
  CHECK(run_grainmesh({"--version"}).exit_code == 0);
  const auto help = run_grainmesh({"domain", "--help"});
  CHECK(help.exit_code == 0);
  CHECK(help.out.find("--set") != std::string::npos);
  CHECK(run_grainmesh({}).exit_code == 2);
}
