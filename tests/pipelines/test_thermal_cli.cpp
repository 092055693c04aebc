// Thermal residual stress through `grainmesh run --solve` with load.delta_T, against exact
// answers: one material (no residual stress, the free expansion), a laminate (the exact
// layer stresses), and Levin's relation between the effective expansion and the effective
// stiffness, which holds for any two-phase microstructure.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "helpers.hpp"
#include "pipelines/laminate.hpp"
#include "view/vtu.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

Json report_of(const fs::path& dir) { return Json::parse(test::read_file(dir / "report.json")); }

const std::vector<double>& cell_array(const VtuContents& v, const std::string& name) {
  for (const CellField& f : v.fields)
    if (f.name == name) return std::get<std::vector<double>>(f.values);
  FAIL("no cell array " << name);
  throw;
}

// Levin's relation in plane strain, computed here from the reported stiffness (not from
// grainmesh's own): the in-plane pressure P delta_T that strains both phases alike leaves
// the cell uniformly strained, so a = (b1 + P / (2 k1)) (1, 1, 0) - P S (1, 1, 0), with
// k = lambda + mu, b = (1 + nu) alpha, S the effective compliance (Voigt), a12 half the
// third component.
std::array<double, 3> levin(const test::Material& one, const test::Material& two, const Json& stiffness) {
  auto k = [](const test::Material& m) { return m.lambda() + m.mu(); };
  auto b = [](const test::Material& m) { return (1 + m.nu) * m.alpha; };
  const double P = -(b(one) - b(two)) / (1 / (2 * k(one)) - 1 / (2 * k(two)));
  const double uniform = b(one) + P / (2 * k(one));
  // S (1, 1, 0): solve C x = (1, 1, 0) by Cramer's rule.
  const std::array<std::array<double, 3>, 3> C{
      {{stiffness["C11"].get<double>(), stiffness["C12"].get<double>(), stiffness["C16"].get<double>()},
       {stiffness["C12"].get<double>(), stiffness["C22"].get<double>(), stiffness["C26"].get<double>()},
       {stiffness["C16"].get<double>(), stiffness["C26"].get<double>(), stiffness["C66"].get<double>()}}};
  auto det = [](const std::array<std::array<double, 3>, 3>& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  std::array<double, 3> x{};
  for (int c = 0; c < 3; ++c) {
    auto m = C;
    for (int r = 0; r < 3; ++r) m[r][c] = r < 2 ? 1.0 : 0.0;
    x[c] = det(m) / det(C);
  }
  return {uniform - P * x[0], uniform - P * x[1], -0.5 * P * x[2]};
}

// The residual state's checks that hold for any two-phase cell: the phase means balance
// (f1 <s>1 + f2 <s>2 = 0 in xx, yy, xy, to 1e-3 of the larger phase mean), the phase of
// lower alpha is in in-plane compression, and the expansion meets Levin's relation
// within 1 % (and the report says so).
void check_two_phase_residual(const Json& report, const std::string& low, const test::Material& low_m,
                              const std::string& high, const test::Material& high_m) {
  const Json& s = report["stresses"]["thermal"];
  const double f_low = s[low]["volume_fraction"].get<double>(), f_high = s[high]["volume_fraction"].get<double>();
  double larger = 0.0;  // the largest in-plane component of either phase's mean
  for (const std::string& phase : {low, high})
    for (const char* c : {"xx", "yy", "xy"}) larger = std::max(larger, std::abs(s[phase]["mean"][c].get<double>()));
  for (const char* c : {"xx", "yy", "xy"}) {
    INFO("component " << c);
    const double low_mean = s[low]["mean"][c].get<double>(), high_mean = s[high]["mean"][c].get<double>();
    CHECK(std::abs(f_low * low_mean + f_high * high_mean) <= 1e-3 * larger);
  }
  auto in_plane = [&](const std::string& phase) {
    return 0.5 * (s[phase]["mean"]["xx"].get<double>() + s[phase]["mean"]["yy"].get<double>());
  };
  CHECK(in_plane(low) < 0.0);   // cooled: the phase that shrinks less is squeezed
  CHECK(in_plane(high) > 0.0);
  const Json& e = report["effective"];
  const std::array<double, 3> exact = levin(low_m, high_m, e["stiffness"]);
  const double scale = std::max(std::abs(exact[0]), std::abs(exact[1]));
  INFO("Levin: " << exact[0] << " " << exact[1] << " " << exact[2] << "; reported " << e["thermal_expansion"].dump());
  CHECK(std::abs(e["thermal_expansion"]["xx"].get<double>() - exact[0]) <= 0.01 * scale);
  CHECK(std::abs(e["thermal_expansion"]["yy"].get<double>() - exact[1]) <= 0.01 * scale);
  CHECK(std::abs(e["thermal_expansion"]["xy"].get<double>() - exact[2]) <= 0.01 * scale);
  CHECK(e["thermal"]["levin_difference"].get<double>() <= 0.01);
}

}  // namespace

