// `grainmesh sweep`: an end-to-end sweep with solving, resuming, shards, collecting, and
// bad input.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "export/foam_options.hpp"
#include "export/foam_solver.hpp"
#include "helpers.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;

namespace {

void write_sweep(const fs::path& file, const std::string& sweep_section) {
  std::ofstream out(file);
  out << test::read_file(test::source_dir() / "data/default.ini") << "\n[sweep]\n" << sweep_section;
}

// "this shard (I/N) ran R" from a sweep's output.
int ran(const std::string& out) {
  std::smatch m;
  REQUIRE(std::regex_search(out, m, std::regex(R"(ran (\d+) )")));
  return std::stoi(m[1]);
}

}  // namespace

TEST_CASE("a sweep solves every point, between the bounds, and resumes where it stopped", "[cli][sweep][physics]") {
  test::ScratchDir dir("sweep");
  write_sweep(dir / "sweep.ini", "tessellation.grains = 20, 40\nphase.matrix.fraction = 0.1, 0.4\nrealisations = 2\n");
  const std::string out = (dir / "out").string();
  const auto r = run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", out, "--jobs", "2", "--solve"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(ran(r.out) == 8);
  std::map<std::pair<std::string, std::string>, double> modulus;  // (grains, matrix) -> sum
  const auto plan = nlohmann::json::parse(test::read_file(dir / "out/plan.json"));
  for (const auto& run : plan["runs"]) {
    const fs::path entry = dir / "out" / run["name"].get<std::string>();
    const auto& point = plan["points"][run["point"].get<std::size_t>()];
    // Named by its values: grains and the matrix fraction, and its realisation.
    CHECK(entry.filename().string() == "grains=" + point["tessellation.grains"].get<std::string>() + ",fraction=" +
                                           point["phase.matrix.fraction"].get<std::string>() + "-r0" +
                                           std::to_string(run["realisation"].get<int>()));
    const auto report = nlohmann::json::parse(test::read_file(entry / "report.json"));
    const auto& e = report["effective"];
    CHECK(e["final_residual"].get<double>() < kSolverTolerance);
    CHECK(e["stress_change"].get<double>() <= kStressTolerance);
    CHECK(e["modulus"].get<double>() > e["reuss"].get<double>());
    CHECK(e["modulus"].get<double>() < e["voigt"].get<double>());
    modulus[{point["tessellation.grains"], point["phase.matrix.fraction"]}] += e["modulus"].get<double>();
    CHECK(test::run_openfoam(entry / "case", "checkMesh").out.find("Mesh OK.") != std::string::npos);
  }
  REQUIRE(modulus.size() == 4);
  for (const char* grains : {"20", "40"}) CHECK(modulus[{grains, "0.4"}] < modulus[{grains, "0.1"}]);

  // Killed part-way: a run lost, another half-written (a staging directory, no report).
  const fs::path lost = test::sweep_run(dir / "out", 1, 0), half = test::sweep_run(dir / "out", 2, 1);
  fs::remove_all(lost);
  const fs::path staging = dir / "out" / std::string(".").append(lost.filename().string()).append(".partial-99999");
  fs::create_directories(staging / "case");  // its staging, left by the kill
  fs::remove(half / "report.json");
  const auto again = run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", out, "--solve"});
  INFO(again.err);
  REQUIRE(again.exit_code == 0);
  CHECK(ran(again.out) == 2);
  CHECK_FALSE(fs::exists(staging));
  CHECK(fs::exists(lost / "report.json"));

  // The summary was written by the sweep itself; --collect writes it again the same.
  const std::string written = test::read_file(dir / "out/summary.csv");
  const auto collect = run_grainmesh({"sweep", "--collect", out});
  REQUIRE(collect.exit_code == 0);
  const std::string csv = test::read_file(dir / "out/summary.csv");
  CHECK(csv == written);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 5);  // a header and one row per point
  CHECK(csv.find("modulus_mean,modulus_std,modulus_ci95") != std::string::npos);
  CHECK(fs::file_size(dir / "out/summary.png") > 5000);
}

