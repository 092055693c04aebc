#include "export/foam.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <unistd.h>

#include "common/allocator.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/foam_file.hpp"

namespace grainmesh {
namespace {

// Pseudo-time steps of one correction each (d2dt2 is steadyState), stopped by
// runTimeControl once OpenFOAM's own residual is below the tolerance (case_stop), or at
// `end_step`. The force through the loaded sides and the range of every displacement
// component are logged each step, for grainmesh's solve (solve_monitor.hpp).
std::string control_dict(const FoamCell& cell, const FoamOptions& o, int end_step, double tighter, int start) {
  const std::string steps = std::to_string(end_step);
  CaseStop stop = case_stop(cell, o);
  stop.tolerance *= tighter;
  // The force through the loaded sides, each correction: right, and top (and front in 3D)
  // for a cyclic case (there from the stress interpolated to the faces: a measure of
  // settling, not the answer).
  std::string range;
  for (const char* side : {"right", "top", "front"}) {
    if (std::string(side) != "right" && !o.cyclic) continue;
    if (std::string(side) == "front" && cell.dimensions() == 2) continue;
    range += std::string("    force_") + side + "\n    {\n        type            surfaceFieldValue;\n"
             "        libs            (fieldFunctionObjects);\n        fields          (" + kStressField + ");\n"
             "        operation       areaIntegrate;\n        regionType      patch;\n        name            " + side +
             ";\n        writeFields     no;\n        writeToFile     no;\n        log             yes;\n    }\n";
  }
  for (const char* op : {"min", "max"})
    range += std::string("    displacement_") + op + "\n    {\n        type            volFieldValue;\n"
             "        libs            (fieldFunctionObjects);\n        fields          (D);\n"
             "        operation       " + op + ";\n        regionType      all;\n        writeFields     no;\n"
             "        writeToFile     no;\n        log             yes;\n    }\n";
  return dictionary_header("system", "controlDict") +
         "application     solidDisplacementFoam;\n\n" +
         (start == 0 ? std::string("startFrom       startTime;\nstartTime       0;\n")
                     : "// Continued from where the last run stopped.\nstartFrom       latestTime;\n") +
         "stopAt          endTime;\n// Each step is one correction of the displacement (d2dt2 steadyState): at most " +
         steps + (end_step == kMaxCorrections ? "" : ", where grainmesh's criterion was met") +
         (tighter == 1.0 ? "" : "; its own stop tightened until the effective stress settles") +
         ".\nendTime         " + steps + ";\ndeltaT          1;\n\n" +
         (o.processes > 1 ? "// Written once, when the run stops; in binary on several processes, where\n"
                            "// decomposePar and reconstructPar would spend longer than the solve on ASCII.\n"
                          : "// Written once, when the run stops. Results in ASCII whatever the mesh's format:\n"
                            "// they are what users read (grainmesh reads either).\n") +
         "writeControl    timeStep;\nwriteInterval   " + steps + ";\npurgeWrite      0;\nwriteFormat     " +
         (o.processes > 1 ? "binary" : "ascii") +
         ";\nwritePrecision  12;\nwriteCompression off;\ntimeFormat      general;\ntimePrecision   6;\n"
         "runTimeModifiable false;\n\n"
         "functions\n{\n" + range +
         "    // Stop once the displacement equation's initial residual is below the tolerance" +
         (stop.alone >= 0 ? ";\n    // the loaded component alone (at a hundredth of it): one material keeps the other exactly\n"
                            "    // zero, and its residual is noise"
                          : "") +
         ";\n    // not before the effective stress has a full window of corrections to be judged by (a\n"
         "    // solve that starts at its answer, one material, would stop at once and not be known settled).\n"
         "    converged\n    {\n        type            runTimeControl;\n        libs            (utilityFunctionObjects);\n"
         "        timeStart       " + std::to_string(start + kStressWindow + 1) + ";\n"
         "        conditions\n        {\n            residual\n            {\n"
         "                type    equationInitialResidual;\n                fields  (" +
         (stop.alone >= 0 ? "D.component(" + std::to_string(stop.alone) + ")" : std::string("D")) + ");\n"
         "                value   " + number_text(stop.tolerance) + ";\n                mode    minimum;\n"
         "            }\n        }\n    }\n" +
         "    // The stress (sigmaD; rho is 1, so it is sigma) whenever the fields are written, also\n"
         "    // when runTimeControl stops the run, where the solver itself writes no sigma.\n"
         "    stress\n    {\n        type            writeObjects;\n        libs            (utilityFunctionObjects);\n"
         "        objects         (" + std::string(kStressField) + ");\n        writeOption     anyWrite;\n        writeControl    writeTime;\n    }\n" +
         (o.cyclic && compact_normal_stress(cell, o) ? "    // grad(D) where the fields are written: with D and sigmaD it gives the force through the\n"
                     "    // cyclic faces, where OpenFOAM writes no face values (grainmesh's homogenisation).\n"
                     "    gradient\n    {\n        type            grad;\n        libs            (fieldFunctionObjects);\n"
                     "        field           D;\n        executeControl  writeTime;\n        writeControl    writeTime;\n    }\n"
                   : "") +
         "}\n";
}

}  // namespace

void write_decompose_dict(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& o) {
  // The factors whose blocks are nearest cubic (square in 2D, nz = 1).
  std::array<int, 3> n{o.processes, 1, 1};
  double best = 1e300;
  const int depth = cell.dimensions() == 3 ? o.processes : 1;
  for (int a = 1; a <= o.processes; ++a)
    for (int c = 1; c <= depth; ++c) {
      if (o.processes % (a * c) != 0) continue;
      const int b = o.processes / (a * c);
      double badness = std::abs(std::log((cell.size.x / a) / (cell.size.y / b)));
      if (cell.dimensions() == 3)
        badness += std::abs(std::log((cell.size.y / b) / (cell.size.z / c))) +
                   std::abs(std::log((cell.size.x / a) / (cell.size.z / c)));
      if (badness < best) best = badness, n = {a, b, c};
    }
  std::string cyclic;
  if (o.cyclic)
    cyclic = "\n// Each cyclic face on the processor of its partner: the jump of D is applied there.\n"
             "constraints\n{\n    cyclics\n    {\n        type    preservePatches;\n"
             "        patches (left right bottom top" + std::string(cell.dimensions() == 3 ? " back front" : "") +
             ");\n    }\n}\n";
  write_text(dir / "system/decomposeParDict",
             dictionary_header("system", "decomposeParDict") + "numberOfSubdomains " + std::to_string(o.processes) +
                 ";\n\n// Blocks of the cell, as near " + (cell.dimensions() == 3 ? "cubic" : "square") +
                 " as the count allows.\nmethod          hierarchical;\n\n"
                 "coeffs\n{\n    n           (" + std::to_string(n[0]) + " " + std::to_string(n[1]) + " " +
                 std::to_string(n[2]) + ");\n    order       xyz;\n}\n" + cyclic);
}

std::array<double, 6> cyclic_strain(const FoamCell& cell, const FoamOptions& o) {
  if (o.strain != std::array<double, 6>{}) return o.strain;
  return {o.displacement / cell.size.x};
}

std::vector<std::string> foam_environment() {
  const char* project = std::getenv("WM_PROJECT_DIR");
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::vector<std::string> env{
      "WM_PROJECT_DIR=" + std::string(project != nullptr && *project != '\0' ? project : kFoamProjectDir),
      // Appended, not ":" + ...: GCC 12 warns wrongly on the latter (bug 105651).
      "GLIBC_TUNABLES=" + malloc_tunables() +
          (tunables != nullptr && *tunables != '\0' ? std::string(":").append(tunables) : std::string())};
  if (geteuid() == 0) env.insert(env.end(), {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"});
  return env;
}

std::vector<std::string> solver_command(const FoamOptions& o) {
  if (o.processes <= 1) return {"solidDisplacementFoam"};
  return {"mpirun", "--oversubscribe", "-np", std::to_string(o.processes), "solidDisplacementFoam", "-parallel"};
}

CaseStop case_stop(const FoamCell& cell, const FoamOptions& o) {
  // One material under a load that moves it along one axis only: the other components are
  // exactly zero and their residuals noise. Their error follows the loaded one's (their
  // range stays about ten times that one's residual, measured), so the loaded one alone at
  // a hundredth of the tolerance also meets the scale-aware criterion.
  bool one_material = true;
  for (const FoamPhase& p : cell.phases)
    one_material = one_material && p.youngs_modulus == cell.phases.front().youngs_modulus &&
                   p.poisson_ratio == cell.phases.front().poisson_ratio;
  // A periodic case's effective stress settles later than a mixed one's (measured: at a
  // residual near 1e-7 under a normal strain, lower under shear): its stop a hundred times
  // tighter, so that it rarely needs continuing (analysis/solve.cpp).
  const double tolerance = o.cyclic ? 0.01 * kSolverTolerance : kSolverTolerance;
  // A temperature change loads every component alike.
  if (!one_material || o.delta_T != 0.0) return {.alone = -1, .tolerance = tolerance};
  if (!o.cyclic) return o.uniaxial ? CaseStop{} : CaseStop{.alone = 0, .tolerance = 0.01 * tolerance};
  // A cyclic case: one normal strain alone moves the cell along its axis only.
  const std::array<double, 6> e = cyclic_strain(cell, o);
  int normal = -1, loaded = 0;
  for (int k = 0; k < 6; ++k)
    if (e[k] != 0.0) ++loaded, normal = k;
  if (loaded != 1 || normal > 2) return {.alone = -1, .tolerance = tolerance};
  return {.alone = normal, .tolerance = 0.01 * tolerance};
}

void write_control_dict(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& o, int end_step,
                        double tighter, int start) {
  write_text(dir / "system/controlDict", control_dict(cell, o, end_step, tighter, start));
}

double load_strain(const FoamCell& cell, const FoamOptions& o) {
  if (o.cyclic && o.strain != std::array<double, 6>{}) {
    double largest = 0.0;
    for (double e : o.strain) largest = std::max(largest, std::abs(e));
    return largest;
  }
  if (o.traction == 0.0) return std::abs(o.displacement) / cell.size.x;
  double softest = 1e300;
  for (const FoamPhase& p : cell.phases) softest = std::min(softest, p.youngs_modulus);
  return std::abs(o.traction) / softest;
}

double thermal_strain(const FoamCell& cell, const FoamOptions& o) {
  double strain = 0.0;
  for (const FoamPhase& p : cell.phases) {
    const double free = cell.dimensions() == 3 ? p.alpha : free_expansion(p, o.plane_stress);
    strain = std::max(strain, std::abs(free * o.delta_T));
  }
  return strain;
}

std::vector<FoamPhase> foam_phases(const std::vector<Phase>& phases) {
  std::vector<FoamPhase> out;
  for (const Phase& p : phases) out.push_back({p.name, p.youngs_modulus, p.poisson_ratio, p.alpha.value_or(0.0)});
  return out;
}

std::vector<std::string> check_load(const FoamCell& cell, const FoamOptions& o) {
  if (!(o.convert_to_meters > 0.0) || !std::isfinite(o.convert_to_meters))
    throw ConfigError("export.convert_to_meters: must be positive, got " + to_text(o.convert_to_meters));
  if (!(o.thickness >= 0.0) || !std::isfinite(o.thickness))
    throw ConfigError("export.thickness: must be positive (or 0 for the mean edge length), got " + to_text(o.thickness));
  if (o.cyclic && !cell.periodic)
    throw ConfigError("export.cyclic: the mesh is not periodic (opposite sides do not match); cyclic patches need a "
                      "periodic mesh, such as grainmesh mesh makes of a periodic tessellation");
  if (o.cyclic && (o.traction != 0.0 || o.uniaxial))
    throw ConfigError(std::string(o.traction != 0.0 ? "load.traction" : "load.uniaxial") +
                      ": not with export.cyclic, whose load is a displacement jump across left/right and whose "
                      "bottom/top pair keeps the mean transverse strain zero");
  // A cell below a nanometre is a unit slip (lengths in metres read as micrometres):
  // continuum elasticity means nothing there.
  const double size = std::max({cell.size.x, cell.size.y, cell.size.z}), metres = size * o.convert_to_meters;
  const std::string in_metres = to_text(size) + " mesh units across, times export.convert_to_meters = " +
                                to_text(o.convert_to_meters) + ": " + to_text(metres) + " m";
  if (metres < 1e-9)
    throw ConfigError("export.convert_to_meters: the cell is " + in_metres +
                      ", below 1 nm: are the lengths in metres? then set export.convert_to_meters = 1");
  // Linear elasticity is a small-strain theory: a strain above 1 % is a slip too, each
  // named by the key that makes it.
  if (o.traction == 0.0 && o.displacement == 0.0 && o.delta_T == 0.0)
    throw ConfigError("load.displacement: is 0, which loads nothing");
  if (o.traction != 0.0) {
    double softest = 1e300;
    for (const FoamPhase& p : cell.phases) softest = std::min(softest, p.youngs_modulus);
    if (std::abs(o.traction) > 0.01 * softest)
      throw ConfigError("load.traction: " + to_text(o.traction) + " Pa is above 1 % of the softest phase's E (" +
                        to_text(softest) + " Pa): strains beyond linear elasticity");
  } else if (std::abs(o.displacement) > 0.01 * cell.size.x) {
    throw ConfigError("load.displacement: " + to_text(o.displacement) + " over a cell " + to_text(cell.size.x) +
                      " wide is a mean strain of " + to_text(std::abs(o.displacement) / cell.size.x, 3) +
                      ", above 1 % (linear elasticity is for small strains): give it in the mesh's units, like the cell");
  }
  // A phase's free thermal strain: cobalt cooled from sintering takes 1.4 %; 5 % is no
  // longer a small strain.
  for (const FoamPhase& p : cell.phases) {
    const double free = std::abs((cell.dimensions() == 3 ? p.alpha : free_expansion(p, o.plane_stress)) * o.delta_T);
    if (free > 0.05)
      throw ConfigError("load.delta_T: " + to_text(o.delta_T) + " K gives phase " + p.name + " (alpha " + to_text(p.alpha) +
                        " /K) a free strain of " + to_text(free, 3) +
                        ", above 5 % (linear elasticity is for small strains): check phase." + p.name + ".alpha (1/K) and load.delta_T (K)");
  }
  std::vector<std::string> warnings;
  if (metres > 1.0)
    warnings.push_back("the cell is " + in_metres +
                       ", above 1 m: grainmesh is made for microstructures; check export.convert_to_meters");
  return warnings;
}

}  // namespace grainmesh
