// Never a silent wrong answer, never lost data: what a new user ran into (issue 17), each
// reproduced as they did it and shown to be refused, warned about or answered right.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>

#include "export/foam_solver.hpp"
#include "helpers.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

Json report_of(const fs::path& dir) { return Json::parse(test::read_file(dir / "report.json")); }

// A refusal: the exit code, one line on stderr holding `says`.
void check_one_line(const test::CommandResult& r, int exit_code, const std::string& says) {
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.exit_code == exit_code);
  CHECK(r.err.find(says) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

// A command timed: its result and its wall-clock seconds.
std::pair<test::CommandResult, double> timed(const std::vector<std::string>& args, const std::string& env = {}) {
  const auto t0 = std::chrono::steady_clock::now();
  auto r = run_grainmesh(args, {}, env);
  return {r, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

// A small cell: quick to mesh and solve.
const std::vector<std::string> kSmall{"--set", "tessellation.grains=30", "--set", "mesh.triangles_per_grain=40"};

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The arguments on the small cell.
std::vector<std::string> small(std::vector<std::string> args) { return args + kSmall; }
// The arguments with `more` after them.
std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) { return args + more; }

}  // namespace

TEST_CASE("no command removes a file outside its own earlier output", "[cli][safety]") {
  test::ScratchDir dir("safety-dirs");
  REQUIRE(run_grainmesh(small({"run", "-o", (dir / "r").string()})).exit_code == 0);
  const std::string vtu = (dir / "r/mesh.vtu").string();

  // The reported loss: `export MESH.vtu -o . --force` in a directory of the user's.
  fs::create_directories(dir / "work");
  std::ofstream(dir / "work/notes.txt") << "mine";
  check_one_line(run_grainmesh({"export", vtu, "-o", ".", "--force"}, dir / "work"), 2, "unrecognised option '--force'");
  check_one_line(run_grainmesh({"export", vtu, "-o", "."}, dir / "work"), 4, "is the current directory");
  // Not even an earlier output of the same command when the shell stands in it.
  REQUIRE(run_grainmesh({"export", vtu, "-o", (dir / "work/case").string()}).exit_code == 0);
  check_one_line(run_grainmesh({"export", vtu, "-o", "."}, dir / "work/case"), 4, "is the current directory");
  check_one_line(run_grainmesh({"export", vtu, "-o", ".."}, dir / "work/case"), 4, "is the current directory");
  CHECK(test::read_file(dir / "work/notes.txt") == "mine");

  // An earlier export is replaced, with what OpenFOAM added to it; with a file of the
  // user's in it, it is not.
  REQUIRE(test::run_openfoam(dir / "work/case", "checkMesh").exit_code == 0);
  CHECK(run_grainmesh({"export", vtu, "-o", (dir / "work/case").string()}).exit_code == 0);
  std::ofstream(dir / "work/case/paraview-state.pvsm") << "mine";
  check_one_line(run_grainmesh({"export", vtu, "-o", (dir / "work/case").string()}), 4,
                 "holds 'paraview-state.pvsm', which grainmesh export did not write");
  CHECK(test::read_file(dir / "work/case/paraview-state.pvsm") == "mine");

  // Another command's output is not this one's to replace.
  check_one_line(run_grainmesh({"export", vtu, "-o", (dir / "r").string()}), 4,
                 "is not the output of grainmesh export but of grainmesh run");
  check_one_line(run_grainmesh(small({"run", "-o", (dir / "work/case").string()})), 4,
                 "is not the output of grainmesh run but of grainmesh export");
  CHECK(fs::exists(dir / "r/case/0/D"));
  // ... but a run replaces its own, and lists what it wrote.
  REQUIRE(run_grainmesh(small({"run", "-o", (dir / "r").string()})).exit_code == 0);
  const Json files = report_of(dir / "r")["files"];
  CHECK(std::find(files.begin(), files.end(), "case") != files.end());
  CHECK(files.size() == test::entries(dir / "r"));
}

TEST_CASE("a changed sweep never yields old results", "[cli][safety][sweep]") {
  test::ScratchDir dir("safety-sweep");
  std::ofstream(dir / "sweep.ini") << test::read_file(test::source_dir() / "data/default.ini")
                                   << "\n[sweep]\nphase.matrix.fraction = 0.2, 0.3\nrealisations = 1\n";
  const std::string out = (dir / "S").string();
  const std::vector<std::string> sweep{"sweep", (dir / "sweep.ini").string(), "-o", out, "--solve", "--set",
                                       "tessellation.grains=20", "--set", "mesh.h=0.12"};
  auto moduli = [&] {
    std::vector<double> m;
    for (std::size_t point : {0, 1}) m.push_back(report_of(test::sweep_run(dir / "S", point, 0))["effective"]["modulus"]);
    return m;
  };
  auto fingerprints_match = [&] {
    const Json plan = Json::parse(test::read_file(dir / "S/plan.json"));
    for (const Json& run : plan["runs"])
      CHECK(report_of(dir / "S" / run["name"].get<std::string>())["config_fingerprint"] == run["fingerprint"]);
  };
  REQUIRE(run_grainmesh(sweep).exit_code == 0);
  const std::vector<double> first = moduli();
  fingerprints_match();

  // The steps: a swept value changed (0.3 -> 0.4), then a phase's E set.
  std::ofstream(dir / "sweep.ini") << test::read_file(test::source_dir() / "data/default.ini")
                                   << "\n[sweep]\nphase.matrix.fraction = 0.2, 0.4\nrealisations = 1\n";
  const auto changed = run_grainmesh(sweep);
  INFO(changed.out << changed.err);
  REQUIRE(changed.exit_code == 0);
  // The new value a new run; the old one's kept aside, never deleted.
  CHECK(changed.out.find("ran 1 (0 of them again, their config changed), 1 were done already") != std::string::npos);
  CHECK(changed.out.find("1 run no longer in the plan kept in " + out + "/retired") != std::string::npos);
  CHECK(fs::exists(dir / "S/retired/fraction=0.3-r00/report.json"));
  CHECK(Json::parse(test::read_file(dir / "S/plan.json"))["points"][1]["phase.matrix.fraction"] == "0.4");
  CHECK(moduli()[0] == first[0]);
  CHECK(moduli()[1] < first[1]);  // more of the soft phase
  fingerprints_match();
  const auto stiffer = run_grainmesh(sweep + std::vector<std::string>{"--set", "phase.particulate.E=900e9"});
  REQUIRE(stiffer.exit_code == 0);
  CHECK(stiffer.out.find("ran 2 (2 of them again") != std::string::npos);
  CHECK(moduli()[0] > first[0]);
  fingerprints_match();
  REQUIRE(run_grainmesh({"sweep", "--collect", out}).exit_code == 0);
  // The summary's first point: the modulus of its one run, as it is now.
  std::istringstream csv(test::read_file(dir / "S/summary.csv"));
  std::string header, row, cell;
  std::getline(csv, header);
  std::getline(csv, row);
  std::istringstream names(header), values(row);
  double mean = 0.0;
  for (std::string name; std::getline(names, name, ',') && std::getline(values, cell, ',');)
    if (name == "modulus_mean") mean = std::stod(cell);
  CHECK(mean == Approx(moduli()[0]).epsilon(1e-9));

  // --collect says what is missing, failed or stale, and leaves it out.
  fs::remove_all(dir / "S/fraction=0.2-r00");
  const auto collect = run_grainmesh({"sweep", "--collect", out});
  CHECK(collect.exit_code == 0);
  CHECK(collect.err.find("warning: sweep --collect: 1 of 2 runs are missing or unsolved and are left out: fraction=0.2-r00") !=
        std::string::npos);
  CHECK(collect.out.find("(1 of 2 runs)") != std::string::npos);
  fs::rename(dir / "S/fraction=0.4-r00", dir / "S/fraction=0.4-r00.failed");
  CHECK(run_grainmesh({"sweep", "--collect", out}).err.find("1 of 2 runs failed and are left out: fraction=0.4-r00") !=
        std::string::npos);

  // A sweep writes only into its own directory.
  fs::create_directories(dir / "mine");
  std::ofstream(dir / "mine/data.csv") << "1,2";
  check_one_line(run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", (dir / "mine").string()}), 4,
                 "is not a grainmesh sweep (no plan.json)");
  std::ofstream(dir / "S/data.csv") << "1,2";
  check_one_line(run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", out}), 4,
                 "holds 'data.csv', which grainmesh sweep did not write");
  check_one_line(run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", "."}, dir / "S"), 4,
                 "is the current directory");
  CHECK(fs::exists(dir / "mine/data.csv"));
}

TEST_CASE("one material, one phase and periodic one-material cells converge in seconds, a phase without grains is "
          "refused", "[cli][safety][physics]") {
  test::ScratchDir dir("safety-solve");
  const double E = 800e9, nu = 0.1, M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));  // plane strain, eps_yy = 0
  for (const bool cyclic : {false, true}) {
    INFO("export.cyclic " << cyclic);
    const fs::path out = dir / (cyclic ? "cyclic" : "patches");
    // The hang: the matrix given the particulates' E.
    const auto [r, seconds] = timed({"run", "-o", out.string(), "--solve", "--set", "phase.matrix.E=800e9", "--set",
                                     std::string("export.cyclic=") + (cyclic ? "true" : "false")});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(seconds < 30);
    const Json e = report_of(out)["effective"];
    CHECK(e["final_residual"].get<double>() < kSolverTolerance);
    CHECK(e["corrections"].get<int>() < 200);
    CHECK(e["modulus"].get<double>() == Approx(M).epsilon(1e-6));  // exact: one material
    // OpenFOAM's own residual of y is noise here, which is why it is not the criterion.
    CHECK(e["component_residuals"][1].get<double>() > kSolverTolerance);
  }
  // Two phases a hair apart: y is tiny, not zero, and OpenFOAM's own residual of it noise
  // (about 6e-6, under the case's tolerance of 1e-5, so the case stops itself; where it
  // would not, the solve runs again to where the measure was met: test_solve_monitor.cpp).
  const auto [hair, hair_seconds] =
      timed({"run", "-o", (dir / "hair").string(), "--solve", "--set", "phase.matrix.E=799.99999e9"});
  INFO(hair.err);
  REQUIRE(hair.exit_code == 0);
  CHECK(hair_seconds < 30);
  const Json he = report_of(dir / "hair")["effective"];
  CHECK(he["final_residual"].get<double>() < kSolverTolerance);
  CHECK(he["result"] == "case/" + std::to_string(he["corrections"].get<int>()));
  CHECK(he["modulus"].get<double>() == Approx(M).epsilon(1e-6));
  // A config with a single phase.
  std::ofstream(dir / "one.ini") << "[domain]\nwidth = 2\nheight = 1\n[tessellation]\ngrains = 20\n"
                                    "lloyd_iterations = 3\n[phase.steel]\nfraction = 1\nE = 200e9\nnu = 0.3\n";
  const auto [one, one_seconds] = timed({"run", (dir / "one.ini").string(), "-o", (dir / "one").string(), "--solve"});
  INFO(one.err);
  REQUIRE(one.exit_code == 0);
  CHECK(one_seconds < 30);
  CHECK(report_of(dir / "one")["effective"]["modulus"].get<double>() ==
        Approx(200e9 * 0.7 / (1.3 * 0.4)).epsilon(1e-6));
  // Two grains for an 80/20 cell: the matrix would get none.
  const auto [two, two_seconds] = timed({"run", "-o", (dir / "two").string(), "--solve", "--set", "tessellation.grains=2"});
  check_one_line(two, 2, "phase.matrix.fraction: a fraction of 0.2 gives the phase none of the 2 grains: use at least 5 grains");
  CHECK(two_seconds < 10);
  CHECK_FALSE(fs::exists(dir / "two"));
  // Two grains that each phase can have: solved.
  const auto halves = run_grainmesh({"run", "-o", (dir / "halves").string(), "--solve", "--set", "tessellation.grains=2",
                                     "--set", "phase.matrix.fraction=0.5"});
  INFO(halves.err);
  CHECK(halves.exit_code == 0);
}

