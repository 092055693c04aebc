// grainmesh run --solve on 3D configs: the periodic cell's six load cases into the 6 x 6
// stiffness with its bounds, and the mixed load, serial and on two MPI processes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "grains3d/conformity_3d.hpp"
#include "common/text_file.hpp"
#include "tessellate/label_image.hpp"
#include "view/picture.hpp"
#include "helpers.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;

namespace {

nlohmann::json solved_report(const fs::path& out, const std::vector<std::string>& sets) {
  std::vector<std::string> args{"run", test::example("grains_3d_wc_co").string(), "-o", out.string(), "--solve",
                                "--set", "tessellation.grains=30", "--set", "mesh.tets_per_grain=200"};
  for (const std::string& s : sets) {
    args.push_back("--set");
    args.push_back(s);
  }
  const auto r = run_grainmesh(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(test::read_file(out / "report.json"));
}

// The share of an image's pixels that are `rgb` darkened by a factor of 0.5 to 1 (to 8-bit
// rounding): a phase's colour on any of the lit sides of a 3D view.
double colour_share(const LabelImage& image, std::array<double, 3> rgb) {
  std::size_t hits = 0;
  for (const std::uint32_t c : image.labels) {
    const std::array<double, 3> px{double(c >> 16 & 0xff), double(c >> 8 & 0xff), double(c & 0xff)};
    const double s = (px[0] + px[1] + px[2]) / (255.0 * (rgb[0] + rgb[1] + rgb[2]));
    bool match = s >= 0.5 && s <= 1.01;
    for (int k = 0; k < 3; ++k) match = match && std::abs(px[k] - 255.0 * s * rgb[k]) <= 3.0;
    hits += match;
  }
  return static_cast<double>(hits) / static_cast<double>(image.labels.size());
}

}  // namespace

TEST_CASE("grainmesh run --solve on a periodic 3D cell: six load cases, the 6 x 6 stiffness, its bounds",
          "[cli][solve][run3d]") {
  test::ScratchDir dir("run3d_solve");
  const auto report = solved_report(dir / "p", {"homogenise.boundary=periodic", "homogenise.solver=openfoam", "homogenise.reference=fe"});
  CHECK(report["solved"].get<bool>());
  CHECK(report["case_cells"]["shape"] == "polyhedra");
  // The xx case's stresses on the section z = output.section x depth.
  for (const char* f : {"stress_xx.png", "von_mises.png", "von_mises_view.png"}) CHECK(fs::file_size(dir / "p" / f) > 10000);
  // The cell seen from outside: both phases' colours (lit, so scaled) cover its surface.
  const LabelImage view = read_label_image(dir / "p" / "mesh_view.png");
  for (int phase : {0, 1}) {
    CAPTURE(phase);
    CHECK(colour_share(view, label_colour(phase)) > 0.02);
  }
  const auto& eff = report["effective"];
  CHECK(eff["boundary"] == "periodic");
  REQUIRE(eff["load_cases"].size() == 6);
  for (std::size_t k = 0; k < 6; ++k) {
    const char* c = std::array{"xx", "yy", "zz", "yz", "xz", "xy"}[k];
    CHECK(fs::exists(dir / "p" / ("case_" + std::string(c)) / "system" / "controlDict"));
    CHECK(eff["load_cases"][k]["name"] == c);
    CHECK(eff["load_cases"][k]["corrections"].get<int>() > 0);
    for (const char* phase : {"WC", "Co"}) CHECK(report["stresses"][c][phase]["von_mises"]["max"].get<double>() > 0.0);
  }
  // Twenty-one components, the tensor symmetric and between the Reuss and Voigt tensors.
  CHECK(eff["stiffness"].size() == 21);
  CHECK(eff["symmetry_error"].get<double>() < 1e-3);
  CHECK(eff["inside_bounds"]["voigt_reuss"].get<bool>());
  // Hashin-Shtrikman's bounds hold for isotropic cells: this small coarse one keeps them
  // to within 2 % (measured: K 0.07 %, G 1.5 % above the upper), a broken one a warning.
  const double K = eff["bulk_modulus"].get<double>(), G = eff["shear_modulus"].get<double>();
  const auto& hs = eff["hashin_shtrikman"];
  CHECK(K > hs["bulk_lower"].get<double>());
  CHECK(K < 1.02 * hs["bulk_upper"].get<double>());
  CHECK(G > hs["shear_lower"].get<double>());
  CHECK(G < 1.02 * hs["shear_upper"].get<double>());
  if (!eff["inside_bounds"]["hashin_shtrikman"].get<bool>())
    CHECK(report["warnings"].dump().find("Hashin-Shtrikman upper bound") != std::string::npos);
  // Engineering constants of a nearly isotropic cell: E between the phases', nu near theirs.
  CHECK(eff["engineering"]["E_x"].get<double>() > 211e9);
  CHECK(eff["engineering"]["E_x"].get<double>() < 700e9);
  CHECK(std::abs(eff["engineering"]["nu_xy"].get<double>() - 0.25) < 0.03);
  CHECK(eff["anisotropy"]["universal"].get<double>() < 0.05);
  // The phases' volumes: the cells', the tessellation's but for the bent faces meshed as one
  // surface, which move no phase by more than its grains move (report: mesh).
  const double moved = report["mesh"]["grain_volume_change_max"].get<double>();
  CHECK(moved < kBentFaceVolume);
  const double achieved = report["phases"][1]["achieved_fraction"].get<double>();
  CHECK(std::abs(eff["volume_fractions"][1].get<double>() - achieved) <= moved * achieved + 1e-9);
  // The mean stress of the xx case: the phases' volume-weighted means of the cell
  // stresses add up to it within 1 % (measured 0.5 %: the cells' gradients, unlike the
  // face forces, do not average to the imposed strain exactly).
  const auto& s = report["stresses"]["xx"];
  const double mean_xx = s["WC"]["volume_fraction"].get<double>() * s["WC"]["mean"]["xx"].get<double>() +
                         s["Co"]["volume_fraction"].get<double>() * s["Co"]["mean"]["xx"].get<double>();
  CHECK(mean_xx == Approx(eff["stiffness"]["C11"].get<double>() * eff["load_cases"][0]["strain"]["xx"].get<double>()).epsilon(1e-2));
  // The stiffness from the volume average of the cells' own stresses: biased next to the
  // interfaces, within 1 % (measured C11 0.4 % above).
  CHECK(eff["volume_average"]["stiffness"]["C11"].get<double>() == Approx(eff["stiffness"]["C11"].get<double>()).epsilon(1e-2));
  // The finite-element reference on the same tetrahedra: between the Reuss and Voigt
  // bounds' diagonals, and the dual cells' answer near it (first order in the cells' size:
  // measured 0.9 to 1.1 % in the normal and 1.8 to 2.0 % in the shear diagonals of this
  // small coarse cell; 100 grains at the default density 0.6 and 1.1 to 1.25 %).
  const auto& ref = eff["reference"];
  CHECK(ref["unknowns"].get<int>() > 1000);
  for (const char* c : {"C11", "C22", "C33", "C44", "C55", "C66"}) {
    INFO(c);
    CHECK(ref["stiffness"][c].get<double>() < eff["voigt"][c].get<double>());
    CHECK(ref["stiffness"][c].get<double>() > eff["reuss"][c].get<double>());
    CHECK(std::abs(eff["discretisation_error"]["stiffness"][c].get<double>()) < 0.03);
  }
}

TEST_CASE("grainmesh run --solve on a 3D cell under the mixed load, serial and on two MPI processes",
          "[cli][solve][run3d][mpi]") {
  test::ScratchDir dir("run3d_mixed");
  const auto one = solved_report(dir / "one", {});
  const auto two = solved_report(dir / "two", {"solve.processes=2"});
  const auto& eff = one["effective"];
  CHECK(eff["boundary"] == "mixed");
  CHECK(eff["inside_bounds"]["voigt_reuss"].get<bool>());
  CHECK(eff["modulus"].get<double>() > eff["reuss"].get<double>());
  CHECK(eff["modulus"].get<double>() < eff["voigt"].get<double>());
  CHECK(two["effective"]["processes"].get<int>() == 2);
  CHECK(two["effective"]["seconds"]["decomposePar"].get<double>() > 0.0);
  CHECK(two["effective"]["modulus"].get<double>() == Approx(eff["modulus"].get<double>()).epsilon(1e-5));

  // One material (Co given WC's constants): held sideways, the cell's modulus is exactly
  // lambda + 2 mu, and every cell carries the same stress, so each phase's mean, von
  // Mises spread and hydrostatic stress are the uniaxial strain's own.
  const auto one_material = solved_report(dir / "uniform", {"phase.Co.E=700e9", "phase.Co.nu=0.24"});
  const double E = 700e9, nu = 0.24, strain = one_material["effective"]["strain_xx"].get<double>();
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  CHECK(one_material["effective"]["modulus"].get<double>() == Approx(lambda + 2 * mu).epsilon(1e-9));
  // The volume average of the cells' stresses: the same uniform state, component by component.
  const auto& average = one_material["effective"]["volume_average"];
  CHECK(average["modulus"].get<double>() == Approx(lambda + 2 * mu).epsilon(1e-9));
  CHECK(average["sigma_yy"].get<double>() == Approx(lambda * strain).epsilon(1e-9));
  CHECK(average["sigma_zz"].get<double>() == Approx(lambda * strain).epsilon(1e-9));
  for (const char* shear : {"sigma_yz", "sigma_xz", "sigma_xy"}) CHECK(std::abs(average[shear].get<double>()) < 1e-9 * mu * strain);
  for (const char* phase : {"WC", "Co"}) {
    CAPTURE(phase);
    const auto& s = one_material["stresses"]["mixed"][phase];
    CHECK(s["mean"]["xx"].get<double>() == Approx((lambda + 2 * mu) * strain).epsilon(1e-9));
    CHECK(s["mean"]["yy"].get<double>() == Approx(lambda * strain).epsilon(1e-9));
    CHECK(std::abs(s["mean"]["xy"].get<double>()) < 1e-9 * lambda * strain);
    CHECK(s["von_mises"]["max"].get<double>() == Approx(2 * mu * strain).epsilon(1e-9));
    CHECK(s["von_mises"]["std"].get<double>() < 1e-9 * mu * strain);
    CHECK(s["hydrostatic"]["mean"].get<double>() == Approx((lambda + 2 * mu / 3) * strain).epsilon(1e-9));
  }
}

TEST_CASE("grainmesh converge and sweep take 3D configs: levels in tetrahedra per grain, the 3D tensor's columns",
          "[cli][solve][run3d]") {
  test::ScratchDir dir("run3d_study");
  const std::string cfg = test::example("grains_3d_wc_co").string();
  // A study of three nested levels on a small periodic cell, solved by OpenFOAM (small: the
  // sanitizer build runs it too, on half the grains and without judging the limits, which
  // need the twelve; the finite elements' third level would solve 512 times the first
  // mesh's tetrahedra in second order).
#ifdef GRAINMESH_SANITIZED
  const std::string grains = "tessellation.grains=6";
#else
  const std::string grains = "tessellation.grains=12";
#endif
  const auto c = run_grainmesh({"converge", cfg, "-o", (dir / "c").string(), "--levels", "3", "--start", "10", "--set",
                                grains, "--set", "homogenise.boundary=periodic", "--set", "homogenise.solver=openfoam"});
  INFO(c.err);
  REQUIRE(c.exit_code == 0);
  const auto study = nlohmann::json::parse(test::read_file(dir / "c" / "report.json"));
  REQUIRE(study["levels"].size() == 3);
  for (int k = 0; k < 3; ++k) {
    CHECK(study["levels"][k]["tets_per_grain"].get<int>() == 10 << (3 * k));
    CHECK(study["levels"][k]["refine"].get<int>() == k);
  }
  // The polyhedra: the dual of eight times the tetrahedra of the level before.
  CHECK(study["levels"][2]["cells"].get<double>() > 4 * study["levels"][1]["cells"].get<double>());
#ifndef GRAINMESH_SANITIZED
  for (const char* q : {"C11", "C22", "C33", "C12", "C13", "C23", "C44", "C55", "C66"}) {
    CAPTURE(q);
    const double finest = study["study"][q]["values"][2].get<double>(), limit = study["study"][q]["limit"].get<double>();
    CHECK(std::abs(limit / finest - 1.0) < 0.02);
  }
#endif
  CHECK(test::read_file(dir / "c" / "convergence.csv").rfind("level,tets_per_grain,cells,seconds,C11,C22,C33", 0) == 0);

  // A sweep over the Co fraction, two realisations each (one in the sanitizer build: the
  // means are the same code), cooled, collected: the 3D tensor's columns and the expansion
  // tensor's, and a stiffer cell with less Co, which expands less (Co's alpha the larger).
#ifdef GRAINMESH_SANITIZED
  const std::string realisations = "1";
#else
  const std::string realisations = "2";
#endif
  const fs::path ini = dir / "sweep.ini";
  write_text_file(ini, test::read_file(cfg) + "\n[sweep]\nphase.Co.fraction = 0.1, 0.25\nrealisations = " + realisations +
                            "\n[homogenise]\nboundary = periodic\n[mesh]\ntets_per_grain = 30\n");
  const auto s = run_grainmesh({"sweep", ini.string(), "-o", (dir / "s").string(), "--solve", "--set",
                                "tessellation.grains=8", "--set", "load.delta_T=-500", "--set",
                                "phase.WC.alpha=5.2e-6", "--set", "phase.Co.alpha=13.8e-6"});
  INFO(s.err);
  REQUIRE(s.exit_code == 0);
  REQUIRE(run_grainmesh({"sweep", "--collect", (dir / "s").string()}).exit_code == 0);
  // summary.csv: a header and a row per point, comma-separated.
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(test::read_file(dir / "s" / "summary.csv"));
  for (std::string line; std::getline(lines, line);) {
    rows.emplace_back();
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) rows.back().push_back(field);
  }
  REQUIRE(rows.size() == 3);
  const std::vector<std::string>& header = rows[0];
  auto column = [&](const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    return at == header.end() ? -1 : static_cast<int>(at - header.begin());
  };
  for (const char* name : {"C33_mean", "C44_mean", "E_z_mean", "universal_anisotropy_mean", "xx_Co_mean_xx_mean",
                           "thermal_Co_mean_xx_mean", "thermal_expansion_zz_mean", "thermal_expansion_xy_mean"}) {
    CAPTURE(name);
    CHECK(column(name) >= 0);
  }
  REQUIRE(column("C11_mean") >= 0);
  CHECK(rows[1][column("runs")] == realisations);
  CHECK(rows[2][column("runs")] == realisations);
  CHECK(std::stod(rows[1][column("C11_mean")]) > std::stod(rows[2][column("C11_mean")]));
  REQUIRE(column("thermal_expansion_xx_mean") >= 0);
  CHECK(std::stod(rows[1][column("thermal_expansion_xx_mean")]) < std::stod(rows[2][column("thermal_expansion_xx_mean")]));
}

