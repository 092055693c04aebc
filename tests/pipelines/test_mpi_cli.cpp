// The solve on several MPI processes (solve.processes): decomposePar, mpirun ... -parallel,
// reconstructPar, then the same homogenisation as the serial solve, and the same answer.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "helpers.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

Json report_of(const fs::path& dir) { return Json::parse(test::read_file(dir / "report.json")); }

}  // namespace

TEST_CASE("on two MPI processes the default cell's mixed modulus and periodic tensor equal the serial ones",
          "[cli][mpi][openfoam]") {
  test::ScratchDir dir("mpi");
  for (const char* boundary : {"mixed", "periodic"}) {
    INFO(boundary);
    Json effective[2];
    for (const int processes : {1, 2}) {
      const fs::path out = dir / (std::string(boundary) + std::to_string(processes));
      const auto r = test::run_grainmesh({"run", "-o", out.string(), "--solve", "--set",
                                          std::string("homogenise.boundary=") + boundary, "--set",
                                          "solve.processes=" + std::to_string(processes), "--set",
                                          "output.pictures=none"});
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
      const Json report = report_of(out);
      effective[processes - 1] = report["effective"];
      CHECK(effective[processes - 1]["processes"].get<int>() == processes);
      // The solve's memory counts the solver's processes with grainmesh's own: more than
      // grainmesh alone needed to export the case.
      CHECK(report["memory_mib"]["solve"].get<double>() > report["memory_mib"]["export"].get<double>() + 20.0);
      // OpenFOAM's steps timed: decomposePar and reconstructPar only on several processes.
      const Json steps = boundary == std::string("mixed") ? effective[processes - 1]["seconds"]
                                                          : effective[processes - 1]["load_cases"][0]["seconds"];
      CHECK(steps["solidDisplacementFoam"].get<double>() > 0.0);
      CHECK((steps["decomposePar"].get<double>() > 0.0) == (processes > 1));
      CHECK((steps["reconstructPar"].get<double>() > 0.0) == (processes > 1));
    }
    // Different GAMG paths stop at different corrections: equal to the stress's own
    // settling tolerance (1e-6; measured: 8e-8 mixed, at most 6e-8 periodic).
    if (std::string(boundary) == "mixed") {
      CHECK(effective[1]["modulus"].get<double>() == Approx(effective[0]["modulus"].get<double>()).epsilon(1e-6));
    } else {
      const double scale = effective[0]["stiffness"]["C11"].get<double>();
      for (const char* c : {"C11", "C22", "C12", "C66", "C16", "C26"})
        CHECK(std::abs(effective[1]["stiffness"][c].get<double>() - effective[0]["stiffness"][c].get<double>()) <=
              1e-6 * scale);
    }
  }
  // The parallel case as written: its Allrun decomposes, solves on two processes and
  // reconstructs; each cyclic face stays on its partner's processor.
  const fs::path parallel_case = dir / "periodic2/case_xx";
  CHECK(fs::exists(parallel_case / "processor1"));
  const std::string allrun = test::read_file(parallel_case / "Allrun");
  CHECK(allrun.find("decomposePar -force") != std::string::npos);
  CHECK(allrun.find("mpirun --oversubscribe -np 2 solidDisplacementFoam -parallel") != std::string::npos);
  CHECK(allrun.find("reconstructPar -latestTime") != std::string::npos);
  CHECK(test::read_file(parallel_case / "system/decomposeParDict").find("preservePatches") != std::string::npos);
}

TEST_CASE("a failing decomposePar or mpirun is named with its log, and no answer is reported", "[cli][mpi]") {
  test::ScratchDir dir("mpi-fail");
  // A stand-in for `program` (first on PATH) that says `says` and exits 3; the case's
  // log of `logged` (the step whose log holds what it said) is named in one line.
  auto refused_with = [&](const std::string& program, const std::string& says, const std::string& logged) {
    const fs::path bin = dir / ("bin-" + program);
    fs::create_directories(bin);
    std::ofstream(bin / program) << "#!/bin/sh\necho '" << says << "'\nexit 3\n";
    fs::permissions(bin / program, fs::perms::owner_all);
    const fs::path out = dir / ("out-" + program);
    const auto r = test::run_grainmesh({"run", "-o", out.string(), "--solve", "--set", "solve.processes=2", "--set",
                                        "output.pictures=none"},
                                       {}, "PATH=" + bin.string() + ":$PATH");
    INFO(program);
    CHECK(r.exit_code == 6);
    CHECK(r.err == "grainmesh: error: --solve: " + program + " failed (exit code 3); see " + out.string() +
                       ".failed/case/log." + logged + "\n");
    CHECK_FALSE(fs::exists(out));
    CHECK(test::read_file(out.string() + ".failed/case/log." + logged).find(says) != std::string::npos);
    CHECK_FALSE(report_of(out.string() + ".failed").contains("effective"));
  };
  refused_with("decomposePar", "FOAM FATAL ERROR: no decomposition", "decomposePar");
  refused_with("mpirun", "mpirun was unable to launch the specified application", "solidDisplacementFoam");
  const fs::path out = dir / "out";
  // A count that is not one refused before any work.
  const auto bad = test::run_grainmesh({"run", "-o", out.string(), "--set", "solve.processes=0"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("solve.processes: must be a count from 1 to 1024, got 0") != std::string::npos);
}
