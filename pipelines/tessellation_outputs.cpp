#include "pipelines/tessellation_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "pipelines/result_pictures.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/box_view.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

namespace {

// The fields both dimensions give: the phases at the top, the rest of the statistics
// (tessellation.json's) beside them.
template <class T>
Json cell_fields(const T& t, std::uint64_t seed) {
  Json statistics = statistics_json(t);
  Json phases = std::move(statistics["phases"]);
  statistics.erase("phases");
  return {{"seed", seed}, {"periodic", t.periodic}, {"grains", t.stats.grains}, {"phases", phases},
          {"statistics", statistics}, {"vertices", t.vertices.size()}, {"regions", t.regions.size()}};
}

// Binder mode's binder: a phase without grains of its own (2D), the matrix grain's (3D).
bool is_binder(const Tessellation& t, std::size_t p) {
  return t.stats.phases[p].grains == 0 && t.stats.phases[p].achieved_fraction > 0.0;
}
bool is_binder(const Tessellation3& t, std::size_t p) {
  return std::any_of(t.grains.begin(), t.grains.end(),
                     [&](const Grain3& g) { return g.matrix && g.phase == static_cast<int>(p); });
}

// The phases with their targets and descriptors (a phase of grains: its contiguity and
// mean intercept; the binder: its mean free path), and the grains' sizes as measured,
// under the summary line.
template <class T>
void print_phases(const T& t, const char* diameter) {
  for (std::size_t p = 0; p < t.phases.size(); ++p) {
    const auto& s = t.stats.phases[p];
    std::printf("  phase %-10s target %.4f achieved %.4f", t.phases[p].name.c_str(), s.target_fraction,
                s.achieved_fraction);
    if (is_binder(t, p)) {
      std::printf(" (binder)");
      if (std::isfinite(s.mean_free_path)) std::printf(", mean free path %.4g", s.mean_free_path);
    } else {
      std::printf(" (%d grain%s)", s.grains, s.grains == 1 ? "" : "s");
      if (s.grains > 0 && std::isfinite(s.contiguity)) std::printf(", contiguity %.3f", s.contiguity);
      if (s.grains > 0 && std::isfinite(s.intercept_length)) std::printf(", mean intercept %.4g", s.intercept_length);
    }
    std::printf("\n");
  }
  if (t.stats.diameter_mean > 0.0)
    std::printf("  grain size: %s diameter %.4g mean, %.3f coefficient of variation\n", diameter,
                t.stats.diameter_mean, t.stats.diameter_std / t.stats.diameter_mean);
}

}  // namespace

Json write_tessellation_files(const std::filesystem::path& dir, const Tessellation& t, const TessellateJob<2>& job,
                              const Drawing& drawing, Warnings&) {
  write_text_file(dir / "tessellation.json", tessellation_to_json(t));
  if (drawing.pictures)
    write_tessellation_png(dir / "tessellation.png", t,
                           {.width_px = job.picture_width, .legend = phase_names(t.phases), .scale_bar = true,
                            .length_unit = drawing.unit});
  Json fields{{"dimensions", 2}, {"width", t.width}, {"height", t.height}};
  fields.update(cell_fields(t, job.seed));
  fields["edges"] = t.edges.size();
  return fields;
}

Json write_tessellation_files(const std::filesystem::path& dir, const Tessellation3& t, const TessellateJob<3>& job,
                              const Drawing& drawing, Warnings& warnings) {
  write_text_file(dir / "tessellation.json", tessellation_to_json(t));
  const double z = section_height(t, job.section * t.depth);
  if (drawing.pictures) {
    try {
      const Section section = tessellation_section(t, z);
      write_mesh_png(dir / "tessellation.png", section.cells,
                     {.width_px = job.picture_width, .fill_by = section.phase, .outline_by = section.grain,
                      .legend = phase_names(t.phases), .scale_bar = true, .length_unit = drawing.unit});
    } catch (const GeometryError& e) {
      // A picture is no reason to fail a run.
      warnings.add("tessellation.png not drawn: the section z = " + to_text(z) + " could not be drawn (" + e.what() +
                   "); another output.section may be");
    }
    try {
      const BoxView view = box_view(t);
      std::vector<int> phase, region_grain;
      for (const int r : view.tet) phase.push_back(t.regions[static_cast<std::size_t>(r)].phase);
      for (const Region3& r : t.regions) region_grain.push_back(r.grain);
      write_mesh_png(dir / "tessellation_view.png", view.mesh,
                     {.width_px = job.picture_width, .fill_by = phase, .outline_by = view.outline(region_grain),
                      .shade = view.shade, .mesh_edges = false, .legend = phase_names(t.phases), .scale_bar = true,
                      .length_unit = drawing.unit});
    } catch (const GeometryError& e) {
      warnings.add(std::string("tessellation_view.png not drawn: ") + e.what());
    }
  }
  Json fields{{"dimensions", 3}, {"width", t.width}, {"height", t.height}, {"depth", t.depth}};
  fields.update(cell_fields(t, job.seed));
  fields["faces"] = t.faces.size();
  fields["section_z"] = z;
  return fields;
}

void write_tessellation_viewer(const std::filesystem::path& dir, const Tessellation& t) {
  write_tessellation_vtp(dir / "tessellation.vtp", t);
}

void write_tessellation_viewer(const std::filesystem::path& dir, const Tessellation3& t) {
  write_tessellation_vtu(dir / "tessellation.vtu", t);
}

void print_tessellation_summary(const Tessellation& t, double seconds) {
  const TessellationStats& s = t.stats;
  std::printf("grainmesh tessellate: %d grains, %zu regions, sharpest corner %.1f deg, shortest edge %.3g (%.3f s)\n",
              s.grains, t.regions.size(), s.sharpest_corner_deg, s.shortest_edge, seconds);
  print_phases(t, "equivalent-circle");
}

void print_tessellation_summary(const Tessellation3& t, double seconds) {
  const Tessellation3Stats& s = t.stats;
  std::printf("grainmesh tessellate: %d grains in 3D, %zu regions, %zu faces, sharpest dihedral %.1f deg, shortest "
              "edge %.3g (%.3f s)\n",
              s.grains, t.regions.size(), t.faces.size(), s.sharpest_dihedral_deg, s.shortest_edge, seconds);
  print_phases(t, "equivalent-sphere");
}

}  // namespace grainmesh
