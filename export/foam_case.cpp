#include "export/foam.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/allocator.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/foam_file.hpp"

namespace grainmesh {

namespace {

// Refuses what the case cannot carry: a phase without a usable E, nu (or alpha, under a
// temperature change), a temperature change off a cyclic case, a triangle without a
// grain or phase, a load the cell cannot take (check_load).
void check_case_input(const ExportMesh& m, const FoamOptions& o) {
  for (const FoamPhase& p : m.phases) {
    if (!(p.youngs_modulus > 0.0) || !std::isfinite(p.youngs_modulus))
      throw ConfigError("phase." + p.name + ".E: must be positive, got " + to_text(p.youngs_modulus));
    if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5))
      throw ConfigError("phase." + p.name + ".nu: must lie in (-1, 0.5), got " + to_text(p.poisson_ratio));
  }
  const bool thermal = o.delta_T != 0.0;
  if (!std::isfinite(o.delta_T)) throw ConfigError("load.delta_T: must be a finite number (K), got " + to_text(o.delta_T));
  if (thermal && (!o.cyclic || o.traction != 0.0))
    throw ConfigError("load.delta_T: a thermal case is a periodic cell's cyclic case (homogenise.boundary = periodic)");
  for (const FoamPhase& p : m.phases)
    if (thermal && !(p.alpha >= 0.0 && std::isfinite(p.alpha)))
      throw ConfigError("phase." + p.name + ".alpha: must be a finite number >= 0 (1/K), got " + to_text(p.alpha));
  if (m.phase.size() != m.mesh.cells() || m.grain.size() != m.mesh.cells())
    throw GeometryError("export: the mesh needs a grain and a phase per triangle");
  for (int ph : m.phase)
    if (ph < 0 || static_cast<std::size_t>(ph) >= m.phases.size())
      throw GeometryError("export: a triangle names phase " + std::to_string(ph) + ", which does not exist");
  check_load(m.cell, m.periodic, m.phases, o);
}

// 0/E, 0/nu from each cell's phase; under a temperature change also 0/alpha and 0/T.
void write_material_fields(const std::filesystem::path& dir, const ExportMesh& m, const PolyMesh& pm,
                           const FoamOptions& o) {
  // Fields from each cell's phase.
  std::vector<double> E(pm.cells), nu(pm.cells), alpha(pm.cells);
  for (int t = 0; t < pm.cells; ++t) {
    E[t] = m.phases[m.phase[t]].youngs_modulus;
    nu[t] = m.phases[m.phase[t]].poisson_ratio;
    alpha[t] = m.phases[m.phase[t]].alpha;
  }
  write_scalar_field(dir / "0/E", "E", "[1 -1 -2 0 0 0 0]", E, pm, o.binary);
  write_scalar_field(dir / "0/nu", "nu", "[0 0 0 0 0 0 0]", nu, pm, o.binary);

  if (o.delta_T != 0.0) {
    // A uniform temperature change: T holds it in every cell and keeps it (its equation is
    // not iterated, see fvSolution); alpha per cell from the phases.
    write_scalar_field(dir / "0/alpha", "alpha", "[0 0 0 -1 0 0 0]", alpha, pm, o.binary);
    write_uniform_scalar_field(dir / "0/T", "T", "[0 0 0 1 0 0 0]", o.delta_T, pm);
  }
}

