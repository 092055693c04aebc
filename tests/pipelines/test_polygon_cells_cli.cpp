// export.cells = polygons end to end: `run` solves the dual cells and reports them,
// `export` turns a mesh.vtu into polygons (and writes them, which `check` and `export`
// read back), and an unknown value is refused.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "helpers.hpp"
#include "pipelines/laminate.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;
using Json = nlohmann::json;

TEST_CASE("export.cells = polygons: the run solves the dual cells, inside the bounds and near the triangles' answer",
          "[cli][dual][openfoam]") {
  test::ScratchDir dir("polygon_cells");
  const std::string config = (test::source_dir() / "data/default.ini").string();
  std::map<std::string, Json> report;
  for (const char* cells : {"triangles", "polygons"}) {
    const auto r = run_grainmesh({"run", config, "-o", (dir / cells).string(), "--quiet", "--solve", "--set",
                                  std::string("export.cells=") + cells});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    report[cells] = Json::parse(test::read_file(dir / cells / "report.json"));
  }
  const Json& poly = report["polygons"];
  const Json& tri = report["triangles"];
  CHECK_FALSE(tri.contains("case_cells"));
  // The solved cells drawn beside the triangles' detail.
  CHECK(fs::file_size(dir / "polygons/cells_detail.png") > 1000);
  CHECK_FALSE(fs::exists(dir / "triangles/cells_detail.png"));
  REQUIRE(poly.contains("case_cells"));
  CHECK(poly["case_cells"]["shape"] == "polygons");
  const double cells = poly["case_cells"]["cells"].get<double>(), triangles = poly["mesh"]["cells"].get<double>();
  // About 100 triangles per grain: a node has about two, a node on a grain boundary one
  // cell per grain.
  CHECK(cells <= 0.7 * triangles);
  CHECK(cells >= 0.5 * triangles);
  // The same mesh: the same triangles under both.
  CHECK(poly["mesh"] == tri["mesh"]);
  const Json& e = poly["effective"];
  CHECK(e["inside_bounds"]["hashin_shtrikman"] == true);
  CHECK(std::abs(e["modulus"].get<double>() / tri["effective"]["modulus"].get<double>() - 1.0) < 0.005);
  // The case's cells are the dual's, and checkMesh finds it OK.
  CHECK(test::read_file(dir / "polygons/case/0/E").find("nonuniform List<scalar> " + std::to_string(static_cast<long>(cells)) + "\n") !=
        std::string::npos);
  // checkMesh finds both OK, and the polygons' worst face less skewed from the line
  // joining its cells' centres than the triangles' (29 against 36 degrees).
  std::map<std::string, double> non_orthogonality;
  for (const char* cells : {"triangles", "polygons"}) {
    const std::string log = test::run_openfoam(dir / cells / "case", "checkMesh").out;
    CHECK(log.find("Mesh OK.") != std::string::npos);
    const std::string label = "Mesh non-orthogonality Max: ";
    REQUIRE(log.find(label) != std::string::npos);
    non_orthogonality[cells] = std::stod(log.substr(log.find(label) + label.size()));
  }
  CHECK(non_orthogonality["polygons"] < non_orthogonality["triangles"]);
}

TEST_CASE("export.cells: grainmesh export makes polygons of a mesh.vtu, and a bad value is refused",
          "[cli][dual]") {
  test::ScratchDir dir("polygon_export");
  const std::string config = (test::source_dir() / "data/default.ini").string();
  REQUIRE(run_grainmesh({"run", config, "-o", (dir / "run").string(), "--quiet"}).exit_code == 0);
  const auto e = run_grainmesh({"export", (dir / "run/mesh.vtu").string(), "--config", config, "-o",
                                (dir / "e").string(), "--set", "export.cells=polygons"});
  INFO(e.err);
  REQUIRE(e.exit_code == 0);
  const Json r = Json::parse(test::read_file(dir / "e/report.json"));
  const Json run = Json::parse(test::read_file(dir / "run/report.json"));
  CHECK(r["cells"].get<double>() < 0.7 * run["mesh"]["cells"].get<double>());
  REQUIRE(test::run_openfoam(dir / "e", "checkMesh").out.find("Mesh OK.") != std::string::npos);

  // The export's mesh.vtu holds the polygons (VTK polygons): the conformity checker
  // passes them, and the export takes them back as they are.
  const std::string tess = (dir / "run/tessellation.json").string(), cells_vtu = (dir / "e/mesh.vtu").string();
  const auto ok = run_grainmesh({"check", tess, cells_vtu});
  INFO(ok.err);
  CHECK(ok.exit_code == 0);
  CHECK(ok.out.find("conforms") != std::string::npos);
  CHECK(ok.out.find(std::to_string(r["cells"].get<long>()) + " polygonal cells") != std::string::npos);
  fs::create_directories(dir / "cells");
  fs::copy_file(cells_vtu, dir / "cells/mesh.vtu");
  fs::copy_file(dir / "run/mesh.json", dir / "cells/mesh.json");
  const auto again = run_grainmesh({"export", (dir / "cells/mesh.vtu").string(), "--config", config, "-o",
                                    (dir / "again").string(), "--set", "export.cells=polygons"});
  INFO(again.err);
  REQUIRE(again.exit_code == 0);
  CHECK(test::read_file(dir / "again/constant/polyMesh/faces") == test::read_file(dir / "e/constant/polyMesh/faces"));
  test::check_refused({{"export", (dir / "cells/mesh.vtu").string(), "--config", config, "--set", "export.cells=triangles"}, 2,
                       "export.cells: is triangles, but"},
                      dir / "bad");

  test::check_refused({{"run", config, "--set", "export.cells=hexagons"}, 2, "export.cells: must be triangles or polygons, got 'hexagons'"},
                      dir / "bad");
  test::check_refused({{"export", (dir / "run/mesh.vtu").string(), "--config", config, "--set", "export.cells=3"}, 2,
                       "export.cells: must be triangles or polygons, got '3'"},
                      dir / "bad");
}