TEST_CASE("a diverging or stalled solve stops within seconds, says why in one line and keeps its log",
          "[cli][safety][physics]") {
  test::ScratchDir dir("safety-fail");
  // Harmonic stiffness at a contrast of 16 diverges (README, Stiffness across interfaces).
  const fs::path out = dir / "div";
  const auto [r, seconds] = timed(small({"run", "-o", out.string(), "--solve", "--set", "phase.matrix.E=50e9", "--set",
                                   "export.stiffness_interpolation=harmonic"}));
  check_one_line(r, kExitSolve, "D: solidDisplacementFoam diverges");
  CHECK(r.err.find("use auto or linear") != std::string::npos);
  CHECK(seconds < 30);
  CHECK_FALSE(fs::exists(out));
  // The log is where the message says, with the rest of the run for a look.
  std::smatch where;
  REQUIRE(std::regex_search(r.err, where, std::regex("see (\\S+)\\n")));
  CHECK(fs::path(where[1].str()) == out.string() + ".failed/case/log.solidDisplacementFoam");
  CHECK(test::read_file(where[1].str()).find("Solving for Dx") != std::string::npos);
  const Json failed = report_of(out.string() + ".failed");
  CHECK(failed["failed"].get<std::string>().find("diverges") != std::string::npos);
  CHECK_FALSE(failed.contains("effective"));
  // A second failure replaces the first one's directory.
  CHECK(run_grainmesh(small({"run", "-o", out.string(), "--solve", "--set", "phase.matrix.E=50e9", "--set",
                       "export.stiffness_interpolation=harmonic"}))
            .exit_code == kExitSolve);

  // A solver whose residual stays put (a stand-in on PATH: OpenFOAM's own does not stall
  // on any case we know of since the criterion weighs each component by its size).
  fs::create_directories(dir / "bin");
  std::ofstream(dir / "bin/solidDisplacementFoam")
      << "#!/bin/sh\ni=0\nwhile [ $i -lt 100000 ]; do i=$((i+1)); echo \"Iteration: $i\"\n"
         "echo 'GAMG:  Solving for Dx, Initial residual = 1e-06, Final residual = 1e-07, No Iterations 1'\n"
         "echo 'GAMG:  Solving for Dy, Initial residual = 1e-06, Final residual = 1e-07, No Iterations 1'\n"
         "echo '    min(region0) of D = (0 -1e-10 0)'\necho '    max(region0) of D = (1e-09 1e-10 0)'\ndone\n";
  fs::permissions(dir / "bin/solidDisplacementFoam", fs::perms::owner_all);
  const auto [stalled, stalled_seconds] =
      timed(small({"run", "-o", (dir / "stall").string(), "--solve"}), "PATH=" + (dir / "bin").string() + ":$PATH");
  check_one_line(stalled, kExitSolve, "D: solidDisplacementFoam stalls: the x displacement's residual has not fallen for 500 corrections");
  CHECK(stalled_seconds < 30);
  CHECK(fs::exists(dir / "stall.failed/case/log.solidDisplacementFoam"));
}