TEST_CASE("sweep shards together run every run exactly once", "[cli][sweep]") {
  test::ScratchDir dir("shards");
  write_sweep(dir / "sweep.ini", "tessellation.grains = 10, 20\nphase.matrix.fraction = 0.2, 0.3\nrealisations = 2\n");
  int total = 0;
  for (const char* shard : {"1/3", "2/3", "3/3"}) {
    const auto r = run_grainmesh(
        {"sweep", (dir / "sweep.ini").string(), "-o", (dir / "out").string(), "--shard", shard, "--set", "mesh.h=0.1"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    total += ran(r.out);
  }
  CHECK(total == 8);
  int reports = 0;
  for (const auto& entry : fs::directory_iterator(dir / "out")) reports += fs::exists(entry.path() / "report.json");
  CHECK(reports == 8);
  const auto rest = run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", (dir / "out").string(), "--set", "mesh.h=0.1"});
  CHECK(ran(rest.out) == 0);
}

TEST_CASE("a sweep whose runs fail names them and what the first to fail said", "[cli][sweep]") {
  test::ScratchDir dir("sweep-failed");
  // 2 grains leave the 20 % matrix without one: both realisations are refused.
  write_sweep(dir / "sweep.ini", "tessellation.grains = 30, 2\nrealisations = 2\n");
  std::ofstream(dir / "sweep.ini", std::ios::app) << "[output]\npictures = none\n";
  const std::string out = (dir / "out").string();
  const auto r = run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", out, "--jobs", "1"});
  CHECK(r.exit_code == 2);  // the first failed run's
  const std::string error = "grainmesh: error: sweep: 2 of 4 runs failed (grains=2-r00, grains=2-r01; grains=2-r00 first: " +
                            (dir / "sweep.ini").string() +
                            ": phase.matrix.fraction: a fraction of 0.2 gives the phase none of the 2 grains: use at least 5 "
                            "grains (tessellation.grains), about 50 for fractions within 1 %); their logs are in " + out +
                            "/logs (run the sweep again to retry them)\n";
  CHECK(r.err.size() >= error.size());
  CHECK(r.err.compare(r.err.size() - error.size(), error.size(), error) == 0);  // last, after the runs' warnings
  CHECK(fs::exists(dir / "out/grains=30-r01/report.json"));
  CHECK_FALSE(fs::exists(dir / "out/grains=2-r00"));
  CHECK(fs::exists(dir / "out/summary.csv"));  // of the runs that did finish
}

TEST_CASE("bad sweep input gives one line naming it", "[cli][sweep]") {
  test::ScratchDir dir("sweep-bad");
  write_sweep(dir / "unknown.ini", "tessellation.grainz = 10, 20\n");
  write_sweep(dir / "empty.ini", "tessellation.grains = ,\n");
  write_sweep(dir / "badvalue.ini", "tessellation.grains = 10, many\n");
  write_sweep(dir / "ok.ini", "tessellation.grains = 10\n");
  write_sweep(dir / "badrange.ini", "tessellation.grains = 10, -5\n");
  const std::vector<test::Refusal> cases{
      {{"sweep", (dir / "unknown.ini").string()}, 2, "sweep.tessellation.grainz: names no config key"},
      {{"sweep", (dir / "empty.ini").string()}, 2, "sweep.tessellation.grains: gives no values"},
      {{"sweep", (dir / "badvalue.ini").string()}, 2, "tessellation.grains: 'many' is not a"},
      {{"sweep", (dir / "ok.ini").string(), "--shard", "4/3"}, 2, "--shard 4/3: expected I/N"},
      {{"sweep", (dir / "ok.ini").string(), "--set", "load.bogus=1"}, 2, "unknown key 'load.bogus'"},
      // A swept value is the sweep file's, not a --set's.
      {{"sweep", (dir / "badrange.ini").string()},
       2,
       (dir / "badrange.ini").string() + ": the sweep's point tessellation.grains=-5: tessellation.grains: must be at least 1"},
  };
  for (const auto& c : cases) test::check_refused(c, dir / "out");
  // A directory that cannot be made: below a plain file.
  std::ofstream(dir / "plain-file") << "x";
  test::check_refused({{"sweep", (dir / "ok.ini").string()}, 4, "cannot create the sweep's directory"},
                      dir / "plain-file/out");
  // --collect on a damaged plan: a count nlohmann would cast to int undefined.
  fs::create_directories(dir / "damaged");
  std::ofstream(dir / "damaged" / "plan.json") << R"({"keys": [], "realisations": 1e80, "points": []})";
  const auto collect = test::run_grainmesh({"sweep", "--collect", (dir / "damaged").string()});
  CHECK(collect.exit_code == 4);
  CHECK(collect.err.find("plan.json: realisations is 1e+80, not a count from 1 to 100000") != std::string::npos);
  // --collect on a directory no sweep wrote: said so, not "plan.json: cannot open file".
  fs::create_directories(dir / "not-a-sweep");
  const auto stray = test::run_grainmesh({"sweep", "--collect", (dir / "not-a-sweep").string()});
  CHECK(stray.exit_code == 4);
  CHECK(stray.err == "grainmesh: error: " + (dir / "not-a-sweep").string() +
                         ": not a grainmesh sweep's directory (no plan.json): give the directory a sweep wrote "
                         "(grainmesh sweep SWEEP.ini -o DIR)\n");
}

TEST_CASE("a periodic sweep summarises every stiffness component and engineering constant, the thermal expansion "
          "and the residual stresses with their 95 % CI",
          "[cli][sweep][homogenise]") {
  test::ScratchDir dir("sweep-periodic");
  write_sweep(dir / "sweep.ini", "tessellation.grains = 20\nrealisations = 3\n");
  const std::string out = (dir / "out").string();
  // Cooled as well: the thermal expansion and residual stresses are summarised too.
  const auto r = run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", out, "--jobs", "2", "--solve", "--set",
                                "homogenise.boundary=periodic", "--set", "output.pictures=false", "--set",
                                "load.delta_T=-1000", "--set", "phase.particulate.alpha=5e-6", "--set",
                                "phase.matrix.alpha=14e-6", "--set", "homogenise.solver=openfoam", "--set",
                                "homogenise.reference=fe"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto c = run_grainmesh({"sweep", "--collect", out});
  INFO(c.err);
  REQUIRE(c.exit_code == 0);
  std::istringstream csv(test::read_file(dir / "out/summary.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  auto columns = [](const std::string& line) {  // CSV: a quoted field may hold commas
    std::vector<std::string> v(1);
    bool quoted = false;
    for (std::size_t k = 0; k < line.size(); ++k) {
      const char ch = line[k];
      if (ch == '"' && quoted && k + 1 < line.size() && line[k + 1] == '"') v.back() += '"', ++k;
      else if (ch == '"') quoted = !quoted;
      else if (ch == ',' && !quoted) v.emplace_back();
      else v.back() += ch;
    }
    return v;
  };
  const auto names = columns(header), values = columns(row);
  REQUIRE(names.size() == values.size());
  auto value = [&](const std::string& name) {
    const auto at = std::find(names.begin(), names.end(), name);
    REQUIRE(at != names.end());
    return std::stod(values[static_cast<std::size_t>(at - names.begin())]);
  };
  for (const char* q : {"C11", "C22", "C12", "C66", "C16", "C26", "E_x", "E_y", "nu_xy", "nu_yx", "G_xy"})
    for (const char* s : {"_mean", "_std", "_ci95"}) CHECK(std::find(names.begin(), names.end(), q + std::string(s)) != names.end());
  // The mean and CI of C11 from the three runs' reports (t = 4.303 for two degrees of freedom).
  std::vector<double> c11;
  for (const char* run : {"grains=20-r00", "grains=20-r01", "grains=20-r02"})
    c11.push_back(nlohmann::json::parse(test::read_file(dir / "out" / run / "report.json"))["effective"]["stiffness"]["C11"]
                      .get<double>());
  const double mean = (c11[0] + c11[1] + c11[2]) / 3;
  double ss = 0.0;
  for (double v : c11) ss += (v - mean) * (v - mean);
  CHECK(value("C11_mean") == Approx(mean).epsilon(1e-9));
  CHECK(value("C11_std") == Approx(std::sqrt(ss / 2)).epsilon(1e-6));
  CHECK(value("C11_ci95") == Approx(4.303 * std::sqrt(ss / 2) / std::sqrt(3.0)).epsilon(1e-6));
  CHECK(value("runs") == 3);
  // The finite-element reference and the answer's error against it, summarised the same way:
  // the mean error is the mean of the runs' own.
  std::vector<double> error;
  for (const char* run : {"grains=20-r00", "grains=20-r01", "grains=20-r02"})
    error.push_back(nlohmann::json::parse(test::read_file(dir / "out" / run / "report.json"))["effective"]
                        ["discretisation_error"]["stiffness"]["C11"].get<double>());
  CHECK(value("discretisation_error_C11_mean") == Approx((error[0] + error[1] + error[2]) / 3).epsilon(1e-9));
  CHECK(std::abs(value("discretisation_error_C11_mean")) < 0.02);
  CHECK(value("reference_C11_mean") == Approx(value("C11_mean")).epsilon(0.02));
  for (const char* column : {"reference_C66_ci95", "reference_shear_modulus_mean", "discretisation_error_C12_std",
                             "discretisation_error_bulk_modulus_mean"})
    CHECK(std::find(names.begin(), names.end(), column) != names.end());
  // The WC-Co descriptors of every phase, summarised the same way.
  std::vector<double> contiguity;
  for (const char* run : {"grains=20-r00", "grains=20-r01", "grains=20-r02"})
    contiguity.push_back(nlohmann::json::parse(test::read_file(dir / "out" / run / "report.json"))["statistics"]
                             ["contiguity"]["particulate"].get<double>());
  CHECK(value("contiguity_particulate_mean") ==
        Approx((contiguity[0] + contiguity[1] + contiguity[2]) / 3).epsilon(1e-9));
  for (const char* q : {"contiguity", "intercept_length", "mean_free_path"})
    for (const char* phase : {"_particulate", "_matrix"})
      for (const char* s : {"_mean", "_std", "_ci95"})
        CHECK(std::find(names.begin(), names.end(), q + std::string(phase) + s) != names.end());
  // The phase stresses: each load case's loaded component and 99th percentile of von Mises.
  std::vector<double> p99;
  for (const char* run : {"grains=20-r00", "grains=20-r01", "grains=20-r02"})
    p99.push_back(nlohmann::json::parse(test::read_file(dir / "out" / run / "report.json"))["stresses"]["xy"]["matrix"]
                      ["von_mises"]["p99"].get<double>());
  CHECK(value("xy_matrix_von_mises_p99_mean") == Approx((p99[0] + p99[1] + p99[2]) / 3).epsilon(1e-9));
  for (const char* column : {"xx_particulate_mean_xx_ci95", "yy_matrix_mean_yy_mean", "xy_particulate_mean_xy_std",
                             "thermal_matrix_mean_xx_mean", "thermal_particulate_mean_yy_ci95",
                             "thermal_matrix_von_mises_p99_std", "thermal_expansion_yy_ci95"})
    CHECK(std::find(names.begin(), names.end(), column) != names.end());
  std::vector<double> a11;
  for (const char* run : {"grains=20-r00", "grains=20-r01", "grains=20-r02"})
    a11.push_back(nlohmann::json::parse(test::read_file(dir / "out" / run / "report.json"))["effective"]
                      ["thermal_expansion"]["xx"].get<double>());
  CHECK(value("thermal_expansion_xx_mean") == Approx((a11[0] + a11[1] + a11[2]) / 3).epsilon(1e-9));
  // K and G, the bounds they are judged by, the achieved fractions, the state, and the
  // runs' warnings, each run's as its report has them.
  for (const char* column : {"bulk_modulus_mean", "shear_modulus_ci95", "voigt_C11_mean", "reuss_C11_mean",
                             "hs_bulk_lower_mean", "hs_shear_upper_mean", "achieved_fraction_matrix_mean",
                             "achieved_fraction_particulate_std"})
    CHECK(std::find(names.begin(), names.end(), column) != names.end());
  std::vector<double> K;
  int warned = 0;
  for (const char* run : {"grains=20-r00", "grains=20-r01", "grains=20-r02"}) {
    const auto report = nlohmann::json::parse(test::read_file(dir / "out" / run / "report.json"));
    K.push_back(report["effective"]["bulk_modulus"].get<double>());
    warned += report["warnings"].empty() ? 0 : 1;
  }
  CHECK(value("bulk_modulus_mean") == Approx((K[0] + K[1] + K[2]) / 3).epsilon(1e-9));
  CHECK(value("runs_with_warnings") == warned);
  // The runs' warnings were said by the sweep itself, not left in their logs alone.
  REQUIRE(warned > 0);
  CHECK(r.err.find("grainmesh: warning: sweep: grains=20-r0") != std::string::npos);
  CHECK(values[static_cast<std::size_t>(std::find(names.begin(), names.end(), "plane_state") - names.begin())] ==
        "plane_strain");
  CHECK(fs::exists(dir / "out/summary.png"));
  // A plot per answer: the moduli, the expansion, each phase's residual stress.
  for (const char* plot : {"summary_bulk_modulus.png", "summary_shear_modulus.png", "summary_thermal_expansion_xx.png",
                           "summary_thermal_matrix_mean_xx.png"})
    CHECK(fs::exists(dir / "out" / plot));
  CHECK_FALSE(fs::exists(dir / "out/grains=20-r00/stress_xx.png"));
}

TEST_CASE("editing a sweep's lists re-runs no unchanged point, deletes no finished run, and the summary follows",
          "[cli][sweep]") {
  test::ScratchDir dir("sweep-edits");
  const std::string out = (dir / "out").string();
  auto sweep = [&](const std::string& fractions) {
    write_sweep(dir / "sweep.ini", "phase.matrix.fraction = " + fractions + "\n");
    std::ofstream(dir / "sweep.ini", std::ios::app) << "[output]\npictures = none\n";
    const auto r = run_grainmesh({"sweep", (dir / "sweep.ini").string(), "-o", out, "--set", "tessellation.grains=20"});
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    return r;
  };
  // A run's identity on disk: its report's inode and modification time (a re-run writes a
  // new report, moved into place as a new file).
  auto identity = [&](const std::string& run) {
    struct stat s {};
    REQUIRE(::stat((dir / "out" / run / "report.json").c_str(), &s) == 0);
    return std::to_string(s.st_ino) + ":" + std::to_string(s.st_mtim.tv_sec) + "." + std::to_string(s.st_mtim.tv_nsec);
  };
  auto summary_rows = [&] {
    const std::string csv = test::read_file(dir / "out/summary.csv");
    return std::count(csv.begin(), csv.end(), '\n') - 1;
  };
  auto seed_of = [&](const std::string& run) {
    return nlohmann::json::parse(test::read_file(dir / "out" / run / "report.json"))["seed"].get<std::uint64_t>();
  };
  CHECK(ran(sweep("0.1, 0.3").out) == 2);
  const std::string a = identity("fraction=0.1-r00"), b = identity("fraction=0.3-r00");
  const std::uint64_t seed_a = seed_of("fraction=0.1-r00");
  CHECK(summary_rows() == 2);
  // Inserted at the front: only the new point runs; the others keep their runs and seeds.
  CHECK(ran(sweep("0.2, 0.1, 0.3").out) == 1);
  CHECK(identity("fraction=0.1-r00") == a);
  CHECK(identity("fraction=0.3-r00") == b);
  CHECK(seed_of("fraction=0.1-r00") == seed_a);
  CHECK(summary_rows() == 3);
  // Reordered: nothing runs.
  CHECK(ran(sweep("0.3, 0.2, 0.1").out) == 0);
  CHECK(identity("fraction=0.1-r00") == a);
  // Shortened: nothing runs, nothing is deleted (kept aside), the summary has what is planned.
  const auto shortened = sweep("0.1");
  CHECK(ran(shortened.out) == 0);
  CHECK(shortened.out.find("2 runs no longer in the plan kept in " + out + "/retired") != std::string::npos);
  CHECK(fs::exists(dir / "out/retired/fraction=0.3-r00/report.json"));
  CHECK(fs::exists(dir / "out/retired/fraction=0.2-r00/report.json"));
  CHECK(summary_rows() == 1);
  // Lengthened again: the kept runs come back, as they were.
  const auto restored = sweep("0.1, 0.3");
  CHECK(ran(restored.out) == 0);
  CHECK(identity("fraction=0.3-r00") == b);
  CHECK_FALSE(fs::exists(dir / "out/retired/fraction=0.3-r00"));
  CHECK(summary_rows() == 2);
}

TEST_CASE("run without --solve does not replace a solved run's answer unless --force", "[cli][safety]") {
  test::ScratchDir dir("unsolved-over-solved");
  const std::string out = (dir / "out").string();
  const std::vector<std::string> small{"--set", "tessellation.grains=10", "--set", "output.pictures=none"};
  auto run = [&](std::vector<std::string> args) {
    args.insert(args.end(), small.begin(), small.end());
    return run_grainmesh(args);
  };
  REQUIRE(run({"run", "-o", out, "--solve", "--quiet"}).exit_code == 0);
  const auto refused = run({"run", "-o", out, "--quiet"});
  CHECK(refused.exit_code == 4);
  CHECK(refused.err == "grainmesh: error: " + out + ": holds a solved run, whose answer a run without --solve would "
                       "replace with none: add --solve, give another OUT, or --force to replace it\n");
  CHECK(nlohmann::json::parse(test::read_file(dir / "out/report.json")).contains("effective"));  // untouched
  CHECK(run({"run", "-o", out, "--quiet", "--force"}).exit_code == 0);
  CHECK_FALSE(nlohmann::json::parse(test::read_file(dir / "out/report.json")).contains("effective"));
  // A periodic cell answered by the finite elements without --solve: run again the same way.
  const std::string fe = (dir / "fe").string();
  for (int k = 0; k < 2; ++k) {
    INFO("run " << k);
    REQUIRE(run({"run", "-o", fe, "--quiet", "--set", "homogenise.boundary=periodic"}).exit_code == 0);
    CHECK(nlohmann::json::parse(test::read_file(dir / "fe/report.json")).contains("effective"));
  }
}