TEST_CASE("a temperature change on one material: no residual stress, the free expansion (1 + nu) alpha in plane "
          "strain and alpha in plane stress",
          "[thermal][physics][cli]") {
  test::ScratchDir dir("thermal-one");
  const test::Material m{800e9, 0.1, 8e-6};
  const double delta_T = -800.0, scale = m.E * m.alpha * std::abs(delta_T);
  for (const bool plane_stress : {false, true}) {
    INFO((plane_stress ? "plane stress" : "plane strain"));
    const fs::path out = dir / (plane_stress ? "stress" : "strain");
    const auto r = test::run_grainmesh(
        {"run", "-o", out.string(), "--solve", "--set", "homogenise.boundary=periodic", "--set", "phase.matrix.E=800e9",
         "--set", "load.delta_T=-800", "--set", "phase.particulate.alpha=8e-6", "--set", "phase.matrix.alpha=8e-6",
         "--set", std::string("load.plane_stress=") + (plane_stress ? "true" : "false")});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const Json report = report_of(out);
    const Json& a = report["effective"]["thermal_expansion"];
    const double free = plane_stress ? m.alpha : (1 + m.nu) * m.alpha;
    CHECK(a["xx"].get<double>() == Approx(free).epsilon(1e-6));
    CHECK(a["yy"].get<double>() == Approx(free).epsilon(1e-6));
    CHECK(std::abs(a["xy"].get<double>()) < 1e-6 * free);
    // Every cell: the in-plane stress zero; out of plane, plane strain holds the cell
    // with sigma_zz = -E alpha delta_T (plane stress: zero, so von Mises is zero).
    const VtuContents results = read_vtu(out / "results.vtu");
    const std::vector<double>& stress = cell_array(results, "stress_thermal");
    const std::vector<double>& mises = cell_array(results, "von_mises_thermal");
    double in_plane = 0.0, out_of_plane = 0.0, worst_mises = 0.0;
    for (std::size_t k = 0; k < mises.size(); ++k) {
      in_plane = std::max({in_plane, std::abs(stress[6 * k]), std::abs(stress[6 * k + 1]), std::abs(stress[6 * k + 3])});
      out_of_plane = std::max(out_of_plane, std::abs(stress[6 * k + 2] - (plane_stress ? 0.0 : -m.E * m.alpha * delta_T)));
      worst_mises = std::max(worst_mises, mises[k]);
    }
    CHECK(in_plane < 1e-6 * scale);
    CHECK(out_of_plane < 1e-6 * scale);
    if (plane_stress) CHECK(worst_mises < 1e-6 * scale);
    CHECK(report["stresses"]["thermal"]["particulate"]["von_mises"]["max"].get<double>() ==
          Approx(plane_stress ? 0.0 : scale).margin(1e-6 * scale));
    CHECK(fs::exists(out / "case_thermal/0/T"));
    CHECK(fs::exists(out / "stress_histogram_thermal.png"));
    // Which state it was, wherever the answer is read: the report, the thermal answer, the
    // config that repeats the run, the summary line.
    const std::string state = plane_stress ? "plane_stress" : "plane_strain";
    CHECK(report["plane_state"] == state);
    CHECK(report["effective"]["thermal"]["plane_state"] == state);
    CHECK(test::read_file(out / "config.ini").find(plane_stress ? "# 2D: solved in plane stress" : "# 2D: solved in plane strain") !=
          std::string::npos);
    CHECK(r.out.find(plane_stress ? "thermal (plane stress)" : "thermal (plane strain)") != std::string::npos);
  }
}

