// The OpenFOAM export, judged by OpenFOAM's own programs: checkMesh on our cases, and
// solidDisplacementFoam against analytical answers.
#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "analysis/foam_fields.hpp"
#include "analysis/homogenise.hpp"
#include "analysis/traction.hpp"
#include "checkmesh.hpp"
#include "common/errors.hpp"
#include "common/text_file.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "export/foam_load.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "export/foam_solver.hpp"
#include "export/polymesh.hpp"
#include "grains/grain_mesh.hpp"
#include "helpers.hpp"
#include "kirsch.hpp"
#include "mesh/quality.hpp"
#include "pipelines/domain_command.hpp"
#include "export/polymesh_2d.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/validate.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {


// The xx components of the stress the solver wrote.
std::vector<double> read_sigma_xx(const fs::path& file, std::size_t cells) {
  std::vector<double> xx;
  const FieldValues sigma = read_cell_field(file, "symmTensor", cells);
  for (std::size_t k = 0; k < sigma.size(); ++k) xx.push_back(sigma[k][0]);
  return xx;
}

// A two-phase cell of 40 grains (seed 5); with `binder`, 30 grains in a 12 % Co matrix (seed 7).
Tessellation microstructure(bool periodic, bool binder = false) {
  TessellationOptions o;
  o.width = 3.0;
  o.height = 1.7;
  o.grains = binder ? 30 : 40;
  o.periodic = periodic;
  o.lloyd_iterations = 3;
  o.phases = {Phase{"WC", 0.0, true, 800e9, 0.1, {}}, Phase{"Co", binder ? 0.12 : 0.2, false, 300e9, 0.1, {}}};
  if (binder) {
    o.phase_mode = PhaseMode::binder;
    o.matrix_phase = 1;
  }
  Rng rng(binder ? 7 : 5);
  return tessellate(o, rng);
}

void check_mesh_ok(const fs::path& case_dir, const ExportMesh<2>& e) { test::check_mesh_ok(case_dir, e.phases, e.phase); }

// The number after `label` in checkMesh's log (NaN when absent).
double logged(const std::string& log, const std::string& label) {
  const auto at = log.find(label);
  return at == std::string::npos ? std::nan("") : std::stod(log.substr(at + label.size()));
}

}  // namespace

TEST_CASE("measure_quality's non-orthogonality and skewness are checkMesh's", "[export][openfoam]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  const ExportMesh<2> e = grain_export_mesh(t, m);
  test::ScratchDir dir("foam_quality");
  write_foam_case(dir.path(), e, {});
  const std::string log = test::run_openfoam(dir.path(), "checkMesh").out;
  const MeshQuality q = measure_quality(m.mesh);
  // checkMesh prints six significant digits.
  CHECK(logged(log, "Mesh non-orthogonality Max: ") == Approx(q.max_non_orthogonality_deg).epsilon(1e-5));
  // checkMesh's average is the angle of the mean cosine; ours the mean angle, which is
  // less (acos is concave on [0, 1]) but close.
  const double average = logged(log, "average: ");
  CHECK(average > q.mean_non_orthogonality_deg);
  CHECK(average < 1.5 * q.mean_non_orthogonality_deg);
  CHECK(logged(log, "Max skewness = ") == Approx(q.max_skewness).epsilon(1e-5));
}

TEST_CASE("checkMesh accepts a periodic two-phase microstructure with patches and with cyclic pairs",
          "[export][openfoam]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  const ExportMesh<2> e = grain_export_mesh(t, m);
  for (bool cyclic : {false, true})
    for (bool binary : {false, true}) {
      INFO("cyclic " << cyclic << " binary " << binary);
      test::ScratchDir dir("foam");
      write_foam_case(dir.path(), e, {.cyclic = cyclic, .binary = binary, .grain_zones = true});
      check_mesh_ok(dir.path(), e);
      const std::string boundary = test::read_file(dir / "constant/polyMesh/boundary");
      CHECK((boundary.find("cyclic") != std::string::npos) == cyclic);
    }
}

