// One config serves every command: `tessellate`, `mesh` and `export` take the run config
// `run` takes, each reading its own keys, and give what `run` gives; a key no stage knows
// is still refused.
#include <catch2/catch.hpp>

#include "helpers.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;

TEST_CASE("the stage commands accept the run config and give the run's outputs", "[cli][config]") {
  test::ScratchDir dir("stage_config");
  const std::string config = (test::source_dir() / "data/default.ini").string();
  const std::string quick = "mesh.triangles_per_grain=30";
  REQUIRE(run_grainmesh({"run", config, "-o", (dir / "run").string(), "--quiet", "--set", quick}).exit_code == 0);

  const auto t = run_grainmesh({"tessellate", config, "-o", (dir / "t").string(), "--set", quick});
  INFO(t.err);
  REQUIRE(t.exit_code == 0);
  const auto m = run_grainmesh({"mesh", (dir / "t/tessellation.json").string(), "--config", config, "-o",
                                (dir / "m").string(), "--set", quick});
  INFO(m.err);
  REQUIRE(m.exit_code == 0);
  const auto e = run_grainmesh({"export", (dir / "m/mesh.vtu").string(), "--config", config, "-o",
                                (dir / "e").string(), "--set", quick});
  INFO(e.err);
  REQUIRE(e.exit_code == 0);

  // The run config's mesh.h-style keys, phases' moduli and load reach their stages.
  CHECK(test::read_file(dir / "t/tessellation.json") == test::read_file(dir / "run/tessellation.json"));
  CHECK(test::read_file(dir / "m/mesh.vtu") == test::read_file(dir / "run/mesh.vtu"));
  for (const char* f : {"constant/polyMesh/points", "constant/polyMesh/faces", "constant/polyMesh/boundary",
                        "constant/polyMesh/cellZones", "0/D", "0/E", "0/nu", "constant/mechanicalProperties",
                        "system/fvSolution"})
    CHECK(test::read_file(dir / "e" / f) == test::read_file(dir / "run/case" / f));

  // A key that no stage knows is refused by each, naming it; nothing is written.
  const std::string bogus = "tessellation.bogus=1";
  const std::vector<std::vector<std::string>> refused{
      {"tessellate", config, "-o", (dir / "t2").string(), "--set", bogus},
      {"mesh", (dir / "t/tessellation.json").string(), "--config", config, "-o", (dir / "t2").string(), "--set", bogus},
      {"export", (dir / "m/mesh.vtu").string(), "--config", config, "-o", (dir / "t2").string(), "--set", bogus}};
  for (const auto& args : refused) {
    INFO(args[0]);
    const auto r = run_grainmesh(args);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("unknown key 'tessellation.bogus'") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "t2"));
  }
}
