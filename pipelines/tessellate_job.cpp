#include "pipelines/tessellate_job.hpp"

#include <cmath>
#include <string>
#include <type_traits>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/random.hpp"
#include "pipelines/cell_config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/config_values.hpp"
#include "pipelines/phase_checks.hpp"
#include "tessellate/neper_import.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/tessellate_3d.hpp"

namespace grainmesh {

namespace {

// tessellation.phase_mode and binder mode's matrix phase: named, else the phase called
// matrix or binder (2D and 3D).
template <class Options>
void read_phase_mode(const Config& c, Options& o) {
  const std::string mode = c.optional_text("tessellation.phase_mode").value_or("grain");
  if (mode == "grain") o.phase_mode = PhaseMode::grain;
  else if (mode == "binder") o.phase_mode = PhaseMode::binder;
  else c.fail("tessellation.phase_mode", "unknown mode '" + mode + "' (grain or binder)");
  if (o.phase_mode == PhaseMode::binder) {
    std::string matrix = c.optional_text("tessellation.matrix_phase").value_or("");
    if (matrix.empty())
      for (const Phase& p : o.phases)
        if (p.name == "matrix" || p.name == "binder") matrix = p.name;
    if (matrix.empty()) c.fail("tessellation.matrix_phase", "binder mode needs the matrix phase's name");
    for (std::size_t p = 0; p < o.phases.size(); ++p)
      if (o.phases[p].name == matrix) o.matrix_phase = static_cast<int>(p);
    if (o.matrix_phase < 0) c.fail("tessellation.matrix_phase", "no phase is named '" + matrix + "'");
    if (o.phases.size() < 2) c.fail("tessellation.matrix_phase", "binder mode needs a grain phase besides the matrix");
  } else if (c.has("tessellation.matrix_phase")) {
    c.fail("tessellation.matrix_phase", "only used with tessellation.phase_mode = binder");
  }
}

// A contiguity target and the phase it is of (2D and 3D).
template <class Options>
void read_contiguity(const Config& c, Options& o) {
  if (c.has("tessellation.contiguity")) {
    const double target = c.number("tessellation.contiguity");
    if (!(target > 0.0 && target < 1.0)) c.fail("tessellation.contiguity", "must lie in (0, 1), got " + c.text("tessellation.contiguity"));
    const bool binder = o.phase_mode == PhaseMode::binder;
    if (binder && o.phases.size() != 2)
      c.fail("tessellation.contiguity", "in binder mode a target for one grain phase beside the matrix, got " +
                                            std::to_string(o.phases.size() - 1) + " grain phases");
    if (c.has("tessellation.arrangement") && o.arrangement != Arrangement::random)
      c.fail("tessellation.contiguity", "give tessellation.arrangement or tessellation.contiguity, not both");
    o.contiguity = target;
    // The phase it is of: named, else (binder mode) the grains' phase, else the rest phase,
    // else the first.
    const std::string name = c.optional_text("tessellation.contiguity_phase").value_or("");
    for (std::size_t p = 0; p < o.phases.size(); ++p)
      if (name.empty() ? (binder ? static_cast<int>(p) != o.matrix_phase : o.phases[p].rest) : o.phases[p].name == name)
        o.contiguity_phase = static_cast<int>(p);
    if (!name.empty() && o.contiguity_phase < 0)
      c.fail("tessellation.contiguity_phase", "no phase is named '" + name + "'");
    if (binder && o.contiguity_phase == o.matrix_phase)
      c.fail("tessellation.contiguity_phase", "binder mode sets the contiguity of the grains, not of the matrix '" + name + "'");
    if (o.contiguity_phase < 0) o.contiguity_phase = 0;
  } else if (c.has("tessellation.contiguity_phase")) {
    c.fail("tessellation.contiguity_phase", "only used with tessellation.contiguity");
  }
}

// A contiguity target missed: refused, with the range the trades reach.
template <class Cell, int D>
void check_contiguity(const Cell& t, const TessellateJob<D>& job) {
  const auto& o = job.options;
  if (!o.contiguity) return;
  const double reached = t.stats.phases[o.contiguity_phase].contiguity;
  if (std::abs(reached - *o.contiguity) <= kContiguityTolerance) return;
  const std::string phase = t.phases[o.contiguity_phase].name;
  const auto& range = t.stats.contiguity_range;
  job.origin.fail("tessellation.contiguity",
         to_text(*o.contiguity) + " is out of reach for phase " + phase + " with these grains and fractions (seed " +
             std::to_string(job.seed) + "): " +
             (range ? (o.phase_mode == PhaseMode::binder ? "binder-free contacts between grains move its contiguity from "
                                                         : "trading like-sized grains' labels moves its contiguity from ") +
                          to_text(range->first, 3) + " to " + to_text(range->second, 3)
                    : "it reached " + to_text(reached, 3)) +
             "; ask within that, or change the fractions or the grains");
}

// tessellation.neper: the file read and checked against the config, its domain the cell;
// the keys that would draw the grains refused. False when the key is not given.
template <class Job>
bool read_neper_input(const Config& c, Job& job, int dimensions) {
  if (!c.has("tessellation.neper")) {
    if (c.has("tessellation.neper_phases")) c.fail("tessellation.neper_phases", "only used with tessellation.neper");
    return false;
  }
  const std::filesystem::path file = c.text("tessellation.neper");
  refuse_drawing_keys(c, "tessellation.neper (" + file.string() + ")");
  try {
    job.neper.tess = read_neper_tess(file);
  } catch (const std::exception& e) {
    c.fail("tessellation.neper", e.what());
  }
  job.neper.file = file;
  const NeperTess& n = job.neper.tess;
  const int dims = n.dimensions;
  const Vec3 size = n.domain.hi - n.domain.lo;
  const std::string sizes = to_text(size.x) + " x " + to_text(size.y) + (dims == 3 ? " x " + to_text(size.z) : "");
  if (dims != dimensions) {
    const std::string fix = dims == 3 ? "set domain.depth (its domain is " + sizes + ")" : "leave domain.depth out";
    c.fail("domain.depth", file.string() + " is a " + std::to_string(dims) + "D tessellation: " + fix);
  }
  auto& o = job.options;
  const char* keys[3] = {"domain.width", "domain.height", "domain.depth"};
  for (int a = 0; a < dimensions; ++a)
    if (c.has(keys[a]) && std::abs(c.number(keys[a]) - size[a]) > 1e-9 * size[a])
      c.fail(keys[a], "must be the domain of " + file.string() + ", " + sizes);
  o.width = size.x;
  o.height = size.y;
  if constexpr (requires { o.depth; }) o.depth = size.z;
  if (c.has("domain.periodic") && c.flag("domain.periodic", n.periodic) != n.periodic)
    c.fail("domain.periodic", file.string() + (n.periodic ? " is periodic: set domain.periodic = true"
                                                          : " is not periodic: set domain.periodic = false") +
                                  " (or leave it out)");
  o.periodic = n.periodic;
  o.grains = n.cells();
  if (c.has("tessellation.neper_phases") && n.groups.empty())
    c.fail("tessellation.neper_phases",
           file.string() + " has no cell groups (*group; Neper's -group) to take the phases from");
  return true;
}

// The keys a plane and a solid cell's job share: the box (its depth in 3D), periodicity,
// grain count, seed, the diagram's settings, the phases, the pictures' width, time limit.
template <class Job>
void read_shared_keys(const Config& c, Job& job) {
  job.origin = c.origin();
  auto& o = job.options;
  constexpr bool solid = requires { o.depth; };
  bool from_image = false;
  if constexpr (solid) {
    if (c.has("tessellation.image")) c.fail("tessellation.image", "label images make 2D cells: leave domain.depth out");
  } else {
    from_image = read_image_input(c, job.image, o);
  }
  if (!from_image && !read_neper_input(c, job, solid ? 3 : 2)) {
    o.width = positive(c, "domain.width");
    o.height = positive(c, "domain.height");
    Vec3 box{o.width, o.height, 0.0};
    if constexpr (solid) box.z = o.depth = positive(c, "domain.depth");
    o.periodic = c.flag("domain.periodic", true);
    const GrainCount count = read_grain_count(c, box, solid ? 3 : 2);
    o.grains = count.grains;
    for (const Vec3& p : count.seeds) {
      if constexpr (solid) o.seeds.push_back(p);
      else o.seeds.push_back({p.x, p.y});
    }
  }
  job.seed = c.unsigned_integer("tessellation.seed", 1);
  const DiagramSettings d = read_diagram_settings(c, o.min_edge);
  o.lloyd_iterations = d.lloyd_iterations;
  o.size_cv = d.size_cv;
  o.min_edge = d.min_edge;
  o.arrangement = d.arrangement;
  o.phases = read_phases(c);
  if (c.has("tessellation.neper_phases"))  // read_neper_input has checked the file has groups
    job.neper.group_phases = read_label_phases(c, "tessellation.neper_phases", o.phases, false);
  const long long width = c.integer("output.picture_width", job.picture_width);
  if (width < 100 || width > 20000) c.fail("output.picture_width", "must be between 100 and 20000");
  job.picture_width = static_cast<int>(width);
  o.deadline = Deadline::after(read_time_limit(c), kTimeLimitKey);
}

// The Neper file's cells as the job's tessellation; a group the phase table misses is
// refused naming tessellation.neper_phases.
template <class Cell, class Job>
Cell read_neper_cell(const Job& job, Rng& rng) {
  const NeperPhases phases{.phases = job.options.phases, .arrangement = job.options.arrangement,
                           .group_phases = job.neper.group_phases};
  try {
    if constexpr (std::is_same_v<Cell, Tessellation>)
      return plane_tessellation(job.neper.tess, phases, rng, job.neper.file.string());
    else
      return solid_tessellation(job.neper.tess, phases, rng, job.neper.file.string());
  } catch (const UnnamedLabelError& e) {
    job.origin.fail("tessellation.neper_phases", e.what());
  }
}

}  // namespace

template <>
TessellateJob<2> read_tessellate_job<2>(const Config& c) {
  c.check_keys(tessellate_config_keys());
  if (cell_dimensions(c) == 3)
    c.fail("domain.depth", "3D cells go through grainmesh tessellate, mesh, run, sweep and converge; export takes "
                           "2D meshes (leave domain.depth out)");
  if (c.has("output.section")) c.fail("output.section", "only for 3D cells (with domain.depth)");
  TessellateJob<2> job;
  read_shared_keys(c, job);
  TessellationOptions& o = job.options;
  read_phase_mode(c, o);
  read_contiguity(c, o);
  if (!job.image.file.empty()) {
    job.image.options.phases = o.phases;
    job.image.options.arrangement = o.arrangement;
    if (c.has("tessellation.image_phases"))
      job.image.options.label_phases =
          read_label_phases(c, "tessellation.image_phases", o.phases, job.image.image.colour);
  }
  return job;
}

template <>
TessellateJob<3> read_tessellate_job<3>(const Config& c) {
  c.check_keys(tessellate_config_keys());
  TessellateJob<3> job;
  read_shared_keys(c, job);
  read_phase_mode(c, job.options);
  read_contiguity(c, job.options);
  job.section = c.number("output.section", job.section);
  if (!(job.section > 0.0 && job.section < 1.0))
    c.fail("output.section", "must lie in (0, 1) (a fraction of domain.depth), got " + c.text("output.section"));
  return job;
}

Tessellation run_tessellate_job(const TessellateJob<2>& job) {
  Rng rng(job.seed);
  if (!job.neper.file.empty()) return read_neper_cell<Tessellation>(job, rng);
  if (!job.image.file.empty()) {
    try {
      return image_tessellation(job.image.image, job.image.options, rng, job.image.file.string());
    } catch (const SmallGrainsError& e) {
      job.origin.fail("tessellation.image_min_grain",
                      std::string(e.what()) + "; merge them (tessellation.image_small_grains = merge) or lower it");
    } catch (const UnnamedLabelError& e) {
      job.origin.fail("tessellation.image_phases", e.what());
    }
  }
  Tessellation t;
  try {
    t = tessellate(job.options, rng);
  } catch (const ConfigError& e) {
    // The only option tessellate() can find unreachable is the binder fraction.
    const TessellationOptions& o = job.options;
    const std::string key = o.matrix_phase >= 0 ? "phase." + o.phases[o.matrix_phase].name + ".fraction" : "phase.*.fraction";
    job.origin.fail(key, e.what());
  }
  check_contiguity(t, job);
  return t;
}

Tessellation3 run_tessellate_job(const TessellateJob<3>& job) {
  Rng rng(job.seed);
  if (!job.neper.file.empty()) return read_neper_cell<Tessellation3>(job, rng);
  Tessellation3 t;
  try {
    t = tessellate_3d(job.options, rng);
  } catch (const ConfigError& e) {
    // The only option tessellate_3d() can find unreachable is the binder fraction.
    const Tessellation3Options& o = job.options;
    if (o.phase_mode != PhaseMode::binder) throw;
    job.origin.fail("phase." + o.phases[std::max(o.matrix_phase, 0)].name + ".fraction", e.what());
  } catch (const GeometryError& e) {
    // The stage's own checks failed: an inconsistency no config should be able to make.
    throw GeometryError(std::string("the 3D tessellation failed its own check (") + e.what() +
                        "): a grainmesh bug, please report it with this config; another " +
                        (job.options.seeds.empty() ? "tessellation.seed" : "placing of tessellation.seeds") +
                        " or tessellation.lloyd_iterations avoids it");
  }
  check_contiguity(t, job);
  return t;
}

void check_phases(const Tessellation& t, const TessellateJob<2>& job, Warnings& warnings) {
  check_phases_have_grains(t.phases, t.stats.phases, t.stats.grains, job.origin, job.options.matrix_phase);
  // With a phase table the fractions are the file's own, not targets.
  if (!job.image.options.label_phases.empty() || !job.neper.group_phases.empty()) return;
  for (const std::string& w : phase_fraction_warnings(t.phases, t.stats.phases, t.stats.grains)) warnings.add(w);
}

void check_phases(const Tessellation3& t, const TessellateJob<3>& job, Warnings& warnings) {
  check_phases_have_grains(t.phases, t.stats.phases, t.stats.grains, job.origin, job.options.matrix_phase);
  if (!job.neper.group_phases.empty()) return;  // the file's own fractions, not targets
  for (const std::string& w : phase_fraction_warnings(t.phases, t.stats.phases, t.stats.grains)) warnings.add(w);
}

}  // namespace grainmesh