TEST_CASE("checkMesh accepts polygonal cells: a periodic two-phase microstructure with patches and cyclic pairs",
          "[export][openfoam][dual]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  const ExportMesh<2> e = export_mesh(t, m, FoamOptions::Cells::polygons);
  for (bool cyclic : {false, true}) {
    INFO("cyclic " << cyclic);
    test::ScratchDir dir("foam_polygons");
    write_foam_case(dir.path(), e, {.cyclic = cyclic, .grain_zones = true});
    check_mesh_ok(dir.path(), e);
  }
}

TEST_CASE("checkMesh accepts polygonal cells of a binder cell and of the fibre and plate-with-hole domains",
          "[export][openfoam][dual]") {
  const Tessellation t = microstructure(true, true);
  const ExportMesh<2> binder = export_mesh(t, mesh_tessellation(t, {.size = 0.05, .phase_size = {}}), FoamOptions::Cells::polygons);
  for (bool cyclic : {false, true}) {
    INFO("binder, cyclic " << cyclic);
    test::ScratchDir dir("foam_binder_polygons");
    write_foam_case(dir.path(), binder, {.cyclic = cyclic});
    check_mesh_ok(dir.path(), binder);
  }
  for (const char* name : {"fibres_6", "plate_with_hole"}) {
    INFO(name);
    const DistMeshResult r = mesh_domain(read_domain_job(Config::from_file(test::example(name))));
    ExportMesh<2> e;
    e.mesh = cell_mesh(r.mesh);
    e.phase = r.phase;
    e.grain = r.phase;  // a domain mesh: each side of the interface one grain
    e.phases = {{"matrix", 3e9, 0.35}};
    if (std::count(e.phase.begin(), e.phase.end(), 1) > 0) e.phases.push_back({"fibre", 70e9, 0.22});
    for (const Vec2 p : r.mesh.points) e.cell.extend(p);
    const ExportMesh<2> poly = polygon_cells(e);
    CHECK(poly.mesh.cells() < 0.6 * static_cast<double>(r.mesh.triangles.size()));
    test::ScratchDir dir("domain_polygons");
    write_foam_case(dir.path(), poly, {.convert_to_meters = 1e-3, .uniaxial = true});
    check_mesh_ok(dir.path(), poly);
  }
}

TEST_CASE("checkMesh accepts the thesis' 6-fibre cell, its two regions as phase zones", "[export][openfoam]") {
  const DistMeshResult r = mesh_domain(read_domain_job(Config::from_file(test::example("fibres_6"))));
  ExportMesh<2> e;
  e.mesh = cell_mesh(r.mesh);
  e.phase = r.phase;  // 1 inside the fibres
  e.grain = r.phase;  // a domain mesh: each side of the interface one grain
  e.phases = {{"matrix", 3e9, 0.35}, {"fibre", 70e9, 0.22}};
  for (const Vec2 p : r.mesh.points) e.cell.extend(p);
  REQUIRE(std::count(e.phase.begin(), e.phase.end(), 1) > 0);
  test::ScratchDir dir("fibres");
  write_foam_case(dir.path(), e, {.convert_to_meters = 1e-3});
  check_mesh_ok(dir.path(), e);
  // The stiffness ratio is 23: the laplacian falls back to linear interpolation, and the
  // solver converges.
  CHECK(test::read_file(dir / "system/fvSchemes").find("laplacian(DD,D) Gauss linear corrected") != std::string::npos);
  const auto solved = test::run_openfoam(dir.path(), "solidDisplacementFoam");
  CHECK(solved.exit_code == 0);
  CHECK(solved.out.find("residual condition satisfied") != std::string::npos);
}

