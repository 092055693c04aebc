#include "analysis/solve.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>

#include "analysis/foam_fields.hpp"
#include "analysis/solve_monitor.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/process.hpp"
#include "common/side_by_side.hpp"
#include "common/text_file.hpp"

namespace grainmesh {

int solves_side_by_side(int processes) {
  return std::max(1, cores() / std::max(1, processes));
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void check_installed(const FoamOptions& o) {
  if (std::system("command -v solidDisplacementFoam > /dev/null 2>&1") != 0)
    throw IoError("--solve: solidDisplacementFoam is not installed (Debian package openfoam; scripts/install-deps.sh)");
  if (o.processes > 1 && std::system("command -v mpirun > /dev/null 2>&1") != 0)
    throw IoError("solve.processes: mpirun is not installed (Debian package openmpi-bin, which openfoam brings)");
}

// How long OpenFOAM's programs may take on a case, scaled to its mesh's files (they read
// them at a megabyte a second at the very least): a utility (decomposePar,
// reconstructPar) in all, the solver between two lines of its log. A program that hangs
// (mpirun waiting for a rank that never starts, say) is stopped there, not at limits.seconds.
ChildBudget utility_budget(double mesh_seconds) { return {.seconds = 120.0 + 20.0 * mesh_seconds}; }
ChildBudget solver_budget(double mesh_seconds) { return {.idle_seconds = 120.0 + 2.0 * mesh_seconds}; }

// Seconds to read the case's polyMesh at a megabyte a second.
double mesh_read_seconds(const std::filesystem::path& case_dir) {
  std::uintmax_t bytes = 0;
  std::error_code ec;
  for (const auto& f : std::filesystem::directory_iterator(case_dir / "constant" / "polyMesh", ec))
    if (f.is_regular_file(ec)) bytes += f.file_size(ec);
  return static_cast<double>(bytes) / 1e6;
}

// One solve of a case: where it runs, how, and how its errors name it.
struct SolveJob {
  std::filesystem::path case_dir, log;
  double mesh_seconds = 0.0;  // mesh_read_seconds
  const Deadline& deadline;
  std::vector<std::string> environment;
  std::vector<std::string> command;
  bool parallel = false;
  std::string field, who;         // errors name the field, and the load case when there are several
  std::filesystem::path shown;    // the case as messages show it
  std::string see;                // "; see LOG"
};

// A utility around the parallel solve (decomposePar, reconstructPar), its log beside;
// its wall-clock seconds.
double run_utility(const SolveJob& job, const std::vector<std::string>& argv) {
  const auto started = std::chrono::steady_clock::now();
  const std::string utility_log = "log." + argv.front();
  const ChildBudget budget = utility_budget(job.mesh_seconds);
  const int status = run_child(argv, job.case_dir, job.case_dir / utility_log, job.deadline, argv.front(), job.environment,
                               {}, budget);
  if (status == kChildOverBudget)
    throw SolveError(job.who + ": " + argv.front() + " did not finish in " + to_text(budget.seconds, 3) +
                     " s (its budget for this mesh); see " + (job.shown / utility_log).string());
  if (status != 0)
    throw SolveError(job.who + ": " + argv.front() + " failed (exit code " + std::to_string(status) + "); see " +
                     (job.shown / utility_log).string());
  return seconds_since(started);
}

// What the monitor watches for: convergence by grainmesh's measure, a stall, divergence (a
// thousand times the displacement the load can give), the case's own stop.
SolveMonitor::Options watch_options(const FoamCell& cell, const FoamOptions& o, const CaseStop& stop) {
  const double load_scale = std::max(load_strain(cell, o), thermal_strain(cell, o)) *
                            std::max({cell.size.x, cell.size.y, cell.size.z});
  return {.tolerance = kSolverTolerance,
          .stall_corrections = 500,
          .diverged_range = 1e3 * load_scale * o.convert_to_meters,
          .case_watches = {stop.alone < 0 || stop.alone == 0, stop.alone < 0 || stop.alone == 1,
                           stop.alone < 0 || stop.alone == 2},
          .case_tolerance = stop.tolerance,
          .case_patience = 50,
          .stress_window = kStressWindow,
          .stress_tolerance = kStressTolerance};
}

// How the runs of the solver ended: the last one's monitor and exit status, and the
// corrections of them all.
struct Followed {
  SolveMonitor monitor;
  int status = 0;
  int total = 0;
};

// Runs until converged. Where the case stops itself on its residual before the effective
// stress has settled (a shear load on one material: the stress converges more slowly than
// the residual), it is continued from where it stopped with its stop ten times tighter (a
// few corrections more each time), up to eight times; each run's log is kept as log.*.N.
// Each run is followed and killed as soon as it stalls, diverges or will not stop on its
// own; its seconds are added to r.solver_seconds.
Followed run_until_converged(const SolveJob& job, const FoamCell& cell, const FoamOptions& o, SolveRun& r) {
  const CaseStop stop = case_stop(cell, o);
  SolveMonitor::Options watch = watch_options(cell, o, stop);
  auto solve = [&](SolveMonitor& monitor) {
    const auto started = std::chrono::steady_clock::now();
    const ChildBudget budget = solver_budget(job.mesh_seconds);
    const int status = run_child(job.command, job.case_dir, job.log, job.deadline, "solidDisplacementFoam",
                                 job.environment, [&](std::string_view text) {
                                   const SolveMonitor::State s = monitor.feed(text);
                                   return s != SolveMonitor::State::running && s != SolveMonitor::State::converged;
                                 }, budget);
    r.solver_seconds += seconds_since(started);
    if (status == kChildOverBudget)
      throw SolveError(job.who + ": " + job.command.front() + " wrote nothing for " + to_text(budget.idle_seconds, 3) +
                       " s (its budget for this mesh) after " + std::to_string(monitor.corrections()) +
                       " corrections, and was stopped" + job.see);
    return status;
  };
  Followed f{SolveMonitor(watch)};
  int start = 0;
  double tighter = 1.0;
  for (int part = 0;; ++part) {
    if (part > 0) {
      std::filesystem::rename(job.log, job.log.string() + "." + std::to_string(part));
      start = std::stoi(latest_time_dir(job.parallel ? job.case_dir / "processor0" : job.case_dir).filename().string());
      tighter *= 0.1;
      watch.case_tolerance = stop.tolerance * tighter;
      write_control_dict(job.case_dir, cell, o, kMaxCorrections, tighter, start);
    }
    f.monitor = SolveMonitor(watch);
    f.status = solve(f.monitor);
    if (f.monitor.state() == SolveMonitor::State::case_stuck) {
      // Converged by the measure, but OpenFOAM's own residual of a component near zero is
      // noise: solved again to exactly where the measure was met (the same corrections, one
      // process, so the same numbers), and written there. What the stopped run may have
      // begun to write (its own stop can fire as it is stopped) is removed first: a later,
      // half-written time would be taken for the result.
      remove_times_after(job.parallel ? job.case_dir / "processor0" : job.case_dir, start);
      for (int p = 1; job.parallel && p < o.processes; ++p)
        remove_times_after(job.case_dir / ("processor" + std::to_string(p)), start);
      write_control_dict(job.case_dir, cell, o, start + f.monitor.converged_at(), tighter, start);
      f.monitor = SolveMonitor(watch);
      f.status = solve(f.monitor);
    }
    f.total += f.monitor.corrections();
    const bool stopped_itself = f.monitor.state() == SolveMonitor::State::running && f.status == 0 &&
                                start + f.monitor.corrections() < kMaxCorrections;
    if (!stopped_itself || part == 8) break;
  }
  return f;
}

// Whether the solve blew up: the monitor saw it diverge, or OpenFOAM stopped on a
// floating-point overflow.
bool diverged(const SolveJob& job, const Followed& f) {
  if (f.monitor.state() == SolveMonitor::State::diverging || f.status == 128 + SIGFPE) return true;
  return read_text_file(job.log, "the solver's log").find("sigFpe") != std::string::npos;
}

// What to try when a solve fails: what the case's own choices suggest.
std::string advice(const FoamCell& cell, const FoamOptions& o) {
  const double contrast = stiffness_contrast(cell.phases, o);
  if (cell.dimensions() == 3)
    return o.cells == FoamOptions::Cells::polygons
               ? ": check the phases' moduli and the mesh (report.json: mesh.min_dihedral_deg); a finer mesh "
                 "(mesh.tets_per_grain) may help"
               : ": export.cells = tetrahedra solves solidDisplacementFoam's plain form, which does not converge on "
                 "every mesh and stiffness contrast; use export.cells = polyhedra (the default)";
  if (harmonic_stiffness(cell, o) && contrast > 3.0)
    return ": the stiffness contrast " + to_text(contrast, 3) +
           " is too high for export.stiffness_interpolation = harmonic; use auto or linear";
  if (harmonic_stiffness(cell, o))
    return ": check the phases' moduli and the mesh quality (q_min), or try export.stiffness_interpolation = linear";
  return ": check the phases' moduli and the mesh quality (q_min); a finer mesh (mesh.triangles_per_grain) may help";
}

// Throws SolveError, with what to do about it, unless the solve converged.
void check_converged(const SolveJob& job, const Followed& f, const FoamCell& cell, const FoamOptions& o) {
  const SolveMonitor& monitor = f.monitor;
  const std::string advice = grainmesh::advice(cell, o);
  const SolveMonitor::State state = monitor.state();
  if (state == SolveMonitor::State::diverging || state == SolveMonitor::State::stalled)
    throw SolveError(job.field + ": solidDisplacementFoam " +
                     (state == SolveMonitor::State::diverging ? "diverges: " : "stalls: ") + monitor.diagnosis() +
                     advice + job.see);
  const std::string text = read_text_file(job.log, "the solver's log");
  if (diverged(job, f))
    throw SolveError(job.field + ": solidDisplacementFoam diverges: floating-point overflow after " +
                     std::to_string(monitor.corrections()) + " corrections" + advice + job.see);
  if (f.status != 0 || text.find("\nEnd") == std::string::npos)
    throw SolveError(job.who + ": " + job.command.front() + " failed (exit code " + std::to_string(f.status) + ")" +
                     job.see);
  if (state != SolveMonitor::State::converged || !(monitor.measure() < kSolverTolerance))
    throw SolveError(job.field + ": solidDisplacementFoam did not converge in " + std::to_string(f.total) +
                     " corrections (residual " + to_text(monitor.measure(), 3) + ", the effective stress's change " +
                     to_text(monitor.stress_change(), 3) + "; tolerances " + to_text(kSolverTolerance) + " and " +
                     to_text(kStressTolerance) + ")" + advice + job.see);
}

}  // namespace

SolveRun run_solver(const std::filesystem::path& case_dir, const FoamCell& cell, const FoamOptions& o,
                    const Deadline& deadline, const std::filesystem::path& case_shown_as, const std::string& load_case) {
  check_installed(o);
  const std::filesystem::path shown = case_shown_as.empty() ? case_dir : case_shown_as;
  const SolveJob job{.case_dir = case_dir,
                     .log = case_dir / "log.solidDisplacementFoam",
                     .mesh_seconds = mesh_read_seconds(case_dir),
                     .deadline = deadline,
                     .environment = foam_environment(),
                     .command = solver_command(o),
                     .parallel = o.processes > 1,
                     .field = load_case.empty() ? "D" : "D (load case " + load_case + ")",
                     .who = load_case.empty() ? std::string("--solve") : "load case " + load_case,
                     .shown = shown,
                     .see = "; see " + (shown / "log.solidDisplacementFoam").string()};
  SolveRun r;
  if (job.parallel) r.decompose_seconds = run_utility(job, {"decomposePar", "-force"});
  FoamOptions used = o;
  Followed f = run_until_converged(job, cell, used, r);
  r.linear_solver = linear_solver_name(linear_solver(cell, used));
  if (diverged(job, f) && linear_solver(cell, used) == FoamOptions::LinearSolver::multigrid) {
    // Multigrid blew up (its coarsest levels are the most fragile): the case solved again
    // from its start with conjugate gradients, the failed run's log kept beside.
    r.linear_solver_fallback = "GAMG diverged after " + std::to_string(f.total) + " corrections (log.solidDisplacementFoam.GAMG); solved again with PCG";
    std::filesystem::rename(job.log, job.log.string() + ".GAMG");
    remove_times_after(case_dir, 0.0);
    for (int p = 0; job.parallel && p < o.processes; ++p) remove_times_after(case_dir / ("processor" + std::to_string(p)), 0.0);
    used.linear_solver = FoamOptions::LinearSolver::conjugate_gradients;
    write_fv_solution(case_dir, cell, used);
    write_control_dict(case_dir, cell, used, kMaxCorrections);
    f = run_until_converged(job, cell, used, r);
    r.linear_solver = linear_solver_name(FoamOptions::LinearSolver::conjugate_gradients);
  }
  check_converged(job, f, cell, used);
  if (job.parallel) r.reconstruct_seconds = run_utility(job, {"reconstructPar", "-latestTime"});
  r.corrections = f.total;
  r.final_residual = f.monitor.measure();
  r.component_residuals = f.monitor.residuals();
  r.stress_change = f.monitor.stress_change();
  r.result_dir = latest_time_dir(case_dir);
  return r;
}

}  // namespace grainmesh