TEST_CASE("export refuses a load it cannot apply, naming the patch or key", "[cli][safety][export]") {
  test::ScratchDir dir("safety-load");
  // A disk's bounding box touches it at four points only; a chamfered L-bracket's right
  // side is a corner.
  std::ofstream(dir / "bracket.ini")
      << "[domain]\nshape = polygon(0 0, 1.5 0, 2 0.5, 1.5 1, 1 1, 1 2, 0 2)\n[size]\nh0 = 0.1\n";
  REQUIRE(run_grainmesh({"domain", test::example("circle_h01").string(), "-o", (dir / "disk").string()}).exit_code == 0);
  REQUIRE(run_grainmesh({"domain", (dir / "bracket.ini").string(), "-o", (dir / "bracket").string()}).exit_code == 0);
  const std::vector<std::string> moduli{"--set", "phase.solid.E=200e9", "--set", "phase.solid.nu=0.3"};
  for (const char* mesh : {"disk", "bracket"}) {
    const auto r = run_grainmesh(with({"export", (dir / mesh / "mesh.vtu").string(), "-o", (dir / "case").string()}, moduli));
    check_one_line(r, 2, "patch 'right' is empty: no mesh edge lies on the cell's right side");
    CHECK_FALSE(fs::exists(dir / "case"));
  }
  // cyclic on a mesh that is not periodic.
  check_one_line(run_grainmesh(with({"export", (dir / "bracket/mesh.vtu").string(), "-o", (dir / "case").string(), "--set",
                                "export.cyclic=true"}, moduli)),
                 2, "export.cyclic: the mesh is not periodic");
  check_one_line(run_grainmesh({"run", "-o", (dir / "case").string(), "--set", "domain.periodic=false", "--set",
                                "export.cyclic=true"}),
                 2, "export.cyclic: the mesh is not periodic");
  // A cell given in metres while the unit is the micrometre: 3e-12 m.
  check_one_line(run_grainmesh({"run", "-o", (dir / "case").string(), "--solve", "--set", "domain.width=3e-6", "--set",
                                "domain.height=1.7e-6"}),
                 2, "export.convert_to_meters: the cell is 3e-06 mesh units across, times export.convert_to_meters = 1e-06: 3e-12 m, below 1 nm");
  // A strain beyond small-strain elasticity.
  check_one_line(run_grainmesh({"run", "-o", (dir / "case").string(), "--set", "load.displacement=0.1"}), 2,
                 "load.displacement: 0.1 over a cell 3 wide is a mean strain of 0.0333, above 1 %");
  CHECK_FALSE(fs::exists(dir / "case"));
  // A cell of metres is warned about, not refused: elasticity has no length scale.
  const auto big = run_grainmesh(small({"run", "-o", (dir / "big").string(), "--set", "export.convert_to_meters=1"}));
  REQUIRE(big.exit_code == 0);
  CHECK(big.err.find("warning: the cell is 3 mesh units across, times export.convert_to_meters = 1: 3 m, above 1 m") !=
        std::string::npos);
  CHECK(report_of(dir / "big")["warnings"].size() == 1);
}

