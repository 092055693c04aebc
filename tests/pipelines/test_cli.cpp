// The grainmesh command, driven as a user would: outputs, reproducibility, bad input.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "helpers.hpp"
#include "view/vtu.hpp"

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

TEST_CASE("grainmesh keys and a command's --help list every config key with its default and meaning", "[cli][config]") {
  const auto all = run_grainmesh({"keys"});
  REQUIRE(all.exit_code == 0);
  // Every key a command's reader checks against (config_keys.hpp), each once, with a default
  // and a meaning: the reference cannot drift from what is read.
  for (const char* key : {"domain.width", "tessellation.seed", "phase.*.alpha", "mesh.tets_per_grain", "export.cells",
                          "load.plane_stress", "homogenise.boundary", "output.cases", "units.checked", "limits.seconds",
                          "distmesh.dptol", "sweep.realisations"}) {
    CAPTURE(key);
    const auto at = all.out.find(std::string("  ") + key + " ");
    REQUIRE(at != std::string::npos);
    const std::string line = all.out.substr(at, all.out.find('\n', at) - at);
    CHECK(line.find(" = ") != std::string::npos);
    CHECK(line.size() > 60);  // a meaning after the default
    CHECK(all.out.find(std::string("  ") + key + " ", at + 1) == std::string::npos);
  }
  // One command's: its keys, not the others'.
  const auto mesh = run_grainmesh({"keys", "mesh"});
  REQUIRE(mesh.exit_code == 0);
  CHECK(mesh.out.find("mesh.triangles_per_grain") != std::string::npos);
  CHECK(mesh.out.find("homogenise.boundary") == std::string::npos);
  const auto help = run_grainmesh({"run", "--help"});
  CHECK(help.exit_code == 0);
  CHECK(help.out.find("homogenise.boundary") != std::string::npos);
  CHECK(help.out.find("tessellation.lloyd_iterations") != std::string::npos);
  const auto bad = run_grainmesh({"keys", "solve"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err == "grainmesh: error: keys: unknown command 'solve' (run, tessellate, mesh, export, domain, sweep)\n");
  // A key a letter or two off (US spelling) is met with the one meant.
  const auto us = run_grainmesh({"run", "-o", "x", "--set", "homogenize.boundary=periodic"});
  CHECK(us.exit_code == 2);
  CHECK(us.err.find("unknown key 'homogenize.boundary' (did you mean homogenise.boundary?)") != std::string::npos);
}

TEST_CASE("a 2D mesh.vtu names its phases, as the 3D one does", "[cli][vtu]") {
  test::ScratchDir dir("mesh-phase-names");
  REQUIRE(run_grainmesh({"run", "-o", (dir / "out").string(), "--set", "tessellation.grains=10", "--set",
                         "output.pictures=none"})
              .exit_code == 0);
  const VtuContents vtu = read_vtu(dir / "out/mesh.vtu");
  REQUIRE(vtu.labels.size() == 1);
  CHECK(vtu.labels[0].name == "phase_names");
  CHECK(vtu.labels[0].labels == std::vector<std::string>{"particulate", "matrix"});
}

TEST_CASE("grainmesh tessellate and mesh draw no picture under output.pictures = none, in 2D and 3D", "[cli]") {
  test::ScratchDir dir("stage-pictures");
  std::ofstream(dir / "solid.ini") << "[domain]\nwidth = 1\nheight = 1\ndepth = 1\n[tessellation]\ngrains = 8\n"
                                      "[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.2\n[mesh]\ntets_per_grain = 60\n";
  const std::string plane = (test::source_dir() / "data/default.ini").string();
  for (const std::string& config : {plane, (dir / "solid.ini").string()}) {
    for (const char* pictures : {"none", "basic"}) {
      const fs::path out = dir / ((config == plane ? "plane-" : "solid-") + std::string(pictures));
      REQUIRE(run_grainmesh({"tessellate", config, "-o", (out / "t").string(), "--set", "tessellation.grains=8", "--set",
                             std::string("output.pictures=") + pictures})
                  .exit_code == 0);
      REQUIRE(run_grainmesh({"mesh", (out / "t/tessellation.json").string(), "-o", (out / "m").string(), "--set",
                             std::string("output.pictures=") + pictures})
                  .exit_code == 0);
      int png = 0;
      for (const fs::path& f : test::files_under(out)) png += f.extension() == ".png";
      INFO(out.filename().string());
      CHECK((png == 0) == (std::string(pictures) == "none"));
      CHECK(fs::exists(out / "t/tessellation.json"));
      CHECK(fs::exists(out / "m/mesh.vtu"));
    }
  }
}
