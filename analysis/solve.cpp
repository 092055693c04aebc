#include "analysis/solve.hpp"

#include <chrono>
#include <csignal>
#include <cstdlib>

#include "analysis/foam_fields.hpp"
#include "analysis/solve_monitor.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/process.hpp"
#include "common/text_file.hpp"

namespace grainmesh {

SolveRun run_solver(const std::filesystem::path& case_dir, const ExportMesh& m, const FoamOptions& o,
                    const Deadline& deadline, const std::filesystem::path& case_shown_as, const std::string& load_case) {
  if (std::system("command -v solidDisplacementFoam > /dev/null 2>&1") != 0)
    throw IoError("--solve: solidDisplacementFoam is not installed (Debian package openfoam; scripts/install-deps.sh)");
  if (o.processes > 1 && std::system("command -v mpirun > /dev/null 2>&1") != 0)
    throw IoError("solve.processes: mpirun is not installed (Debian package openmpi-bin, which openfoam brings)");
  const std::filesystem::path log = case_dir / "log.solidDisplacementFoam";
  // Errors name the field, and the load case when there are several.
  const std::string field = load_case.empty() ? "D" : "D (load case " + load_case + ")";
  const std::string who = load_case.empty() ? std::string("--solve") : "load case " + load_case;
  const std::filesystem::path shown = case_shown_as.empty() ? case_dir : case_shown_as;  // in messages
  const std::string see = "; see " + (shown / log.filename()).string();
  const std::vector<std::string> environment = foam_environment();
  const std::vector<std::string> command = solver_command(o);
  const bool parallel = o.processes > 1;
  auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  // A utility around the parallel solve (decomposePar, reconstructPar), its log beside;
  // its wall-clock seconds.
  auto utility = [&](const std::vector<std::string>& argv) {
    const auto started = std::chrono::steady_clock::now();
    const std::string utility_log = "log." + argv.front();
    const int status = run_child(argv, case_dir, case_dir / utility_log, deadline, argv.front(), environment);
    if (status != 0)
      throw SolveError(who + ": " + argv.front() + " failed (exit code " + std::to_string(status) + "); see " +
                       (shown / utility_log).string());
    return seconds_since(started);
  };
  SolveRun r;
  if (parallel) r.decompose_seconds = utility({"decomposePar", "-force"});

  // A thousand times the displacement the load can give is divergence, not an answer.
  const double load_scale = std::max(load_strain(m.cell, m.phases, o), thermal_strain(m.phases, o)) *
                            std::max(m.cell.width(), m.cell.height());
  const CaseStop stop = case_stop(m, o);
  SolveMonitor::Options watch{.tolerance = kSolverTolerance,
                              .stall_corrections = 500,
                              .diverged_range = 1e3 * load_scale * o.convert_to_meters,
                              .case_watches = {stop.alone != 1, stop.alone != 0},
                              .case_tolerance = stop.tolerance,
                              .case_patience = 50,
                              .stress_window = kStressWindow,
                              .stress_tolerance = kStressTolerance};
  // One run of the solver, followed: killed as soon as it stalls, diverges or will not
  // stop on its own.
  auto solve = [&](SolveMonitor& monitor) {
    const auto started = std::chrono::steady_clock::now();
    const int status = run_child(command, case_dir, log, deadline, "solidDisplacementFoam", environment,
                                 [&](std::string_view text) {
                                   const SolveMonitor::State s = monitor.feed(text);
                                   return s != SolveMonitor::State::running && s != SolveMonitor::State::converged;
                                 });
    r.solver_seconds += seconds_since(started);
    return status;
  };
  // Runs until converged. Where the case stops itself on its residual before the
  // effective stress has settled (a shear load on one material: the stress converges
  // more slowly than the residual), it is continued from where it stopped with its stop ten
  // times tighter (a few corrections more each time), up to eight times; each run's log is
  // kept as log.*.N.
  SolveMonitor monitor(watch);
  int status = 0, start = 0, total = 0;
  double tighter = 1.0;
  for (int part = 0;; ++part) {
    if (part > 0) {
      std::filesystem::rename(log, log.string() + "." + std::to_string(part));
      start = std::stoi(latest_time_dir(parallel ? case_dir / "processor0" : case_dir).filename().string());
      tighter *= 0.1;
      watch.case_tolerance = stop.tolerance * tighter;
      write_control_dict(case_dir, m, o, kMaxCorrections, tighter, start);
    }
    monitor = SolveMonitor(watch);
    status = solve(monitor);
    if (monitor.state() == SolveMonitor::State::case_stuck) {
      // Converged by the measure, but OpenFOAM's own residual of a component near zero is
      // noise: solved again to exactly where the measure was met (the same corrections, one
      // process, so the same numbers), and written there.
      write_control_dict(case_dir, m, o, start + monitor.converged_at(), tighter, start);
      monitor = SolveMonitor(watch);
      status = solve(monitor);
    }
    total += monitor.corrections();
    const bool stopped_itself = monitor.state() == SolveMonitor::State::running && status == 0 &&
                                start + monitor.corrections() < kMaxCorrections;
    if (!stopped_itself || part == 8) break;
  }

  // What to do about a solve that goes nowhere.
  const std::string advice =
      harmonic_stiffness(m, o) && stiffness_contrast(m, o) > 3.0
          ? ": the stiffness contrast " + to_text(stiffness_contrast(m, o), 3) +
                " is too high for export.stiffness_interpolation = harmonic; use auto or linear"
          : ": check the phases' moduli and the mesh quality (q_min), or try export.stiffness_interpolation = linear";
  const SolveMonitor::State state = monitor.state();
  if (state == SolveMonitor::State::diverging || state == SolveMonitor::State::stalled)
    throw SolveError(field + ": solidDisplacementFoam " +
                     (state == SolveMonitor::State::diverging ? "diverges: " : "stalls: ") + monitor.diagnosis() +
                     advice + see);
  const std::string text = read_text_file(log, "the solver's log");
  if (status == 128 + SIGFPE || text.find("sigFpe") != std::string::npos)
    throw SolveError(field + ": solidDisplacementFoam diverges: floating-point overflow after " +
                     std::to_string(monitor.corrections()) + " corrections" + advice + see);
  if (status != 0 || text.find("\nEnd") == std::string::npos)
    throw SolveError(who + ": " + command.front() +
                     " failed (exit code " + std::to_string(status) + ")" + see);
  if (state != SolveMonitor::State::converged || !(monitor.measure() < kSolverTolerance))
    throw SolveError(field + ": solidDisplacementFoam did not converge in " + std::to_string(total) +
                     " corrections (residual " + to_text(monitor.measure(), 3) + ", the effective stress's change " +
                     to_text(monitor.stress_change(), 3) + "; tolerances " + to_text(kSolverTolerance) + " and " +
                     to_text(kStressTolerance) + ")" + advice + see);

  if (parallel) r.reconstruct_seconds = utility({"reconstructPar", "-latestTime"});
  r.corrections = total;
  r.final_residual = monitor.measure();
  r.component_residuals = monitor.residuals();
  r.stress_change = monitor.stress_change();
  r.result_dir = latest_time_dir(case_dir);
  return r;
}

}  // namespace grainmesh