TEST_CASE("doubtful results warn on stderr and in report.json, and phase-size jumps are graded", "[cli][safety]") {
  test::ScratchDir dir("safety-warn");
  // A per-phase size jump (the issue: q_min 0.27 and 4 regions unconverged, only q_min said).
  const auto fine = run_grainmesh({"run", test::example("grains_wc_co").string(), "-o", (dir / "fine").string(), "--set",
                                   "phase.Co.size=0.01"});
  REQUIRE(fine.exit_code == 0);
  CHECK(report_of(dir / "fine")["mesh"]["q_min"].get<double>() > 0.6);
  // Each warning one line on stderr and an entry in the report.
  auto check_warned = [&](const std::string& name, const std::vector<std::string>& args, const std::string& says) {
    const auto r = run_grainmesh(with({"run", "-o", (dir / name).string()}, args));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("grainmesh: warning: " + says) != std::string::npos);
    bool reported = false;
    const Json report = report_of(dir / name);
    for (const auto& w : report["warnings"]) reported = reported || w.get<std::string>().find(says) == 0;
    CHECK(reported);
  };
  check_warned("iterations", small({"--set", "mesh.max_iterations=3"}), "mesh: ");
  // The steepest grading allowed cannot bridge a size jump of four.
  check_warned("steep", kSmall + std::vector<std::string>{"--set", "phase.matrix.size=0.02", "--set", "mesh.gradient=10"},
               "mesh: q_min");
  check_warned("target", {"--set", "tessellation.grains=4"}, "phase.particulate.fraction: 0.7842 achieved for a target of 0.8");
  // The default cell's modulus from the tractions lies inside Hashin-Shtrikman, and nothing
  // warns; the area average of the cell stresses, kept beside it, lies above.
  const auto bound = run_grainmesh({"run", "-o", (dir / "bound").string(), "--solve"});
  REQUIRE(bound.exit_code == 0);
  CHECK(bound.err.find("warning") == std::string::npos);
  const Json be = report_of(dir / "bound")["effective"];
  CHECK(be["modulus"].get<double>() < be["hashin_shtrikman"]["upper"].get<double>());
  CHECK(be["modulus"].get<double>() > be["hashin_shtrikman"]["lower"].get<double>());
  CHECK(be["inside_bounds"]["hashin_shtrikman"].get<bool>());
  CHECK(be["volume_average"]["modulus"].get<double>() > be["hashin_shtrikman"]["upper"].get<double>());
  const Json quiet = report_of(dir / "fine");
  CHECK(quiet.contains("warnings"));
}

