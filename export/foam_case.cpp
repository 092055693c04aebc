#include "export/foam_case.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/allocator.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/foam_file.hpp"
#include "export/foam_solver.hpp"
#include "export/pin_translation.hpp"
#include "export/polymesh_2d.hpp"
#include "export/polymesh_files.hpp"

namespace grainmesh {

namespace {

// 0/E, 0/nu from each cell's phase; under a temperature change also 0/alpha and 0/T.
void write_material_fields(const std::filesystem::path& dir, const FoamCell& cell, const std::vector<int>& phase,
                           const PolyMesh& pm, const FoamOptions& o) {
  // Fields from each cell's phase.
  std::vector<double> E(pm.cells), nu(pm.cells), alpha(pm.cells);
  for (int t = 0; t < pm.cells; ++t) {
    E[t] = cell.phases[phase[t]].youngs_modulus;
    nu[t] = cell.phases[phase[t]].poisson_ratio;
    alpha[t] = cell.phases[phase[t]].alpha;
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
void write_displacement(const std::filesystem::path& dir, const FoamCell& cell, const std::vector<Vec3>& centroid,
                        const PolyMesh& pm, const FoamOptions& o) {
  // Displacement: the load on `right`, symmetry or traction-free elsewhere. The solve
  // starts from the displacement a uniform cell would take under the imposed mean strain
  // (left, bottom and back held): only the fluctuation is left to the corrections.
  const std::string d = number_text(o.displacement * o.convert_to_meters);
  const std::array<double, 6> e = o.cyclic ? cyclic_strain(cell, o)
                                  : o.traction == 0.0 ? std::array<double, 6>{o.displacement / cell.size.x}
                                                      : std::array<double, 6>{};
  // The displacement of the mean strain at c (mesh units from the cell's low corner), metres.
  auto affine = [&](Vec3 c) {
    return o.convert_to_meters * Vec3{e[0] * c.x + e[5] * c.y + e[4] * c.z, e[5] * c.x + e[1] * c.y + e[3] * c.z,
                                      e[4] * c.x + e[3] * c.y + e[2] * c.z};
  };
  std::vector<double> initial(3 * static_cast<std::size_t>(pm.cells), 0.0);
  for (int t = 0; t < pm.cells; ++t) {
    const Vec3 u = affine(centroid[t]);
    initial[3 * t] = u.x, initial[3 * t + 1] = u.y, initial[3 * t + 2] = u.z;
  }
  FoamFile D(dir / "0/D", "volVectorField", "0", "D", o.binary);
  D.text("dimensions      [0 1 0 0 0 0 0];\n\ninternalField   nonuniform List<vector> ").vectors(initial);
  D.text(";\n\nboundaryField\n{\n");
  for (const PolyMesh::Patch& p : pm.patches) {
    std::string entry = constraint_entry(p);
    const Vec3 jump = p.type == "cyclic" ? cyclic_jump(e, p.name, cell, o.convert_to_meters) : Vec3{};
    if (is_pin_patch(p)) {
      // The face fixing the periodic cell's translation (pin_translation.hpp): the mean
      // strain's displacement there.
      const Vec3 u = affine(p.at);
      entry = "type            fixedValue;\n        value           uniform (" + number_text(u.x + 0.0) + " " +
              number_text(u.y + 0.0) + " " + number_text(u.z + 0.0) + ");";
    } else if (p.type == "cyclic" && jump != Vec3{}) {
      // Periodic: D jumps across the pair by the macroscopic strain times the separation
      // (given on the low patch of the pair), so the mean strain is the one imposed.
      const bool low = p.name == "left" || p.name == "bottom" || p.name == "back";
      entry = "type            fixedJump;\n        patchType       cyclic;\n" +
              (low ? "        jump            uniform (" + number_text(jump.x) + " " + number_text(jump.y) + " " +
                         number_text(jump.z) + ");\n"
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
void write_schemes(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& o) {
  const bool thermal = o.delta_T != 0.0;
  const bool harmonic = harmonic_stiffness(cell, o);
  const std::string stiffness = harmonic
      ? "    // The stiffness interpolated harmonically across faces: exact at phase interfaces.\n"
        "    laplacian(DD,D) Gauss harmonic corrected;\n"
      : std::string(cell.dimensions() == 3 ? "    // The stiffness interpolated linearly: harmonic diverges in 3D.\n"
                                           : "    // The stiffness interpolated linearly: harmonic diverges at this stiffness contrast.\n") +
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
  write_fv_solution(dir, cell, o);
}

// Allrun: checkMesh and the solve (decomposed and put together again on several
// processes), each step's output in its log, in the environment --solve gives them.
void write_allrun(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& o) {
  // Each step's output in its log; a failing step says so and stops.
  auto step = [](const std::string& command, const std::string& log) {
    return command + " > " + log + " 2>&1 || { echo \"" + command + " failed: see " + log + "\"; exit 1; }\n";
  };
  std::string solve;
  for (const std::string& word : solver_command(o)) solve += (solve.empty() ? "" : " ") + word;
  if (o.processes > 1) {
    write_decompose_dict(dir, cell, o);
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

void check_case(const FoamCell& cell, const std::vector<int>& grain, const std::vector<int>& phase, std::size_t cells,
                const FoamOptions& o) {
  for (const FoamPhase& p : cell.phases) {
    if (!(p.youngs_modulus > 0.0) || !std::isfinite(p.youngs_modulus))
      throw ConfigError("phase." + p.name + ".E: must be positive, got " + to_text(p.youngs_modulus));
    if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5))
      throw ConfigError("phase." + p.name + ".nu: must lie in (-1, 0.5), got " + to_text(p.poisson_ratio));
  }
  const bool thermal = o.delta_T != 0.0;
  if (!std::isfinite(o.delta_T)) throw ConfigError("load.delta_T: must be a finite number (K), got " + to_text(o.delta_T));
  if (thermal && (!o.cyclic || o.traction != 0.0))
    throw ConfigError("load.delta_T: a thermal case is a periodic cell's cyclic case (homogenise.boundary = periodic)");
  for (const FoamPhase& p : cell.phases)
    if (thermal && !(p.alpha >= 0.0 && std::isfinite(p.alpha)))
      throw ConfigError("phase." + p.name + ".alpha: must be a finite number >= 0 (1/K), got " + to_text(p.alpha));
  if (phase.size() != cells || grain.size() != cells)
    throw GeometryError("export: the mesh needs a grain and a phase per cell");
  for (int ph : phase)
    if (ph < 0 || static_cast<std::size_t>(ph) >= cell.phases.size())
      throw GeometryError("export: a cell names phase " + std::to_string(ph) + ", which does not exist");
  check_load(cell, o);
}

void write_case_files(const std::filesystem::path& dir, const FoamCell& cell, const std::vector<int>& phase,
                      const std::vector<Vec3>& centroid, const PolyMesh& pm, const FoamOptions& o,
                      const std::filesystem::path& polymesh_from) {
  for (const char* sub : {"constant/polyMesh", "0", "system"}) std::filesystem::create_directories(dir / sub);
  if (polymesh_from.empty())
    write_polymesh(dir / "constant/polyMesh", pm, o);
  else
    std::filesystem::copy(polymesh_from, dir / "constant/polyMesh",
                          std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
  write_material_fields(dir, cell, phase, pm, o);
  write_displacement(dir, cell, centroid, pm, o);
  write_properties(dir, o);
  write_control_dict(dir, cell, o, kMaxCorrections);
  write_schemes(dir, cell, o);
  write_allrun(dir, cell, o);
  write_text(dir / "case.foam", "");
}

namespace {

// The case files of a checked 2D case around its built polyMesh: each cell's centroid from
// the cell's low corner, the fields, properties and dictionaries.
void write_checked_case(const std::filesystem::path& dir, const ExportMesh<2>& m, const PolyMesh& pm, const FoamOptions& o,
                        const std::filesystem::path& polymesh_from) {
  std::vector<Vec3> centroid(m.mesh.cells());
  for (std::size_t t = 0; t < centroid.size(); ++t) {
    const Vec2 c = cell_centroid(m.mesh, t) - m.cell.lo;
    centroid[t] = {c.x, c.y, 0.0};
  }
  write_case_files(dir, foam_cell(m), m.phase, centroid, pm, o, polymesh_from);
}

}  // namespace

PolyMesh write_foam_case(const std::filesystem::path& dir, const ExportMesh<2>& m, const FoamOptions& o) {
  check_case(foam_cell(m), m.grain, m.phase, m.mesh.cells(), o);
  const PolyMesh pm = build_polymesh(m, o);
  write_checked_case(dir, m, pm, o, {});
  return pm;
}

void write_foam_case(const std::filesystem::path& dir, const ExportMesh<2>& m, const PolyMesh& pm, const FoamOptions& o,
                     const std::filesystem::path& polymesh_from) {
  check_case(foam_cell(m), m.grain, m.phase, m.mesh.cells(), o);  // each load case's own load
  write_checked_case(dir, m, pm, o, polymesh_from);
}

}  // namespace grainmesh