TEST_CASE("solidDisplacementFoam converges on a two-phase microstructure case", "[export][openfoam]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  test::ScratchDir dir("solve");
  write_foam_case(dir.path(), grain_export_mesh(t, m), {});
  // The thesis' phases (800 and 300 GPa) differ by less than 3 in stiffness: harmonic.
  CHECK(test::read_file(dir / "system/fvSchemes").find("laplacian(DD,D) Gauss harmonic corrected") != std::string::npos);
  // Run as Allrun runs it, on its own: the case's runTimeControl stops it once OpenFOAM's
  // own residual of every component is below the tolerance, long before its bound.
  const auto r = test::run_openfoam(dir.path(), "solidDisplacementFoam");
  INFO(r.out.substr(r.out.size() > 3000 ? r.out.size() - 3000 : 0));
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("\nEnd") != std::string::npos);
  CHECK(r.out.find("residual condition satisfied") != std::string::npos);
  const std::regex residual(R"(Solving for D[xy], Initial residual = ([0-9.eE+-]+))");
  std::vector<double> last;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), residual); it != std::sregex_iterator(); ++it)
    last.push_back(std::stod((*it)[1]));
  REQUIRE(last.size() >= 2);
  CHECK(std::max(last[last.size() - 1], last[last.size() - 2]) < kSolverTolerance);
  CHECK(last.size() < 2 * 1000);
  // Written once, at the step it stopped.
  const fs::path result = latest_time_dir(dir.path());
  CHECK(result.filename() == std::to_string(last.size() / 2));
  CHECK(fs::exists(result / kStressField));
}

namespace {

// Two layers of phases 0 and 1 filling [0, 2] x [0, 1]: split at x = 1 (interfaces across
// the load) or at y = 0.5 (along it).
Tessellation two_layers(bool across, const std::vector<Phase>& phases) {
  Tessellation t;
  t.width = 2.0;
  t.height = 1.0;
  t.periodic = false;
  t.phases = phases;
  if (across) {
    t.vertices = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}};
    t.regions = {{.grain = 0, .phase = 0, .rings = {{0, 1, 4, 5}}}, {.grain = 1, .phase = 1, .rings = {{1, 2, 3, 4}}}};
    t.edges = {{0, 1, 0, -1}, {1, 2, 1, -1}, {2, 3, 1, -1}, {3, 4, 1, -1}, {4, 5, 0, -1}, {5, 0, 0, -1}, {1, 4, 0, 1}};
  } else {
    t.vertices = {{0, 0}, {2, 0}, {2, 0.5}, {2, 1}, {0, 1}, {0, 0.5}};
    t.regions = {{.grain = 0, .phase = 0, .rings = {{0, 1, 2, 5}}}, {.grain = 1, .phase = 1, .rings = {{5, 2, 3, 4}}}};
    t.edges = {{0, 1, 0, -1}, {1, 2, 0, -1}, {2, 3, 1, -1}, {3, 4, 1, -1}, {4, 5, 1, -1}, {5, 0, 0, -1}, {5, 2, 1, 0}};
  }
  for (int g = 0; g < 2; ++g)
    t.grains.push_back({.id = g, .phase = g, .seed = {}, .area = region_area(t, t.regions[g]), .neighbours = {1 - g},
                        .matrix = false});
  validate(t);
  return t;
}


}  // namespace

TEST_CASE("a two-layer laminate has the analytical plane-strain modulus across and along its layers",
          "[export][openfoam][physics]") {
  const std::vector<Phase> phases{Phase{"stiff", 0.5, false, 200e9, 0.3, {}}, Phase{"soft", 0.5, false, 90e9, 0.2, {}}};
  // Plane-strain modulus M and Lame lambda of each phase; the layers are equally thick.
  double M[2], L[2];
  for (int p = 0; p < 2; ++p) {
    const double E = phases[p].youngs_modulus, nu = phases[p].poisson_ratio;
    M[p] = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    L[p] = E * nu / ((1 + nu) * (1 - 2 * nu));
  }
  auto mean = [](double a, double b) { return 0.5 * (a + b); };
  const double across = 1.0 / mean(1 / M[0], 1 / M[1]);
  const double along = mean(M[0], M[1]) - mean(L[0] * L[0] / M[0], L[1] * L[1] / M[1]) +
                       std::pow(mean(L[0] / M[0], L[1] / M[1]), 2) / mean(1 / M[0], 1 / M[1]);
  for (bool is_across : {true, false}) {
    INFO((is_across ? "interfaces across the load" : "interfaces along the load"));
    const Tessellation t = two_layers(is_across, phases);
    const GrainMesh m = mesh_tessellation(t, {.size = 0.05, .phase_size = {}});
    // The triangles and their dual's polygons (export.cells) alike.
    for (const auto cells : {FoamOptions::Cells::triangles, FoamOptions::Cells::polygons}) {
      INFO((cells == FoamOptions::Cells::polygons ? "polygons" : "triangles"));
      test::ScratchDir dir("laminate");
      const FoamOptions o{};  // right moved by 0.001, symmetry elsewhere, plane strain
      const ExportMesh<2> e = export_mesh(t, m, cells);
      const PolyMesh pm = write_foam_case(dir.path(), e, o);
      const MixedHomogenised<3> h = solve_mixed(dir.path(), e, pm, o);
      CHECK(h.strain_xx == o.displacement / t.width);  // the mean of d(ux)/dx, exactly
      CHECK(h.modulus == Approx(is_across ? across : along).epsilon(0.01));
    }
  }
}

