#include "export/foam_solver.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

bool harmonic_stiffness(const FoamCell& cell, const FoamOptions& o) {
  return o.interpolation == FoamOptions::Interpolation::harmonic ||
         (o.interpolation == FoamOptions::Interpolation::automatic && cell.dimensions() == 2 &&
          stiffness_contrast(cell.phases, o) <= 3.0);
}

FoamOptions::LinearSolver linear_solver(const FoamCell& cell, const FoamOptions& o) {
  if (o.linear_solver != FoamOptions::LinearSolver::automatic) return o.linear_solver;
  return cell.dimensions() == 2 ? FoamOptions::LinearSolver::multigrid : FoamOptions::LinearSolver::conjugate_gradients;
}

const char* linear_solver_name(FoamOptions::LinearSolver solver) {
  return solver == FoamOptions::LinearSolver::multigrid ? "GAMG" : "PCG";
}

void write_fv_solution(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& o) {
  const bool thermal = o.delta_T != 0.0;
  const bool multigrid = linear_solver(cell, o) == FoamOptions::LinearSolver::multigrid;
  write_text(dir / "system/fvSolution",
             dictionary_header("system", "fvSolution") +
                 "solvers\n{\n    D\n    {\n" +
                 (multigrid ? "        solver          GAMG;\n        tolerance       1e-12;\n"
                              "        relTol          0.1;\n        smoother        GaussSeidel;\n    }\n"
                            : std::string(o.linear_solver == FoamOptions::LinearSolver::automatic
                                              ? "        // Not GAMG: in 3D it blew up on the rounding noise of a component whose\n"
                                                "        // solution is zero.\n"
                                              : "        // Not GAMG: it diverged on this case (grainmesh's solve fell back on PCG).\n") +
                                  "        solver          PCG;\n        preconditioner  DIC;\n        tolerance       1e-12;\n"
                                  "        relTol          0.1;\n    }\n") +
                 (thermal ? "    // T is uniform: met at once, never iterated.\n    T\n    {\n        solver          PCG;\n"
                            "        preconditioner  none;\n        tolerance       1e300;\n        relTol          0;\n    }\n"
                          : "") +
                 "}\n\n"
                 "// One correction per (pseudo-)time step: system/controlDict says when to stop.\n" +
                 (compact_normal_stress(cell, o)
                      ? std::string()
                      : "// The force through a face S . sigma_f (sigma interpolated linearly), the implicit\n"
                        "// Laplacian only a predictor that cancels at convergence: the compact form diverges on\n"
                        "// tetrahedra with least-squares gradients, and with Gauss ones is not exact for a\n"
                        "// uniform strain (one material: C44 7 % low at 11k tetrahedra).\n") +
                 "stressAnalysis\n{\n    compactNormalStress " + (compact_normal_stress(cell, o) ? "yes" : "no") +
                 ";\n    nCorrectors     1;\n    D               " +
                 number_text(kSolverTolerance) + ";\n}\n");
}

}  // namespace grainmesh