TEST_CASE("a laminate cooled: the exact layer stresses and free expansion, the phase means balanced, Levin's relation "
          "met, cooled and then pulled by superposition",
          "[thermal][physics][cli]") {
  test::ScratchDir dir("thermal-laminate");
  const test::Material hard{600e9, 0.2, 5e-6}, soft{200e9, 0.3, 14e-6};
  const double f = 0.3, delta_T = -1000.0;
  const fs::path ini = dir / "laminate.ini";
  // The phase means are the face forces' virial (exactly balanced; its error is first order
  // in the interface cells' size: 1.3 % at a boundary size of 0.01, 0.66 % at 0.005).
  std::ofstream(ini) << test::laminate_config(hard, soft, /*normal_to_x=*/true, 0.005)
                     << "[homogenise]\nboundary = periodic\n[load]\ndelta_T = -1000\n";
  const auto r = test::run_grainmesh(
      {"run", ini.string(), "-o", (dir / "out").string(), "--solve", "--set", "homogenise.solver=openfoam", "--set",
       "homogenise.reference=fe"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Json report = report_of(dir / "out");

  // The exact layered answer (plane strain, layers normal to x, free on average): sigma_xx
  // zero in both layers, a common strain e along the layers with the layers' sigma_yy
  // averaging to zero; each layer's eps_xx from its sigma_xx = 0.
  auto layer_exx = [&](const test::Material& m, double e) { return (m.three_K() * m.alpha * delta_T - m.lambda() * e) / m.M(); };
  auto layer_syy = [&](const test::Material& m, double e) {
    return m.lambda() * layer_exx(m, e) + m.M() * e - m.three_K() * m.alpha * delta_T;
  };
  auto mean_syy = [&](double e) { return (1 - f) * layer_syy(hard, e) + f * layer_syy(soft, e); };
  const double e = -mean_syy(0.0) / (mean_syy(1.0) - mean_syy(0.0));  // mean_syy is linear in e
  const double a11 = ((1 - f) * layer_exx(hard, e) + f * layer_exx(soft, e)) / delta_T, a22 = e / delta_T;
  const Json& a = report["effective"]["thermal_expansion"];
  CHECK(a["xx"].get<double>() == Approx(a11).epsilon(0.01));
  CHECK(a["yy"].get<double>() == Approx(a22).epsilon(0.01));
  // The finite-element reference follows the layers: exact; and the expansion's error it
  // states is the answer's own against the exact expansion.
  const Json& ref = report["effective"]["reference"]["thermal_expansion"];
  const Json& error = report["effective"]["discretisation_error"]["thermal_expansion"];
  CHECK(ref["xx"].get<double>() == Approx(a11).epsilon(1e-9));
  CHECK(ref["yy"].get<double>() == Approx(a22).epsilon(1e-9));
  CHECK(error["xx"].get<double>() == Approx(a["xx"].get<double>() / a11 - 1).margin(1e-8));
  CHECK(error["yy"].get<double>() == Approx(a["yy"].get<double>() / a22 - 1).margin(1e-8));
  for (const auto& [name, material] : {std::pair{"hard", hard}, std::pair{"soft", soft}}) {
    INFO(name);
    const Json& s = report["stresses"]["thermal"][name];
    const double syy = layer_syy(material, e);
    const double szz = material.lambda() * (layer_exx(material, e) + e) - material.three_K() * material.alpha * delta_T;
    CHECK(s["mean"]["yy"].get<double>() == Approx(syy).epsilon(0.01));
    CHECK(s["mean"]["zz"].get<double>() == Approx(szz).epsilon(0.01));
    CHECK(std::abs(s["mean"]["xx"].get<double>()) < 0.01 * std::abs(syy));
    CHECK(s["von_mises"]["std"].get<double>() < 0.01 * s["von_mises"]["mean"].get<double>());  // uniform layers
  }
  check_two_phase_residual(report, "hard", hard, "soft", soft);

  // Cooled, then pulled by the xx load case: the phase means add up to the xx case's mean
  // stress, and each phase's is its residual plus its share of the load.
  const Json& loaded = report["stresses"]["thermal_xx"];
  const Json& pulled = report["stresses"]["xx"];
  const double load = report["effective"]["load_cases"][0]["stress"]["xx"].get<double>();
  double sum = 0.0;
  for (const char* name : {"hard", "soft"}) {
    INFO(name);
    sum += loaded[name]["volume_fraction"].get<double>() * loaded[name]["mean"]["xx"].get<double>();
    CHECK(loaded[name]["mean"]["yy"].get<double>() ==
          Approx(report["stresses"]["thermal"][name]["mean"]["yy"].get<double>() + pulled[name]["mean"]["yy"].get<double>())
              .epsilon(1e-9));
  }
  CHECK(sum == Approx(load).epsilon(1e-3));
  const VtuContents results = read_vtu(dir / "out/results.vtu");
  for (const char* name : {"stress_thermal", "displacement_thermal", "stress_thermal_xx", "von_mises_thermal_xx"})
    CHECK_NOTHROW(cell_array(results, name));
}

TEST_CASE("the default cell cooled as WC-Co: the phase means balanced, the carbide in compression, Levin's relation "
          "met",
          "[thermal][physics][cli]") {
  test::ScratchDir dir("thermal-default");
  const auto r = test::run_grainmesh({"run", "-o", (dir / "out").string(), "--solve", "--set",
                                      "homogenise.boundary=periodic", "--set", "load.delta_T=-1000", "--set",
                                      "phase.particulate.alpha=5e-6", "--set", "phase.matrix.alpha=14e-6"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Json report = report_of(dir / "out");
  check_two_phase_residual(report, "particulate", {800e9, 0.1, 5e-6}, "matrix", {300e9, 0.1, 14e-6});
  CHECK(report["effective"]["load_cases"].size() == 4);
  CHECK(report["warnings"].empty());  // none of them about Levin
}

TEST_CASE("a thermal load refuses what it cannot do in one line, leaving nothing", "[thermal][cli]") {
  test::ScratchDir dir("thermal-refusals");
  const std::vector<std::string> periodic{"run", "--set", "homogenise.boundary=periodic", "--set", "load.delta_T=-1000"};
  auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = periodic;
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  const std::vector<test::Refusal> refusals{
      {with({"--set", "phase.matrix.alpha=14e-6"}), 2, "phase.particulate.alpha: missing: load.delta_T = -1000 needs"},
      {with({"--set", "phase.particulate.alpha=-5e-6", "--set", "phase.matrix.alpha=14e-6"}),
       2,
       "phase.particulate.alpha: must be >= 0 (1/K), got -5e-6"},
      {{"run", "--set", "load.delta_T=-1000", "--set", "phase.particulate.alpha=5e-6", "--set", "phase.matrix.alpha=14e-6"},
       2,
       "load.delta_T: needs homogenise.boundary = periodic"},
      {with({"--set", "phase.particulate.alpha=x", "--set", "phase.matrix.alpha=14e-6"}), 2, "phase.particulate.alpha: "},
      // Each slip named by its own key, not as "load.traction: 0 Pa is above 1 % of ... (0 Pa)".
      {with({"--set", "phase.particulate.alpha=5e-6", "--set", "phase.matrix.alpha=14e-6", "--set", "load.displacement=0.1"}),
       2,
       "load.displacement: 0.1 over a cell 3 wide is a mean strain of 0.0333, above 1 %"},
      {with({"--set", "phase.particulate.alpha=5.2", "--set", "phase.matrix.alpha=14e-6"}),
       2,
       "phase.particulate.alpha: 5.2 /K is above 1e-3 /K: alpha is in 1/K (WC 5.2e-6, not 5.2 (ppm/K)); if it is meant, "
       "set units.checked = true"},
      {with({"--set", "phase.particulate.alpha=2e-3", "--set", "phase.matrix.alpha=14e-6", "--set", "units.checked=true"}),
       2,
       "load.delta_T: -1000 K gives phase particulate (alpha 0.002 /K) a free strain of 2.2, above 5 %"},
      {with({"--set", "phase.particulate.alpha=5e-6", "--set", "phase.matrix.alpha=14e-6", "--set", "phase.matrix.E=300"}),
       2,
       "phase.matrix.E: 300 Pa is below 1 MPa: E is in Pa (WC 700e9, not 300 (GPa)); if it is meant, set units.checked = true"},
  };
  int k = 0;
  for (const test::Refusal& r : refusals) test::check_refused(r, dir / ("out" + std::to_string(k++)));
}