TEST_CASE("a plate with a hole under tension has Kirsch's stress at the top of the hole", "[export][openfoam][physics]") {
  // Symmetry on the left and bottom, the traction pulling on the right, the top free.
  const ExportMesh<2> triangles = test::plate_with_hole();
  const double R = test::kHoleRadius, T = test::kPlateTraction;
  for (const bool polygons : {false, true}) {
    INFO((polygons ? "polygons" : "triangles"));
    const ExportMesh<2> e = polygons ? polygon_cells(triangles) : triangles;
    test::ScratchDir dir("plate");
    const FoamOptions o{.convert_to_meters = 1.0, .traction = T, .uniaxial = true};
    const PolyMesh pm = write_foam_case(dir.path(), e, o);
    REQUIRE(test::run_openfoam(dir.path(), "checkMesh").out.find("Mesh OK.") != std::string::npos);
    const MixedHomogenised<3> h = solve_mixed(dir.path(), e, pm, o);
    const std::vector<double> sxx = read_sigma_xx(h.run.result_dir / kStressField, e.mesh.cells());
    // The cells nearest the top of the hole, where sigma_xx peaks at 3 T.
    std::vector<std::pair<double, int>> near;
    for (std::size_t k = 0; k < sxx.size(); ++k) near.emplace_back(norm(cell_centroid(e.mesh, k) - Vec2{0.0, R}), static_cast<int>(k));
    std::sort(near.begin(), near.end());
    for (int i = 0; i < 3; ++i) {
      const int k = near[i].second;
      const Vec2 c0 = cell_centroid(e.mesh, k);
      INFO("cell at " << c0.x << " " << c0.y << ": sigma_xx " << sxx[k] << " Kirsch " << test::kirsch_sigma_xx(c0));
      CHECK(test::kirsch_sigma_xx(c0) > 2.5 * T);
      CHECK(sxx[k] == Approx(test::kirsch_sigma_xx(c0)).epsilon(0.05));
    }
  }
}

TEST_CASE("cyclic cases: the displacement jump across left/right loads the periodic cell", "[export][openfoam][physics]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  const ExportMesh<2> e = grain_export_mesh(t, m);
  const FoamOptions cyclic{.cyclic = true};

  // Two phases: periodic and symmetric boundaries give nearly the same mean stress.
  test::ScratchDir periodic("cyclic"), patches("patches");
  const PolyMesh cyclic_mesh = write_foam_case(periodic.path(), e, cyclic);
  const PolyMesh patch_mesh = write_foam_case(patches.path(), e, {});
  const MixedHomogenised<3> with_cyclic = solve_mixed(periodic.path(), e, cyclic_mesh, cyclic);
  const MixedHomogenised<3> with_patches = solve_mixed(patches.path(), e, patch_mesh, {});
  CHECK(with_cyclic.sigma_xx == Approx(with_patches.sigma_xx).epsilon(0.02));
  CHECK_THROWS_AS(write_foam_case(periodic.path() / "x", e, {.cyclic = true, .uniaxial = true}), ConfigError);
}