TEST_CASE("grainmesh converge with polygonal cells counts the case's cells, and with the finite elements as "
          "OpenFOAM's reference states each level's error against them",
          "[cli][dual][openfoam][converge]") {
  test::ScratchDir dir("polygon_converge");
  // (The sanitizer build runs the study on 16 grains: its OpenFOAM solves took 80 s on 100.)
#ifdef GRAINMESH_SANITIZED
  const std::string grains = "tessellation.grains=16";
#else
  const std::string grains = "tessellation.grains=100";
#endif
  const auto r = run_grainmesh({"converge", "-o", (dir / "c").string(), "--levels", "3", "--start", "8", "--set",
                                "export.cells=polygons", "--set", "homogenise.boundary=periodic", "--set",
                                "homogenise.solver=openfoam", "--set", "homogenise.reference=fe", "--set", grains});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Json study = Json::parse(test::read_file(dir / "c/report.json"));
  REQUIRE(study.contains("levels"));
  std::vector<Json> runs;
  for (const Json& level : study["levels"]) {
    runs.push_back(Json::parse(test::read_file(dir / "c" / level["directory"].get<std::string>() / "report.json")));
    const Json& run = runs.back();
    CHECK(level["cells"].get<double>() == run["case_cells"]["cells"].get<double>());
    // The dual of the mesh split `refine` times: a cell per node (more where a grain
    // boundary splits it), fewer than the triangles, more than half as many.
    const double triangles = run["mesh"]["cells"].get<double>() * std::pow(4.0, level["refine"].get<int>());
    CHECK(level["cells"].get<double>() < triangles);
    CHECK(level["cells"].get<double>() > 0.5 * triangles);
  }
  // Each level's error against the finite elements is its run's; the study's estimate is
  // the finest level's own (its difference from the reference plus the reference's
  // estimate), and OpenFOAM's error shrinks level by level.
  for (const char* q : {"C11", "C22", "C12", "C66"}) {
    CAPTURE(q);
    const Json& st = study["study"][q];
    CHECK(st["error_basis"] == "reference");
    const Json& finest = runs.back()["effective"];
    CHECK(st["error_estimate"].get<double>() == finest["error_estimate"]["stiffness"][q].get<double>());
    CHECK(st["error_estimate"].get<double>() >= std::abs(finest["discretisation_error"]["stiffness"][q].get<double>()));
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const double error = study["levels"][k]["reference_error"][q].get<double>();
      CHECK(error == runs[k]["effective"]["discretisation_error"]["stiffness"][q].get<double>());
      if (k > 0) CHECK(std::abs(error) < std::abs(study["levels"][k - 1]["reference_error"][q].get<double>()));
    }
  }
  CHECK(r.out.find(" % against the finite elements), ") != std::string::npos);  // the summary says so
}

TEST_CASE("polygonal cells on one material: the exact modulus and uniform phase statistics", "[cli][dual][openfoam][physics]") {
  // The default cell with both phases 800 GPa, nu 0.1, as polygons: the mixed load's
  // uniaxial strain e gives sigma_xx = M e in every cell, so the modulus is M and each
  // phase's statistics are the uniform state's (as test_homogenise_cli holds triangles to).
  test::ScratchDir dir("polygon_one");
  const test::Material m{800e9, 0.1};
  const auto r = run_grainmesh({"run", "-o", (dir / "one").string(), "--quiet", "--solve", "--set", "phase.matrix.E=800e9",
                                "--set", "export.cells=polygons"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Json report = Json::parse(test::read_file(dir / "one/report.json"));
  REQUIRE(report.contains("case_cells"));
  CHECK(report["effective"]["modulus"].get<double>() == Approx(m.M()).epsilon(1e-3));
  const double strain = 0.001 / 3.0;
  const Json& stresses = report["stresses"]["mixed"];
  double fractions = 0.0;
  for (const char* phase : {"particulate", "matrix"}) {
    INFO(phase);
    const Json& s = stresses[phase];
    fractions += s["volume_fraction"].get<double>();
    CHECK(s["mean"]["xx"].get<double>() == Approx(m.M() * strain).epsilon(1e-4));
    CHECK(s["mean"]["zz"].get<double>() == Approx(m.lambda() * strain).epsilon(1e-4));
    CHECK(s["von_mises"]["mean"].get<double>() == Approx(2 * m.mu() * strain).epsilon(1e-4));
    CHECK(s["von_mises"]["std"].get<double>() < 1e-4 * m.M() * strain);
    CHECK(s["partition"].get<double>() == Approx(1.0).epsilon(1e-4));
  }
  CHECK(fractions == Approx(1.0).epsilon(1e-12));
  CHECK(stresses["matrix"]["volume_fraction"].get<double>() == Approx(0.2).epsilon(0.02));
}
