// `grainmesh run`: the one-shot pipeline, its OUT layout, its reproducibility from
// config.ini, and bad input.
#include <algorithm>
#include <fstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "export/foam_solver.hpp"
#include "helpers.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;

TEST_CASE("grainmesh run without a config writes the whole OUT layout, and its case passes checkMesh", "[cli][run]") {
  test::ScratchDir dir("run");
  const auto r = run_grainmesh({"run", "-o", (dir / "out").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());  // no progress display when stderr is no terminal
  for (const char* f : {"tessellation.json", "tessellation.png", "mesh.vtu", "mesh.png", "config.ini", "report.json",
                        "case/constant/polyMesh/faces", "case/0/D", "case/system/fvSolution", "case/Allrun"})
    CHECK(fs::exists(dir / "out" / f));
  const auto report = nlohmann::json::parse(test::read_file(dir / "out/report.json"));
  CHECK(report["grains"].get<int>() == 100);
  CHECK(report["phases"][1]["name"] == "matrix");
  CHECK(report["phases"][1]["achieved_fraction"].get<double>() == Approx(0.2).epsilon(0.01));
  CHECK(report["mesh"]["q_min"].get<double>() >= 0.6);
  CHECK(report["mesh"]["cells"].get<int>() > 8000);
  for (const char* stage : {"tessellate", "mesh", "export", "total"}) CHECK(report["seconds"][stage].get<double>() > 0.0);
  CHECK(report["case"] == "case");
  // The WC-Co descriptors, as tessellation.json has them.
  const auto tessellation = nlohmann::json::parse(test::read_file(dir / "out/tessellation.json"));
  for (const char* key : {"contiguity", "intercept_length", "mean_free_path"})
    CHECK(report["statistics"][key] == tessellation["statistics"][key]);
  const double contiguity = report["statistics"]["contiguity"]["particulate"].get<double>();
  CHECK((contiguity > 0.5 && contiguity < 1.0));  // the hard phase mostly touches itself at 80 %
  CHECK(report["statistics"]["mean_free_path"]["matrix"].get<double>() > 0.0);
  const auto check = test::run_openfoam(dir / "out/case", "checkMesh");
  CHECK(check.out.find("Mesh OK.") != std::string::npos);

  // config.ini repeats the run: every file the same, byte for byte, but the report's timings.
  const auto again = run_grainmesh({"run", (dir / "out/config.ini").string(), "-o", (dir / "again").string()});
  INFO(again.err);
  REQUIRE(again.exit_code == 0);
  int compared = 0;
  for (const fs::path& rel : test::files_under(dir / "again")) {
    if (rel.filename() == "report.json") continue;
    INFO(rel.string());
    CHECK(test::read_file(dir / "again" / rel) == test::read_file(dir / "out" / rel));
    ++compared;
  }
  CHECK(compared >= 15);
  // The summary names what is there: with the pictures, and without (output.pictures = false).
  const auto bare = run_grainmesh({"run", "-o", (dir / "bare").string(), "--set", "output.pictures=false"});
  REQUIRE(bare.exit_code == 0);
  CHECK(!fs::exists(dir / "bare/mesh.png"));
  for (const auto& [out, printed] : {std::pair{dir / "out", r.out}, std::pair{dir / "bare", bare.out}}) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(out))
      names.push_back(entry.path().filename().string() + (entry.is_directory() ? "/" : ""));
    std::sort(names.begin(), names.end());
    std::string expected = "wrote " + out.string() + "/{";
    for (std::size_t k = 0; k < names.size(); ++k) expected += (k > 0 ? ", " : "") + names[k];
    INFO(printed);
    CHECK(printed.find(expected + "}") != std::string::npos);
  }
  CHECK(r.out.find("mesh.png") != std::string::npos);
  CHECK(bare.out.find(".png") == std::string::npos);
}

TEST_CASE("bad run input gives one line naming it and never a report", "[cli][run]") {
  test::ScratchDir dir("run-bad");
  std::ofstream(dir / "plain-file") << "x";
  const std::vector<test::Refusal> cases{
      {{"run", "--set", "tessellation.bogus=1"}, 2, "unknown key 'tessellation.bogus'"},
      {{"run", "--set", "mesh.h=abc"}, 2, "mesh.h: 'abc' is not a number"},
      {{"run", "--set", "mesh.grading=0"}, 2, "mesh.grading: must lie between 0.05 and 10"},
      {{"run", "--set", "phase.matrix.nu=0.7"}, 2, "phase.matrix.nu: must lie in (-1, 0.5)"},
      {{"run", "--set", "export.cyclic=perhaps"}, 2, "export.cyclic"},
      {{"run", "--set", "output.pictures=some"}, 2, "output.pictures: must be none, basic or all, got 'some'"},
      {{"run", (dir / "missing.ini").string()}, 4, "missing.ini: cannot open config file"},
  };
  for (const auto& c : cases) test::check_refused(c, dir / "out");
  // An output directory that cannot be made: below a plain file.
  const auto r = run_grainmesh({"run", "-o", (dir / "plain-file/out").string()});
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("plain-file") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(dir / "plain-file/out/report.json"));
}