// 0/D: the load on `right`, symmetry or traction-free elsewhere, or the jump across the
// cyclic pairs.
void write_displacement(const std::filesystem::path& dir, const ExportMesh& m, const PolyMesh& pm,
                        const FoamOptions& o) {
  // Displacement: the load on `right`, symmetry or traction-free elsewhere. The solve
  // starts from the displacement a uniform cell would take under the imposed mean strain
  // (left and bottom held): only the fluctuation is left to the corrections.
  const std::string d = number_text(o.displacement * o.convert_to_meters);
  const std::array<double, 3> mean_strain = o.cyclic ? cyclic_strain(m, o)
                                            : o.traction == 0.0
                                                ? std::array<double, 3>{o.displacement / m.cell.width(), 0.0, 0.0}
                                                : std::array<double, 3>{};
  std::vector<double> initial(3 * static_cast<std::size_t>(pm.cells), 0.0);
  for (int t = 0; t < pm.cells; ++t) {
    const Vec2 c = cell_centroid(m.mesh, static_cast<std::size_t>(t)) - m.cell.lo;
    initial[3 * t] = (mean_strain[0] * c.x + mean_strain[2] * c.y) * o.convert_to_meters;
    initial[3 * t + 1] = (mean_strain[2] * c.x + mean_strain[1] * c.y) * o.convert_to_meters;
  }
  FoamFile D(dir / "0/D", "volVectorField", "0", "D", o.binary);
  D.text("dimensions      [0 1 0 0 0 0 0];\n\ninternalField   nonuniform List<vector> ").vectors(initial);
  D.text(";\n\nboundaryField\n{\n");
  for (const PolyMesh::Patch& p : pm.patches) {
    std::string entry = constraint_entry(p);
    const std::array<double, 3>& e = mean_strain;
    const bool x_pair = p.name == "left" || p.name == "right";
    const double L = (x_pair ? m.cell.width() : m.cell.height()) * o.convert_to_meters;
    const double jump_x = (x_pair ? e[0] : e[2]) * L, jump_y = (x_pair ? e[2] : e[1]) * L;
    if (p.type == "cyclic" && (jump_x != 0.0 || jump_y != 0.0)) {
      // Periodic: D jumps across the pair by the macroscopic strain times the separation
      // (given on the low patch of the pair), so the mean strain is the one imposed.
      const bool low = p.name == "left" || p.name == "bottom";
      entry = "type            fixedJump;\n        patchType       cyclic;\n" +
              (low ? "        jump            uniform (" + number_text(jump_x) + " " + number_text(jump_y) + " 0);\n"
                   : std::string()) +
              "        value           uniform (0 0 0);";
    } else if (entry.empty() && p.name == "right" && o.traction != 0.0) {
      entry = "type            tractionDisplacement;\n        traction        uniform (" + number_text(o.traction) +
              " 0 0);\n        pressure        uniform 0;\n        value           uniform (0 0 0);";
    } else if (entry.empty() && p.name == "right") {
      // The normal component fixed, the tangential free (zero gradient).
      entry = "type            directionMixed;\n        refValue        uniform (" + d +
              " 0 0);\n        refGradient     uniform (0 0 0);\n        valueFraction   uniform (1 0 0 0 0 0);\n"
              "        value           uniform (" + d + " 0 0);";
    } else if (entry.empty()) {
      entry = "type            tractionDisplacement;\n        traction        uniform (0 0 0);\n"
              "        pressure        uniform 0;\n        value           uniform (0 0 0);";
    }
    D.text("    " + p.name + "\n    {\n        " + entry + "\n    }\n");
  }
  D.text("}\n").write();

}

// constant/mechanicalProperties and thermalProperties.
void write_properties(const std::filesystem::path& dir, const FoamOptions& o) {
  const bool thermal = o.delta_T != 0.0;
  write_text(dir / "constant/mechanicalProperties",
             dictionary_header("constant", "mechanicalProperties") +
                 "// E and nu vary by phase: read from 0/E and 0/nu.\nrho\n{\n    type        uniform;\n"
                 "    value       1;\n}\n\nnu\n{\n    type        field;\n}\n\nE\n{\n    type        field;\n}\n\n"
                 "planeStress     " + std::string(o.plane_stress ? "yes" : "no") + ";\n");
  write_text(dir / "constant/thermalProperties",
             dictionary_header("constant", "thermalProperties") +
                 (thermal ? "// The temperature change in 0/T (uniform), alpha per cell in 0/alpha. C and k only\n"
                            "// set how T would diffuse; it is uniform and stays so.\nthermalStress   yes;\n\n"
                            "C\n{\n    type        uniform;\n    value       1;\n}\n\n"
                            "k\n{\n    type        uniform;\n    value       1;\n}\n\n"
                            "alpha\n{\n    type        field;\n}\n"
                          : "thermalStress   no;\n"));
}

