#include "pipelines/homogenise.hpp"

#include <cmath>
#include <cstdlib>
#include <csignal>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/process.hpp"
#include "pipelines/solve_monitor.hpp"

namespace grainmesh {

namespace {

struct Moduli {
  double M, K, mu;                // sigma_xx/eps_xx at eps_yy = 0; 2D bulk; shear
  double s_xx, s_xy;              // in-plane compliance
};

Moduli moduli(const FoamPhase& p, bool plane_stress) {
  const double E = p.youngs_modulus, nu = p.poisson_ratio;
  const double mu = E / (2 * (1 + nu));
  const double lambda = plane_stress ? E * nu / (1 - nu * nu) : E * nu / ((1 + nu) * (1 - 2 * nu));
  return {lambda + 2 * mu, lambda + mu, mu, plane_stress ? 1 / E : (1 - nu * nu) / E,
          plane_stress ? -nu / E : -nu * (1 + nu) / E};
}

// The cell values of an ASCII field file written by OpenFOAM: a stream at the first
// value's opening parenthesis, and their count. `type` is the list's element type.
std::istringstream cell_values(const std::filesystem::path& file, const std::string& type, std::size_t& n) {
  const std::string text = read_text_file(file, "the solver's result");
  const std::string list = "List<" + type + ">";
  const auto at = text.find(list);
  if (at == std::string::npos) throw GeometryError(file.string() + ": no cell values");
  std::istringstream in(text.substr(at + list.size()));
  char paren = 0;
  in >> n >> paren;
  return in;
}

}  // namespace

ElasticBounds elastic_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                             bool plane_stress) {
  ElasticBounds b;
  double s_xx = 0.0, s_xy = 0.0;
  std::vector<Moduli> m;
  for (std::size_t p = 0; p < phases.size(); ++p) {
    m.push_back(moduli(phases[p], plane_stress));
    b.voigt += fractions[p] * m.back().M;
    s_xx += fractions[p] * m.back().s_xx;
    s_xy += fractions[p] * m.back().s_xy;
  }
  // Uniform stress (sx, sy) with the mean eps_yy = s_xy sx + s_yy sy zero; s_yy = s_xx.
  b.reuss = 1.0 / (s_xx - s_xy * s_xy / s_xx);
  if (phases.size() == 2) {
    // Two-dimensional Hashin-Shtrikman bounds on K and mu, for well-ordered phases.
    const int hard = m[0].mu >= m[1].mu ? 0 : 1, soft = 1 - hard;
    if (m[hard].K >= m[soft].K) {
      auto bound = [&](int ref, int other) {
        const Moduli& r = m[ref];
        const Moduli& o = m[other];
        const double fr = fractions[ref], fo = fractions[other];
        const double K = o.K == r.K ? r.K : r.K + fo / (1 / (o.K - r.K) + fr / (r.K + r.mu));
        const double mu =
            o.mu == r.mu ? r.mu : r.mu + fo / (1 / (o.mu - r.mu) + fr * (r.K + 2 * r.mu) / (2 * r.mu * (r.K + r.mu)));
        return K + mu;
      };
      b.hs_upper = bound(hard, soft);
      b.hs_lower = bound(soft, hard);
    }
  }
  return b;
}

std::vector<CellStress> read_cell_stress(const std::filesystem::path& sigma_file) {
  std::size_t n = 0;
  std::istringstream in = cell_values(sigma_file, "symmTensor", n);
  std::vector<CellStress> out(n);
  char paren = 0;
  for (CellStress& c : out) {  // (xx xy xz yy yz zz)
    double xz, yz, zz;
    in >> paren >> c.xx >> c.xy >> xz >> c.yy >> yz >> zz >> paren;
  }
  if (!in) throw GeometryError(sigma_file.string() + ": unreadable cell values");
  return out;
}

std::vector<double> read_cell_displacement(const std::filesystem::path& d_file) {
  std::size_t n = 0;
  std::istringstream in = cell_values(d_file, "vector", n);
  std::vector<double> out(n);
  char paren = 0;
  for (double& d : out) {  // (x y z)
    double x, y, z;
    in >> paren >> x >> y >> z >> paren;
    d = std::sqrt(x * x + y * y + z * z);
  }
  if (!in) throw GeometryError(d_file.string() + ": unreadable cell values");
  return out;
}

std::filesystem::path latest_time_dir(const std::filesystem::path& case_dir) {
  std::filesystem::path best;
  double latest = 0.0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(case_dir, ec)) {
    if (!entry.is_directory()) continue;
    const std::string name = entry.path().filename().string();
    char* end = nullptr;
    const double t = std::strtod(name.c_str(), &end);
    if (end == name.c_str() || *end != '\0' || !(t > latest)) continue;
    latest = t;
    best = entry.path();
  }
  if (best.empty()) throw SolveError(case_dir.string() + ": the solver wrote no result (no time directory after 0)");
  return best;
}