TEST_CASE("grainmesh run --solve homogenises: the modulus lies between Reuss and Voigt and falls with the matrix",
          "[cli][run][physics]") {
  test::ScratchDir dir("solve");
  double previous = 1e300;
  for (const char* matrix : {"0.1", "0.3", "0.5"}) {
    INFO("matrix fraction " << matrix);
    const fs::path out = dir / (std::string("m") + matrix);
    const auto r = run_grainmesh({"run", "-o", out.string(), "--solve", "--set", std::string("phase.matrix.fraction=") + matrix,
                                  "--set", "tessellation.grains=40"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto e = nlohmann::json::parse(test::read_file(out / "report.json"))["effective"];
    const double modulus = e["modulus"].get<double>();
    CHECK(modulus > e["reuss"].get<double>());
    CHECK(modulus < e["voigt"].get<double>());
    CHECK(e["final_residual"].get<double>() < kSolverTolerance);
    CHECK(e["stress_change"].get<double>() <= kStressTolerance);
    CHECK(modulus < previous);  // the matrix is the softer phase
    previous = modulus;
    CHECK(fs::exists(out / e["result"].get<std::string>() / kStressField));
    for (const char* picture : {"stress_xx.png", "stress_yy.png", "stress_xy.png", "displacement.png"})
      CHECK(fs::file_size(out / picture) > 10000);
  }
  // output.pictures = basic: the tessellation, the mesh, sigma_xx and results.vtu; none:
  // none of them.
  for (const char* which : {"basic", "none"}) {
    const fs::path out = dir / which;
    const auto r = run_grainmesh({"run", "-o", out.string(), "--solve", "--set", "tessellation.grains=40", "--set",
                                  std::string("output.pictures=") + which});
    REQUIRE(r.exit_code == 0);
    const bool basic = std::string(which) == "basic";
    for (const char* picture : {"tessellation.png", "mesh.png", "stress_xx.png", "results.vtu"})
      CHECK(fs::exists(out / picture) == basic);
    for (const char* picture : {"mesh_detail.png", "stress_yy.png", "stress_xy.png", "displacement.png"})
      CHECK_FALSE(fs::exists(out / picture));
  }
}

TEST_CASE("a run of more than 100,000 cells writes its case in binary unless export.format says ascii",
          "[cli][run][export]") {
#ifdef GRAINMESH_SANITIZED
  SUCCEED("100,000 cells mesh ten times slower in the sanitizer build: the release build tests this");
#else
  test::ScratchDir dir("binary-case");
  const auto big = run_grainmesh({"run", "-o", (dir / "big").string(), "--set", "tessellation.grains=1100", "--set",
                                  "domain.width=10", "--set", "domain.height=5.67", "--set", "output.pictures=none"});
  INFO(big.err);
  REQUIRE(big.exit_code == 0);
  const auto report = nlohmann::json::parse(test::read_file(dir / "big/report.json"));
  REQUIRE(report["mesh"]["cells"].get<int>() > 100'000);
  CHECK(report["case_format"] == "binary");
  CHECK(test::read_file(dir / "big/case/constant/polyMesh/owner").find("format      binary;") != std::string::npos);
  // The default cell stays ASCII.
  const auto small = run_grainmesh({"run", "-o", (dir / "small").string(), "--set", "output.pictures=none"});
  REQUIRE(small.exit_code == 0);
  CHECK(nlohmann::json::parse(test::read_file(dir / "small/report.json"))["case_format"] == "ascii");
#endif
}

TEST_CASE("output.cases = answers keeps a solved run's answers and drops its cases", "[cli][run]") {
  test::ScratchDir dir("answers-only");
  const std::vector<std::string> small{"--set", "tessellation.grains=20", "--set", "homogenise.boundary=periodic"};
  auto run = [&](const std::string& out, std::vector<std::string> args) {
    args.insert(args.begin(), {"run", "-o", (dir / out).string(), "--quiet"});
    args.insert(args.end(), small.begin(), small.end());
    return run_grainmesh(args);
  };
  REQUIRE(run("kept", {"--solve"}).exit_code == 0);
  const auto r = run("answers", {"--solve", "--set", "output.cases=answers"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto kept = nlohmann::json::parse(test::read_file(dir / "kept/report.json"));
  const auto answers = nlohmann::json::parse(test::read_file(dir / "answers/report.json"));
  // The same answer, its results and pictures; no case directory, and a small fraction of the disk.
  CHECK(answers["effective"]["stiffness"] == kept["effective"]["stiffness"]);
  for (const char* file : {"results.vtu", "stress_xx.png", "tessellation.json", "mesh.vtu", "config.ini"})
    CHECK(fs::exists(dir / "answers" / file));
  for (const char* name : {"case_xx", "case_yy", "case_xy"}) {
    CHECK(fs::exists(dir / "kept" / name));
    CHECK_FALSE(fs::exists(dir / "answers" / name));
  }
  CHECK(answers["cases"] == "dropped once solved (output.cases = answers)");
  std::uintmax_t kept_bytes = 0, answer_bytes = 0;
  for (const auto& f : fs::recursive_directory_iterator(dir / "kept")) kept_bytes += f.is_regular_file() ? f.file_size() : 0;
  for (const auto& f : fs::recursive_directory_iterator(dir / "answers")) answer_bytes += f.is_regular_file() ? f.file_size() : 0;
  CHECK(answer_bytes < kept_bytes / 2);
  // Nothing to keep but cases without a solve: refused, naming the key.
  test::check_refused({{"run", "--set", "output.cases=answers"}, 2, "output.cases: answers keeps a solved run's answers"},
                      dir / "refused");
  test::check_refused({{"run", "--set", "output.cases=some"}, 2, "output.cases: must be keep or answers, got 'some'"},
                      dir / "refused");
}
