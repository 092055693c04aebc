#include "pipelines/result_pictures.hpp"

#include <tuple>

#include "analysis/phase_statistics.hpp"
#include "view/picture.hpp"

namespace grainmesh {

void write_field_pictures(const std::filesystem::path& dir, const CaseFields& fields,
                          const std::vector<StressState>& sigma, const ExportMesh<2>& m, int picture_width, bool all,
                          const std::string& unit) {
  if (picture_width == 0) return;
  std::vector<double> sxx, syy, sxy, d = displacement_length(fields);
  for (const StressState& s : sigma) sxx.push_back(1e-6 * s.xx), syy.push_back(1e-6 * s.yy), sxy.push_back(1e-6 * s.xy);
  for (double& v : d) v *= 1e9;
  // The stress components are signed (a diverging map, white at zero); |D| is not.
  std::vector<std::tuple<std::string, std::vector<double>, std::string, bool>> pictures{
      {"stress_xx.png", sxx, "sigma_xx (MPa)", true}};
  if (all) {
    pictures.emplace_back("stress_yy.png", syy, "sigma_yy (MPa)", true);
    pictures.emplace_back("stress_xy.png", sxy, "tau_xy (MPa)", true);
    pictures.emplace_back("displacement.png", d, "|D| (nm)", false);
  }
  for (const auto& [name, field, title, signed_field] : pictures)
    write_mesh_png(dir / name, m.mesh,
                   {.width_px = picture_width, .fill_by = {}, .outline_by = m.grain, .view = {}, .field = field,
                    .field_name = title, .signed_field = signed_field, .legend = {}, .scale_bar = true, .length_unit = unit});
}

void write_stress_histogram(const std::filesystem::path& file, const std::string& load_case,
                            const std::vector<StressState>& cell_stress, const Tessellation& t, const ExportMesh<2>& m) {
  const int phases = static_cast<int>(t.phases.size());
  write_stress_histogram(file, load_case, von_mises_histograms(cell_stress, m.mesh, m.phase, phases, kHistogramBins),
                         phase_names(t.phases), "area");
}

void write_stress_histogram(const std::filesystem::path& file, const std::string& load_case,
                            std::vector<std::vector<Vec2>> histograms, const std::vector<std::string>& phase_names,
                            const std::string& of_what) {
  Plot plot{.x_label = "von Mises stress (MPa), load case " + load_case, .y_label = "share of the phase's " + of_what,
            .series = {}};
  for (std::size_t p = 0; p < histograms.size(); ++p) {
    for (Vec2& point : histograms[p]) point.x *= 1e-6;
    plot.series.push_back({phase_names[p], histograms[p], true, static_cast<int>(p)});
  }
  write_plot_png(file, plot);
}


std::vector<std::string> phase_names(const std::vector<Phase>& phases) {
  std::vector<std::string> names;
  for (const Phase& p : phases) names.push_back(p.name);
  return names;
}

}  // namespace grainmesh