TEST_CASE("3D pictures' scale bars carry the run's length unit", "[cli][run3d]") {
  // The same cell in micrometres and in millimetres: the same geometry, the pictures' scale
  // bars labelled apart (they read "1" alone before).
  test::ScratchDir dir("scale-unit");
  std::ofstream(dir / "cell.ini") << "[domain]\nwidth = 1\nheight = 1\ndepth = 1\n[tessellation]\ngrains = 8\n"
                                     "[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.2\n[mesh]\ntets_per_grain = 60\n";
  for (const char* unit : {"1e-6", "1e-3"})
    REQUIRE(test::run_grainmesh({"run", (dir / "cell.ini").string(), "-o", (dir / unit).string(), "--quiet", "--set",
                                 std::string("export.convert_to_meters=") + unit})
                .exit_code == 0);
  for (const char* picture : {"tessellation.png", "mesh.png"}) {
    CAPTURE(picture);
    CHECK(test::read_file(dir / "1e-6" / picture) != test::read_file(dir / "1e-3" / picture));
  }
  CHECK(test::read_file(dir / "1e-6/mesh.vtu") == test::read_file(dir / "1e-3/mesh.vtu"));  // the same mesh
}

// Release build only: the binder's own code is the tessellation's, which the sanitizer build
// runs in tests/tessellate/test_binder_3d.cpp; the mesh and the solve are grain mode's.
#ifndef GRAINMESH_SANITIZED
TEST_CASE("grainmesh run --solve in 3D binder mode: the binder's fraction exact, the modulus inside the bounds",
          "[cli][solve][run3d][binder3d]") {
  test::ScratchDir dir("run3d_binder");
  const fs::path out = dir / "b";
  const auto r = run_grainmesh({"run", test::example("grains_3d_wc_co").string(), "-o", out.string(), "--solve", "--set",
                                "tessellation.grains=8", "--set", "tessellation.phase_mode=binder", "--set",
                                "tessellation.matrix_phase=Co", "--set", "tessellation.arrangement=", "--set",
                                "phase.Co.fraction=0.3"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto report = nlohmann::json::parse(test::read_file(out / "report.json"));
  // The mesh's surfaces as fine as the layer is thick, the cores coarser.
  CHECK(report["statistics"]["binder_layer"].get<double>() > 0.0);
  CHECK(report["size"].get<double>() == Approx(report["statistics"]["binder_layer"].get<double>()));
  CHECK(report["conforming"].get<bool>());
  const auto& eff = report["effective"];
  CHECK(eff["inside_bounds"]["voigt_reuss"].get<bool>());
  CHECK(eff["modulus"].get<double>() > eff["reuss"].get<double>());
  CHECK(eff["modulus"].get<double>() < eff["voigt"].get<double>());
  // The binder's fraction exact, the eight grains wrapped by it (no contact asked for).
  CHECK(report["phases"][1]["achieved_fraction"].get<double>() == Approx(0.3).epsilon(1e-9));
  CHECK(report["statistics"]["binder_contacts"].get<int>() == 0);
  CHECK(report["statistics"]["contiguity"]["WC"].get<double>() == 0.0);
  // Its dual passes checkMesh: the thin layer's sharp corners gave 26 highly skewed faces
  // before the dual was mended where checkMesh would fail (polymesh_dual_3d.hpp).
  CHECK(test::run_openfoam(out / "case", "checkMesh").out.find("Mesh OK.") != std::string::npos);
}

namespace {

// The binder example at 8 grains, 20 % Co and a WC contiguity of 0.3 on `seed`, run into
// `out`; its report.
nlohmann::json run_touching_binder(const fs::path& out, int seed, std::string& err, std::string* summary = nullptr) {
  const auto r = run_grainmesh({"run", test::example("grains_3d_wc_co_binder").string(), "-o", out.string(), "--set",
                                "tessellation.grains=8", "--set", "phase.Co.fraction=0.2", "--set", "domain.width=1",
                                "--set", "domain.height=1", "--set", "domain.depth=1", "--set", "tessellation.contiguity=0.3",
                                "--set", "tessellation.seed=" + std::to_string(seed), "--set", "output.pictures=none"});
  err = r.err;
  if (summary != nullptr) *summary = r.out;
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(test::read_file(out / "report.json"));
}

}  // namespace

TEST_CASE("grainmesh run in 3D binder mode with grains touching: the dual passes checkMesh", "[cli][run3d][binder3d]") {
  // Seed 1: the plain dual fails 59 faces here (highly skewed and worse than 90 degrees
  // non-orthogonal, at the WC grains' tips in the layer). Mended, none, and the report
  // says what was mended.
  test::ScratchDir dir("run3d_binder_contacts");
  const fs::path out = dir / "b";
  std::string err, summary;
  const auto report = run_touching_binder(out, 1, err, &summary);
  INFO(err);
  CHECK(report["statistics"]["contiguity"]["WC"].get<double>() == Approx(0.3).margin(0.05));
  const auto& mending = report["case_cells"]["dual_mending"];
  CHECK(mending["folded_points"].get<int>() + mending["joined_cells"].get<int>() > 0);
  // The summary line says what was mended, as the report counts it.
  CHECK(summary.find("polyhedral cells; mended: " + std::to_string(mending["folded_points"].get<int>()) +
                     " points folded, " + std::to_string(mending["joined_cells"].get<int>()) + " cells joined)") !=
        std::string::npos);
  CHECK(mending["failing_faces"] == 0);
  CHECK(mending["failing_cells"] == 0);
  CHECK(err.find("still fail checkMesh") == std::string::npos);
  const auto check = test::run_openfoam(out / "case", "checkMesh");
  INFO(check.out.substr(check.out.size() > 1500 ? check.out.size() - 1500 : 0));
  CHECK(check.out.find("Mesh OK.") != std::string::npos);
}

TEST_CASE("grainmesh run in 3D binder mode: faces the mending leaves are reported, as checkMesh finds them",
          "[cli][run3d][binder3d]") {
  // Seed 2 of the same cell keeps two faces (a WC tip in the layer): the run warns, the
  // report counts them, and checkMesh fails the case on as many non-orthogonal faces.
  test::ScratchDir dir("run3d_binder_left");
  const fs::path out = dir / "b";
  std::string err, summary;
  const auto report = run_touching_binder(out, 2, err, &summary);
  INFO(err);
  const int failing = report["case_cells"]["dual_mending"]["failing_faces"].get<int>();
  CHECK(failing > 0);
  CHECK(summary.find(", " + std::to_string(failing) + " faces and 0 cells still failing checkMesh's limits)") !=
        std::string::npos);
  CHECK(err.find(std::to_string(failing) + " faces and 0 cells of the dual polyhedra still fail checkMesh") !=
        std::string::npos);
  const auto check = test::run_openfoam(out / "case", "checkMesh");
  INFO(check.out.substr(check.out.size() > 1500 ? check.out.size() - 1500 : 0));
  CHECK(check.out.find("Mesh OK.") == std::string::npos);
  CHECK(check.out.find("Number of non-orthogonality errors: " + std::to_string(failing) + ".") != std::string::npos);
}
#endif