TEST_CASE("small things a new user tripped over", "[cli][safety]") {
  test::ScratchDir dir("safety-small");
  // A UTF-8 byte order mark.
  std::ofstream(dir / "bom.ini") << "\xEF\xBB\xBF" << test::read_file(test::example("circle_h01"));
  CHECK(run_grainmesh({"domain", (dir / "bom.ini").string(), "-o", (dir / "bom").string()}).exit_code == 0);
  // mesh given a directory or a .vtu.
  REQUIRE(run_grainmesh(small({"run", "-o", (dir / "r").string()})).exit_code == 0);
  check_one_line(run_grainmesh({"mesh", (dir / "r").string(), "-o", (dir / "m").string()}), 4,
                 "r: is a directory (expected the tessellation file)");
  const auto vtu = run_grainmesh({"mesh", (dir / "r/mesh.vtu").string(), "-o", (dir / "m").string()});
  check_one_line(vtu, 3, "mesh.vtu: not a tessellation.json of grainmesh tessellate: not JSON (at line 1, column 1: syntax error");
  CHECK(vtu.err.find("json.exception") == std::string::npos);
  // A key set twice with --set is blamed on --set.
  check_one_line(run_grainmesh({"run", "-o", (dir / "x").string(), "--set", "tessellation.grains=5", "--set",
                                "tessellation.grains=6"}),
                 2, "error: --set: tessellation.grains: given 2 times");
  // KEY= unsets a key, so grain_size can replace the default's grains.
  const auto unset = run_grainmesh({"run", "-o", (dir / "u").string(), "--set", "tessellation.grains=", "--set",
                                    "tessellation.grain_size=0.5", "--set", "mesh.triangles_per_grain=30"});
  INFO(unset.err);
  REQUIRE(unset.exit_code == 0);
  CHECK(report_of(dir / "u")["grains"].get<int>() == 26);  // 3 x 1.7 / (pi 0.5^2 / 4)
  CHECK(test::read_file(dir / "u/config.ini").find("grains = ") == std::string::npos);
  // A misspelt phase.
  check_one_line(run_grainmesh({"run", "-o", (dir / "x").string(), "--set", "phase.Matrix.E=300e9"}), 2,
                 "--set: phase.Matrix.E: unknown phase 'Matrix' (phases: particulate, matrix)");
  // Uniaxial: no bounds to print, and none printed as 0.
  const auto uniaxial = run_grainmesh(small({"run", "-o", (dir / "uni").string(), "--solve", "--set", "load.uniaxial=true"}));
  INFO(uniaxial.err);
  REQUIRE(uniaxial.exit_code == 0);
  CHECK(uniaxial.out.find("solved: effective modulus") != std::string::npos);
  CHECK(uniaxial.out.find("Reuss") == std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x"));
}

TEST_CASE("a case that fails one of checkMesh's checks is a warning, not a silent log line", "[cli][safety][openfoam]") {
  test::ScratchDir dir("checkmesh-fails");
  // A stand-in checkMesh on PATH that fails a check the way OpenFOAM's does (a 3D case had
  // two faces of skewness 5.4: "Failed 1 mesh checks" in its log, and nothing said so).
  const fs::path bin = dir / "bin";
  fs::create_directories(bin);
  std::ofstream(bin / "checkMesh") << "#!/bin/sh\necho 'Checking geometry...'\n"
                                      "echo ' ***Max skewness = 5.4, 2 highly skew faces detected which may impair the "
                                      "quality of the results'\necho 'Failed 1 mesh checks.'\necho End\n";
  fs::permissions(bin / "checkMesh", fs::perms::owner_all);
  const auto r = test::run_grainmesh({"run", "-o", (dir / "out").string(), "--solve", "--quiet", "--set",
                                      "tessellation.grains=20", "--set", "output.pictures=none"},
                                     {}, "PATH=" + test::shell_quote(bin.string()) + ":$PATH");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("grainmesh: warning: checkMesh: failed 1 mesh check in case (Max skewness = 5.4, 2 highly skew faces") !=
        std::string::npos);
  const auto report = nlohmann::json::parse(test::read_file(dir / "out/report.json"));
  CHECK(report["mesh_check"]["failed_checks"] == 1);
  bool warned = false;
  for (const auto& w : report["warnings"]) warned = warned || w.get<std::string>().rfind("checkMesh: failed 1", 0) == 0;
  CHECK(warned);
  // The real checkMesh on the same cell: passed, and said so.
  const auto ok = test::run_grainmesh({"run", "-o", (dir / "ok").string(), "--solve", "--quiet", "--set",
                                       "tessellation.grains=20", "--set", "output.pictures=none"});
  REQUIRE(ok.exit_code == 0);
  CHECK(nlohmann::json::parse(test::read_file(dir / "ok/report.json"))["mesh_check"]["failed_checks"] == 0);
  CHECK(ok.err.find("checkMesh") == std::string::npos);
}