// system/fvSchemes and fvSolution.
void write_schemes(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& o) {
  const bool thermal = o.delta_T != 0.0;
  const bool harmonic = harmonic_stiffness(m, o);
  const std::string stiffness = harmonic
      ? "    // The stiffness interpolated harmonically across faces: exact at phase interfaces.\n"
        "    laplacian(DD,D) Gauss harmonic corrected;\n"
      : "    // The stiffness interpolated linearly: harmonic diverges at this stiffness contrast.\n"
        "    laplacian(DD,D) Gauss linear corrected;\n";
  write_text(dir / "system/fvSchemes",
             dictionary_header("system", "fvSchemes") +
                 "d2dt2Schemes\n{\n    default         steadyState;\n}\n\nddtSchemes\n{\n    default         Euler;\n}\n\n"
                 "gradSchemes\n{\n    default         leastSquares;\n" +
                 (thermal ? "    // The thermal force as a sum over faces: each cell's share of the interfaces.\n"
                            "    grad((threeKalpha*T)) Gauss linear;\n"
                          : "") +
                 "}\n\n"
                 "divSchemes\n{\n    default         none;\n    div(sigmaD)     Gauss linear;\n}\n\n"
                 "laplacianSchemes\n{\n    default         none;\n" + stiffness +
                 "    laplacian(DT,T) Gauss linear corrected;\n}\n\n"
                 "interpolationSchemes\n{\n    default         linear;\n}\n\nsnGradSchemes\n{\n    default         none;\n}\n");
  write_text(dir / "system/fvSolution",
             dictionary_header("system", "fvSolution") +
                 "solvers\n{\n    D\n    {\n        solver          GAMG;\n        tolerance       1e-12;\n"
                 "        relTol          0.1;\n        smoother        GaussSeidel;\n    }\n" +
                 (thermal ? "    // T is uniform: met at once, never iterated.\n    T\n    {\n        solver          PCG;\n"
                            "        preconditioner  none;\n        tolerance       1e300;\n        relTol          0;\n    }\n"
                          : "") +
                 "}\n\n"
                 "// One correction per (pseudo-)time step: system/controlDict says when to stop.\n"
                 "stressAnalysis\n{\n    compactNormalStress yes;\n    nCorrectors     1;\n    D               " +
                 number_text(kSolverTolerance) + ";\n}\n");
}

// Allrun: checkMesh and the solve (decomposed and put together again on several
// processes), each step's output in its log, in the environment --solve gives them.
void write_allrun(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& o) {
  // Each step's output in its log; a failing step says so and stops.
  auto step = [](const std::string& command, const std::string& log) {
    return command + " > " + log + " 2>&1 || { echo \"" + command + " failed: see " + log + "\"; exit 1; }\n";
  };
  std::string solve;
  for (const std::string& word : solver_command(o)) solve += (solve.empty() ? "" : " ") + word;
  if (o.processes > 1) {
    write_decompose_dict(dir, m, o);
    solve = "if [ \"$(id -u)\" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi\n" +
            step("decomposePar -force", "log.decomposePar") + step(solve, "log.solidDisplacementFoam") +
            step("reconstructPar -latestTime", "log.reconstructPar");
  } else {
    solve = step(solve, "log.solidDisplacementFoam");
  }
  write_text(dir / "Allrun",
             "#!/bin/sh\n# Checks the mesh and solves; logs in log.*.\ncd \"${0%/*}\" || exit 1\n"
             "export WM_PROJECT_DIR=\"${WM_PROJECT_DIR:-" + std::string(kFoamProjectDir) + "}\"\n"
             "export GLIBC_TUNABLES=\"" + malloc_tunables() + "${GLIBC_TUNABLES:+:$GLIBC_TUNABLES}\"\n" +
             step("checkMesh", "log.checkMesh") + solve);
  std::filesystem::permissions(dir / "Allrun", std::filesystem::perms::owner_exec | std::filesystem::perms::group_exec |
                                                   std::filesystem::perms::others_exec,
                               std::filesystem::perm_options::add);
}

}  // namespace

PolyMesh write_foam_case(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& o) {
  check_case_input(m, o);
  const PolyMesh pm = build_polymesh(m, o);
  for (const char* sub : {"constant/polyMesh", "0", "system"}) std::filesystem::create_directories(dir / sub);
  write_polymesh(dir / "constant/polyMesh", pm, o);
  write_material_fields(dir, m, pm, o);
  write_displacement(dir, m, pm, o);
  write_properties(dir, o);
  write_control_dict(dir, m, o, kMaxCorrections);
  write_schemes(dir, m, o);
  write_allrun(dir, m, o);
  write_text(dir / "case.foam", "");
  return pm;
}

}  // namespace grainmesh