Homogenised solve_and_homogenise(const std::filesystem::path& case_dir, const ExportMesh& m, const FoamOptions& o,
                                 const Deadline& deadline, const std::filesystem::path& case_shown_as) {
  if (std::system("command -v solidDisplacementFoam > /dev/null 2>&1") != 0)
    throw IoError("--solve: solidDisplacementFoam is not installed (Debian package openfoam; scripts/install-deps.sh)");
  const std::filesystem::path log = case_dir / "log.solidDisplacementFoam";
  const std::string see = "; see " + ((case_shown_as.empty() ? case_dir : case_shown_as) / log.filename()).string();
  setenv("WM_PROJECT_DIR", "/usr/share/openfoam", /*overwrite=*/0);  // OpenFOAM's programs need it

  // A thousand times the displacement the load can give is divergence, not an answer.
  const double load_scale = load_strain(m.cell, m.phases, o) * std::max(m.cell.width(), m.cell.height());
  const CaseStop stop = case_stop(m, o);
  const SolveMonitor::Options watch{.tolerance = kSolverTolerance,
                                    .stall_corrections = 500,
                                    .diverged_range = 1e3 * load_scale * o.convert_to_meters,
                                    .case_watches = {true, !stop.x_alone},
                                    .case_tolerance = stop.tolerance,
                                    .case_patience = 50};
  // One run of the solver, followed: killed as soon as it stalls, diverges or will not
  // stop on its own.
  auto solve = [&](SolveMonitor& monitor) {
    return run_child({"solidDisplacementFoam"}, case_dir, log, deadline, "solidDisplacementFoam",
                     [&](std::string_view text) {
                       const SolveMonitor::State s = monitor.feed(text);
                       return s != SolveMonitor::State::running && s != SolveMonitor::State::converged;
                     });
  };
  SolveMonitor monitor(watch);
  int status = solve(monitor);
  if (monitor.state() == SolveMonitor::State::case_stuck) {
    // Converged by the measure, but OpenFOAM's own residual of a component near zero is
    // noise: solved again to exactly where the measure was met (the same corrections, one
    // process, so the same numbers), and written there.
    write_control_dict(case_dir, m, o, monitor.converged_at());
    monitor = SolveMonitor(watch);
    status = solve(monitor);
  }

  // What to do about a solve that goes nowhere.
  const std::string advice =
      harmonic_stiffness(m, o) && stiffness_contrast(m, o) > 3.0
          ? ": the stiffness contrast " + to_text(stiffness_contrast(m, o), 3) +
                " is too high for export.stiffness_interpolation = harmonic; use auto or linear"
          : ": check the phases' moduli and the mesh quality (q_min), or try export.stiffness_interpolation = linear";
  const SolveMonitor::State state = monitor.state();
  if (state == SolveMonitor::State::diverging || state == SolveMonitor::State::stalled)
    throw SolveError(std::string("D: solidDisplacementFoam ") +
                     (state == SolveMonitor::State::diverging ? "diverges: " : "stalls: ") + monitor.diagnosis() +
                     advice + see);
  const std::string text = read_text_file(log, "the solver's log");
  if (status == 128 + SIGFPE || text.find("sigFpe") != std::string::npos)
    throw SolveError("D: solidDisplacementFoam diverges: floating-point overflow after " +
                     std::to_string(monitor.corrections()) + " corrections" + advice + see);
  if (status != 0 || text.find("\nEnd") == std::string::npos)
    throw SolveError("--solve: solidDisplacementFoam failed (exit code " + std::to_string(status) + ")" + see);
  if (state != SolveMonitor::State::converged || !(monitor.measure() < kSolverTolerance))
    throw SolveError("D: solidDisplacementFoam did not converge in " + std::to_string(monitor.corrections()) +
                     " corrections (residual " + to_text(monitor.measure(), 3) + ", above " +
                     to_text(kSolverTolerance) + ")" + advice + see);

  Homogenised h;
  h.corrections = monitor.corrections();
  h.final_residual = monitor.measure();
  h.component_residuals = monitor.residuals();
  h.result_dir = latest_time_dir(case_dir);
  // Cell k is triangle k.
  const std::vector<CellStress> sigma = read_cell_stress(h.result_dir / kStressField);
  if (sigma.size() != m.mesh.triangles.size())
    throw GeometryError((h.result_dir / kStressField).string() + ": " + std::to_string(sigma.size()) +
                        " cells, the mesh has " + std::to_string(m.mesh.triangles.size()));
  double area = 0.0;
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    const double a = triangle_area(m.mesh, static_cast<int>(k));
    h.sigma_xx += a * sigma[k].xx;
    h.sigma_yy += a * sigma[k].yy;
    h.sigma_xy += a * sigma[k].xy;
    area += a;
  }
  h.sigma_xx /= area;
  h.sigma_yy /= area;
  h.sigma_xy /= area;
  // Left held, right moved by the displacement (or its jump across a cyclic pair): the
  // mean of d(ux)/dx over the cell is exactly displacement / width.
  h.strain_xx = o.displacement / m.cell.width();
  h.modulus = h.sigma_xx / h.strain_xx;
  return h;
}

}  // namespace grainmesh