#ifndef GRAINMESH_SANITIZED
// (Release build only: AddressSanitizer reserves terabytes of address space and cannot run
// under an address-space limit at all.)
TEST_CASE("under ulimit -v, finite elements too big for what is left are refused naming the key, and running out of "
          "memory anywhere is one line, nothing written either way",
          "[cli][safety][fe]") {
  test::ScratchDir dir("memory_limit");
  auto limit = [](double mib) { return "prlimit --as=" + std::to_string(static_cast<long long>(mib * 1024 * 1024)); };
  // A 12-grain 3D cell meshed fine: the mesh takes little, the second-order elements'
  // factor a few hundred MiB (measured: the run's peak 340 MB resident without a limit;
  // under 450 MiB of address space about 170 MiB are left when the factor is analysed).
  const auto fe = test::run_grainmesh({"run", test::example("grains_3d_wc_co").string(), "-o", (dir / "fe").string(),
                                       "--quiet", "--set", "homogenise.boundary=periodic", "--set",
                                       "tessellation.grains=12", "--set", "mesh.tets_per_grain=3000", "--set",
                                       "output.pictures=none"},
                                      {}, limit(450));
  INFO(fe.err);
  CHECK(fe.exit_code == 2);
  CHECK(fe.err.find("homogenise.solver = fe: the finite elements on this mesh") != std::string::npos);
  CHECK(fe.err.find("available: set homogenise.solver = openfoam") != std::string::npos);
  // The default cell split three times (312,576 triangles) under 700 MiB: out of memory
  // before the finite elements' check (or refused by it, on a machine that maps less).
  const auto big = test::run_grainmesh({"run", "-o", (dir / "big").string(), "--quiet", "--set",
                                        "homogenise.boundary=periodic", "--set", "mesh.triangles_per_grain=25", "--set",
                                        "mesh.refine=3", "--set", "output.pictures=none"},
                                       {}, limit(700));
  INFO(big.err);
  CHECK((big.exit_code == 1 || big.exit_code == 2));
  CHECK((big.err.find("grainmesh: error: out of memory: the run needs more") != std::string::npos ||
         big.err.find("homogenise.solver = fe: the finite elements on this mesh") != std::string::npos));
  for (const test::CommandResult* r : {&fe, &big}) {
    // The error, one line, last.
    const auto at = r->err.find("grainmesh: error: ");
    REQUIRE(at != std::string::npos);
    CHECK(r->err.find('\n', at) == r->err.size() - 1);
  }
  CHECK(test::entries(dir.path()) == 0);
}
#endif