TEST_CASE("cyclic faces are paired through the mesh's periodic node pairs", "[export]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  ExportMesh<2> e = grain_export_mesh(t, m);
  CHECK(e.pairs == m.pairs);  // carried from the mesh stage, not made again
  const PolyMesh pm = build_polymesh(e, {.cyclic = true});
  // Face k of left is the image of face k of right: its points moved by W; so is the
  // pinned pair's one face (pin_translation.hpp), cut from the middle of the sides.
  const std::size_t n = m.mesh.points.size();
  auto point = [&](int p) { return pm.points2d[static_cast<std::size_t>(p) % n]; };
  auto span = [&](int f) {  // the face's extent along the side: exact
    std::pair<double, double> y{1e300, -1e300};
    for (int q = pm.face_start[f]; q < pm.face_start[f + 1]; ++q)
      y = {std::min(y.first, point(pm.face_points[q]).y), std::max(y.second, point(pm.face_points[q]).y)};
    return y;
  };
  for (const auto& [low, high] : {std::pair{"left", "right"}, std::pair{"pin_left", "pin_right"}}) {
    CAPTURE(low);
    REQUIRE(patch_index(pm, low) >= 0);
    REQUIRE(patch_index(pm, high) == patch_index(pm, low) + 2);  // each right after its side's
    const auto& left = pm.patches[patch_index(pm, low)];
    const auto& right = pm.patches[patch_index(pm, high)];
    REQUIRE(left.size == right.size);
    for (int k = 0; k < left.size; ++k) CHECK(span(left.start + k) == span(right.start + k));
  }
  const auto& pin = pm.patches[patch_index(pm, "pin_left")];
  CHECK(pin.size == 1);
  CHECK(pin.type == "patch");

  // Without its pair, a node's faces have no partner: refused, naming the sides.
  e.pairs.axis[0].pop_back();
  CHECK_THROWS_WITH(build_polymesh(e, {.cyclic = true}), Catch::Contains("the faces of left and right do not pair"));
}

TEST_CASE("the export refuses a mesh without one grain and one phase per triangle", "[export]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  const ExportMesh<2> e = grain_export_mesh(t, m);
  REQUIRE(e.grain == m.grain);
  REQUIRE(e.phase == m.phase);
  test::ScratchDir dir("foam_labels");
  for (bool grain : {true, false}) {
    ExportMesh<2> short_labels = e;
    (grain ? short_labels.grain : short_labels.phase).pop_back();
    CHECK_THROWS_WITH(write_foam_case(dir.path() / "x", short_labels, {}),
                      Catch::Contains("the mesh needs a grain and a phase per cell"));
  }
  CHECK_FALSE(fs::exists(dir.path() / "x"));
}

TEST_CASE("the displacement starts from the field a uniform cell takes under the imposed mean strain, ASCII or "
          "binary",
          "[export]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  const ExportMesh<2> e = grain_export_mesh(t, m);
  // The default load (right moved in x, symmetry elsewhere) and a periodic mixed strain.
  const FoamOptions mixed{};
  const FoamOptions cyclic{.cyclic = true, .strain = {1e-3, -4e-4, 0.0, 0.0, 0.0, 2.5e-4}};
  FoamOptions binary = cyclic;  // read back from raw doubles
  binary.binary = true;
  for (const FoamOptions& o : {mixed, cyclic, binary}) {
    test::ScratchDir dir("initial");
    const PolyMesh pm = write_foam_case(dir.path(), e, o);
    const FieldValues D = read_cell_field(dir / "0/D", "vector", static_cast<std::size_t>(pm.cells));
    const std::array<double, 6> strain =
        o.cyclic ? cyclic_strain(foam_cell(e), o) : std::array<double, 6>{o.displacement / e.cell.width()};
    if (o.cyclic) CHECK(strain == o.strain);
    double worst = 0.0;
    for (int k = 0; k < pm.cells; ++k) {
      const Vec2 c = cell_centroid(e.mesh, k) - e.cell.lo;
      const Vec2 expected{strain[0] * c.x + strain[5] * c.y, strain[5] * c.x + strain[1] * c.y};
      worst = std::max({worst, std::abs(D[k][0] - expected.x * o.convert_to_meters),
                        std::abs(D[k][1] - expected.y * o.convert_to_meters), std::abs(D[k][2])});
    }
    // Held at left and bottom, the cell's far sides moved by the mean strain times its size.
    CHECK(worst <= 1e-12 * std::abs(strain[0]) * e.cell.width() * o.convert_to_meters);
  }
}

