#include "pipelines/tessellate_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "domain/shape_parser.hpp"
#include "pipelines/cell_config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/material_units.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/tessellate_3d_command.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"
#include "tessellate/tessellate.hpp"

namespace grainmesh {





namespace {

// o.grains (and o.seeds) from tessellation.grains, .grain_size or .seeds.
void read_grain_count(const Config& c, TessellationOptions& o) {
  if (c.has("tessellation.grains") && c.has("tessellation.grain_size"))
    c.fail("tessellation.grain_size", "give either tessellation.grains or tessellation.grain_size, not both");
  if (c.has("tessellation.seeds")) {
    if (c.has("tessellation.grain_size"))
      c.fail("tessellation.grain_size", "give tessellation.seeds or tessellation.grain_size, not both");
    for (const auto& text : c.all("tessellation.seeds"))
      for (const Vec2 p : parse_point_list(text, c.source() + ": tessellation.seeds")) {
        if (!(p.x >= 0.0 && p.x <= o.width && p.y >= 0.0 && p.y <= o.height))
          c.fail("tessellation.seeds", "seed (" + to_text(p.x) + ", " + to_text(p.y) + ") lies outside the cell [0, " +
                                           to_text(o.width) + "] x [0, " + to_text(o.height) + "]");
        o.seeds.push_back(p);
      }
    if (o.seeds.empty()) c.fail("tessellation.seeds", "no seed given (x y, x y, ...)");
    if (o.seeds.size() > 10'000'000) c.fail("tessellation.seeds", "more than 10 million seeds");
    o.grains = static_cast<int>(o.seeds.size());
    if (c.has("tessellation.grains") && c.integer("tessellation.grains", 0) != o.grains)
      c.fail("tessellation.grains", "is " + c.text("tessellation.grains") + " but tessellation.seeds gives " +
                                        std::to_string(o.grains) + " seeds: set it to that or leave it out");
  } else if (c.has("tessellation.grain_size")) {
    const double d = positive(c, "tessellation.grain_size");  // mean equivalent-circle diameter
    const double n = std::round(o.width * o.height / (0.25 * std::numbers::pi * d * d));
    if (n < 1.0) c.fail("tessellation.grain_size", "is larger than the cell: no grain fits");
    if (n > 1e7) c.fail("tessellation.grain_size", "gives " + to_text(n) + " grains, more than 10 million");
    o.grains = static_cast<int>(n);
  } else {
    const long long n = c.integer("tessellation.grains", 100);
    if (n < 1) c.fail("tessellation.grains", "must be at least 1, got " + c.text("tessellation.grains"));
    if (n > 10'000'000) c.fail("tessellation.grains", "must be at most 10 million");
    o.grains = static_cast<int>(n);
  }
}

// Binder mode's matrix phase: named, else the phase called matrix or binder.
void read_matrix_phase(const Config& c, TessellationOptions& o) {
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

// A contiguity target and the phase it is of (grain mode only).
void read_contiguity(const Config& c, TessellationOptions& o) {
  if (c.has("tessellation.contiguity")) {
    const double target = c.number("tessellation.contiguity");
    if (!(target > 0.0 && target < 1.0)) c.fail("tessellation.contiguity", "must lie in (0, 1), got " + c.text("tessellation.contiguity"));
    if (o.phase_mode != PhaseMode::grain)
      c.fail("tessellation.contiguity", "a target only in grain mode (in binder mode the binder keeps the grains apart)");
    if (c.has("tessellation.arrangement") && o.arrangement != Arrangement::random)
      c.fail("tessellation.contiguity", "give tessellation.arrangement or tessellation.contiguity, not both");
    o.contiguity = target;
    // The phase it is of: named, else the rest phase, else the first.
    const std::string name = c.optional_text("tessellation.contiguity_phase").value_or("");
    for (std::size_t p = 0; p < o.phases.size(); ++p)
      if (name.empty() ? o.phases[p].rest : o.phases[p].name == name) o.contiguity_phase = static_cast<int>(p);
    if (!name.empty() && o.contiguity_phase < 0)
      c.fail("tessellation.contiguity_phase", "no phase is named '" + name + "'");
    if (o.contiguity_phase < 0) o.contiguity_phase = 0;
  } else if (c.has("tessellation.contiguity_phase")) {
    c.fail("tessellation.contiguity_phase", "only used with tessellation.contiguity");
  }
}

}  // namespace

TessellateJob read_tessellate_job(const Config& c) {
  c.check_keys(tessellate_config_keys());
  if (cell_dimensions(c) == 3)
    c.fail("domain.depth", "3D cells go through grainmesh tessellate, mesh, run, sweep and converge; export takes "
                           "2D meshes (leave domain.depth out)");
  if (c.has("output.section")) c.fail("output.section", "only for 3D cells (with domain.depth)");
  TessellateJob job;
  job.origin = c.origin();
  TessellationOptions& o = job.options;
  o.width = positive(c, "domain.width");
  o.height = positive(c, "domain.height");
  o.periodic = c.flag("domain.periodic", true);
  read_grain_count(c, o);
  job.seed = c.unsigned_integer("tessellation.seed", 1);
  const DiagramSettings d = read_diagram_settings(c, o.min_edge);
  o.lloyd_iterations = d.lloyd_iterations;
  o.size_cv = d.size_cv;
  o.min_edge = d.min_edge;
  o.arrangement = d.arrangement;
  const std::string mode = c.optional_text("tessellation.phase_mode").value_or("grain");
  if (mode == "grain") o.phase_mode = PhaseMode::grain;
  else if (mode == "binder") o.phase_mode = PhaseMode::binder;
  else c.fail("tessellation.phase_mode", "unknown mode '" + mode + "' (grain or binder)");
  o.phases = read_phases(c);
  read_matrix_phase(c, o);
  read_contiguity(c, o);
  const long long width = c.integer("output.picture_width", job.picture_width);
  if (width < 100 || width > 20000) c.fail("output.picture_width", "must be between 100 and 20000");
  o.deadline = Deadline::after(read_time_limit(c), kTimeLimitKey);
  job.picture_width = static_cast<int>(width);
  return job;
}

namespace {

// A contiguity target missed: refused, with the range the trades reach.
void check_contiguity(const Tessellation& t, const TessellateJob& job) {
  const TessellationOptions& o = job.options;
  if (!o.contiguity) return;
  const double reached = t.stats.phases[o.contiguity_phase].contiguity;
  if (std::abs(reached - *o.contiguity) <= kContiguityTolerance) return;
  const std::string phase = t.phases[o.contiguity_phase].name;
  const auto& range = t.stats.contiguity_range;
  job.origin.fail("tessellation.contiguity",
         to_text(*o.contiguity) + " is out of reach for phase " + phase + " with these grains and fractions (seed " +
             std::to_string(job.seed) + "): " +
             (range ? "trading like-sized grains' labels moves its contiguity from " + to_text(range->first, 3) + " to " +
                          to_text(range->second, 3)
                    : "it reached " + to_text(reached, 3)) +
             "; ask within that, or change the fractions or the grains");
}

}  // namespace

Tessellation run_tessellate_job(const TessellateJob& job) {
  Rng rng(job.seed);
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

PictureOptions tessellation_picture(const Tessellation& t, int width, const std::string& length_unit) {
  PictureOptions o{.width_px = width, .scale_bar = true, .length_unit = length_unit};
  for (const Phase& p : t.phases) o.legend.push_back(p.name);
  return o;
}

void check_phases_have_grains(const Tessellation& t, const TessellateJob& job) {
  // A phase without a grain is not in the microstructure at all: its properties would
  // never reach the solver. A grain has about 1 / N of the cell, so 1 / fraction grains
  // give every phase one.
  for (std::size_t p = 0; p < t.phases.size(); ++p) {
    const PhaseStats& s = t.stats.phases[p];
    if (s.grains > 0 || static_cast<int>(p) == job.options.matrix_phase) continue;
    const double needed = std::ceil(1.0 / s.target_fraction - 1e-9);
    job.origin.fail("phase." + t.phases[p].name + ".fraction",
           "a fraction of " + to_text(s.target_fraction) + " gives the phase none of the " +
               std::to_string(t.stats.grains) + " grains: use at least " + to_text(needed) +
               " grains (tessellation.grains), about 50 for fractions within 1 %");
  }
}

std::vector<std::string> tessellation_warnings(const Tessellation& t) {
  std::vector<std::string> warnings;
  for (std::size_t p = 0; p < t.phases.size(); ++p) {
    const PhaseStats& s = t.stats.phases[p];
    if (std::abs(s.achieved_fraction - s.target_fraction) > 0.01)
      warnings.push_back("phase." + t.phases[p].name + ".fraction: " + to_text(s.achieved_fraction, 4) +
                         " achieved for a target of " + to_text(s.target_fraction, 4) + " with " +
                         std::to_string(t.stats.grains) + " grains (about 50 or more meet targets within 0.01)");
  }
  return warnings;
}

void run_tessellate_command(const Config& c, const std::filesystem::path& out) {
  if (cell_dimensions(c) == 3) return run_tessellate_3d_command(c, out);
  claim_output(out, "tessellate");
  const TessellateJob job = read_tessellate_job(c);
  const auto start = std::chrono::steady_clock::now();
  const Tessellation t = run_tessellate_job(job);
  check_phases_have_grains(t, job);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Warnings warnings;
  for (const std::string& w : tessellation_warnings(t)) warnings.add(w);

  StagedOutput staged(out, "tessellate");
  write_text_file(staged.dir() / "tessellation.json", tessellation_to_json(t));
  write_tessellation_vtp(staged.dir() / "tessellation.vtp", t);
  write_tessellation_png(staged.dir() / "tessellation.png", t, tessellation_picture(t, job.picture_width));
  const TessellationStats& s = t.stats;
  Json report;
  report["config"] = c.source();
  report["dimensions"] = 2;
  report["seed"] = job.seed;
  report["width"] = t.width;
  report["height"] = t.height;
  report["periodic"] = t.periodic;
  report["grains"] = s.grains;
  report["phases"] = phases_json(t);
  report["statistics"] = descriptors_json(t);
  report["removed_grains"] = s.removed_grains;
  report["area_mean"] = s.area_mean;
  report["area_std"] = s.area_std;
  report["diameter_mean"] = s.diameter_mean;
  report["diameter_std"] = s.diameter_std;
  report["neighbours_mean"] = s.neighbours_mean;
  report["edges_per_grain_mean"] = s.edges_per_grain_mean;
  report["edge_threshold"] = s.edge_threshold;
  report["shortest_edge"] = s.shortest_edge;
  report["shortest_torus_edge"] = s.shortest_torus_edge;
  report["sharpest_corner_deg"] = s.sharpest_corner_deg;
  report["collapsed_edges"] = s.collapsed_edges;
  report["side_jogs"] = s.side_jogs;
  report["pushed_vertices"] = s.pushed_vertices;
  report["binder_offset"] = s.binder_offset;
  report["vertices"] = t.vertices.size();
  report["edges"] = t.edges.size();
  report["regions"] = t.regions.size();
  report["seconds"] = seconds;
  add_time_limit(report, job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();

  std::printf("grainmesh tessellate: %d grains, %zu regions, sharpest corner %.1f deg, shortest edge %.3g (%.3f s)\n",
              s.grains, t.regions.size(), s.sharpest_corner_deg, s.shortest_edge, seconds);
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    std::printf("  phase %-10s target %.4f achieved %.4f (%d grains)\n", t.phases[p].name.c_str(),
                s.phases[p].target_fraction, s.phases[p].achieved_fraction, s.phases[p].grains);
  std::printf("  wrote %s/{tessellation.json, tessellation.vtp, tessellation.png, report.json}\n", out.string().c_str());
}

}  // namespace grainmesh
