#include "pipelines/converge_command.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <variant>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/limit_bounds.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "pipelines/convergence_study.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/run_command.hpp"
#include "pipelines/run_config.hpp"
#include "pipelines/run_plan.hpp"
#include "pipelines/solve_cell.hpp"

namespace grainmesh {

namespace {

// A quantity a level's answer gives and, where the finite-element reference was solved
// beside it (homogenise.reference = fe), its error against it and the answer's error
// estimate from it (the error plus the reference's own estimate: add_reference).
struct Quantity {
  std::string name;
  double value = 0.0;
  std::optional<double> reference_error, reference_estimate;
};

// The quantities a level's answer gives: the mixed modulus (and the biased volume average
// beside it), or the periodic stiffness's normal entries (the diagonal, then those off it)
// and its shears' diagonal: C11, C22, C12, C66 in 2D.
template <std::size_t N>
std::vector<Quantity> quantities(const Answer<N>& a) {
  if (const auto* m = std::get_if<MixedAnswer<N>>(&a.effective))
    return {{"modulus", m->modulus, {}, {}}, {"volume_average_modulus", m->volume_average_modulus, {}, {}}};
  const PeriodicAnswer<N>& p = std::get<PeriodicAnswer<N>>(a.effective);
  const Stiffness<N>& C = p.verdict.stiffness;
  constexpr std::size_t d = voigt_dimensions<N>();
  std::vector<Quantity> q;
  auto add = [&](std::size_t i, std::size_t j) {
    q.push_back({stiffness_name<N>(i, j), C[i][j], {}, {}});
    if (p.reference && p.error_estimate) {
      q.back().reference_error = p.reference->stiffness_error[i][j];
      q.back().reference_estimate = p.error_estimate->stiffness[i][j];
    }
  };
  for (std::size_t k = 0; k < d; ++k) add(k, k);
  for (std::size_t i = 0; i < d; ++i)
    for (std::size_t j = i + 1; j < d; ++j) add(i, j);
  for (std::size_t k = d; k < N; ++k) add(k, k);
  return q;
}

// The key the study's levels set: triangles per grain, or tetrahedra per grain in 3D.
std::string level_key(const Config& c) {
  return cell_dimensions(c) == 3 ? "mesh.tets_per_grain" : "mesh.triangles_per_grain";
}
// The study's checks: its levels, and no key that fixes an element size or the
// refinement the levels set. Whether its levels are solved by OpenFOAM: not when the
// finite elements answer (homogenise.solver = fe).
bool check_study(const Config& c, const ConvergeOptions& o) {
  if (o.levels < 3 || o.levels > kMaxRefine + 1)
    throw ConfigError("converge: --levels " + std::to_string(o.levels) + ": give 3 to " +
                      std::to_string(kMaxRefine + 1) + " (Richardson extrapolation needs three levels; each has " +
                      (cell_dimensions(c) == 3 ? "8" : "4") + " times the cells of the one before)");
  if (o.start < 4 || o.start > 100000) throw ConfigError("converge: --start " + std::to_string(o.start) + ": give 4 to 100000");
  const bool openfoam = read_run_plan(c, /*solve=*/true).solver == Solver::openfoam;
  for (const auto& [key, value] : c.entries()) {
    if (key == "mesh.size" || key == "mesh.h" || key == "mesh.boundary_size" || key == "mesh.junction_size" ||
        (key.rfind("phase.", 0) == 0 && key.size() > 5 && key.compare(key.size() - 5, 5, ".size") == 0))
      c.fail(key, "fixes an element size, which would not follow the study's levels (" + level_key(c) +
                      " = --start); remove it to study convergence");
    if (key == "mesh.refine") c.fail(key, "is what the study's levels set (0 to --levels - 1); remove it");
  }
  return openfoam;
}

// Runs the levels into `dir`, the finest level's answer into `finest`; a failed solve
// keeps the study so far as DIR.failed.
Levels run_levels(const Config& c, const std::string& ini, StagedOutput& staged, const ConvergeOptions& o,
                  bool openfoam, std::optional<RunAnswer>& finest) {
  const std::filesystem::path dir = staged.dir();
  Levels l;
  std::vector<std::string>& names = l.names;
  std::vector<std::vector<double>>& values = l.values;
  std::vector<double>&cells = l.cells, &tpg = l.tpg, &seconds = l.seconds;
  Json& levels = l.json;
  l.dimensions = cell_dimensions(c);
  const double children = l.dimensions == 3 ? 8.0 : 4.0;
  for (int k = 0; k < o.levels; ++k) {
    // The coarsest level meshed at --start elements per grain, each level after it that
    // mesh split once more (mesh.refine): the same geometry at every level.
    const double per_grain = o.start * std::pow(children, k);
    const std::string name = "level-" + std::to_string(k);
    const Config level = Config::from_text(
        ini, c.source(), {level_key(c) + "=" + std::to_string(o.start), "mesh.refine=" + std::to_string(k)});
    std::fprintf(stderr, "grainmesh converge: level %d of %d: %d %s per grain, split %d time%s\n", k + 1, o.levels,
                 o.start, l.dimensions == 3 ? "tetrahedra" : "triangles", k, k == 1 ? "" : "s");
    RunResult run;
    try {
      run = run_run_command(level, dir / name, /*solve=*/openfoam, /*quiet=*/true, /*summary=*/false);
    } catch (const SolveError& e) {
      // Kept for a look, as a run keeps its failed solve: the study so far as DIR.failed,
      // the message naming the log where it now is.
      std::string what = e.what();
      const std::string staging = dir.string(), kept = staged.failed_dir().string();
      for (std::size_t at = what.find(staging); at != std::string::npos; at = what.find(staging, at + kept.size()))
        what.replace(at, staging.size(), kept);
      write_report(staged, Json{{"config", c.source()}, {"levels", levels}, {"failed", what}});
      staged.keep_as_failed();
      throw SolveError(what);
    }
    const auto q = std::visit([](const auto& a) { return quantities(a); }, *run.answer);
    finest = std::move(run.answer);
    if (names.empty()) {
      for (const Quantity& qi : q) names.push_back(qi.name);
      values.resize(names.size());
      l.reference_estimates.resize(names.size());
    }
    Json reference_errors = Json::object();
    for (std::size_t i = 0; i < q.size(); ++i) {
      values[i].push_back(q[i].value);
      l.reference_estimates[i].push_back(q[i].reference_estimate);
      if (q[i].reference_error) reference_errors[q[i].name] = *q[i].reference_error;
    }
    cells.push_back(static_cast<double>(run.solved_cells));
    tpg.push_back(per_grain);
    seconds.push_back(run.seconds);
    levels.push_back({{per_grain_name(l.dimensions), per_grain},
                      {"refine", k},
                      {"directory", name},
                      {"cells", cells.back()},
                      {"seconds", seconds.back()}});
    if (!reference_errors.empty()) levels.back()["reference_error"] = reference_errors;
  }

  return l;
}

}  // namespace

void run_converge_command(const Config& c, const std::filesystem::path& out, const ConvergeOptions& o) {
  const bool openfoam = check_study(c, o);
  claim_output(out, "converge");
  StagedOutput staged(out, "converge");
  const std::filesystem::path dir = staged.dir();
  const std::string ini = config_ini(c);
  std::optional<RunAnswer> finest;
  const Levels l = run_levels(c, ini, staged, o, openfoam, finest);
  const Study st = study_of(l);
  write_text_file(dir / "convergence.csv", convergence_csv(l, st));
  write_convergence_png(dir / "convergence.png", l, st);
  const std::vector<std::string>& names = l.names;
  const std::vector<double>& tpg = l.tpg;
  const std::vector<RichardsonEstimate>& estimates = st.estimates;
  const std::vector<std::optional<int>>& within = st.within;
  write_text_file(dir / "config.ini", ini);
  Json report{{"config", c.source()}, {"levels", l.json}, {"study", st.json}, {"tolerance", kWithin}};
  Warnings warnings;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!estimates[i].asymptotic && !estimates[i].settled)
      warnings.add("converge: " + names[i] + " does not converge monotonically over the last three levels; its limit " +
                   "is the finest value (add levels)");
  StudyLimits limits;
  for (std::size_t i = 0; i < names.size(); ++i) limits.emplace_back(names[i], estimates[i].limit);
  for (const std::string& broken : std::visit([&](const auto& a) { return limits_outside_bounds(a, limits); }, *finest))
    warnings.add("converge: " + broken + ": the levels are not yet in the asymptotic range (add levels, or start finer)");
  write_report(staged, report, warnings);
  staged.commit();
  const char* elements = l.dimensions == 3 ? "tetrahedra" : "triangles";
  std::printf("grainmesh converge: %d nested levels (%d %s per grain, split up to %d times) in %s\n", o.levels, o.start,
              elements, o.levels - 1, out.string().c_str());
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string from = within[i] ? "within 0.1 % of it from " + to_text(tpg[static_cast<std::size_t>(*within[i])]) +
                                             " " + elements + " per grain"
                                       : "no level within 0.1 % of it";
    const char* basis = st.bases[i] == "reference"    ? "against the finite elements"
                        : st.bases[i] == "richardson" ? "from the limit"
                                                      : "from the levels' spread";
    std::printf("  %s: limit %.6g (order %s; the finest level within %s %% %s), %s\n", names[i].c_str(),
                estimates[i].limit, estimates[i].order ? to_text(*estimates[i].order, 3).c_str() : "-",
                to_text(100.0 * st.errors[i], 2).c_str(), basis, from.c_str());
  }
}

}  // namespace grainmesh