TEST_CASE("a thermal case carries the temperature change and each cell's alpha, and only on cyclic pairs",
          "[export][thermal]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.15, .phase_size = {}});
  ExportMesh<2> e = grain_export_mesh(t, m);
  e.phases[0].alpha = 5e-6;
  e.phases[1].alpha = 14e-6;
  test::ScratchDir dir("thermal-case");
  const FoamOptions o{.cyclic = true, .strain = {-1e-3, -1e-3, 0.0, 0.0, 0.0, 0.0}, .delta_T = -700.0};
  const PolyMesh pm = write_foam_case(dir.path(), e, o);
  const std::size_t cells = static_cast<std::size_t>(pm.cells);
  const FieldValues alpha = read_cell_field(dir / "0/alpha", "scalar", cells);
  const FieldValues T = read_cell_field(dir / "0/T", "scalar", cells);
  for (std::size_t k = 0; k < cells; ++k) {
    CHECK(alpha[k][0] == e.phases[e.phase[k]].alpha);
    CHECK(T[k][0] == -700.0);
  }
  const std::string thermal = test::read_file(dir / "constant/thermalProperties");
  CHECK(thermal.find("thermalStress   yes;") != std::string::npos);
  CHECK(test::read_file(dir / "system/fvSchemes").find("grad((threeKalpha*T)) Gauss linear;") != std::string::npos);
  // The thermal stress the solver's sigmaD leaves out: threeK alpha delta_T per cell.
  const std::vector<double> s = thermal_stress(e.phases, e.phase, o);
  const FoamPhase& wc = e.phases[0];
  CHECK(s[static_cast<std::size_t>(std::find(e.phase.begin(), e.phase.end(), 0) - e.phase.begin())] ==
        Approx(wc.youngs_modulus / (1 - 2 * wc.poisson_ratio) * wc.alpha * -700.0));
  // Not on patches, and not with a negative alpha.
  CHECK_THROWS_AS(write_foam_case(dir.path() / "x", e, {.delta_T = -700.0}), ConfigError);
  e.phases[1].alpha = -1e-6;
  CHECK_THROWS_WITH(write_foam_case(dir.path() / "y", e, o), Catch::Contains("phase.Co.alpha: must be"));
}

TEST_CASE("a case that stops itself before its effective stress has settled is continued until it has",
          "[export][openfoam]") {
  const Tessellation t = microstructure(true);
  const GrainMesh m = mesh_tessellation(t, {.size = 0.08, .phase_size = {}});
  const ExportMesh<2> e = grain_export_mesh(t, m);
  test::ScratchDir loose("loose"), as_written("as-written");
  const PolyMesh pm = write_foam_case(loose.path(), e, {});
  write_foam_case(as_written.path(), e, {});
  // The case's own stop made a thousand times looser than written: it stops long before
  // the stress settles.
  const fs::path control = loose / "system/controlDict";
  const std::string text = test::read_file(control);
  const std::regex stop_value(R"(value\s+([0-9.eE+-]+);)");
  std::smatch found;
  REQUIRE(std::regex_search(text, found, stop_value));
  CHECK(std::stod(found[1]) == kSolverTolerance);
  write_text_file(control, std::regex_replace(text, stop_value, "value   0.01;"));
  const MixedHomogenised<3> continued = solve_mixed(loose.path(), e, pm, {});
  const MixedHomogenised<3> straight = solve_mixed(as_written.path(), e, pm, {});
  CHECK(fs::exists(loose / "log.solidDisplacementFoam.1"));  // the first run's log, kept
  CHECK(!fs::exists(as_written / "log.solidDisplacementFoam.1"));
  CHECK(continued.run.stress_change <= kStressTolerance);
  CHECK(continued.modulus == Approx(straight.modulus).epsilon(1e-5));
}
