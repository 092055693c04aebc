// `grainmesh export`, driven as a user would: a case from a grain mesh and from a domain
// mesh, replacing an earlier export, and bad input.
#include <algorithm>
#include <fstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "analysis/foam_fields.hpp"
#include "export/foam_solver.hpp"
#include "helpers.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;

TEST_CASE("grainmesh export writes a case that OpenFOAM runs, from grain and domain meshes", "[cli][export]") {
  test::ScratchDir dir("export");
  REQUIRE(run_grainmesh({"tessellate", test::example("grains_wc_co").string(), "-o", (dir / "t").string(), "--set",
                         "tessellation.grains=30"})
              .exit_code == 0);
  REQUIRE(run_grainmesh({"mesh", (dir / "t/tessellation.json").string(), "-o", (dir / "m").string(), "--set",
                         "mesh.triangles_per_grain=40"})
              .exit_code == 0);
  const std::string vtu = (dir / "m/mesh.vtu").string();
  const auto r = run_grainmesh({"export", vtu, "-o", (dir / "case").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* f : {"constant/polyMesh/faces", "constant/polyMesh/cellZones", "constant/polyMesh/faceZones", "0/D",
                        "0/E", "0/nu", "constant/mechanicalProperties", "system/fvSolution", "Allrun", "case.foam",
                        "mesh.vtu", "report.json"})
    CHECK(fs::exists(dir / "case" / f));
  const auto report = nlohmann::json::parse(test::read_file(dir / "case/report.json"));
  CHECK(report["phases"][0]["name"] == "WC");
  CHECK(report["phases"][1]["E"].get<double>() == 211e9);
  const auto allrun = std::system(("sh " + test::shell_quote((dir / "case/Allrun").string()) + " > /dev/null").c_str());
  CHECK(allrun == 0);
  CHECK(test::read_file(dir / "case/log.checkMesh").find("Mesh OK.") != std::string::npos);
  const fs::path result = latest_time_dir(dir / "case");
  CHECK(fs::exists(result / kStressField));

  // An earlier export, with what Allrun added to it, is replaced; see test_safety_cli.cpp
  // for what is not.
  CHECK(run_grainmesh({"export", vtu, "-o", (dir / "case").string(), "--set", "export.format=binary"}).exit_code == 0);
  CHECK_FALSE(fs::exists(result));

  // A domain mesh: its two regions become the phases matrix and inclusion.
  REQUIRE(run_grainmesh({"domain", test::example("fibres_6").string(), "-o", (dir / "f").string()}).exit_code == 0);
  const auto fibres = run_grainmesh({"export", (dir / "f/mesh.vtu").string(), "-o", (dir / "fcase").string(), "--set",
                                     "phase.matrix.E=3e9", "--set", "phase.matrix.nu=0.35", "--set",
                                     "phase.inclusion.E=70e9", "--set", "phase.inclusion.nu=0.22"});
  INFO(fibres.err);
  REQUIRE(fibres.exit_code == 0);
  const auto check = test::run_openfoam(dir / "fcase", "checkMesh");
  CHECK(check.out.find("Mesh OK.") != std::string::npos);
  CHECK(check.out.find("inclusion") != std::string::npos);
}

TEST_CASE("bad export input gives one line naming what is wrong and no case", "[cli][export]") {
  test::ScratchDir dir("export-bad");
  REQUIRE(run_grainmesh({"tessellate", test::example("grains_wc_co").string(), "-o", (dir / "t").string(), "--set",
                         "tessellation.grains=20"})
              .exit_code == 0);
  REQUIRE(run_grainmesh({"mesh", (dir / "t/tessellation.json").string(), "-o", (dir / "m").string(), "--set",
                         "mesh.triangles_per_grain=20"})
              .exit_code == 0);
  REQUIRE(run_grainmesh({"domain", test::example("fibres_6").string(), "-o", (dir / "f").string()}).exit_code == 0);
  const std::string vtu = (dir / "m/mesh.vtu").string();
  std::ofstream(dir / "broken.vtu") << "<VTKFile type=\"UnstructuredGrid\"";
  std::ofstream(dir / "broken.json") << "{}";
  fs::create_directories(dir / "full");
  std::ofstream(dir / "full/keep.txt") << "mine";
  const std::vector<test::Refusal> cases{
      {{"export", (dir / "none.vtu").string()}, 4, "none.vtu"},
      {{"export", (dir / "broken.vtu").string()}, 4, "broken.vtu"},
      {{"export", (dir / "f/mesh.vtu").string()}, 2, "phase.matrix.E: missing"},
      {{"export", vtu, "--set", "phase.WC.nu=0.5"}, 2, "phase.WC.nu: must lie in (-1, 0.5), got 0.5"},
      {{"export", vtu, "--set", "phase.WC.E=-1"}, 2, "phase.WC.E: must be positive"},
      {{"export", vtu, "--set", "phase.Ni.E=1e9"}, 2, "phase.Ni.E: the mesh has no phase named 'Ni'"},
      {{"export", vtu, "--set", "export.format=hdf5"}, 2, "export.format: must be a list of ascii or binary (the OpenFOAM case), gmsh"},
      {{"export", vtu, "--set", "export.format=binary, ascii"}, 2, "export.format: names the case's encoding twice"},
      {{"export", vtu, "--set", "export.convert_to_meters=0"}, 2, "export.convert_to_meters: must be positive"},
      {{"export", vtu, "--set", "export.cyclic=maybe"}, 2, "export.cyclic"},
  };
  for (const auto& c : cases) test::check_refused(c, dir / "out");
  const auto full = run_grainmesh({"export", vtu, "-o", (dir / "full").string()});
  CHECK(full.exit_code == 4);
  CHECK(full.err.find("not a grainmesh output") != std::string::npos);
  CHECK(test::entries(dir / "full") == 1);
}
