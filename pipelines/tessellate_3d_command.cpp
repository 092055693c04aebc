#include "pipelines/tessellate_3d_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string_view>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "domain/shape_parser.hpp"
#include "pipelines/cell_config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"
#include "view/vtu.hpp"
#include "tessellate/tessellate_3d.hpp"

namespace grainmesh {

namespace {

// Keys of the 2D stage with no 3D meaning yet, and why.
void refuse_2d_only(const Config& c) {
  for (const char* key : {"tessellation.matrix_phase", "tessellation.contiguity",
                          "tessellation.contiguity_phase"})
    if (c.has(key)) c.fail(key, "not available for 3D cells yet (domain.depth is set)");
  if (c.optional_text("tessellation.phase_mode").value_or("grain") != "grain")
    c.fail("tessellation.phase_mode", "3D cells have grain mode only so far, got '" + c.text("tessellation.phase_mode") + "'");
}

// o.grains and o.seeds from tessellation.grains, .grain_size (mean equivalent-sphere
// diameter) or .seeds ("x y z, x y z, ...").
void read_grain_count(const Config& c, Tessellation3Options& o) {
  if (c.has("tessellation.grains") && c.has("tessellation.grain_size"))
    c.fail("tessellation.grain_size", "give either tessellation.grains or tessellation.grain_size, not both");
  const Vec3 box{o.width, o.height, o.depth};
  if (c.has("tessellation.seeds")) {
    if (c.has("tessellation.grain_size"))
      c.fail("tessellation.grain_size", "give tessellation.seeds or tessellation.grain_size, not both");
    for (const auto& text : c.all("tessellation.seeds")) {
      std::string_view rest = text;
      while (!rest.empty()) {
        const std::size_t comma = rest.find(',');
        const std::vector<double> v = parse_numbers(rest.substr(0, comma), 3, c.source() + ": tessellation.seeds (x y z, x y z, ...)");
        const Vec3 p{v[0], v[1], v[2]};
        for (int a = 0; a < 3; ++a)
          if (!(p[a] >= 0.0 && p[a] <= box[a]))
            c.fail("tessellation.seeds", "seed (" + to_text(p.x) + ", " + to_text(p.y) + ", " + to_text(p.z) +
                                             ") lies outside the box [0, " + to_text(o.width) + "] x [0, " +
                                             to_text(o.height) + "] x [0, " + to_text(o.depth) + "]");
        o.seeds.push_back(p);
        rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
      }
    }
    if (o.seeds.empty()) c.fail("tessellation.seeds", "no seed given (x y z, x y z, ...)");
    if (o.seeds.size() > 1'000'000) c.fail("tessellation.seeds", "more than a million seeds");
    o.grains = static_cast<int>(o.seeds.size());
    if (c.has("tessellation.grains") && c.integer("tessellation.grains", 0) != o.grains)
      c.fail("tessellation.grains", "is " + c.text("tessellation.grains") + " but tessellation.seeds gives " +
                                        std::to_string(o.grains) + " seeds: set it to that or leave it out");
  } else if (c.has("tessellation.grain_size")) {
    const double d = positive(c, "tessellation.grain_size");
    const double n = std::round(o.width * o.height * o.depth / (std::numbers::pi / 6.0 * d * d * d));
    if (n < 1.0) c.fail("tessellation.grain_size", "is larger than the box: no grain fits");
    if (n > 1e6) c.fail("tessellation.grain_size", "gives " + to_text(n) + " grains, more than a million");
    o.grains = static_cast<int>(n);
  } else {
    const long long n = c.integer("tessellation.grains", 100);
    if (n < 1) c.fail("tessellation.grains", "must be at least 1, got " + c.text("tessellation.grains"));
    if (n > 1'000'000) c.fail("tessellation.grains", "must be at most a million in 3D");
    o.grains = static_cast<int>(n);
  }
}

}  // namespace

Tessellate3Job read_tessellate_3d_job(const Config& c) {
  c.check_keys(tessellate_config_keys());
  refuse_2d_only(c);
  Tessellate3Job job;
  job.origin = c.origin();
  Tessellation3Options& o = job.options;
  o.width = positive(c, "domain.width");
  o.height = positive(c, "domain.height");
  o.depth = positive(c, "domain.depth");
  o.periodic = c.flag("domain.periodic", true);
  read_grain_count(c, o);
  job.seed = c.unsigned_integer("tessellation.seed", 1);
  const DiagramSettings d = read_diagram_settings(c, o.min_edge);
  o.lloyd_iterations = d.lloyd_iterations;
  o.size_cv = d.size_cv;
  o.min_edge = d.min_edge;
  o.arrangement = d.arrangement;
  o.phases = read_phases(c);
  const long long width = c.integer("output.picture_width", job.picture_width);
  if (width < 100 || width > 20000) c.fail("output.picture_width", "must be between 100 and 20000");
  job.picture_width = static_cast<int>(width);
  job.section = c.number("output.section", job.section);
  if (!(job.section > 0.0 && job.section < 1.0)) c.fail("output.section", "must lie in (0, 1) (a fraction of domain.depth), got " + c.text("output.section"));
  o.deadline = Deadline::after(read_time_limit(c), kTimeLimitKey);
  return job;
}

Tessellation3 run_tessellate_3d_job(const Tessellate3Job& job, Warnings& warnings) {
  Rng rng(job.seed);
  Tessellation3 t;
  try {
    t = tessellate_3d(job.options, rng);
  } catch (const GeometryError& e) {
    // The stage's own checks failed: an inconsistency no config should be able to make.
    throw GeometryError(std::string("the 3D tessellation failed its own check (") + e.what() +
                        "): a grainmesh bug, please report it with this config; another " +
                        (job.options.seeds.empty() ? "tessellation.seed" : "placing of tessellation.seeds") +
                        " or tessellation.lloyd_iterations avoids it");
  }
  const Tessellation3Stats& s = t.stats;
  for (std::size_t p = 0; p < t.phases.size(); ++p) {
    const PhaseStats& ps = s.phases[p];
    if (ps.grains == 0)
      job.origin.fail("phase." + t.phases[p].name + ".fraction",
             "a fraction of " + to_text(ps.target_fraction) + " gives the phase none of the " + std::to_string(s.grains) +
                 " grains: use at least " + to_text(std::ceil(1.0 / ps.target_fraction - 1e-9)) +
                 " grains (tessellation.grains), about 50 for fractions within 1 %");
  }
  for (std::size_t p = 0; p < t.phases.size(); ++p) {
    const PhaseStats& ps = s.phases[p];
    if (std::abs(ps.achieved_fraction - ps.target_fraction) > 0.01)
      warnings.add("phase." + t.phases[p].name + ".fraction: " + to_text(ps.achieved_fraction, 4) + " achieved for a target of " +
                   to_text(ps.target_fraction, 4) + " with " + std::to_string(s.grains) + " grains");
  }
  return t;
}

Json write_tessellation_3d_files(const std::filesystem::path& dir, const Tessellation3& t, const Tessellate3Job& job,
                                 bool pictures, const std::string& length_unit, Warnings& warnings) {
  write_text_file(dir / "tessellation.json", tessellation_to_json(t));
  write_tessellation_vtu(dir / "tessellation.vtu", t);
  const double z = section_height(t, job.section * t.depth);
  if (pictures) {
    try {
      const Section section = tessellation_section(t, z);
      PictureOptions picture{.width_px = job.picture_width, .fill_by = section.phase, .outline_by = section.grain,
                             .scale_bar = true, .length_unit = length_unit};
      for (const Phase& p : t.phases) picture.legend.push_back(p.name);
      write_mesh_png(dir / "tessellation.png", section.cells, picture);
    } catch (const GeometryError& e) {
      // A picture is no reason to fail a run.
      warnings.add("tessellation.png not drawn: the section z = " + to_text(z) + " could not be drawn (" + e.what() +
                   "); another output.section may be");
    }
  }
  // The phases at the top, as in 2D; the rest of tessellation.json's statistics beside them.
  Json statistics = statistics_json(t.stats, t.phases);
  Json phases = std::move(statistics["phases"]);
  statistics.erase("phases");
  return {{"dimensions", 3},
          {"seed", job.seed},
          {"width", t.width},
          {"height", t.height},
          {"depth", t.depth},
          {"periodic", t.periodic},
          {"grains", t.stats.grains},
          {"phases", phases},
          {"statistics", statistics},
          {"section_z", z},
          {"vertices", t.vertices.size()},
          {"faces", t.faces.size()},
          {"regions", t.regions.size()}};
}

void print_tessellation_3d_summary(const Tessellation3& t, double seconds) {
  const Tessellation3Stats& s = t.stats;
  std::printf("grainmesh tessellate: %d grains in 3D, %zu regions, %zu faces, sharpest dihedral %.1f deg, shortest edge %.3g (%.3f s)\n",
              s.grains, t.regions.size(), t.faces.size(), s.sharpest_dihedral_deg, s.shortest_edge, seconds);
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    std::printf("  phase %-10s target %.4f achieved %.4f (%d grains)\n", t.phases[p].name.c_str(), s.phases[p].target_fraction,
                s.phases[p].achieved_fraction, s.phases[p].grains);
}

void run_tessellate_3d_command(const Config& c, const std::filesystem::path& out) {
  claim_output(out, "tessellate");
  const Tessellate3Job job = read_tessellate_3d_job(c);
  const auto start = std::chrono::steady_clock::now();
  Warnings warnings;
  const Tessellation3 t = run_tessellate_3d_job(job, warnings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  StagedOutput staged(out, "tessellate");
  Json report{{"config", c.source()}};
  report.update(write_tessellation_3d_files(staged.dir(), t, job, true, {}, warnings));
  report["seconds"] = seconds;
  add_time_limit(report, job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();

  print_tessellation_3d_summary(t, seconds);
  std::printf("  wrote %s/{tessellation.json, tessellation.vtu, tessellation.png (section z = %g), report.json}\n",
              out.string().c_str(), report["section_z"].get<double>());
}

}  // namespace grainmesh
