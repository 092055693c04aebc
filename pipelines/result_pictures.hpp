// Pictures of a solved run: the fields over the cells and each phase's distribution of
// von Mises stress; and the phases' names, which results.vtu and the pictures show.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/stress_measures.hpp"
#include "export/export_mesh.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// Pictures of a solved case's fields over the cells, grain boundaries drawn (the thesis'
// 3.14-3.15), stresses in MPa, the displacement in nm, a scale bar in `unit`; none when
// picture_width is 0, sigma_xx alone when not `all`.
void write_field_pictures(const std::filesystem::path& dir, const CaseFields& fields,
                          const std::vector<StressState>& sigma, const ExportMesh<2>& m, int picture_width, bool all,
                          const std::string& unit);

// stress_histogram.png: each phase's distribution of von Mises stress in a load case, in
// kHistogramBins bins.
inline constexpr int kHistogramBins = 40;
void write_stress_histogram(const std::filesystem::path& file, const std::string& load_case,
                            const std::vector<StressState>& cell_stress, const Tessellation& t, const ExportMesh<2>& m);
// The same picture from each phase's histogram of von Mises stress in Pa (phase_histograms),
// its share `of_what` ("area", "volume").
void write_stress_histogram(const std::filesystem::path& file, const std::string& load_case,
                            std::vector<std::vector<Vec2>> histograms, const std::vector<std::string>& phase_names,
                            const std::string& of_what);

// The phases' names, in their order (the legends' and the VTU files' phase_names).
std::vector<std::string> phase_names(const std::vector<Phase>& phases);

}  // namespace grainmesh
