// Pictures of meshes (PNG, drawn with cairo), so a user sees what was made.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry.hpp"
#include "mesh/trimesh.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct PictureOptions {
  int width_px = 1200;  // image width; the height follows the mesh's aspect ratio
  int margin_px = 20;
  std::vector<int> outline_by{};  // #T labels: thick lines where they differ; empty = the region
  std::optional<Box> view{};      // draw only this window (a detail); default = the whole mesh
  // A field to show instead of the regions: one value per triangle, coloured (viridis)
  // from its 1st to its 99th percentile, with a colour bar titled `field_name` below.
  std::vector<double> field{};
  std::string field_name{};
};

// Triangles filled by region (region 0 grey-blue, 1 orange, further labels from a
// fixed palette) or by a field, thin mesh edges when they are at least a few pixels long,
// and thick lines along the mesh boundary and between regions (outline_by). Throws IoError.
void write_mesh_png(const std::filesystem::path& file, const TriMesh& mesh, const PictureOptions& options = {});

// The cell with its regions filled by phase (holes left open), grain boundaries in thin
// dark lines and the cell's sides in a thick one. Throws IoError.
void write_tessellation_png(const std::filesystem::path& file, const Tessellation& t,
                            const PictureOptions& options = {});

// A 2D plot: series of points (markers) or polylines, with axes, ticks and a legend.
struct PlotSeries {
  std::string name;     // empty: drawn, but not in the legend
  std::vector<Vec2> points;
  bool line = false;    // a polyline through the points (in their order), dashed
  int colour = 0;       // index into a fixed palette
  std::vector<double> error{};  // points: a bar of +- this at each (e.g. a 95 % CI); empty: none
};
struct Plot {
  std::string x_label, y_label;
  std::vector<PlotSeries> series;
  int width_px = 900, height_px = 600;
};
// Throws IoError when the file cannot be written or nothing is to be drawn.
void write_plot_png(const std::filesystem::path& file, const Plot& plot);

}  // namespace grainmesh
